// `shadowscope sweep path`: a camera or light path of a scene file, frame by frame, with the
// flicker and seam measures of geometry/analysis/stability_metrics.h.
#include "app/output_folder.h"
#include "app/resources.h"
#include "sweep_command.h"
#include "sweep_frame.h"

#include "geometry/analysis/stability_metrics.h"
#include "geometry/io/scene_file.h"
#include "geometry/scene/path_interpolation.h"
#include "ui/charts/chart.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace app {

namespace {

struct PathRow {
    int frame = 0;
    double t = 0, gammaDeg = 0, angleDeg = 0;
    geometry::analysis::FlickerStats flicker;      // screen space: the same pixel
    geometry::analysis::FlickerStats worldFlicker; // world space: the same point (reprojected)
    geometry::analysis::SeamStats seam;
    double p95 = 0, falseLit = 0, falseShadow = 0, nPrime = 0;
    bool glError = false;
};

std::string pathCsv(const std::vector<PathRow>& rows) {
    std::string out = "frame,t,gamma_deg,angle_deg,flicker,flicker_pixels,seam_median,seam_p95,seam_pairs,"
                      "seam_raw_median,seam_baseline,p95,false_lit,false_shadow,n_prime,gl_errors,flicker_world,"
                      "flicker_world_pixels\n";
    const auto num = formatCsvNumber;
    for (const PathRow& r : rows)
        out += std::to_string(r.frame) + "," + num(r.t) + "," + num(r.gammaDeg) + "," + num(r.angleDeg) + "," +
               num(r.flicker.rate) + "," + std::to_string(r.flicker.stable) + "," + num(r.seam.median) + "," +
               num(r.seam.p95) + "," + std::to_string(r.seam.pairs) + "," + num(r.seam.rawMedian) + "," +
               num(r.seam.baselineMedian) + "," + num(r.p95) + "," + num(r.falseLit) + "," + num(r.falseShadow) + "," +
               num(r.nPrime) + "," + (r.glError ? "1" : "0") + "," + num(r.worldFlicker.rate) + "," +
               std::to_string(r.worldFlicker.stable) + "\n";
    return out;
}

ui::charts::ChartSeries series(const std::vector<PathRow>& rows, std::string name, int colour,
                               double (*value)(const PathRow&), bool skipFirst = false) {
    ui::charts::ChartSeries s;
    s.name = std::move(name);
    s.colour = ui::charts::paletteColour(colour);
    for (const PathRow& r : rows)
        if (!(skipFirst && r.frame == 0)) s.points.push_back({double(r.frame), value(r)});
    return s;
}

std::string pathSvg(const std::vector<PathRow>& rows, const std::string& title) {
    const ui::charts::ChartAxis frames{"frame", false, std::nullopt, std::nullopt};
    const auto chart = [&](std::string title, ui::charts::ChartAxis y) {
        ui::charts::Chart c;
        c.title = std::move(title);
        c.x = frames;
        c.y = std::move(y);
        return c;
    };
    ui::charts::Chart flicker = chart("Flicker: stable-truth pixels that flip", {"fraction", false, 0.0, std::nullopt});
    flicker.series.push_back(series(
        rows, "flicker (screen)", 0, [](const PathRow& r) { return r.flicker.rate; }, true));
    flicker.series.push_back(series(
        rows, "flicker (world)", 1, [](const PathRow& r) { return r.worldFlicker.rate; }, true));
    ui::charts::Chart seam =
        chart("Seams: jump of m across split boundaries", {"median seam (1 = none)", false, 1.0, std::nullopt});
    seam.series.push_back(series(rows, "across split boundaries", 1, [](const PathRow& r) {
        return r.seam.pairs ? r.seam.median : NAN; // no boundary on screen: no point
    }));
    seam.series.push_back(
        series(rows, "inside one split (baseline)", 2, [](const PathRow& r) { return r.seam.baselineMedian; }));
    ui::charts::Chart p95 = chart("Aliasing error m, p95 over receivers", {"p95 m", true, std::nullopt, std::nullopt});
    p95.series.push_back(series(rows, "p95 m", 3, [](const PathRow& r) { return r.p95; }));
    return ui::charts::chartsToSvg(title, {flicker, seam, p95}, 3, 420, 300);
}

double mean(const std::vector<PathRow>& rows, double (*value)(const PathRow&), bool (*use)(const PathRow&)) {
    double sum = 0;
    int n = 0;
    for (const PathRow& r : rows)
        if (use(r)) sum += value(r), ++n;
    return n ? sum / n : 0.0;
}

/// The scene file's path --path names; unknown names are an error listing the paths there are.
geometry::io::ScenePath findPath(const geometry::io::SceneFile& file, const SweepPathOptions& o) {
    const auto it = file.paths.find(o.path);
    if (it == file.paths.end()) {
        std::string names;
        for (const auto& [name, p] : file.paths) names += (names.empty() ? "" : ", ") + name;
        throw std::invalid_argument("--path " + o.path + ": scene '" + o.render.scene + "' has no such path (" +
                                    (names.empty() ? std::string("it has none") : "available: " + names) + ")");
    }
    return it->second;
}

/// The file's scene with its camera and light where --view, --camera and --light put them (the path's start).
geometry::scene::Scene startScene(geometry::io::SceneFile& file, const RenderOptions& render) {
    geometry::scene::Scene scene = std::move(file.scene);
    if (!render.view.empty()) {
        const auto view = file.views.find(render.view);
        if (view == file.views.end())
            throw std::invalid_argument("--view " + render.view + ": scene '" + render.scene + "' has no such view");
        scene.camera = view->second.camera;
        scene.lights[0] = view->second.light;
    }
    if (render.camera) scene.camera.eye = render.camera->eye, scene.camera.target = render.camera->target;
    checkLightIndex(render.lightIndex, scene);
    if (render.light) scene.lights[render.lightIndex].direction = *render.light;
    return scene;
}

/// One frame's row; the flicker compares it with the frame before (none for the first).
PathRow pathRow(int i, double t, const SweepFrame& f, const SweepFrame& previous, const geometry::scene::Camera& camera,
                geometry::shadow::Viewport size) {
    PathRow r;
    r.frame = i;
    r.t = t;
    r.gammaDeg = f.plan.gammaDeg;
    r.angleDeg = f.plan.lightViewAngleDeg;
    r.seam = geometry::analysis::seamStats(f.in.m, f.in.aux, f.in.receiver, f.in.positions, f.in.normals, camera.eye,
                                           size.width, size.height);
    if (i > 0) {
        const auto pair =
            geometry::analysis::framePairFlicker(previous.in, previous.plan.eyeProj * previous.plan.eyeView, f.in);
        r.flicker = pair.screen;
        r.worldFlicker = pair.world;
    }
    r.p95 = f.in.aliasing.p95;
    r.falseLit = f.in.truth->falseLit;
    r.falseShadow = f.in.truth->falseShadow;
    r.nPrime = f.plan.splits.front().nPrime;
    r.glError = !f.glErrors.empty();
    return r;
}

/// Renders the path frame by frame from `scene`'s camera and light; the GL errors go to `glErrors`, per frame.
std::vector<PathRow> walkPath(SweepRenderer& sweeper, const SweepPathOptions& o, const geometry::io::ScenePath& path,
                              const geometry::scene::Scene& scene, std::vector<std::string>& glErrors) {
    std::vector<PathRow> rows;
    SweepFrame previous;
    SweepProgress progress("sweep path " + o.path, o.frames);
    for (int i = 0; i < o.frames; ++i) {
        const double t = geometry::scene::pathParameter(i, o.frames);
        const geometry::scene::Camera camera =
            path.cameras.empty() ? scene.camera : geometry::scene::cameraAlongPath(path.cameras, t);
        std::vector<geometry::scene::Light> lights = scene.lights;
        lights[path.lightIndex] =
            geometry::scene::lightAlongPath(lights[path.lightIndex], {path.lights, path.lightPositions}, t);
        const renderer::MeasureView view = renderer::measureView(camera, lights, o.render.lightIndex);
        geometry::shadow::validateFrustum(camera.near, camera.far, camera.fovYDeg);
        SweepFrame f = sweeper.render(o.render.settings, camera, view.light, o.render.size, view.others);
        const PathRow& r = rows.emplace_back(pathRow(i, t, f, previous, camera, o.render.size));
        if (r.glError) glErrors.push_back("frame " + std::to_string(i) + ": " + f.glErrors);
        previous = std::move(f);
        progress.step(i + 1, "frame " + std::to_string(i));
    }
    return rows;
}

/// Writes path.csv.
void writePathCsv(const std::filesystem::path& csv, const std::vector<PathRow>& rows) {
    std::ofstream out(csv, std::ios::binary);
    out << pathCsv(rows);
    out.close();
    if (!out) throw std::runtime_error("cannot write " + csv.string());
}

/// The title of path.svg: the path, the scene, the frame size and the shadow settings that matter most.
std::string pathTitle(const SweepPathOptions& o, const std::string& sceneName) {
    const geometry::shadow::ShadowSettings& s = o.render.settings;
    return "Path '" + o.path + "' of " + sceneName + ", " + std::to_string(o.frames) + " frames, " +
           std::to_string(o.render.size.width) + "x" + std::to_string(o.render.size.height) + ", " +
           std::to_string(s.resolution) + "² maps, " + std::to_string(s.splits.count) + " split(s) " +
           std::string(geometry::shadow::splitSchemeName(s.splits.scheme));
}

/// Prints the summary line: the path's means of flicker, seams and p95.
void printPathSummary(const std::vector<PathRow>& rows, int frames) {
    const auto all = [](const PathRow&) { return true; };
    const auto afterFirst = [](const PathRow& r) { return r.frame > 0; };
    const auto withSeams = [](const PathRow& r) { return r.seam.pairs > 0; };
    std::cout << "summary: frames " << frames << ", flicker mean "
              << formatCsvNumber(mean(
                     rows, [](const PathRow& r) { return r.flicker.rate; }, afterFirst))
              << ", world-space flicker mean "
              << formatCsvNumber(mean(
                     rows, [](const PathRow& r) { return r.worldFlicker.rate; }, afterFirst))
              << ", seam median mean "
              << formatCsvNumber(mean(
                     rows, [](const PathRow& r) { return r.seam.median; }, withSeams))
              << " (raw "
              << formatCsvNumber(mean(
                     rows, [](const PathRow& r) { return r.seam.rawMedian; }, withSeams))
              << ", baseline "
              << formatCsvNumber(mean(
                     rows, [](const PathRow& r) { return r.seam.baselineMedian; }, all))
              << ", crossings per frame "
              << formatCsvNumber(mean(
                     rows, [](const PathRow& r) { return double(r.seam.pairs); }, all))
              << "), p95 mean "
              << formatCsvNumber(mean(
                     rows, [](const PathRow& r) { return r.p95; }, all))
              << '\n';
}

} // namespace

int runSweepPath(const SweepPathOptions& o) {
    if (o.frames < 1 || o.frames > kMaxPathFrames)
        throw std::invalid_argument("--frames: " + std::to_string(o.frames) + " must be within 1.." +
                                    std::to_string(kMaxPathFrames));
    geometry::shadow::validateOrThrow(o.render.settings);
    geometry::io::SceneFile file = geometry::io::resolveScene(findResource(o.render.scene), {}, o.render.up);
    const geometry::io::ScenePath path = findPath(file, o);
    const geometry::scene::Scene scene = startScene(file, o.render);
    createOutputFolder(o.render.out);
    const std::filesystem::path dir(o.render.out);

    SweepRenderer sweeper(scene, o.render.backend);
    std::vector<std::string> glErrors;
    const std::vector<PathRow> rows = walkPath(sweeper, o, path, scene, glErrors);
    const std::filesystem::path csv = dir / "path.csv", svg = dir / "path.svg";
    writePathCsv(csv, rows);
    ui::charts::writeSvgText(svg, pathSvg(rows, pathTitle(o, scene.name)));
    for (const auto& e : glErrors) std::cerr << "shadowscope: GL error: " << e << '\n';
    std::cout << csv.string() << '\n' << svg.string() << '\n';
    printPathSummary(rows, o.frames);
    return glErrors.empty() ? 0 : 1;
}

} // namespace app
