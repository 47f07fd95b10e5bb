#pragma once
// metrics.json's `lights[i]` blocks (docs/design.md §3.10): each light as the scene describes it, its
// maps, and the metrics of a frame that inspects it; and the aliasing error m of the worst light at
// each pixel.
#include "geometry/analysis/inspection.h"
#include "headless_frame.h"

#include <nlohmann/json.hpp>

namespace app {

/// The light's own members (type, direction, position, cone, range, radius).
[[nodiscard]] nlohmann::json lightDescription(const geometry::scene::Light& light);

/// Fills j["lights"] (one block per scene light) and j["aliasing_worst_light"]. `inspected` is the
/// inspection of f.light (already made, with the truth if any). Every other light is drawn again as the
/// inspected one and measured, with `truth` (truthSamples² samples) when given, so f's read-backs
/// describe the last of them after. With truth, j["truth_all_lights"] pools every light's receivers.
void addLightMetrics(nlohmann::json& j, HeadlessFrame& f, const geometry::shadow::Viewport& size,
                     const renderer::ViewOptions& views, const geometry::analysis::Inspection& inspected,
                     const geometry::analysis::GroundTruth* truth = nullptr, int truthSamples = 1);

} // namespace app
