#include "render_command.h"

#include "headless_frame.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace app {

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
    for (const auto& info : geometry::settingsDeclaration()) settings[std::string(info.key)] = info.format(o.settings);
    j["settings"] = settings;
    nlohmann::json splits = nlohmann::json::array();
    for (size_t i = 0; i < f.plan.splits.size(); ++i) {
        const auto& s = f.plan.splits[i];
        splits.push_back({{"near", s.near}, {"far", s.far}, {"n_prime", s.warped() ? nlohmann::json(s.nPrime) : nlohmann::json("inf")},
                          {"lambda", s.lambda}, {"resolution", s.resolution}, {"empty", s.empty()},
                          {"triangles", i < stats.splitTriangles.size() ? stats.splitTriangles[i] : 0}});
    }
    j["splits"] = splits;
    j["shadow_map_resolution_used"] = stats.shadowResolution;
    j["warnings"] = stats.warnings;
    j["triangles"] = f.scene.triangleCount();
    j["gamma_deg"] = f.plan.gammaDeg;
    j["light_view_angle_deg"] = f.plan.lightViewAngleDeg;
    j["camera"] = {{"eye", {f.scene.camera.eye.x, f.scene.camera.eye.y, f.scene.camera.eye.z}},
                   {"target", {f.scene.camera.target.x, f.scene.camera.target.y, f.scene.camera.target.z}},
                   {"near", f.scene.camera.near},
                   {"far", f.scene.camera.far}};
    j["light"] = {f.plan.l.x, f.plan.l.y, f.plan.l.z};
    j["timing_ms"] = {{"shadow", stats.gpu.of(Pass::Shadow)},
                      {"eye", stats.gpu.of(Pass::Eye)},
                      {"light_view", stats.gpu.of(Pass::LightView)},
                      {"total", stats.gpu.total()}};
    j["plan_us"] = f.planMicroseconds;
    j["triangles_submitted"] = {{"shadow", stats.shadowTriangles}, {"eye", stats.eyeTriangles}};
    return j;
}

int runRender(const RenderOptions& o) {
    const HeadlessFrame f = renderHeadless(o);
    std::error_code ec;
    std::filesystem::create_directories(o.out, ec);
    if (ec) throw std::runtime_error("cannot create output folder " + o.out + ": " + ec.message());
    const auto dir = std::filesystem::path(o.out);
    const std::string eye = (dir / "eye.png").string(), light = (dir / "light.png").string(),
                      metrics = (dir / "metrics.json").string();
    renderer::writePng(eye, f.renderer->readEye());
    renderer::writePng(light, f.renderer->readLight());
    std::ofstream out(metrics);
    out << frameMetrics(f, o).dump(2) << '\n';
    if (!out) throw std::runtime_error("cannot write " + metrics);
    if (const std::string errors = renderer::takeGlErrors(); !errors.empty())
        throw std::runtime_error("GL error: " + errors);
    for (const auto& w : f.renderer->stats().warnings) std::cerr << "shadowscope: warning: " << w << '\n';
    std::cout << eye << '\n' << light << '\n' << metrics << '\n';
    return 0;
}

} // namespace app
