#pragma once
// Draws one frame from a shadow plan: shadow pass per split, eye pass, light view. Makes no
// shadow-math decisions: every matrix and bias comes from the plan.
#include "gpu_scene.h"
#include "gpu_timers.h"
#include "image.h"
#include "program.h"
#include "render_targets.h"
#include "geometry/shadow_plan.h"

#include <memory>

namespace renderer {

struct FrameStats {
    uint64_t shadowTriangles = 0; // over all splits
    uint64_t eyeTriangles = 0;
    PassTimes gpu;                // from an earlier frame (see GpuTimers)
};

class Renderer {
public:
    /// Needs a current GL context; uploads the scene.
    explicit Renderer(const geometry::Scene& scene);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    void setScene(const geometry::Scene& scene);
    /// Renders the eye view at `viewport` and the light view of split `lightSplit` at
    /// `lightViewSize`² into textures.
    void render(const geometry::ShadowPlan& plan, const geometry::Viewport& viewport, int lightViewSize,
                int lightSplit = 0);

    [[nodiscard]] GLuint eyeTexture() const noexcept { return eye_.texture(); }
    [[nodiscard]] GLuint lightTexture() const noexcept { return light_.texture(); }
    [[nodiscard]] Image readEye() const { return readTexture(eye_.texture(), eye_.width(), eye_.height()); }
    [[nodiscard]] Image readLight() const { return readTexture(light_.texture(), light_.width(), light_.height()); }
    [[nodiscard]] const FrameStats& stats() const noexcept { return stats_; }
    /// Blocks until the GPU times of every rendered frame are in; for one-shot exports.
    const PassTimes& waitForTimings() noexcept;

private:
    void shadowPass(const geometry::ShadowPlan& plan);
    void eyePass(const geometry::ShadowPlan& plan, const geometry::Viewport& viewport);
    /// Fraction of the array layer a split's map uses (splits may have lower resolution).
    [[nodiscard]] float mapScale(const geometry::SplitPlan& split) const noexcept;
    void lightViewPass(const geometry::ShadowPlan& plan, int size, int split);

    std::unique_ptr<GpuScene> scene_;
    Program depthProgram_{"depth.vert", "depth.frag"};
    Program eyeProgram_{"eye.vert", "eye.frag"};
    Program lightViewProgram_{"fullscreen.vert", "light_view.frag"};
    GLuint emptyVao_ = 0;
    ShadowMapArray shadowMaps_;
    ColorTarget eye_, light_;
    GpuTimers timers_;
    FrameStats stats_;
};

} // namespace renderer
