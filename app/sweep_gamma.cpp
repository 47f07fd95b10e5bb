// `shadowscope sweep gamma`: the light turned about the eye, every warp method at every angle.
#include "app/output_folder.h"
#include "sweep_command.h"
#include "sweep_frame.h"

#include "geometry/analysis/caster_coverage.h"
#include "geometry/analysis/stability_metrics.h"
#include "geometry/scene/light_angle.h"
#include "geometry/shadow/warp.h"
#include "ui/charts/chart.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <stdexcept>

namespace app {

namespace {

geometry::shadow::WarpMethod parseMethod(const std::string& name) {
    for (int m = 0; m < int(geometry::shadow::kEnumCount<geometry::shadow::WarpMethod>); ++m)
        if (geometry::shadow::warpMethodName(geometry::shadow::WarpMethod(m)) == name)
            return geometry::shadow::WarpMethod(m);
    std::string list;
    for (int m = 0; m < int(geometry::shadow::kEnumCount<geometry::shadow::WarpMethod>); ++m)
        list +=
            (list.empty() ? "" : ", ") + std::string(geometry::shadow::warpMethodName(geometry::shadow::WarpMethod(m)));
    throw std::invalid_argument("--methods: unknown warp method '" + name + "' (expected " + list + ")");
}

SweepRecord record(double angleDeg, const std::string& method, const SweepFrame& f) {
    SweepRecord r;
    r.angleDeg = angleDeg;
    r.method = method;
    r.gammaDeg = f.plan.gammaDeg;
    const auto& s0 = f.plan.splits.front();
    r.nPrime = s0.nPrime;
    r.lambda = s0.lambda;
    r.nPrimeMin = std::numeric_limits<double>::infinity();
    for (const auto& s : f.plan.splits)
        if (!s.empty()) r.nPrimeMin = std::min(r.nPrimeMin, s.nPrime);
    const auto& a = f.in.aliasing;
    r.p50 = a.p50;
    r.p95 = a.p95;
    r.max = a.max;
    r.mean = a.mean;
    r.receivers = double(a.count);
    r.singular = a.singular;
    r.falseLit = f.in.truth->falseLit;
    r.falseShadow = f.in.truth->falseShadow;
    r.glErrors = f.glErrors.empty() ? 0 : 1;
    const geometry::analysis::CasterCoverage c = geometry::analysis::casterCoverage(
        f.plan, f.in.positions, f.in.aux, f.in.receiver, *f.in.occluded, f.in.shadow);
    r.clippedCasters = c.clipped;
    r.falseLitClipped = c.falseLitClipped;
    return r;
}

ui::charts::Chart methodChart(const std::vector<SweepRecord>& rows, const std::vector<std::string>& methods,
                              std::string title, ui::charts::ChartAxis y,
                              const std::function<double(const SweepRecord&)>& value, bool skipUniform) {
    ui::charts::Chart c;
    c.title = std::move(title);
    c.x = {"light-view angle acos(v·l), degrees (0: light behind the eye, 180: facing it)", false, 0.0, 180.0};
    c.y = std::move(y);
    for (size_t k = 0; k < methods.size(); ++k) {
        if (skipUniform && methods[k] == "uniform") continue;
        ui::charts::ChartSeries s;
        s.name = methods[k];
        s.colour = ui::charts::paletteColour(int(k));
        for (const SweepRecord& r : rows)
            if (r.method == methods[k]) s.points.push_back({r.angleDeg, value(r)});
        c.series.push_back(std::move(s));
    }
    return c;
}

/// The warps --methods names, each once, in the order given, with the names as given.
struct SweptMethods {
    std::vector<geometry::shadow::WarpMethod> methods;
    std::vector<std::string> names;
};

/// Parses --methods; a method named twice, or none, is an error.
SweptMethods parseMethods(const std::vector<std::string>& given) {
    SweptMethods out;
    for (const auto& name : given) {
        const auto m = parseMethod(name);
        if (std::find(out.methods.begin(), out.methods.end(), m) != out.methods.end())
            throw std::invalid_argument("--methods: '" + name + "' is given twice");
        out.methods.push_back(m);
        out.names.push_back(name);
    }
    if (out.methods.empty()) throw std::invalid_argument("--methods: no method given");
    return out;
}

/// Renders every method at every angle (angle by angle); the GL errors go to `glErrors`, per frame.
std::vector<SweepRecord> renderSweep(SweepRenderer& sweeper, const SweepGammaOptions& o,
                                     const geometry::scene::Scene& scene, const std::vector<double>& angles,
                                     const SweptMethods& swept, std::vector<std::string>& glErrors) {
    const std::vector<geometry::shadow::WarpMethod>& methods = swept.methods;
    const std::vector<std::string>& names = swept.names;
    const glm::vec3 v = scene.camera.viewDir();
    const glm::vec3 reference = scene.lights[0].l();
    std::vector<SweepRecord> rows;
    SweepProgress progress("sweep gamma", int(angles.size() * methods.size()));
    for (const double angle : angles) {
        const geometry::scene::Light light{geometry::scene::lightAtViewAngle(v, reference, float(angle))};
        // Uniform at every angle, swept or not: the continuity rule compares each warp with it.
        const auto renderMethod = [&](geometry::shadow::WarpMethod method, const std::string& name) {
            geometry::shadow::ShadowSettings settings = o.render.settings;
            settings.warp.method = method;
            const SweepFrame f = sweeper.render(settings, scene.camera, light, o.render.size);
            if (!f.glErrors.empty()) glErrors.push_back(name + " at " + formatCsvNumber(angle) + " deg: " + f.glErrors);
            return record(angle, name, f);
        };
        const SweepRecord uniform = renderMethod(geometry::shadow::WarpMethod::Uniform, "uniform");
        for (size_t k = 0; k < methods.size(); ++k) {
            SweepRecord r =
                methods[k] == geometry::shadow::WarpMethod::Uniform ? uniform : renderMethod(methods[k], names[k]);
            r.p95Uniform = uniform.p95;
            rows.push_back(r);
            progress.step(int(rows.size()), names[k] + " at " + formatCsvNumber(angle) + " deg");
        }
    }
    return rows;
}

/// Writes sweep.csv.
void writeSweepCsv(const std::filesystem::path& csv, const std::vector<SweepRecord>& rows) {
    std::ofstream out(csv, std::ios::binary);
    out << sweepCsvHeader() << '\n';
    for (const auto& r : rows) out << sweepCsvRow(r) << '\n';
    out.close();
    if (!out) throw std::runtime_error("cannot write " + csv.string());
}

/// The charts' common subtitle: the scene and view, the frame size, the map size and the splits.
std::string sweepWhere(const SweepGammaOptions& o, const std::string& sceneName) {
    return sceneName + (o.render.view.empty() ? "" : " " + o.render.view) + ", " + std::to_string(o.render.size.width) +
           "x" + std::to_string(o.render.size.height) + ", " + std::to_string(o.render.settings.resolution) +
           "² maps, " + std::to_string(o.render.settings.splits.count) + " split(s)";
}

/// The sweep's charts, each with the file it goes to: n', p95 m, the gain over uniform, false lit, false shadow.
std::vector<std::pair<std::filesystem::path, ui::charts::Chart>> sweepCharts(const std::filesystem::path& dir,
                                                                             const std::vector<SweepRecord>& rows,
                                                                             const std::vector<std::string>& names,
                                                                             const std::string& where) {
    // m at the shader's cap for a singular J (receivers edge-on to the light) is not a measurement:
    // those points are left out of the m charts rather than squashing every curve.
    const auto measured = [](double m) { return m < geometry::analysis::kSingularM ? m : NAN; };
    return {
        {dir / "n_prime.svg",
         methodChart(
             rows, names, "n' of split 0 (uniform: ∞, not drawn) — " + where, {"n'", true, std::nullopt, std::nullopt},
             [](const SweepRecord& r) { return r.nPrime; }, true)},
        {dir / "p95.svg", methodChart(
                              rows, names, "p95 of m over receivers — " + where,
                              {"p95 m (pixels per texel)", true, std::nullopt, std::nullopt},
                              [&](const SweepRecord& r) { return measured(r.p95); }, false)},
        {dir / "gain.svg", methodChart(
                               rows, names, "p95 m relative to uniform (the continuity measure) — " + where,
                               {"p95 m / p95 m of uniform", true, std::nullopt, std::nullopt},
                               [&](const SweepRecord& r) { return measured(r.p95) / measured(r.p95Uniform); }, false)},
        {dir / "false_lit.svg", methodChart(
                                    rows, names, "False lit (truth shadowed, rendered lit) — " + where,
                                    {"fraction of receiver pixels", false, 0.0, std::nullopt},
                                    [](const SweepRecord& r) { return r.falseLit; }, false)},
        {dir / "false_shadow.svg", methodChart(
                                       rows, names, "False shadow (truth lit, rendered shadowed) — " + where,
                                       {"fraction of receiver pixels", false, 0.0, std::nullopt},
                                       [](const SweepRecord& r) { return r.falseShadow; }, false)},
    };
}

} // namespace

int runSweepGamma(const SweepGammaOptions& o) {
    const SweptMethods swept = parseMethods(o.methods);
    const std::vector<double> angles = sweepAngles(o.fromDeg, o.toDeg, o.stepDeg);
    geometry::shadow::validateOrThrow(o.render.settings);
    const geometry::scene::Scene scene = loadScene(o.render);
    geometry::shadow::validateFrustum(scene.camera.near, scene.camera.far, scene.camera.fovYDeg);
    createOutputFolder(o.render.out);
    const std::filesystem::path dir(o.render.out);

    SweepRenderer sweeper(scene, o.render.backend);
    std::vector<std::string> glErrors;
    const std::vector<SweepRecord> rows = renderSweep(sweeper, o, scene, angles, swept, glErrors);

    const std::filesystem::path csv = dir / "sweep.csv";
    writeSweepCsv(csv, rows);
    const auto charts = sweepCharts(dir, rows, swept.names, sweepWhere(o, scene.name));
    for (const auto& [path, chart] : charts) ui::charts::writeSvg(path, chart, 860, 480);
    for (const auto& e : glErrors) std::cerr << "shadowscope: GL error: " << e << '\n';
    std::cout << csv.string() << '\n';
    for (const auto& [path, chart] : charts) std::cout << path.string() << '\n';
    // A GL error fails the run with or without --check, as it fails `render`.
    if (!o.check) return glErrors.empty() ? 0 : 1;
    const auto failures = checkSweep(rows, o.thresholds);
    for (const auto& f : failures) std::cerr << "shadowscope: check failed: " << f << '\n';
    return failures.empty() && glErrors.empty() ? 0 : 1;
}

} // namespace app
