#include "tune_command.h"

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
                   "+ false lit); fractions of the receiver pixels; soft (mean |s - v| against the sun's disk: set "
                   "light.angular_diameter_deg > 0), umbra (mean s in the truth's umbra: light bleeding)")
        ->required();
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

std::string describe(const TuneEvaluation& e) {
    std::ostringstream os;
    const auto& f = e.figures;
    os << "p95 " << f.p95 << ", interior " << f.interior << ", edge " << f.edge << ", misclassified " << f.misclassified
       << ", frame " << f.frameMs << " ms, " << double(f.memoryBytes) / (1024.0 * 1024.0) << " MiB";
    return os.str();
}

void writeCsv(const std::filesystem::path& path, const geometry::analysis::Tuner& tuner, std::optional<size_t> chosen) {
    std::ofstream csv(path);
    csv << "index,stage,width,height,label,p95,interior,edge,misclassified,frame_ms,memory_mib,cost_ms,"
           "violation,meets,chosen,settings\n";
    const auto& evals = tuner.evaluations();
    for (size_t i = 0; i < evals.size(); ++i) {
        const TuneEvaluation& e = evals[i];
        const auto& f = e.figures;
        csv << i << ',' << stageName(e.request.stage) << ',' << e.request.size.width << ',' << e.request.size.height
            << ",\"" << e.request.label << "\"," << f.p95 << ',' << f.interior << ',' << f.edge << ','
            << f.misclassified << ',' << f.frameMs << ',' << double(f.memoryBytes) / (1024.0 * 1024.0) << ','
            << f.frameMs << ',' << e.violation << ',' << (e.meets() ? 1 : 0) << ',' << (chosen == i ? 1 : 0) << ",\""
            << spaceSettings(tuner, e.candidate) << "\"\n";
    }
    if (!csv) throw std::runtime_error("cannot write " + path.string());
}

} // namespace

int runTune(const TuneCommandOptions& o) {
    using namespace geometry::analysis;
    const TuneTarget target = parseTuneTarget(o.target);
    std::vector<TuneAxis> space = defaultTuneSpace();
    for (const auto& spec : o.spaces) overrideTuneAxis(space, spec);
    if (o.common.presets.size() > 1) throw std::invalid_argument("--preset: tune starts from one preset");
    geometry::shadow::ShadowSettings start;
    if (!o.common.presets.empty()) start = geometry::io::loadPreset(findResource(o.common.presets.front()));
    for (const auto& a : o.common.assignments) geometry::shadow::applyAssignment(start, a);
    Tuner tuner(start, space, target, {.size = o.common.size, .budgetEvals = o.budgetEvals});

    geometry::io::SceneFile file = geometry::io::resolveScene(findResource(o.common.scene), {}, o.common.up);
    geometry::scene::Scene& scene = file.scene;
    std::vector<renderer::MeasureView> views;
    std::string viewNames;
    std::vector<std::string> names = o.common.views;
    if (names.empty()) // every canonical view, as bench
        for (const auto& [name, view] : file.views) names.push_back(name);
    for (const auto& name : names) {
        const auto it = file.views.find(name);
        if (it == file.views.end()) throw std::invalid_argument("--view " + name + ": the scene has no such view");
        views.push_back({it->second.camera, it->second.light});
        viewNames += (viewNames.empty() ? "" : ", ") + name;
    }
    if (views.empty()) {
        views.push_back({scene.camera, scene.light});
        viewNames = "the scene's camera";
    }
    const std::filesystem::path dir(o.common.out);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create output folder " + dir.string() + ": " + ec.message());

    auto context = renderer::createHeadlessContext(renderer::parseBackend(o.common.backend));
    renderer::Renderer r(scene);
    const GroundTruth truth(scene);
    const double spaceSize = tuneSpaceSize(tuner.space());
    std::cerr << "tune: " << scene.name << " (" << viewNames << "), target " << formatTuneTarget(target)
              << ", a space of " << spaceSize << " configurations, at most " << o.budgetEvals << " evaluations on "
              << context->rendererString() << '\n';
    const auto t0 = std::chrono::steady_clock::now();
    while (const auto request = tuner.next()) {
        ensureCasterLod(r, scene, request->settings);
        const TuneFigures f = renderer::measureTuneRequest(r, *request, scene.bounds(), views, truth, o.truth.samples,
                                                           {.warmup = 1, .frames = o.frames});
        tuner.report(f);
        const TuneEvaluation& e = tuner.evaluations().back();
        std::cerr << "[" << tuner.evaluations().size() << "/" << o.budgetEvals << "] " << stageName(request->stage)
                  << ' ' << request->size.width << 'x' << request->size.height << ' ' << request->label << ": "
                  << describe(e) << (e.meets() ? " - meets" : " - misses") << '\n';
    }
    if (const std::string errors = renderer::takeGlErrors(); !errors.empty())
        throw std::runtime_error("GL error: " + errors);
    const double minutes = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / 60.0;

    const std::optional<size_t> chosen = tuner.recommended();
    writeCsv(dir / "tune.csv", tuner, chosen);
    std::vector<ui::charts::TunePoint> points;
    for (size_t i = 0; i < tuner.evaluations().size(); ++i) {
        const TuneEvaluation& e = tuner.evaluations()[i];
        points.push_back({e.request.label, e.figures.frameMs, targetRatio(e.figures, target),
                          e.request.stage == TuneStage::Full, chosen == i});
    }
    const ui::charts::Chart chart = ui::charts::tuneChart(points, formatTuneTarget(target));
    ui::charts::writeSvg(dir / "tune.svg", chart, 1000, 620);
    writePng((dir / "tune.png").string(), ui::renderChartImage(chart, 1000, 620));

    std::ostringstream summary;
    summary << tuner.evaluations().size() << " evaluations (" << tuner.fullEvaluations()
            << " at full size, of a space of " << spaceSize << " configurations) in " << minutes << " min";
    for (const char* f : {"tune.csv", "tune.svg", "tune.png"}) std::cout << (dir / f).string() << '\n';
    if (chosen) {
        const TuneEvaluation& e = tuner.evaluations()[*chosen];
        const std::string path = (dir / "recommended.json").string();
        geometry::io::savePreset(path, e.candidate, "recommended",
                                 "shadowscope tune on " + scene.name + " (" + viewNames + ") at " +
                                     std::to_string(o.common.size.width) + "x" + std::to_string(o.common.size.height) +
                                     ": meets " + formatTuneTarget(target) + "; " + describe(e));
        std::cout << path << '\n'
                  << "recommended: " << e.request.label << " (" << describe(e) << ")\n"
                  << summary.str() << '\n';
        return 0;
    }
    const std::optional<size_t> near = tuner.closest();
    if (!near) throw std::runtime_error("tune: nothing was evaluated");
    const TuneEvaluation& e = tuner.evaluations()[*near];
    const std::string path = (dir / "closest.json").string();
    geometry::io::savePreset(path, e.candidate, "closest",
                             "shadowscope tune on " + scene.name + ": closest to " + formatTuneTarget(target) +
                                 ", misses " + describeMisses(e.figures, target));
    std::cout << path << '\n'
              << "no configuration meets " << formatTuneTarget(target) << "; closest: " << e.request.label << " ("
              << describe(e) << "), misses " << describeMisses(e.figures, target) << '\n'
              << summary.str() << '\n';
    return 3;
}

} // namespace app
