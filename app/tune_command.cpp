// Index
//   addTuneCommand ....... the options
//   writeCsv, describe ... tune.csv and the figures as printed (modelled cost; measured time apart)
//   fewestReceivers ...... what decides the screening size
//   calibrateCost ........ --calibrate-cost: the cost model's fit on this backend
//   startSettings, tuneViews ... what runTune starts from
//   measureRequests ...... measures what the tuner asks for
//   writeTuneChart ....... tune.svg, tune.png
//   reportRecommended, reportClosest ... the preset saved, what is printed, the exit code
//   runTune .............. the search, its files and exit code

#include "tune_command.h"
#include "app/output_folder.h"

#include "app/caster_lod_setup.h"
#include "app/resources.h"

#include "geometry/analysis/ground_truth.h"
#include "geometry/analysis/image.h"
#include "geometry/analysis/tuner.h"
#include "geometry/io/preset.h"
#include "geometry/io/scene_file.h"
#include "renderer/context.h"
#include "renderer/measure.h"
#include "renderer/renderer.h"
#include "ui/chart_image.h"
#include "ui/charts/tune_chart.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace app {

using geometry::analysis::TuneEvaluation;
using geometry::analysis::TuneStage;

void addTuneCommand(CLI::App& cmd, TuneCommandOptions& o) {
    addRenderOptions(cmd, o.common, OptionUse::Bench);
    cmd.add_option("--target", o.target,
                   "KEY=VALUE[,KEY=VALUE...]: the figures to reach, each at or below its value. Keys: p95 (aliasing "
                   "m), interior (interior false shadow + false lit), edge (edge error), misclassified (false shadow "
                   "+ false lit), contact (shadow lost near contacts: peter-panning); fractions of the receiver "
                   "pixels; interior_abs (mean |s - c| inside lit and shadowed regions), edge_width (the wrong band "
                   "across edges, texels), soft (mean |s - v| against the sun's disk: set "
                   "light.angular_diameter_deg > 0), umbra (mean s in the truth's umbra: light bleeding)");
    cmd.add_flag("--calibrate-cost", o.calibrateCost,
                 "Fit the cost model tune ranks by (ns per triangle, texel, tap, pixel) to this backend: measures a "
                 "fixed set of configurations on the views and writes cost_model.json (docs/design.md \"Cost "
                 "model\")");
    cmd.add_option("--space", o.spaces,
                   "KEY=v1,v2,...: search these values of a setting (replaces its default candidates, or adds the "
                   "key; repeatable)");
    addTruthOptions(cmd, o.truth, "");
    cmd.add_option("--budget-evals", o.budgetEvals, "Measurements in all, screening and full-size confirmation")
        ->check(CLI::Range(2, 100000))
        ->capture_default_str();
    cmd.add_option("--frames", o.frames, "Timed frames per measurement (after one warm-up)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
}

namespace {

std::string stageName(TuneStage s) { return s == TuneStage::Screen ? "screen" : "full"; }

/// Every searched key's value, "key=value;…" (the configuration in tune.csv).
std::string spaceSettings(const geometry::analysis::Tuner& tuner, const geometry::shadow::ShadowSettings& s) {
    std::string out;
    for (const auto& axis : tuner.space())
        if (const auto* info = geometry::shadow::findSetting(axis.key))
            out += (out.empty() ? "" : ";") + axis.key + "=" + info->format(s);
    return out;
}

/// The figures that decide, and the modelled cost: the same on every run (no measured time).
std::string describe(const geometry::analysis::TuneFigures& f) {
    std::ostringstream os;
    os << "p95 " << f.p95 << ", interior " << f.interior << ", edge " << f.edge << ", edge width " << f.edgeWidth
       << " texels, contact " << f.contact << ", interior |s-c| " << f.interiorAbs << ", misclassified "
       << f.misclassified << ", cost " << f.costMs << " ms, " << double(f.memoryBytes) / (1024.0 * 1024.0) << " MiB";
    return os.str();
}

void writeCsv(const std::filesystem::path& path, const geometry::analysis::Tuner& tuner, std::optional<size_t> chosen) {
    std::ofstream csv(path);
    // frame_ms, measured, comes last: the one column that differs between two runs.
    csv << "index,stage,width,height,label,p95,interior,edge,edge_width,contact,interior_abs,misclassified,cost_ms,"
           "memory_mib,violation,meets,chosen,settings,frame_ms\n";
    const auto& evals = tuner.evaluations();
    for (size_t i = 0; i < evals.size(); ++i) {
        const TuneEvaluation& e = evals[i];
        const auto& f = e.figures;
        csv << i << ',' << stageName(e.request.stage) << ',' << e.request.size.width << ',' << e.request.size.height
            << ",\"" << e.request.label << "\"," << f.p95 << ',' << f.interior << ',' << f.edge << ',' << f.edgeWidth
            << ',' << f.contact << ',' << f.interiorAbs << ',' << f.misclassified << ',' << f.costMs << ','
            << double(f.memoryBytes) / (1024.0 * 1024.0) << ',' << e.violation << ',' << (e.meets() ? 1 : 0) << ','
            << (chosen == i ? 1 : 0) << ",\"" << spaceSettings(tuner, e.candidate) << "\"," << f.frameMs << '\n';
    }
    if (!csv) throw std::runtime_error("cannot write " + path.string());
}

/// Receiver pixels of the fewest-receiver view at full size: a property of the scene and the views,
/// measured once with the start settings (tuner.h decides the screening size from it).
double fewestReceivers(renderer::Renderer& r, const geometry::shadow::ShadowSettings& start,
                       const geometry::scene::Aabb& S, const std::vector<renderer::MeasureView>& views,
                       geometry::shadow::Viewport size) {
    double fewest = 0;
    for (size_t v = 0; v < views.size(); ++v) {
        const renderer::Measurement m =
            renderer::measure(r, start, S, views[v].camera, views[v].light, size,
                              {.warmup = 0, .frames = 1, .timed = false}, nullptr, views[v].others);
        const double n = double(std::count(m.inspection.receiver.begin(), m.inspection.receiver.end(), uint8_t(1)));
        fewest = v == 0 ? n : std::min(fewest, n);
    }
    return fewest;
}

/// --calibrate-cost: a fixed set of configurations spanning the kinds of work (resolution, splits,
/// filter taps, peeling, moments, sizes), each measured on every view; the least-squares fit.
int calibrateCost(renderer::Renderer& r, const geometry::shadow::ShadowSettings& start,
                  const geometry::scene::Scene& scene, const std::vector<renderer::MeasureView>& views,
                  const TuneCommandOptions& o, const std::string& rendererString, const std::filesystem::path& dir) {
    using namespace geometry::analysis;
    const std::vector<std::vector<std::string>> configs{
        {"shadow_map.resolution=512"},
        {"shadow_map.resolution=4096"},
        {"splits.count=4", "splits.scheme=pssm", "shadow_map.resolution=2048"},
        {"splits.count=8", "splits.scheme=pssm", "shadow_map.resolution=1024"},
        {"filter.type=pcf", "filter.kernel=7"},
        {"filter.type=pcf", "filter.kernel=3", "shadow_map.resolution=1024"},
        {"filter.type=disk", "filter.taps=32"},
        {"filter.type=pcss", "filter.taps=16", "light.angular_diameter_deg=0.5"},
        {"filter.type=vsm", "filter.kernel=5"},
        {"filter.type=evsm4", "filter.kernel=9", "shadow_map.resolution=1024"},
        {"bias.type=midpoint"},
        {"bias.type=dual_depth", "splits.count=3", "splits.scheme=pssm"}};
    std::vector<CostSample> samples;
    std::ofstream csv(dir / "cost_calibration.csv");
    csv << "config,view,width,height," << [] {
        std::string h;
        for (const auto name : workKindNames()) h += std::string(name) + ",";
        return h;
    }() << "ms\n";
    for (const auto& config : configs) {
        geometry::shadow::ShadowSettings s = start;
        std::string label;
        for (const auto& a : config) {
            geometry::shadow::applyAssignment(s, a);
            label += (label.empty() ? "" : " ") + a;
        }
        for (const geometry::shadow::Viewport size :
             {o.common.size, geometry::shadow::Viewport{o.common.size.width / 2, o.common.size.height / 2}})
            for (size_t v = 0; v < views.size(); ++v) {
                ensureCasterLod(r, scene, s);
                const renderer::Measurement m =
                    renderer::measure(r, s, scene.bounds(), views[v].camera, views[v].light, size,
                                      {.warmup = 1, .frames = o.frames}, nullptr, views[v].others);
                const double ms = std::isfinite(m.gpuMs) ? m.gpuMs : m.cpuMs;
                const WorkCounts w = countWork(s, m.plan, m.shadowTriangles, m.eyeTriangles, size);
                samples.push_back({w, ms});
                csv << '"' << label << "\"," << v << ',' << size.width << ',' << size.height << ',';
                for (const double x : w.values()) csv << x << ',';
                csv << ms << '\n';
                std::cerr << "calibrate: " << label << " view " << v << " " << size.width << 'x' << size.height << ": "
                          << ms << " ms\n";
            }
    }
    const CostModel model = fitCostModel(samples, rendererString);
    const std::filesystem::path path = dir / "cost_model.json";
    std::ofstream out(path);
    out << costModelJson(model) << '\n';
    if (!out || !csv) throw std::runtime_error("cannot write " + path.string());
    double worst = 0;
    for (const CostSample& c : samples) worst = std::max(worst, std::abs(model.costMs(c.work) - c.ms) / c.ms);
    std::cout << path.string() << '\n'
              << (dir / "cost_calibration.csv").string() << '\n'
              << "cost model fitted to " << samples.size() << " frames; the worst frame off by " << 100.0 * worst
              << " %\n";
    return 0;
}

/// The search's start: the one --preset (or the defaults) with every --set applied.
geometry::shadow::ShadowSettings startSettings(const TuneCommandOptions& o) {
    if (o.common.presets.size() > 1) throw std::invalid_argument("--preset: tune starts from one preset");
    geometry::shadow::ShadowSettings start;
    if (!o.common.presets.empty()) start = geometry::io::loadPreset(findResource(o.common.presets.front()));
    for (const auto& a : o.common.assignments) geometry::shadow::applyAssignment(start, a);
    return start;
}

/// The views tune measures every configuration on.
struct TuneViews {
    std::vector<renderer::MeasureView> views;
    std::vector<std::string> names; // empty when the scene's camera stands in for views
    std::string line;               // the names for messages: "a, b" or "the scene's camera"
};

/// The --view views, else every canonical view (as bench), else the scene's camera; each inspects the
/// scene's light `inspected` with every other light drawn too (a view names the first light).
TuneViews tuneViews(const geometry::io::SceneFile& file, const std::vector<std::string>& asked, size_t inspected) {
    checkLightIndex(inspected, file.scene);
    std::vector<geometry::scene::Light> lights = file.scene.lights;
    TuneViews out;
    out.names = asked;
    if (out.names.empty())
        for (const auto& [name, view] : file.views) out.names.push_back(name);
    for (const auto& name : out.names) {
        const auto it = file.views.find(name);
        if (it == file.views.end()) throw std::invalid_argument("--view " + name + ": the scene has no such view");
        lights[0] = it->second.light;
        out.views.push_back(renderer::measureView(it->second.camera, lights, inspected));
        out.line += (out.line.empty() ? "" : ", ") + name;
    }
    if (out.views.empty()) {
        out.views.push_back(renderer::measureView(file.scene, inspected));
        out.line = "the scene's camera";
    }
    return out;
}

/// Measures what the tuner asks for until it is done; returns each evaluation's figures per view.
std::vector<std::vector<geometry::analysis::TuneFigures>>
measureRequests(geometry::analysis::Tuner& tuner, renderer::Renderer& r, geometry::scene::Scene& scene,
                const std::vector<renderer::MeasureView>& views, const geometry::analysis::GroundTruth& truth,
                const geometry::analysis::CostModel& costModel, const TuneCommandOptions& o) {
    std::vector<std::vector<geometry::analysis::TuneFigures>> perView;
    while (const auto request = tuner.next()) {
        ensureCasterLod(r, scene, request->settings);
        perView.emplace_back();
        const geometry::analysis::TuneFigures f =
            renderer::measureTuneRequest(r, *request, scene.bounds(), views, truth, o.truth.samples, costModel,
                                         {.warmup = 1, .frames = o.frames}, &perView.back());
        tuner.report(f);
        const TuneEvaluation& e = tuner.evaluations().back();
        std::cerr << "[" << tuner.evaluations().size() << "/" << o.budgetEvals << "] " << stageName(request->stage)
                  << ' ' << request->size.width << 'x' << request->size.height << ' ' << request->label << ": "
                  << describe(e.figures) << ", measured " << f.frameMs << " ms"
                  << (e.meets() ? " - meets" : " - misses") << '\n';
    }
    return perView;
}

/// tune.svg and tune.png: every evaluation's modelled cost against its distance to the target.
void writeTuneChart(const std::filesystem::path& dir, const geometry::analysis::Tuner& tuner,
                    const geometry::analysis::TuneTarget& target, std::optional<size_t> chosen) {
    std::vector<ui::charts::TunePoint> points;
    for (size_t i = 0; i < tuner.evaluations().size(); ++i) {
        const TuneEvaluation& e = tuner.evaluations()[i];
        points.push_back({e.request.label, e.figures.costMs, geometry::analysis::targetRatio(e.figures, target),
                          e.request.stage == TuneStage::Full, chosen == i});
    }
    const ui::charts::Chart chart = ui::charts::tuneChart(points, geometry::analysis::formatTuneTarget(target));
    ui::charts::writeSvg(dir / "tune.svg", chart, 1000, 620);
    geometry::analysis::writePng((dir / "tune.png").string(), ui::renderChartImage(chart, 1000, 620));
}

/// Saves the chosen configuration as recommended.json and prints it; exit code 0.
int reportRecommended(const std::filesystem::path& dir, const TuneEvaluation& e, const std::string& sceneName,
                      const std::string& viewLine, geometry::shadow::Viewport size,
                      const geometry::analysis::TuneTarget& target, const std::string& summary) {
    const std::string path = (dir / "recommended.json").string();
    geometry::io::savePreset(path, e.candidate, "recommended",
                             "shadowscope tune on " + sceneName + " (" + viewLine + ") at " +
                                 std::to_string(size.width) + "x" + std::to_string(size.height) + ": meets " +
                                 geometry::analysis::formatTuneTarget(target) + "; " + describe(e.figures));
    std::cout << path << '\n'
              << "recommended: " << e.request.label << " (" << describe(e.figures) << ", measured " << e.figures.frameMs
              << " ms)\n"
              << summary << '\n';
    return 0;
}

/// Nothing met the target: saves the closest as closest.json, prints what it misses, per view too; exit code 3.
int reportClosest(const std::filesystem::path& dir, const TuneEvaluation& e,
                  const std::vector<geometry::analysis::TuneFigures>& perView, const std::vector<std::string>& names,
                  const std::string& sceneName, const geometry::analysis::TuneTarget& target,
                  const std::string& summary) {
    using geometry::analysis::describeMisses;
    using geometry::analysis::formatTuneTarget;
    std::vector<std::string> viewList = names;
    if (viewList.empty()) viewList.push_back("the scene's camera");
    const std::string path = (dir / "closest.json").string();
    geometry::io::savePreset(path, e.candidate, "closest",
                             "shadowscope tune on " + sceneName + ": closest to " + formatTuneTarget(target) +
                                 ", misses " + describeMisses(e.figures, target) + "; " + describe(e.figures));
    std::cout << path << '\n'
              << "no configuration meets " << formatTuneTarget(target) << "; closest: " << e.request.label << " ("
              << describe(e.figures) << "), misses " << describeMisses(e.figures, target) << '\n';
    // Which view misses what, with its figures.
    for (size_t v = 0; v < perView.size() && v < viewList.size(); ++v) {
        const geometry::analysis::TuneFigures& f = perView[v];
        const std::string misses = describeMisses(f, target);
        std::cout << "  view " << viewList[v] << ": " << (misses.empty() ? "meets" : "misses " + misses) << " ("
                  << describe(f) << ")\n";
    }
    std::cout << summary << '\n';
    return 3;
}

} // namespace

int runTune(const TuneCommandOptions& o) {
    using namespace geometry::analysis;
    if (o.target.empty() && !o.calibrateCost) throw std::invalid_argument("--target is required");
    const TuneTarget target = o.calibrateCost && o.target.empty() ? TuneTarget{} : parseTuneTarget(o.target);
    std::vector<TuneAxis> space = defaultTuneSpace();
    for (const auto& spec : o.spaces) overrideTuneAxis(space, spec);
    const geometry::shadow::ShadowSettings start = startSettings(o);
    // Checked before anything is loaded or measured: a bad target, space or start is a one-line error.
    if (!o.calibrateCost) (void)Tuner(start, space, target, {.size = o.common.size, .budgetEvals = o.budgetEvals});

    geometry::io::SceneFile file = geometry::io::resolveScene(findResource(o.common.scene), {}, o.common.up);
    geometry::scene::Scene& scene = file.scene;
    const TuneViews views = tuneViews(file, o.common.views, o.common.lightIndex);
    const std::filesystem::path dir(o.common.out);
    createOutputFolder(dir);

    auto context = renderer::createHeadlessContext(renderer::parseBackend(o.common.backend));
    renderer::Renderer r(scene);
    if (o.calibrateCost)
        return calibrateCost(r, start, scene, views.views, o,
                             std::string(renderer::backendName(context->backend())) + ": " + context->rendererString(),
                             dir);
    bool calibrated = false;
    const CostModel costModel = storedCostModel(context->rendererString(), &calibrated);
    if (!calibrated)
        std::cerr << "tune: no cost model calibrated for " << context->rendererString() << "; ranking with "
                  << costModel.backend << "'s (tune --calibrate-cost fits one)\n";
    ensureCasterLod(r, scene, start);
    Tuner tuner(start, space, target,
                {.size = o.common.size,
                 .budgetEvals = o.budgetEvals,
                 .receiverPixels = fewestReceivers(r, start, scene.bounds(), views.views, o.common.size)});
    const GroundTruth truth = GroundTruth::borrowing(scene);
    const double spaceSize = tuneSpaceSize(tuner.space());
    std::cerr << "tune: " << scene.name << " (" << views.line << "), target " << formatTuneTarget(target)
              << ", a space of " << spaceSize << " configurations, at most " << o.budgetEvals << " evaluations on "
              << context->rendererString() << ", screening at "
              << (tuner.screensAtHalfSize() ? "half size" : "full size (half size could not resolve the target)")
              << '\n';
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<std::vector<TuneFigures>> perView =
        measureRequests(tuner, r, scene, views.views, truth, costModel, o);
    if (const std::string errors = renderer::takeGlErrors(); !errors.empty())
        throw std::runtime_error("GL error: " + errors);
    const double minutes = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / 60.0;

    const std::optional<size_t> chosen = tuner.recommended();
    writeCsv(dir / "tune.csv", tuner, chosen);
    writeTuneChart(dir, tuner, target, chosen);

    std::ostringstream summary;
    summary << tuner.evaluations().size() << " evaluations (" << tuner.fullEvaluations()
            << " at full size, of a space of " << spaceSize << " configurations) in " << minutes << " min";
    for (const char* f : {"tune.csv", "tune.svg", "tune.png"}) std::cout << (dir / f).string() << '\n';
    if (chosen)
        return reportRecommended(dir, tuner.evaluations()[*chosen], scene.name, views.line, o.common.size, target,
                                 summary.str());
    const std::optional<size_t> near = tuner.closest();
    if (!near) throw std::runtime_error("tune: nothing was evaluated");
    return reportClosest(dir, tuner.evaluations()[*near], perView[*near], views.names, scene.name, target,
                         summary.str());
}

} // namespace app
