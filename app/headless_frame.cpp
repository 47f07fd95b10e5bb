#include "headless_frame.h"

#include "caster_lod_setup.h"
#include "renderer/plan_frame.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

namespace app {

int lightViewSize(int shadowRes) noexcept { return std::clamp(shadowRes, 16, 1024); }

HeadlessFrame renderHeadless(const RenderOptions& options, int warmupFrames, renderer::ViewOptions views) {
    return renderHeadless(loadScene(options), options, warmupFrames, views);
}

HeadlessFrame renderHeadless(geometry::scene::Scene scene, const RenderOptions& options, int warmupFrames,
                             renderer::ViewOptions views) {
    HeadlessFrame f;
    f.scene = std::move(scene);
    f.context = renderer::createHeadlessContext(renderer::parseBackend(options.backend));
    const geometry::shadow::ShadowSettings& settings = options.settings;
    f.renderer = std::make_unique<renderer::Renderer>(f.scene);
    if (views.lightViewSize <= 0) views.lightViewSize = lightViewSize(settings.resolution);
    ensureCasterLod(*f.renderer, f.scene, settings);
    f.light = options.lightIndex;
    if (f.light >= f.scene.lights.size())
        throw std::runtime_error("--light " + std::to_string(f.light) + ": the scene has " +
                                 std::to_string(f.scene.lights.size()) + " light(s), numbered from 0");
    for (int i = 0; i <= warmupFrames; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        f.plans.clear();
        for (const auto& light : f.scene.lights)
            f.plans.push_back(
                renderer::planFrame(*f.renderer, settings, f.scene.bounds(), f.scene.camera, light, options.size));
        f.plan = f.plans[f.light];
        f.planMicroseconds = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
        f.renderer->render(f.plans, options.size, views, f.light);
    }
    f.renderer->waitForTimings();
    return f;
}

} // namespace app
