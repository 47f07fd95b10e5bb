#include "renderer/plan_frame.h"

namespace renderer {

geometry::shadow::ShadowPlan planFrame(Renderer& renderer, const geometry::shadow::ShadowSettings& settings,
                                       const geometry::scene::Aabb& S, const geometry::scene::Camera& camera,
                                       const geometry::scene::DirectionalLight& light,
                                       const geometry::shadow::Viewport& viewport) {
    geometry::shadow::ShadowPlan plan = geometry::shadow::planShadows(settings, S, camera, light, viewport);
    if (settings.focus != geometry::shadow::FocusMode::Samples) return plan;
    const geometry::shadow::SampleBounds samples = renderer.eyeSamples(plan, viewport);
    return geometry::shadow::planShadows(settings, S, camera, light, viewport, &samples);
}

} // namespace renderer
