#pragma once
// The Charts panel's trade-off sweep: every preset and the current settings measured on the view
// shown (3 frames each, GPU median, aliasing p95, truth figures when truth is on, world-space
// flicker along a scene path when one is chosen), one configuration per dashboard frame so the UI
// stays live. The same figures as `bench`.
#include "measure_context.h"
#include "ui/charts/tradeoff_chart.h"

#include <optional>
#include <string>
#include <vector>

namespace ui {

class TradeoffSweep {
public:
    struct Config {
        std::string label, preset;
        geometry::shadow::ShadowSettings settings;
    };
    /// What one configuration measured: every figure the chart's axes can show.
    struct Figures {
        std::string label, preset;
        double gpuMs = 0, cpuMs = 0, memoryMiB = 0, p95 = 0;
        double interior = NAN, edge = NAN, misclassified = NAN, umbra = NAN; // with ground truth on
        double soft = NAN;    // with ground truth and a sun of non-zero size
        double flicker = NAN; // world-space, along the path (when the sweep ran with one)
    };

    /// The chart's axes and the scene path walked for flicker ("" none): the tab's choices.
    charts::TradeoffX x = charts::TradeoffX::GpuMs;
    charts::TradeoffY y = charts::TradeoffY::P95;
    std::string path;

    /// Starts measuring `configs` (results so far are dropped), walking the current `path`.
    void start(std::vector<Config> configs);
    void cancel() noexcept { running_ = false; }
    /// Measures the next configuration; returns a status line (done, or a configuration's error).
    std::optional<std::string> step(const MeasureContext& c);
    [[nodiscard]] bool running() const noexcept { return running_; }
    /// Configurations measured / all, in [0, 1].
    [[nodiscard]] float progress() const noexcept;
    /// The results so far on the chosen axes.
    [[nodiscard]] std::vector<charts::TradeoffPoint> points() const;

private:
    std::vector<Config> configs_;
    size_t next_ = 0;
    bool running_ = false;
    std::vector<Figures> results_;
    std::string runningPath_; // the path of the sweep under way
    MeasureRenderer renderer_;
};

} // namespace ui
