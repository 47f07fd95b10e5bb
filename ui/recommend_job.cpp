#include "recommend_job.h"

#include "renderer/measure.h"
#include "ui/charts/tune_chart.h"

#include <sstream>

namespace ui {

void RecommendJob::start(std::unique_ptr<geometry::analysis::Tuner> tuner, const geometry::scene::Camera& camera,
                         const geometry::scene::Light& light, std::vector<geometry::scene::Light> others) {
    tuner_ = std::move(tuner);
    camera_ = camera;
    light_ = light;
    others_ = std::move(others);
    result_.reset();
    summary_.clear();
    running_ = true;
    showChart = true;
}

std::string RecommendJob::finish() {
    running_ = false;
    const auto& evals = tuner_->evaluations();
    std::ostringstream os;
    if (const auto best = tuner_->recommended()) {
        result_ = evals[*best].candidate;
        os << "recommended: " << evals[*best].request.label << " (cost " << evals[*best].figures.costMs
           << " ms modelled, " << evals[*best].figures.frameMs << " ms measured)";
    } else if (const auto near = tuner_->closest()) {
        os << "nothing met " << target << "; closest: " << evals[*near].request.label << ", misses "
           << geometry::analysis::describeMisses(evals[*near].figures, tuner_->target());
    }
    os << " - " << evals.size() << " evaluations, " << tuner_->fullEvaluations() << " at full size";
    summary_ = os.str();
    return summary_;
}

std::optional<std::string> RecommendJob::step(const MeasureContext& c) {
    if (!running_ || !tuner_) return std::nullopt;
    const auto request = tuner_->next();
    if (!request) return finish();
    if (!c.scene.truth) {
        running_ = false;
        return std::string("Recommend: the scene has no ray-traced truth");
    }
    renderer::Renderer& r = renderer_.get(c);
    try {
        // The stored llvmpipe calibration ranks here too: the dashboard issues no GL query of its own.
        tuner_->report(renderer::measureTuneRequest(
            r, *request, c.scene.file.scene.bounds(), {{camera_, light_, others_}}, *c.scene.truth, 1,
            geometry::analysis::storedCostModel("llvmpipe"), {.warmup = 1, .frames = 2}));
    } catch (const std::exception& e) {
        running_ = false;
        return std::string("Recommend: ") + e.what();
    }
    return std::nullopt;
}

void RecommendJob::cancel() {
    running_ = false;
    if (!tuner_) return;
    if (const auto best = tuner_->recommended()) result_ = tuner_->evaluations()[*best].candidate;
    summary_ = "cancelled after " + std::to_string(tuner_->evaluations().size()) + " evaluations";
}

charts::Chart RecommendJob::chart() const {
    std::vector<charts::TunePoint> points;
    const auto chosen = tuner_->recommended();
    for (size_t i = 0; i < tuner_->evaluations().size(); ++i) {
        const auto& e = tuner_->evaluations()[i];
        points.push_back({e.request.label, e.figures.costMs,
                          geometry::analysis::targetRatio(e.figures, tuner_->target()),
                          e.request.stage == geometry::analysis::TuneStage::Full, chosen == i});
    }
    return charts::tuneChart(points, geometry::analysis::formatTuneTarget(tuner_->target()));
}

} // namespace ui
