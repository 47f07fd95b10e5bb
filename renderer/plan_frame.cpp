#include "renderer/plan_frame.h"

#include <chrono>

namespace renderer {

geometry::shadow::ShadowPlan planFrame(Renderer& renderer, const geometry::shadow::ShadowSettings& settings,
                                       const geometry::scene::Aabb& S, const geometry::scene::Camera& camera,
                                       const geometry::scene::Light& light, const geometry::shadow::Viewport& viewport,
                                       double* planMicroseconds) {
    using Clock = std::chrono::steady_clock;
    double us = 0;
    const auto plan = [&](const geometry::shadow::SampleBounds* samples) {
        const auto t0 = Clock::now();
        geometry::shadow::ShadowPlan p = geometry::shadow::planShadows(settings, S, camera, light, viewport, samples);
        us += std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
        return p;
    };
    geometry::shadow::ShadowPlan result = plan(nullptr);
    if (settings.focus == geometry::shadow::FocusMode::Samples && !light.positional()) { // positional: geometric
        const geometry::shadow::SampleBounds samples = renderer.eyeSamples(result, viewport);
        result = plan(&samples);
    }
    if (planMicroseconds) *planMicroseconds = us;
    return result;
}

} // namespace renderer
