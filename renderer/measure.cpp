#include "renderer/measure.h"

#include "geometry/analysis/stability_metrics.h"
#include "geometry/analysis/statistics.h"
#include "geometry/scene/path_interpolation.h"
#include "renderer/inspection.h"
#include "renderer/plan_frame.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

namespace renderer {

Measurement measure(Renderer& renderer, const geometry::shadow::ShadowSettings& settings,
                    const geometry::scene::Aabb& S, const geometry::scene::Camera& camera,
                    const geometry::scene::Light& light, const geometry::shadow::Viewport& viewport,
                    const MeasureOptions& options, const geometry::analysis::GroundTruth* truth) {
    ViewOptions views;
    views.lightViewSize = 16;
    views.overlays = false;
    views.unwarped = false;
    Measurement out;
    std::vector<double> gpu, cpu, shadow;
    const int total = std::max(options.warmup, 0) + std::max(options.frames, 1);
    for (int i = 0; i < total; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        out.plan = planFrame(renderer, settings, S, camera, light, viewport);
        renderer.render(out.plan, viewport, views);
        if (!options.timed) continue;
        glFinish();
        const double cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        const PassTimes& t = renderer.waitForTimings();
        if (i < options.warmup) continue;
        cpu.push_back(cpuMs);
        if (t.valid) gpu.push_back(t.frame()), shadow.push_back(t.of(Pass::Shadow));
    }
    out.gpuMs = geometry::analysis::median(std::span(gpu));
    out.cpuMs = geometry::analysis::median(std::span(cpu));
    out.shadowGpuMs = geometry::analysis::median(std::span(shadow));
    out.gpuFrames = int(gpu.size());
    for (const uint64_t n : renderer.stats().splitTriangles) out.shadowTriangles += n;
    for (const uint64_t n : renderer.stats().splitTrianglesFull) out.shadowTrianglesWithoutLod += n;
    out.shadowMemoryBytes = renderer.stats().shadowMemoryBytes;
    out.eyeTriangles = renderer.stats().eyeTriangles;
    out.inspection = inspect(renderer, out.plan, truth, options.truthSamples);
    return out;
}

geometry::analysis::TuneFigures
measureTuneRequest(Renderer& renderer, const geometry::analysis::TuneRequest& request, const geometry::scene::Aabb& S,
                   const std::vector<MeasureView>& views, const geometry::analysis::GroundTruth& truth,
                   int truthSamples, const geometry::analysis::CostModel& costModel, const MeasureOptions& options,
                   std::vector<geometry::analysis::TuneFigures>* perView) {
    std::vector<geometry::analysis::TuneFigures> figures;
    MeasureOptions o = options;
    o.truthSamples = truthSamples;
    for (const MeasureView& view : views) {
        const Measurement m = measure(renderer, request.settings, S, view.camera, view.light, request.size, o, &truth);
        const geometry::analysis::WorkCounts work =
            geometry::analysis::countWork(request.settings, m.plan, m.shadowTriangles, m.eyeTriangles, request.size);
        figures.push_back(geometry::analysis::tuneFigures(
            m.inspection, costModel.costMs(work), std::isfinite(m.gpuMs) ? m.gpuMs : m.cpuMs, m.shadowMemoryBytes));
    }
    if (perView) *perView = figures;
    return geometry::analysis::combineViews(figures);
}

PathFigures measurePath(Renderer& renderer, const geometry::shadow::ShadowSettings& settings,
                        const geometry::scene::Aabb& S, const MeasurePath& path, const MeasureView& start, int frames,
                        const geometry::shadow::Viewport& size, const geometry::analysis::GroundTruth& truth,
                        int truthSamples) {
    std::vector<double> world, screen, seams;
    std::optional<geometry::analysis::Inspection> previous;
    glm::mat4 previousViewProj(1.f);
    for (int i = 0; i < frames; ++i) {
        const double t = geometry::scene::pathParameter(i, frames);
        const geometry::scene::Camera camera =
            path.cameras.empty() ? start.camera : geometry::scene::cameraAlongPath(path.cameras, t);
        const geometry::scene::Light light{path.lights.empty() ? start.light.direction
                                                               : geometry::scene::lightAlongPath(path.lights, t)};
        Measurement m = measure(renderer, settings, S, camera, light, size,
                                {.warmup = 0, .frames = 1, .timed = false, .truthSamples = truthSamples}, &truth);
        geometry::analysis::Inspection& in = m.inspection;
        const auto seam = geometry::analysis::seamStats(in.m, in.aux, in.receiver, in.positions, in.normals, camera.eye,
                                                        in.width, in.height);
        if (seam.pairs > 0) seams.push_back(seam.median);
        if (previous) {
            const auto pair = geometry::analysis::framePairFlicker(*previous, previousViewProj, in);
            world.push_back(pair.world.rate);
            screen.push_back(pair.screen.rate);
        }
        previousViewProj = m.plan.eyeProj * m.plan.eyeView;
        previous = std::move(in);
    }
    PathFigures f;
    if (!world.empty()) {
        double sum = 0, sumScreen = 0;
        for (size_t k = 0; k < world.size(); ++k) sum += world[k], sumScreen += screen[k];
        f.flickerMean = sum / double(world.size());
        f.flickerScreen = sumScreen / double(screen.size());
        f.flickerP95 = geometry::analysis::percentile(std::span(world), 95);
    }
    if (!seams.empty()) f.seam = geometry::analysis::median(std::span(seams));
    return f;
}

} // namespace renderer
