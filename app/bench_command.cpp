#include "bench_command.h"
#include "app/output_folder.h"

#include "app/caster_lod_setup.h"
#include "app/resources.h"

#include "geometry/analysis/ground_truth.h"
#include "geometry/io/preset.h"
#include "geometry/io/scene_file.h"
#include "geometry/shadow/shadow_plan.h"
#include "renderer/context.h"
#include "renderer/measure.h"
#include "renderer/renderer.h"
#include "ui/chart_image.h"
#include "ui/charts/chart.h"
#include "ui/charts/tradeoff_chart.h"

#include <CLI/CLI.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace app {

namespace {

std::vector<std::string> splitList(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string item; std::getline(in, item, sep);) out.push_back(item);
    return out;
}

struct Sweep {
    std::string key;
    std::vector<std::string> values;
};

std::vector<Sweep> parseSweeps(const std::vector<std::string>& sweeps) {
    std::vector<Sweep> out;
    for (const auto& s : sweeps) {
        const auto eq = s.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == s.size())
            throw std::invalid_argument("--sweep " + s + ": expected key=v1,v2,...");
        Sweep sw{s.substr(0, eq), splitList(s.substr(eq + 1), ',')};
        if (!geometry::shadow::findSetting(sw.key))
            throw std::invalid_argument("--sweep " + s + ": unknown setting '" + sw.key + "'");
        for (const auto& v : sw.values) { // validate each value now, with the key's range in the message
            geometry::shadow::ShadowSettings probe;
            geometry::shadow::applySetting(probe, sw.key, v);
        }
        out.push_back(std::move(sw));
    }
    return out;
}

} // namespace

std::vector<BenchConfiguration> benchConfigurations(const BenchOptions& o) {
    const std::vector<Sweep> sweeps = parseSweeps(o.sweeps);
    size_t combinations = 1;
    for (const auto& s : sweeps) {
        combinations *= std::max<size_t>(s.values.size(), 1);
        if (combinations > 4096) throw std::invalid_argument("--sweep: more than 4096 configurations");
    }
    std::vector<std::pair<std::string, geometry::shadow::ShadowSettings>> bases;
    if (o.common.presets.empty()) bases.emplace_back("", geometry::shadow::ShadowSettings{});
    for (const auto& p : o.common.presets) bases.emplace_back(p, geometry::io::loadPreset(findResource(p)));
    if (bases.size() * combinations > 4096) throw std::invalid_argument("bench: more than 4096 configurations");
    std::vector<BenchConfiguration> out;
    for (const auto& [path, base] : bases) {
        const std::string stem = path.empty() ? "" : std::filesystem::path(path).stem().string();
        for (size_t c = 0; c < combinations; ++c) {
            BenchConfiguration cfg;
            cfg.preset = stem;
            cfg.settings = base;
            for (const auto& a : o.common.assignments) geometry::shadow::applyAssignment(cfg.settings, a);
            std::string label = stem.empty() ? "defaults" : stem;
            size_t rest = c;
            std::vector<std::string> parts(sweeps.size());
            for (size_t i = sweeps.size(); i-- > 0;) { // the last sweep varies fastest
                const std::string& v = sweeps[i].values[rest % sweeps[i].values.size()];
                rest /= sweeps[i].values.size();
                geometry::shadow::applySetting(cfg.settings, sweeps[i].key, v);
                parts[i] = sweeps[i].key + "=" + v;
            }
            for (const auto& p : parts) label += " " + p;
            cfg.label = label;
            out.push_back(std::move(cfg));
        }
    }
    return out;
}

void addBenchCommand(CLI::App& cmd, BenchOptions& o) {
    addRenderOptions(cmd, o.common, OptionUse::Bench);
    cmd.add_option("--sweep", o.sweeps, "key=v1,v2,...: one configuration per value (repeatable: all combinations)");
    cmd.add_option("--frames", o.frames, "Timed frames per configuration and view")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    // At least one: llvmpipe reports a bogus GL_TIME_ELAPSED (hours) for a new renderer's first frame.
    cmd.add_option("--warmup", o.warmup, "Untimed frames first (at least 1)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    addTruthOptions(cmd, o.truth, "Also measure misclassification against ray-traced truth (Embree)");
    addShardOption(cmd, o.shard, "configurations (each measures every view)");
    cmd.add_option("--path", o.path,
                   "Also walk this camera/light path of the scene file in --frames frames per configuration: "
                   "flicker_mean, flicker_p95 (world space), flicker_screen and seam columns");
    cmd.add_option("--x", o.x, "Trade-off chart x axis")
        ->check(CLI::IsMember(ui::charts::tradeoffXNames()))
        ->capture_default_str();
    cmd.add_option("--y", o.y,
                   "Trade-off chart y axis (interior, edge, misclassified, umbra need --truth; soft --truth and "
                   "light.angular_diameter_deg > 0; flicker --path)")
        ->check(CLI::IsMember(ui::charts::tradeoffYNames()))
        ->capture_default_str();
}

namespace {

struct Row {
    size_t configIndex = 0, viewIndex = 0; // in the whole run (every shard)
    std::string config, preset, view;
    double gamma = 0, gpuMs = 0, cpuMs = 0, p95 = 0, falseLit = 0, falseShadow = 0, memoryMiB = 0, shadowMs = 0;
    double soft = NAN; // soft_mean_abs, with truth and a sun of non-zero size
    uint64_t shadowTriangles = 0, shadowTrianglesWithoutLod = 0;
    geometry::analysis::TruthClasses classes; // with truth
    bool truth = false;
};

ui::charts::Chart benchChart(const std::vector<BenchConfiguration>& configs, const std::vector<Row>& rows,
                             const std::vector<renderer::PathFigures>& paths, ui::charts::TradeoffX xAxis,
                             ui::charts::TradeoffY yAxis) {
    // One point per configuration: the mean cost over the views; the geometric-mean p95 or the
    // mean fraction over the views; the path's mean flicker.
    using ui::charts::TradeoffX;
    using ui::charts::TradeoffY;
    std::vector<ui::charts::TradeoffPoint> points;
    for (size_t c = 0; c < configs.size(); ++c) {
        const auto& cfg = configs[c];
        double x = 0, y = 0;
        int n = 0;
        for (const Row& r : rows) {
            if (r.config != cfg.label) continue;
            const double cost = xAxis == TradeoffX::GpuMs ? r.gpuMs : xAxis == TradeoffX::CpuMs ? r.cpuMs : r.memoryMiB;
            const auto& k = r.classes;
            const double figure = yAxis == TradeoffY::P95        ? std::log(r.p95)
                                  : yAxis == TradeoffY::Interior ? k.interiorFalseShadow + k.interiorFalseLit
                                  : yAxis == TradeoffY::Edge     ? k.edgeError
                                  : yAxis == TradeoffY::Soft     ? r.soft
                                  : yAxis == TradeoffY::Umbra    ? k.umbraLight
                                                                 : r.falseLit + r.falseShadow;
            if (!std::isfinite(cost) || !std::isfinite(figure)) continue;
            x += cost;
            y += figure;
            ++n;
        }
        double value = n ? (yAxis == TradeoffY::P95 ? std::exp(y / n) : y / n) : NAN;
        if (yAxis == TradeoffY::Flicker) value = c < paths.size() ? paths[c].flickerMean : NAN;
        points.push_back({cfg.label, cfg.preset, n ? x / n : NAN, value});
    }
    ui::charts::Chart chart = ui::charts::tradeoffChart(points, xAxis, yAxis);
    if (rows.size() > configs.size()) chart.title += ", mean over views";
    return chart;
}

using NamedView = std::pair<std::string, geometry::io::CanonicalView>;

/// The views to measure: those --view names, else every view of the scene file, else its own camera and light.
std::vector<NamedView> benchViews(const geometry::io::SceneFile& file, const std::vector<std::string>& names) {
    std::vector<NamedView> views;
    if (names.empty())
        for (const auto& v : file.views) views.emplace_back(v);
    for (const auto& name : names) {
        const auto it = file.views.find(name);
        if (it == file.views.end()) throw std::invalid_argument("--view " + name + ": the scene has no such view");
        views.emplace_back(*it);
    }
    if (views.empty())
        views.emplace_back("default", geometry::io::CanonicalView{file.scene.camera, file.scene.lights[0]});
    return views;
}

/// Rejects a --y whose figure the run would not measure: the truth figures without --truth, flicker without --path.
void checkChartAxes(const BenchOptions& o, ui::charts::TradeoffY yAxis) {
    const bool needsTruth = yAxis == ui::charts::TradeoffY::Interior || yAxis == ui::charts::TradeoffY::Edge ||
                            yAxis == ui::charts::TradeoffY::Misclassified || yAxis == ui::charts::TradeoffY::Soft ||
                            yAxis == ui::charts::TradeoffY::Umbra;
    if (needsTruth && !o.truth.enabled) throw std::invalid_argument("--y " + o.y + " needs --truth");
    if (yAxis == ui::charts::TradeoffY::Flicker && o.path.empty())
        throw std::invalid_argument("--y flicker needs --path");
}

/// The scene file's path that --path names, or none when --path is empty.
std::optional<geometry::io::ScenePath> benchPath(const geometry::io::SceneFile& file, const std::string& name) {
    if (name.empty()) return std::nullopt;
    const auto it = file.paths.find(name);
    if (it == file.paths.end()) throw std::invalid_argument("--path " + name + ": the scene has no such path");
    return it->second;
}

/// The results row of one configuration measured at one view.
Row benchRow(const BenchConfiguration& cfg, const std::string& viewName, const renderer::Measurement& m) {
    const geometry::analysis::Inspection& in = m.inspection;
    Row row;
    row.config = cfg.label;
    row.preset = cfg.preset;
    row.view = viewName;
    row.gamma = m.plan.gammaDeg;
    row.gpuMs = m.gpuMs;
    row.cpuMs = m.cpuMs;
    row.p95 = in.aliasing.p95;
    row.memoryMiB = double(m.shadowMemoryBytes) / (1024.0 * 1024.0);
    row.shadowMs = m.shadowGpuMs;
    row.shadowTriangles = m.shadowTriangles;
    row.shadowTrianglesWithoutLod = m.shadowTrianglesWithoutLod;
    if (in.truth) {
        row.truth = true;
        row.falseLit = in.truth->falseLit;
        row.falseShadow = in.truth->falseShadow;
        if (in.truthClasses) row.classes = *in.truthClasses;
        if (in.softTruth) row.soft = in.softTruth->meanAbs;
    }
    return row;
}

constexpr const char* kResultsCsvHeader =
    "config,preset,view,gamma_deg,gpu_ms_median,cpu_ms_median,p95,false_lit,false_shadow,misclassified,"
    "shadow_memory_mib,frames,width,height,renderer,interior_false_shadow,interior_false_lit,edge_error,"
    "edge_displacement_texels,ambiguous,flicker_mean,flicker_p95,flicker_screen,seam,shadow_ms_median,"
    "shadow_triangles,shadow_triangles_without_lod,soft_mean_abs,umbra_light,contact_false_lit,contact_gap_p95,"
    "interior_mean_abs,edge_width_px,edge_width_texels,truth_singular\n";

/// One line of results.csv: a row, with the path figures of its configuration when there was a --path.
std::string resultsCsvLine(const Row& w, const BenchOptions& o, const renderer::PathFigures& f, bool hasPath,
                           const std::string& rendererName) {
    std::ostringstream csv;
    csv << '"' << w.config << "\"," << w.preset << ',' << w.view << ',' << w.gamma << ',' << w.gpuMs << ',' << w.cpuMs
        << ',' << w.p95 << ',';
    if (w.truth) csv << w.falseLit << ',' << w.falseShadow << ',' << (w.falseLit + w.falseShadow);
    else csv << ",,";
    csv << ',' << w.memoryMiB << ',' << o.frames << ',' << o.common.size.width << ',' << o.common.size.height << ",\""
        << rendererName << "\",";
    const auto& c = w.classes;
    if (w.truth)
        csv << c.interiorFalseShadow << ',' << c.interiorFalseLit << ',' << c.edgeError << ','
            << c.edgeDisplacementTexelsMedian << ',' << c.ambiguous;
    else csv << ",,,,";
    if (hasPath) csv << ',' << f.flickerMean << ',' << f.flickerP95 << ',' << f.flickerScreen << ',' << f.seam;
    else csv << ",,,,";
    csv << ',' << w.shadowMs << ',' << w.shadowTriangles << ',' << w.shadowTrianglesWithoutLod << ',';
    if (std::isfinite(w.soft)) csv << w.soft;
    csv << ',';
    if (w.truth)
        csv << c.umbraLight << ',' << c.contactFalseLit << ',' << c.contactGapP95 << ',' << c.interiorMeanAbs << ','
            << c.edgeWidthPx << ',' << c.edgeWidthTexels << ',' << c.singular;
    else csv << ",,,,,,";
    csv << '\n';
    return csv.str();
}

/// Writes results.csv from its lines.
void writeResultsCsv(const std::filesystem::path& dir, const std::vector<std::string>& lines) {
    std::string csv = kResultsCsvHeader;
    for (const std::string& line : lines) csv += line;
    writeTextFile(dir / "results.csv", csv);
}

/// NaN as JSON writes it (null), and back.
nlohmann::json figure(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
double figure(const nlohmann::json& j) { return j.is_number() ? j.get<double>() : NAN; }

/// What the chart needs of a row, and its results.csv line: results.json, which `merge` reads.
nlohmann::json rowJson(const Row& w, const std::string& csvLine) {
    const auto& c = w.classes;
    return {{"config_index", w.configIndex},
            {"view_index", w.viewIndex},
            {"config", w.config},
            {"preset", w.preset},
            {"view", w.view},
            {"gpu_ms", figure(w.gpuMs)},
            {"cpu_ms", figure(w.cpuMs)},
            {"memory_mib", figure(w.memoryMiB)},
            {"p95", figure(w.p95)},
            {"truth", w.truth},
            {"false_lit", figure(w.falseLit)},
            {"false_shadow", figure(w.falseShadow)},
            {"soft", figure(w.soft)},
            {"interior_false_shadow", figure(c.interiorFalseShadow)},
            {"interior_false_lit", figure(c.interiorFalseLit)},
            {"edge_error", figure(c.edgeError)},
            {"umbra_light", figure(c.umbraLight)},
            {"csv", csvLine}};
}

Row rowFromJson(const nlohmann::json& j) {
    Row w;
    w.configIndex = j.at("config_index").get<size_t>();
    w.viewIndex = j.at("view_index").get<size_t>();
    w.config = j.at("config").get<std::string>();
    w.preset = j.at("preset").get<std::string>();
    w.view = j.at("view").get<std::string>();
    w.gpuMs = figure(j.at("gpu_ms"));
    w.cpuMs = figure(j.at("cpu_ms"));
    w.memoryMiB = figure(j.at("memory_mib"));
    w.p95 = figure(j.at("p95"));
    w.truth = j.at("truth").get<bool>();
    w.falseLit = figure(j.at("false_lit"));
    w.falseShadow = figure(j.at("false_shadow"));
    w.soft = figure(j.at("soft"));
    w.classes.interiorFalseShadow = figure(j.at("interior_false_shadow"));
    w.classes.interiorFalseLit = figure(j.at("interior_false_lit"));
    w.classes.edgeError = figure(j.at("edge_error"));
    w.classes.umbraLight = figure(j.at("umbra_light"));
    return w;
}

/// The chart (tradeoff.svg and .png) of configurations, rows and path figures.
void writeChart(const std::filesystem::path& dir, const std::vector<BenchConfiguration>& configs,
                const std::vector<Row>& rows, const std::vector<renderer::PathFigures>& paths, ui::charts::TradeoffX x,
                ui::charts::TradeoffY y) {
    const ui::charts::Chart chart = benchChart(configs, rows, paths, x, y);
    ui::charts::writeSvg(dir / "tradeoff.svg", chart, 1000, 620);
    geometry::analysis::writePng((dir / "tradeoff.png").string(), ui::renderChartImage(chart, 1000, 620));
}

} // namespace

int runBench(const BenchOptions& o) {
    // --shard: configurations dealt round robin; each measures every view, so a configuration's
    // rows (and the ratios between them) come from one machine.
    const std::vector<BenchConfiguration> all = benchConfigurations(o);
    std::vector<BenchConfiguration> configs;
    std::vector<size_t> configIndex; // configs[i] is all[configIndex[i]]
    for (size_t c = 0; c < all.size(); ++c)
        if (!o.shard || c % o.shard->count == o.shard->index) {
            configs.push_back(all[c]);
            configIndex.push_back(c);
        }
    geometry::io::SceneFile file = geometry::io::resolveScene(findResource(o.common.scene), {}, o.common.up);
    const std::vector<NamedView> views = benchViews(file, o.common.views);
    const ui::charts::TradeoffX xAxis = ui::charts::parseTradeoffX(o.x).value_or(ui::charts::TradeoffX::GpuMs);
    const ui::charts::TradeoffY yAxis = ui::charts::parseTradeoffY(o.y).value_or(ui::charts::TradeoffY::P95);
    checkChartAxes(o, yAxis);
    checkLightIndex(o.common.lightIndex, file.scene);
    const std::optional<geometry::io::ScenePath> path = benchPath(file, o.path);
    createOutputFolder(o.common.out);

    auto context = renderer::createHeadlessContext(renderer::parseBackend(o.common.backend));
    geometry::scene::Scene& scene = file.scene;
    renderer::Renderer r(scene);
    std::unique_ptr<geometry::analysis::GroundTruth> truth;
    if (o.truth.enabled || path)
        truth = std::make_unique<geometry::analysis::GroundTruth>(geometry::analysis::GroundTruth::borrowing(scene));
    std::cerr << "bench: " << configs.size() << " configuration(s) × " << views.size() << " view(s), " << o.frames
              << " frames each on " << context->rendererString()
              << (o.shard ? ", shard " + o.shard->text() + " of " + std::to_string(all.size()) + " configurations"
                          : std::string())
              << '\n';

    std::vector<Row> rows;
    bool gpuTimes = true;
    const size_t total = configs.size() * views.size();
    for (size_t c = 0; c < configs.size(); ++c)
        for (size_t v = 0; v < views.size(); ++v) {
            const BenchConfiguration& cfg = configs[c];
            const auto& [viewName, view] = views[v];
            scene.camera = view.camera;
            scene.lights[0] = view.light; // a view names the first light (geometry/io/scene_file.h)
            ensureCasterLod(r, scene, cfg.settings);
            const renderer::MeasureView measured = renderer::measureView(scene, o.common.lightIndex);
            const renderer::Measurement m =
                renderer::measure(r, cfg.settings, scene.bounds(), scene.camera, measured.light, o.common.size,
                                  {.warmup = o.warmup, .frames = o.frames, .truthSamples = o.truth.samples},
                                  o.truth.enabled ? truth.get() : nullptr, measured.others);
            if (m.gpuFrames == 0) gpuTimes = false;
            Row& row = rows.emplace_back(benchRow(cfg, viewName, m));
            row.configIndex = configIndex[c];
            row.viewIndex = v;
            std::cerr << "[" << rows.size() << "/" << total << "] " << cfg.label << " @ " << viewName << ": GPU "
                      << row.gpuMs << " ms, CPU " << row.cpuMs << " ms, p95 m " << row.p95 << '\n';
        }
    std::vector<renderer::PathFigures> paths(configs.size());
    if (path)
        for (size_t c = 0; c < configs.size(); ++c) {
            scene.camera = views.front().second.camera;
            scene.lights[0] = views.front().second.light;
            paths[c] =
                renderer::measurePath(r, configs[c].settings, scene.bounds(),
                                      {path->cameras, {path->lights, path->lightPositions}, path->lightIndex}, scene,
                                      o.common.lightIndex, o.frames, o.common.size, *truth, o.truth.samples);
            std::cerr << "[path " << o.path << ", " << (c + 1) << "/" << configs.size() << "] " << configs[c].label
                      << ": world-space flicker " << paths[c].flickerMean << ", screen " << paths[c].flickerScreen
                      << ", seam " << paths[c].seam << '\n';
        }
    if (const std::string errors = renderer::takeGlErrors(); !errors.empty())
        throw std::runtime_error("GL error: " + errors);

    const std::filesystem::path dir(o.common.out);
    std::vector<std::string> lines;
    nlohmann::json results = {{"kind", "bench"},
                              {"config_count", all.size()},
                              {"x", o.x},
                              {"y", o.y},
                              {"gpu_times", gpuTimes},
                              {"rows", nlohmann::json::array()},
                              {"paths", nlohmann::json::array()}};
    for (const auto& cfg : all) results["configs"].push_back({{"label", cfg.label}, {"preset", cfg.preset}});
    for (const Row& row : rows) {
        const size_t c =
            size_t(std::find(configIndex.begin(), configIndex.end(), row.configIndex) - configIndex.begin());
        lines.push_back(resultsCsvLine(row, o, paths[c], path.has_value(), context->rendererString()));
        results["rows"].push_back(rowJson(row, lines.back()));
    }
    for (size_t c = 0; c < configs.size(); ++c)
        results["paths"].push_back({{"config_index", configIndex[c]}, {"flicker_mean", figure(paths[c].flickerMean)}});
    writeResultsCsv(dir, lines);
    const ui::charts::TradeoffX x =
        xAxis == ui::charts::TradeoffX::GpuMs && !gpuTimes ? ui::charts::TradeoffX::CpuMs : xAxis;
    writeChart(dir, configs, rows, paths, x, yAxis);
    writeTextFile(dir / "results.json", results.dump(1) + "\n");
    for (const char* f : {"results.csv", "tradeoff.svg", "tradeoff.png", "results.json"})
        std::cout << (dir / f).string() << '\n';
    return 0;
}

int mergeBench(const std::vector<nlohmann::json>& shards, const std::string& out) {
    const auto fail = [](const std::string& problem) { throw std::invalid_argument("merge: " + problem); };
    const nlohmann::json& first = shards.front();
    const size_t count = first.at("config_count").get<size_t>();
    std::vector<BenchConfiguration> configs(count);
    for (size_t c = 0; c < count; ++c) {
        configs[c].label = first.at("configs").at(c).at("label").get<std::string>();
        configs[c].preset = first.at("configs").at(c).at("preset").get<std::string>();
    }
    std::vector<Row> rows;
    std::vector<std::string> lines;
    std::vector<renderer::PathFigures> paths(count);
    std::vector<bool> seen(count, false);
    bool gpuTimes = true;
    for (const nlohmann::json& s : shards) {
        if (s.at("configs") != first.at("configs") || s.at("x") != first.at("x") || s.at("y") != first.at("y"))
            fail("the folders come from different bench runs (configurations or chart axes differ)");
        gpuTimes = gpuTimes && s.at("gpu_times").get<bool>();
        for (const auto& p : s.at("paths")) {
            const size_t c = p.at("config_index").get<size_t>();
            if (c >= count || seen[c])
                fail("configuration " + std::to_string(c) + " is in two shards (or out of range)");
            seen[c] = true;
            paths[c].flickerMean = figure(p.at("flicker_mean"));
        }
        for (const auto& r : s.at("rows")) {
            rows.push_back(rowFromJson(r));
            lines.push_back(r.at("csv").get<std::string>());
        }
    }
    for (size_t c = 0; c < count; ++c)
        if (!seen[c]) fail("configuration '" + configs[c].label + "' is in no folder (a shard missing?)");
    // The order one unsharded run writes: configuration, then view.
    std::vector<size_t> order(rows.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return std::tie(rows[a].configIndex, rows[a].viewIndex) < std::tie(rows[b].configIndex, rows[b].viewIndex);
    });
    std::vector<Row> sortedRows;
    std::vector<std::string> sortedLines;
    nlohmann::json merged = first;
    merged["gpu_times"] = gpuTimes;
    merged["rows"] = nlohmann::json::array();
    merged["paths"] = nlohmann::json::array();
    for (const size_t i : order) {
        sortedRows.push_back(rows[i]);
        sortedLines.push_back(lines[i]);
        merged["rows"].push_back(rowJson(rows[i], lines[i]));
    }
    for (size_t c = 0; c < count; ++c)
        merged["paths"].push_back({{"config_index", c}, {"flicker_mean", figure(paths[c].flickerMean)}});
    const std::filesystem::path dir(out);
    createOutputFolder(out);
    writeResultsCsv(dir, sortedLines);
    // The chart's PNG is drawn with GL (ImGui's renderer), on the CPU: the same pixels on every machine.
    const auto context = renderer::createHeadlessContext(renderer::parseBackend("osmesa"));
    const ui::charts::TradeoffX xAxis =
        ui::charts::parseTradeoffX(first.at("x").get<std::string>()).value_or(ui::charts::TradeoffX::GpuMs);
    const ui::charts::TradeoffY yAxis =
        ui::charts::parseTradeoffY(first.at("y").get<std::string>()).value_or(ui::charts::TradeoffY::P95);
    writeChart(dir, configs, sortedRows, paths,
               xAxis == ui::charts::TradeoffX::GpuMs && !gpuTimes ? ui::charts::TradeoffX::CpuMs : xAxis, yAxis);
    writeTextFile(dir / "results.json", merged.dump(1) + "\n");
    for (const char* f : {"results.csv", "tradeoff.svg", "tradeoff.png", "results.json"})
        std::cout << (dir / f).string() << '\n';
    return 0;
}

} // namespace app
