#pragma once
// The frame loop shared by `sweep gamma` and `sweep path`: one GL context, one Renderer and one
// ground-truth BVH for the whole run, re-planned and re-rendered per step (a sweep of hundreds of
// frames must not pay for a context and a scene upload each time).
#include "geometry/analysis/ground_truth.h"
#include "geometry/shadow/shadow_plan.h"
#include "renderer/context.h"
#include "renderer/measure.h"
#include "renderer/renderer.h"

#include <memory>
#include <span>
#include <string>

namespace app {

struct SweepFrame {
    geometry::shadow::ShadowPlan plan;
    geometry::analysis::Inspection in; // with truth (in.occluded, in.truth)
    std::string glErrors;              // renderer::takeGlErrors() after this frame; empty when clean
};

class SweepRenderer {
public:
    /// Creates the headless context (backend name as --backend), uploads `scene`, builds the BVH.
    SweepRenderer(const geometry::scene::Scene& scene, const std::string& backend);

    /// Plans, renders one frame and reads it back with ground truth for `light`; the `others` lights
    /// are drawn in the same frame (renderer::measure). The truth rays of the previous frame are
    /// reused when camera, light and viewport are unchanged (the eye pass, and so every receiver
    /// position, does not depend on the shadow settings).
    [[nodiscard]] SweepFrame render(const geometry::shadow::ShadowSettings& settings,
                                    const geometry::scene::Camera& camera, const geometry::scene::Light& light,
                                    const geometry::shadow::Viewport& viewport,
                                    std::span<const geometry::scene::Light> others = {});

    [[nodiscard]] const renderer::GlContext& context() const noexcept { return *context_; }

private:
    geometry::scene::Scene scene_;
    std::unique_ptr<renderer::GlContext> context_;
    std::unique_ptr<renderer::Renderer> renderer_;
    geometry::analysis::GroundTruth truth_;
    // The last frame's truth and what it was computed for.
    glm::mat4 truthView_{0.f}, truthProj_{0.f};
    geometry::analysis::TruthLight truthLight_{glm::vec3(0.f)};
    std::vector<uint8_t> truthOccluded_;
};

/// A one-line progress display on stderr ("LABEL: 37/361 (10 %), 12 s, ~1 min left"), rewritten
/// in place at most five times a second, on a terminal only (logs and tests stay clean).
class SweepProgress {
public:
    SweepProgress(std::string label, int total);
    ~SweepProgress();
    SweepProgress(const SweepProgress&) = delete;
    SweepProgress& operator=(const SweepProgress&) = delete;
    void step(int done, const std::string& detail);

private:
    std::string label_;
    int total_;
    bool terminal_;
    bool shown_ = false;
    double start_, last_ = -1.0;
};

} // namespace app
