#include "renderer/measure.h"

#include "geometry/analysis/stability_metrics.h"
#include "geometry/analysis/statistics.h"
#include "geometry/scene/path_interpolation.h"
#include "renderer/inspection.h"
#include "renderer/plan_frame.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace renderer {

Measurement measure(Renderer& renderer, const geometry::shadow::ShadowSettings& settings,
                    const geometry::scene::Aabb& S, const geometry::scene::Camera& camera,
                    const geometry::scene::Light& light, const geometry::shadow::Viewport& viewport,
                    const MeasureOptions& options, const geometry::analysis::GroundTruth* truth,
                    std::span<const geometry::scene::Light> others) {
    ViewOptions views;
    views.lightViewSize = 16;
    views.overlays = false;
    views.unwarped = false;
    Measurement out;
    std::vector<double> gpu, cpu, shadow;
    std::vector<geometry::shadow::ShadowPlan> plans;
    const int total = std::max(options.warmup, 0) + std::max(options.frames, 1);
    for (int i = 0; i < total; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        if (others.empty()) {
            out.plan = planFrame(renderer, settings, S, camera, light, viewport);
            renderer.render(out.plan, viewport, views);
        } else {
            plans.clear();
            for (const geometry::scene::Light& other : others)
                plans.push_back(planFrame(renderer, settings, S, camera, other, viewport));
            plans.push_back(planFrame(renderer, settings, S, camera, light, viewport));
            out.plan = plans.back();
            renderer.render(plans, viewport, views, plans.size() - 1);
        }
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

MeasureView measureView(const geometry::scene::Camera& camera, std::span<const geometry::scene::Light> lights,
                        size_t inspected) {
    if (inspected >= lights.size())
        throw std::out_of_range("light " + std::to_string(inspected) + ": the scene has " +
                                std::to_string(lights.size()) + " light(s), numbered from 0");
    MeasureView view{camera, lights[inspected]};
    for (size_t k = 0; k < lights.size(); ++k)
        if (k != inspected) view.others.push_back(lights[k]);
    return view;
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
        const Measurement m =
            measure(renderer, request.settings, S, view.camera, view.light, request.size, o, &truth, view.others);
        const geometry::analysis::WorkCounts work =
            geometry::analysis::countWork(request.settings, m.plan, m.shadowTriangles, m.eyeTriangles, request.size);
        figures.push_back(geometry::analysis::tuneFigures(
            m.inspection, costModel.costMs(work), std::isfinite(m.gpuMs) ? m.gpuMs : m.cpuMs, m.shadowMemoryBytes));
    }
    if (perView) *perView = figures;
    return geometry::analysis::combineViews(figures);
}

PathFigures measurePath(Renderer& renderer, const geometry::shadow::ShadowSettings& settings,
                        const geometry::scene::Aabb& S, const MeasurePath& path, const geometry::scene::Scene& start,
                        size_t inspected, int frames, const geometry::shadow::Viewport& size,
                        const geometry::analysis::GroundTruth& truth, int truthSamples) {
    if (path.lightIndex >= start.lights.size())
        throw std::out_of_range("the path moves light " + std::to_string(path.lightIndex) + " but the scene has " +
                                std::to_string(start.lights.size()));
    std::vector<double> world, screen, seams;
    std::optional<geometry::analysis::Inspection> previous;
    glm::mat4 previousViewProj(1.f);
    for (int i = 0; i < frames; ++i) {
        const double t = geometry::scene::pathParameter(i, frames);
        const geometry::scene::Camera camera =
            path.cameras.empty() ? start.camera : geometry::scene::cameraAlongPath(path.cameras, t);
        std::vector<geometry::scene::Light> lights = start.lights;
        lights[path.lightIndex] = geometry::scene::lightAlongPath(lights[path.lightIndex], path.light, t);
        const MeasureView view = measureView(camera, lights, inspected);
        Measurement m =
            measure(renderer, settings, S, camera, view.light, size,
                    {.warmup = 0, .frames = 1, .timed = false, .truthSamples = truthSamples}, &truth, view.others);
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
