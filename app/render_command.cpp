#include "render_command.h"
#include "app/output_folder.h"

#include "dashboard_setup.h"
#include "geometry/analysis/ground_truth.h"
#include "geometry/analysis/heatmap.h"
#include "geometry/analysis/stability_metrics.h"
#include "geometry/analysis/view_images.h"
#include "headless_frame.h"
#include "light_metrics.h"
#include "renderer/inspection.h"
#include "ui/dashboard_headless.h"

#include <CLI/CLI.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace app {

const std::vector<std::string>& viewNames() {
    static const std::vector<std::string> names = {"eye",    "light",  "light_unwarped", "aliasing", "truth",
                                                   "splits", "texels", "dashboard",      "pixels",   "shadow_map",
                                                   "soft"};
    return names;
}

using geometry::analysis::Inspection;
using renderer::inspect;

nlohmann::json frameMetrics(const HeadlessFrame& f, const RenderOptions& o) {
    const auto& stats = f.renderer->stats();
    using renderer::Pass;
    nlohmann::json j;
    j["renderer"] = f.context->rendererString();
    j["gl_version"] = f.context->versionString();
    j["backend"] = renderer::backendName(f.context->backend());
    j["scene"] = f.scene.name;
    j["size"] = {o.size.width, o.size.height};
    j["shadow_res"] = o.settings.resolution;
    nlohmann::json settings;
    for (const auto& info : geometry::shadow::settingsDeclaration())
        settings[std::string(info.key)] = info.format(o.settings);
    j["settings"] = settings;
    nlohmann::json splits = nlohmann::json::array();
    for (size_t i = 0; i < f.plan.splits.size(); ++i) {
        const auto& s = f.plan.splits[i];
        splits.push_back(
            {{"near", s.near},
             {"far", s.far},
             {"n_prime", s.warped() ? nlohmann::json(s.nPrime) : nlohmann::json("inf")},
             {"lambda", s.lambda},
             {"resolution", s.resolution},
             {"empty", s.empty()},
             {"samples", s.samples},
             {"skipped", s.skipped},
             {"triangles", i < stats.splitTriangles.size() ? stats.splitTriangles[i] : 0},
             {"triangles_without_lod", i < stats.splitTrianglesFull.size() ? stats.splitTrianglesFull[i] : 0}});
    }
    j["splits"] = splits;
    j["shadow_map_resolution_used"] = stats.shadowResolution;
    // The plan's (budget, settings without effect) then the renderer's (GL limits, caster LOD).
    std::vector<std::string> warnings = f.plan.warnings;
    warnings.insert(warnings.end(), stats.warnings.begin(), stats.warnings.end());
    j["warnings"] = warnings;
    j["triangles"] = f.scene.triangleCount();              // held in memory
    j["placed_triangles"] = f.scene.placedTriangleCount(); // in the world: instances count once per placement
    j["gamma_deg"] = f.plan.gammaDeg;
    j["light_view_angle_deg"] = f.plan.lightViewAngleDeg;
    j["camera"] = {{"eye", {f.scene.camera.eye.x, f.scene.camera.eye.y, f.scene.camera.eye.z}},
                   {"target", {f.scene.camera.target.x, f.scene.camera.target.y, f.scene.camera.target.z}},
                   {"near", f.scene.camera.near},
                   {"far", f.scene.camera.far}};
    j["light"] = {f.plan.l.x, f.plan.l.y, f.plan.l.z};
    j["focus"] = {{"mode", f.plan.fittedToSamples ? "samples" : "geometry"},
                  {"samples", f.plan.sampleCount},
                  {"sample_depth_range", {f.plan.sampleDepthRange.x, f.plan.sampleDepthRange.y}}};
    j["timing_ms"] = {{"prepass", stats.gpu.of(Pass::Prepass)},
                      {"shadow", stats.gpu.of(Pass::Shadow)},
                      {"eye", stats.gpu.of(Pass::Eye)},
                      {"light_view", stats.gpu.of(Pass::LightView)},
                      {"frame", stats.gpu.frame()},
                      {"total", stats.gpu.total()}};
    j["plan_us"] = f.planMicroseconds;
    j["triangles_submitted"] = {{"shadow", stats.shadowTriangles}, {"eye", stats.eyeTriangles}};
    j["shadow_memory_bytes"] = stats.shadowMemoryBytes;
    // technique = virtual: the pages of this frame (docs/design.md §3.11); null for fitted maps.
    const auto& v = stats.virtualPages;
    j["virtual_pages"] = v.active
                             ? nlohmann::json{{"requested", v.requested},
                                              {"allocated", v.allocated},
                                              {"drawn", v.drawn},
                                              {"cached", v.cached},
                                              {"drawn_total", v.drawnTotal},
                                              {"pool_pages", v.poolPages},
                                              {"pool_occupied", v.occupied},
                                              {"pool_occupancy", v.poolPages ? double(v.occupied) / v.poolPages : 0.0},
                                              {"memory_bytes", v.memoryBytes},
                                              {"finest_level", v.finestLevel},
                                              {"uncovered_pixels", v.uncovered},
                                              {"page_triangles", v.pageTriangles},
                                              {"warning", v.warning}}
                             : nlohmann::json(nullptr);
    return j;
}

void addExportOptions(CLI::App& cmd, ExportOptions& e) {
    std::string names;
    for (const auto& v : viewNames()) names += (names.empty() ? "" : ",") + v;
    cmd.add_option("--views", e.views, "Views to write, comma-separated: " + names)
        ->delimiter(',')
        ->check(CLI::IsMember(viewNames()))
        ->capture_default_str();
    addTruthOptions(cmd, e.truth, "Ray-trace ground truth (Embree) and report misclassified pixels");
    cmd.add_option("--texel-grid", e.texelGrid, "texels view: draw every N-th texel line")->check(CLI::Range(1, 4096));
    cmd.add_option("--light-split", e.lightSplit, "light views: show this split's map")
        ->check(CLI::Range(0, geometry::shadow::kMaxSplits - 1));
    cmd.add_option_function<std::string>(
        "--depth-range",
        [&e](const std::string& text) {
            float lo = 0, hi = 0;
            char comma = 0;
            std::istringstream in(text);
            if (!(in >> lo >> comma >> hi) || comma != ',' || !(in >> std::ws).eof() || !std::isfinite(lo) ||
                !std::isfinite(hi) || lo < 0.f || hi > 1.f || !(lo < hi))
                throw std::invalid_argument("--depth-range: expected LO,HI with 0 <= LO < HI <= 1, got '" + text + "'");
            e.depthRange = {lo, hi};
        },
        "light view: depth shown from black to white (map depth, 0..1); default: fitted to B_i");
    cmd.add_flag("--light-texels", e.lightTexels, "light view: tint the texels that visible pixels sample");
    cmd.add_option("--heatmap-blend", e.heatmapBlend,
                   "aliasing/truth views: 0 heatmap alone, up to 1 over the eye view")
        ->check(CLI::Range(0.0, 1.0));
}

namespace {

struct Writer {
    std::filesystem::path dir;
    std::vector<std::string> written;
    void png(const std::string& name, const geometry::analysis::Image& img) {
        const std::string path = (dir / name).string();
        geometry::analysis::writePng(path, img);
        written.push_back(path);
    }
    void pfm(const std::string& name, const std::vector<float>& values, int w, int h) {
        const std::string path = (dir / name).string();
        geometry::analysis::writePfm(path, values, w, h);
        written.push_back(path);
    }
};

bool wants(const ExportOptions& e, const std::string& view) {
    return std::find(e.views.begin(), e.views.end(), view) != e.views.end();
}

/// metrics.json's `seam`: the jump of m across split boundaries, seamStats as `sweep path` records it
/// per frame (its seam_* columns). A figure over no pixels is null (NaN), so a bound on it fails.
nlohmann::json seamMetrics(const Inspection& in, const glm::vec3& eye) {
    const geometry::analysis::SeamStats s =
        geometry::analysis::seamStats(in.m, in.aux, in.receiver, in.positions, in.normals, eye, in.width, in.height);
    const auto figure = [](double v, size_t pairs) { return pairs ? v : std::numeric_limits<double>::quiet_NaN(); };
    return {{"median", figure(s.median, s.pairs)},
            {"p95", figure(s.p95, s.pairs)},
            {"pairs", s.pairs},
            {"raw_median", figure(s.rawMedian, s.pairs)},
            {"baseline", figure(s.baselineMedian, s.baselinePairs)},
            {"baseline_pairs", s.baselinePairs}};
}

} // namespace

void validateExports(const ExportOptions& e) {
    if (wants(e, "truth") && !e.truth.enabled) throw std::invalid_argument("--views truth needs --truth");
    if (wants(e, "pixels") && !e.truth.enabled) throw std::invalid_argument("--views pixels needs --truth");
    if (wants(e, "soft") && !e.truth.enabled)
        throw std::invalid_argument("--views soft needs --truth (and light.angular_diameter_deg > 0)");
}

int runRender(const RenderOptions& o, const ExportOptions& e) {
    validateExports(e);
    const RenderOutput output = renderInto(loadScene(o), o, e);
    for (const auto& warning : output.warnings) std::cerr << "shadowscope: warning: " << warning << '\n';
    for (const auto& path : output.written) std::cout << path << '\n';
    return 0;
}

RenderOutput renderInto(geometry::scene::Scene scene, const RenderOptions& o, const ExportOptions& e) {
    validateExports(e);
    renderer::ViewOptions views;
    views.lightViewSize = lightViewSize(o.settings.resolution);
    views.lightSplit = e.lightSplit;
    views.unwarped = wants(e, "light_unwarped");
    views.depthRange = e.depthRange;
    HeadlessFrame f = renderHeadless(std::move(scene), o, 1, views);
    if (e.lightSplit >= int(f.plan.splits.size()))
        throw std::invalid_argument("--light-split " + std::to_string(e.lightSplit) + ": the plan has " +
                                    std::to_string(f.plan.splits.size()) + " split(s)");
    createOutputFolder(o.out);
    Writer w{std::filesystem::path(o.out), {}};

    // The GL buffers hold the normals now, and nothing this command does later reads the scene's (the
    // truth traces positions and indices): at plant scale their 12 bytes a vertex are 7 a triangle.
    for (geometry::scene::Mesh& mesh : f.scene.meshes) std::vector<glm::vec3>().swap(mesh.normals);
    std::unique_ptr<geometry::analysis::GroundTruth> truth;
    if (e.truth.enabled)
        truth = std::make_unique<geometry::analysis::GroundTruth>(geometry::analysis::GroundTruth::borrowing(f.scene));
    const Inspection in = inspect(*f.renderer, f.plan, truth.get(), e.truth.samples);
    geometry::analysis::Image eye = f.renderer->readEye();
    if (wants(e, "eye")) w.png("eye.png", eye);
    if (wants(e, "light")) {
        geometry::analysis::Image light = f.renderer->readLight();
        if (e.lightTexels)
            tintSampledTexels(light, in, e.lightSplit,
                              std::min(f.plan.splits[e.lightSplit].resolution, f.renderer->stats().shadowResolution));
        w.png("light.png", light);
    }
    if (wants(e, "light_unwarped")) w.png("light_unwarped.png", f.renderer->readUnwarpedLight());
    if (wants(e, "aliasing")) {
        w.png("aliasing.png", aliasingView(in, eye, e.heatmapBlend));
        w.pfm("aliasing.pfm", in.m, in.width, in.height);
    }
    if (wants(e, "splits")) w.png("splits.png", splitsView(eye, in, f.plan));
    if (wants(e, "shadow_map") && f.plan.virtualMap.enabled) { // technique = virtual: the physical pages as they lie
        const auto* map = f.renderer->virtualMap();
        const glm::ivec2 size = map->atlasSize();
        const std::vector<float> bottomUp = map->readAtlas();
        std::vector<float> topDown(bottomUp.size());
        for (int row = 0; row < size.y; ++row)
            std::copy_n(bottomUp.begin() + std::ptrdiff_t(size_t(size.y - 1 - row) * size_t(size.x)), size.x,
                        topDown.begin() + std::ptrdiff_t(size_t(row) * size_t(size.x)));
        w.pfm("shadow_map_pages.pfm", topDown, size.x, size.y);
    } else if (wants(e, "shadow_map")) // the raw depth each split's map holds, for diffing between frames and tools
        for (int i = 0; i < int(f.plan.splits.size()); ++i) {
            const int res = std::min(f.plan.splits[size_t(i)].resolution, f.renderer->stats().shadowResolution);
            w.pfm("shadow_map_" + std::to_string(i) + ".pfm", f.renderer->readShadowMap(i, res), res, res);
        }
    if (wants(e, "texels")) w.png("texels.png", texelsView(eye, in, e.texelGrid));
    if (e.truth.enabled) {
        w.pfm("shadow.pfm", in.shadow, in.width, in.height);
        std::vector<float> t(in.coverage.size()); // the truth's lit fraction c (0 or 1 at one sample)
        for (size_t i = 0; i < t.size(); ++i) t[i] = in.receiver[i] ? in.coverage[i] : NAN;
        w.pfm("truth.pfm", t, in.width, in.height);
        if (wants(e, "truth")) w.png("truth.png", truthView(in, eye, e.heatmapBlend));
        if (wants(e, "soft")) w.png("soft.png", softView(in, eye, e.heatmapBlend));
        if (wants(e, "pixels"))
            for (const auto& layer :
                 geometry::analysis::pixelLayers(in, f.plan.eye, f.plan.v, geometry::analysis::truthLight(f.plan)))
                w.pfm("pixels_" + layer.name + ".pfm", layer.values, in.width, in.height);
    }
    if (wants(e, "dashboard")) {
        // The GUI's dashboard at --size, drawn headless with the same settings (same layout and pixels).
        ui::LoadedScene scene = loadDashboardScene(o);
        ui::DashboardState state = initialDashboardState(scene, o);
        ui::HeadlessDashboard dashboard(std::move(scene), state, dashboardOptions(o), o.size.width, o.size.height);
        w.png("dashboard.png", dashboard.render());
    }
    nlohmann::json j = frameMetrics(f, o);
    addInspectionMetrics(j, in);
    if (f.plan.splits.size() >= 2) j["seam"] = seamMetrics(in, f.scene.camera.eye);
    if (const std::string errors = renderer::takeGlErrors(); !errors.empty())
        throw std::runtime_error("GL error: " + errors);
    addLightMetrics(j, f, o.size, views, in, truth.get(),
                    e.truth.samples); // draws the others again: after every export
    const std::string metrics = (w.dir / "metrics.json").string();
    std::ofstream out(metrics);
    out << j.dump(2) << '\n';
    if (!out) throw std::runtime_error("cannot write " + metrics);
    w.written.push_back(metrics);
    if (const std::string errors = renderer::takeGlErrors(); !errors.empty())
        throw std::runtime_error("GL error: " + errors);
    std::vector<std::string> warnings = f.plan.warnings;
    for (const auto& warning : f.renderer->stats().warnings) warnings.push_back(warning);
    return {std::move(j), std::move(w.written), std::move(eye), std::move(warnings)};
}

} // namespace app
