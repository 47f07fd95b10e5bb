#pragma once
// One OSMesa context and renderer per scene, kept for the whole test binary (contexts are costly).
#include "geometry/scene/scene.h"
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
};

} // namespace testutil
