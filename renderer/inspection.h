#pragma once
// Reads back the last frame once and hands it to the analysis (geometry/analysis/inspection.h).
#include "geometry/analysis/inspection.h"
#include "renderer/renderer.h"

namespace renderer {

/// The last frame's per-pixel outputs (needs the GL context; the analysis does not, so the
/// dashboard runs makeInspection on a worker thread).
[[nodiscard]] geometry::analysis::FrameReadback readBack(const Renderer& r, const geometry::shadow::ShadowPlan& plan);

/// Reads back the last frame and computes the statistics; `truth` adds the ground-truth pass with
/// truthSamples² samples per pixel (addTruth), each compared with the eye pass drawn again at those
/// samples (Renderer::readShadowSamples) when truthSamples > 1.
[[nodiscard]] geometry::analysis::Inspection inspect(Renderer& r, const geometry::shadow::ShadowPlan& plan,
                                                     const geometry::analysis::GroundTruth* truth,
                                                     int truthSamples = 1);

} // namespace renderer
