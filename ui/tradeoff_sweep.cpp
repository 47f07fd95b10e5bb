#include "tradeoff_sweep.h"

#include "renderer/measure.h"

#include <algorithm>

namespace ui {

void TradeoffSweep::start(std::vector<Config> configs) {
    configs_ = std::move(configs);
    results_.clear();
    runningPath_ = path;
    next_ = 0;
    running_ = true;
}

float TradeoffSweep::progress() const noexcept { return float(next_) / float(std::max<size_t>(configs_.size(), 1)); }

std::optional<std::string> TradeoffSweep::step(const MeasureContext& c) {
    if (!running_) return std::nullopt;
    if (next_ >= configs_.size()) {
        running_ = false;
        return "trade-off sweep done: " + std::to_string(results_.size()) + " configurations";
    }
    renderer::Renderer& r = renderer_.get(c);
    geometry::scene::Scene& scene = c.scene.file.scene;
    const auto& cfg = configs_[next_++];
    const auto* truth = c.truth ? c.scene.truth.get() : nullptr;
    try {
        const renderer::MeasureView view = renderer::measureView(scene, c.light);
        const renderer::Measurement m =
            renderer::measure(r, cfg.settings, scene.bounds(), scene.camera, view.light, c.size,
                              {.warmup = 1, .frames = 3, .truthSamples = c.truthSamples}, truth, view.others);
        Figures f{cfg.label,
                  cfg.preset,
                  m.gpuMs,
                  m.cpuMs,
                  double(m.shadowMemoryBytes) / (1024.0 * 1024.0),
                  m.inspection.aliasing.p95};
        if (const auto& t = m.inspection.truthClasses) {
            f.interior = t->interiorFalseShadow + t->interiorFalseLit;
            f.edge = t->edgeError;
            f.umbra = t->umbraLight;
        }
        if (const auto& t = m.inspection.truth) f.misclassified = t->falseShadow + t->falseLit;
        if (const auto& t = m.inspection.softTruth) f.soft = t->meanAbs;
        const auto& paths = c.scene.file.paths;
        if (const auto p = paths.find(runningPath_); p != paths.end() && c.scene.truth)
            f.flicker = renderer::measurePath(
                            r, cfg.settings, scene.bounds(),
                            {p->second.cameras, {p->second.lights, p->second.lightPositions}, p->second.lightIndex},
                            scene, c.light, 10, c.size, *c.scene.truth, c.truthSamples)
                            .flickerMean;
        results_.push_back(f);
    } catch (const std::exception& e) {
        return "trade-off sweep: " + cfg.label + ": " + e.what();
    }
    return std::nullopt;
}

std::vector<charts::TradeoffPoint> TradeoffSweep::points() const {
    std::vector<charts::TradeoffPoint> out;
    for (const auto& f : results_) {
        const double vx = x == charts::TradeoffX::GpuMs   ? f.gpuMs
                          : x == charts::TradeoffX::CpuMs ? f.cpuMs
                                                          : f.memoryMiB;
        const double vy = y == charts::TradeoffY::P95             ? f.p95
                          : y == charts::TradeoffY::Interior      ? f.interior
                          : y == charts::TradeoffY::Edge          ? f.edge
                          : y == charts::TradeoffY::Misclassified ? f.misclassified
                          : y == charts::TradeoffY::Soft          ? f.soft
                          : y == charts::TradeoffY::Umbra         ? f.umbra
                                                                  : f.flicker;
        out.push_back({f.label, f.preset, vx, vy});
    }
    return out;
}

} // namespace ui
