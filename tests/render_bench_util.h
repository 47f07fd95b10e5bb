#pragma once
// One OSMesa context and renderer per scene, kept for the whole test binary (contexts are costly).
#include "geometry/scene/scene.h"
#include "geometry/shadow/shadow_plan.h"
#include "renderer/context.h"
#include "renderer/renderer.h"

#include <memory>

namespace testutil {

struct SceneBench {
    std::unique_ptr<renderer::GlContext> context = renderer::createOSMesaContext();
    geometry::scene::Scene scene;
    std::unique_ptr<renderer::Renderer> r;
    explicit SceneBench(geometry::scene::Scene s)
        : scene(std::move(s)), r(std::make_unique<renderer::Renderer>(scene)) {}

    /// Plans `settings` for the scene's camera and light and renders the plan (64² light view).
    geometry::shadow::ShadowPlan render(const geometry::shadow::ShadowSettings& settings,
                                        geometry::shadow::Viewport vp) {
        context->makeCurrent();
        const auto plan = geometry::shadow::planShadows(settings, scene.bounds(), scene.camera, scene.lights[0], vp);
        r->render(plan, vp, 64);
        return plan;
    }
};

} // namespace testutil
