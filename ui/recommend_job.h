#pragma once
// The Trade-off tab's "Recommend": the tune search (geometry/analysis/tuner.h) on the view shown when
// it started, one measurement per dashboard frame so the UI stays live; the best settings found,
// a summary line and the tune chart.
#include "measure_context.h"

#include "geometry/analysis/tuner.h"
#include "ui/charts/chart.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ui {

class RecommendJob {
public:
    /// The tab's fields: the target text, the evaluation budget, tune chart or trade-off chart.
    std::string target = "p95=2,interior=0.001,edge=0.02";
    int budget = 40;
    bool showChart = false;

    /// Starts `tuner`'s search at the view (`camera`, `light`, the scene's `others` lights drawn too);
    /// forgets the last result.
    void start(std::unique_ptr<geometry::analysis::Tuner> tuner, const geometry::scene::Camera& camera,
               const geometry::scene::Light& light, std::vector<geometry::scene::Light> others = {});
    /// Measures the tuner's next request; when the search ends (or fails) returns its summary line.
    std::optional<std::string> step(const MeasureContext& c);
    /// Stops the search, keeping the best settings so far.
    void cancel();
    [[nodiscard]] bool running() const noexcept { return running_; }
    [[nodiscard]] double progress() const noexcept { return tuner_ ? tuner_->progress() : 0.0; }
    [[nodiscard]] bool started() const noexcept { return tuner_ != nullptr; }
    [[nodiscard]] const std::optional<geometry::shadow::ShadowSettings>& result() const noexcept { return result_; }
    [[nodiscard]] const std::string& summary() const noexcept { return summary_; }
    /// Every evaluation so far, cost against the target ratio (needs started()).
    [[nodiscard]] charts::Chart chart() const;

private:
    std::string finish();

    std::unique_ptr<geometry::analysis::Tuner> tuner_;
    bool running_ = false;
    std::optional<geometry::shadow::ShadowSettings> result_;
    std::string summary_;
    geometry::scene::Camera camera_;
    geometry::scene::Light light_;
    std::vector<geometry::scene::Light> others_;
    MeasureRenderer renderer_;
};

} // namespace ui
