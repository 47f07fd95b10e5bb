#pragma once
// Measuring one configuration, the one path that bench, the sweeps and the dashboard's trade-off
// sweep share: plan and render warm-up frames, then timed frames (the GPU time of the shadow and
// eye passes by timer queries, the CPU time of planning plus drawing up to glFinish), and read the
// last frame back with its statistics. It decides nothing about shadows: the plan does.
#include "geometry/analysis/cost_model.h"
#include "geometry/analysis/inspection.h"
#include "geometry/analysis/tuner.h"
#include "geometry/scene/path_interpolation.h"
#include "geometry/scene/scene.h"
#include "geometry/shadow/shadow_plan.h"
#include "renderer/renderer.h"

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace renderer {

struct MeasureOptions {
    int warmup = 1;       // untimed frames first (llvmpipe's first timer query of a new renderer is bogus)
    int frames = 3;       // timed frames
    bool timed = true;    // false: frames are rendered but not timed (no glFinish, no timer wait)
    int truthSamples = 1; // per axis, when a GroundTruth is given
};

struct Measurement {
    geometry::shadow::ShadowPlan plan;         // of the last frame
    geometry::analysis::Inspection inspection; // of the last frame; truth when a GroundTruth was given
    double gpuMs = 0, cpuMs = 0;               // medians over the timed frames; NaN when none was valid
    double shadowGpuMs = 0;                    // the shadow passes' GPU median (part of gpuMs)
    uint64_t shadowTriangles = 0;              // drawn by the last frame's shadow passes
    uint64_t shadowTrianglesWithoutLod = 0;    // … as many as they would draw without caster LOD
    uint64_t eyeTriangles = 0;                 // drawn by the last frame's eye pass
    int gpuFrames = 0;                         // timed frames with a valid GPU timer
    uint64_t shadowMemoryBytes = 0;
};

/// Measures `settings` on the scene with bounds `S`, seen by `camera` under `light`, at `viewport`.
/// The scene's `others` lights are planned and drawn in the same frames (their passes are timed and
/// their triangles counted; docs/design.md §3.10), `light` last: the inspection describes `light`.
/// The light views are drawn at 16² without overlays: they are not what is measured.
[[nodiscard]] Measurement measure(Renderer& renderer, const geometry::shadow::ShadowSettings& settings,
                                  const geometry::scene::Aabb& S, const geometry::scene::Camera& camera,
                                  const geometry::scene::Light& light, const geometry::shadow::Viewport& viewport,
                                  const MeasureOptions& options, const geometry::analysis::GroundTruth* truth = nullptr,
                                  std::span<const geometry::scene::Light> others = {});

/// A camera and its light: one view a configuration is measured on; `others`, the scene's other
/// lights, drawn too but not inspected.
struct MeasureView {
    geometry::scene::Camera camera;
    geometry::scene::Light light;
    std::vector<geometry::scene::Light> others = {};
};

/// The view from `camera` that inspects `lights[inspected]` with every other light drawn too.
/// Throws std::out_of_range for an index past the lights.
[[nodiscard]] MeasureView measureView(const geometry::scene::Camera& camera,
                                      std::span<const geometry::scene::Light> lights, size_t inspected = 0);
[[nodiscard]] inline MeasureView measureView(const geometry::scene::Scene& scene, size_t inspected = 0) {
    return measureView(scene.camera, scene.lights, inspected);
}

/// Measures a tune request (geometry/analysis/tuner.h) on every view with truth: the figures tune
/// ranks, combined over the views (combineViews). Cost: `costModel`'s for the work each frame
/// counts; frame time: the GPU median, the CPU median where the timer gave nothing. `perView`, when
/// given, receives each view's figures.
[[nodiscard]] geometry::analysis::TuneFigures
measureTuneRequest(Renderer& renderer, const geometry::analysis::TuneRequest& request, const geometry::scene::Aabb& S,
                   const std::vector<MeasureView>& views, const geometry::analysis::GroundTruth& truth,
                   int truthSamples, const geometry::analysis::CostModel& costModel, const MeasureOptions& options = {},
                   std::vector<geometry::analysis::TuneFigures>* perView = nullptr);

/// A camera/light path (keys as a scene file's "paths" hold them; empty: the start stays put). The
/// light keys move the scene's light `lightIndex`.
struct MeasurePath {
    std::vector<geometry::scene::Camera> cameras;
    geometry::scene::LightPathKeys light;
    size_t lightIndex = 0;
};

/// One configuration walked along a path: world-space flicker over the frame pairs (mean and 95th
/// percentile), screen-space flicker (mean) and the median seam (geometry/analysis/stability_metrics.h).
struct PathFigures {
    double flickerMean = NAN, flickerP95 = NAN, flickerScreen = NAN, seam = NAN;
};

/// Renders `frames` frames along `path` (untimed), starting from `start`'s camera and lights where
/// the path has no keys, every light drawn and `start.lights[inspected]` inspected, with truth
/// (truthSamples² samples) for the flicker's truth condition. Throws std::out_of_range for a light
/// index past start's lights.
[[nodiscard]] PathFigures measurePath(Renderer& renderer, const geometry::shadow::ShadowSettings& settings,
                                      const geometry::scene::Aabb& S, const MeasurePath& path,
                                      const geometry::scene::Scene& start, size_t inspected, int frames,
                                      const geometry::shadow::Viewport& size,
                                      const geometry::analysis::GroundTruth& truth, int truthSamples = 1);

} // namespace renderer
