#pragma once
// One headless frame: context, plan, render, timings. Shared by `render` and the tests.
#include "render_options.h"
#include "renderer/context.h"
#include "renderer/renderer.h"

#include <memory>
#include <vector>

namespace app {

struct HeadlessFrame {
    std::unique_ptr<renderer::GlContext> context;
    geometry::scene::Scene scene;
    std::vector<geometry::shadow::ShadowPlan> plans; // one per scene light
    size_t light = 0;                                // the inspected light (RenderOptions::light)
    geometry::shadow::ShadowPlan plan;               // plans[light]
    double planMicroseconds = 0;
    std::unique_ptr<renderer::Renderer> renderer;
};

/// Renders `warmupFrames` + 1 frames of the options' scene (every light; the read-backs describe
/// options.light) and waits for GPU timings.
[[nodiscard]] HeadlessFrame renderHeadless(const RenderOptions& options, int warmupFrames = 1,
                                           renderer::ViewOptions views = {});
/// The same for a scene already loaded (and seen from the options' view): options.scene is not read.
[[nodiscard]] HeadlessFrame renderHeadless(geometry::scene::Scene scene, const RenderOptions& options,
                                           int warmupFrames = 1, renderer::ViewOptions views = {});

/// Edge of the square light-view image for a shadow-map resolution.
[[nodiscard]] int lightViewSize(int shadowRes) noexcept;

} // namespace app
