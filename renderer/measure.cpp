#include "renderer/measure.h"

#include "geometry/analysis/statistics.h"
#include "renderer/inspection.h"

#include <chrono>
#include <cmath>
#include <vector>

namespace renderer {

Measurement measure(Renderer& renderer, const geometry::shadow::ShadowSettings& settings,
                    const geometry::scene::Aabb& S, const geometry::scene::Camera& camera,
                    const geometry::scene::DirectionalLight& light, const geometry::shadow::Viewport& viewport,
                    const MeasureOptions& options, const geometry::analysis::GroundTruth* truth) {
    ViewOptions views;
    views.lightViewSize = 16;
    views.overlays = false;
    views.unwarped = false;
    Measurement out;
    std::vector<double> gpu, cpu;
    const int total = std::max(options.warmup, 0) + std::max(options.frames, 1);
    for (int i = 0; i < total; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        out.plan = geometry::shadow::planShadows(settings, S, camera, light, viewport);
        renderer.render(out.plan, viewport, views);
        if (!options.timed) continue;
        glFinish();
        const double cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        const PassTimes& t = renderer.waitForTimings();
        if (i < options.warmup) continue;
        cpu.push_back(cpuMs);
        if (t.valid) gpu.push_back(t.frame());
    }
    out.gpuMs = geometry::analysis::median(std::span(gpu));
    out.cpuMs = geometry::analysis::median(std::span(cpu));
    out.gpuFrames = int(gpu.size());
    out.shadowMemoryBytes = renderer.stats().shadowMemoryBytes;
    out.inspection = inspect(renderer, out.plan, truth, options.truthSamples);
    return out;
}

geometry::analysis::TuneFigures measureTuneRequest(Renderer& renderer, const geometry::analysis::TuneRequest& request,
                                                   const geometry::scene::Aabb& S,
                                                   const std::vector<MeasureView>& views,
                                                   const geometry::analysis::GroundTruth& truth, int truthSamples,
                                                   const MeasureOptions& options) {
    std::vector<geometry::analysis::TuneFigures> figures;
    MeasureOptions o = options;
    o.truthSamples = truthSamples;
    for (const MeasureView& view : views) {
        const Measurement m = measure(renderer, request.settings, S, view.camera, view.light, request.size, o, &truth);
        figures.push_back(geometry::analysis::tuneFigures(m.inspection, std::isfinite(m.gpuMs) ? m.gpuMs : m.cpuMs,
                                                          m.shadowMemoryBytes));
    }
    return geometry::analysis::combineViews(figures);
}

} // namespace renderer
