#pragma once
// Planning one frame with what the renderer can measure: the planner decides, the renderer only
// supplies this frame's eye samples (focus.mode = samples; docs/design.md §3.7).
#include "geometry/shadow/shadow_plan.h"
#include "renderer/renderer.h"

namespace renderer {

/// The geometric plan; with focus.mode = samples, the plan fitted to this frame's samples, which
/// `renderer` reduces from an eye depth pre-pass that its next render() of this camera reuses.
/// `planMicroseconds`, when given, receives the CPU time of the planner alone (not the pre-pass).
[[nodiscard]] geometry::shadow::ShadowPlan
planFrame(Renderer& renderer, const geometry::shadow::ShadowSettings& settings, const geometry::scene::Aabb& S,
          const geometry::scene::Camera& camera, const geometry::scene::Light& light,
          const geometry::shadow::Viewport& viewport, double* planMicroseconds = nullptr);

} // namespace renderer
