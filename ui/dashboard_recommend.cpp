// The Trade-off tab's "Recommend": the tune search (geometry/analysis/tuner.h) on the current view,
// one measurement per dashboard frame so the UI stays live, with progress, Cancel, the tune chart
// and "Apply to A" / "Apply to B".
#include "dashboard.h"

#include "renderer/measure.h"
#include "ui/charts/chart_imgui.h"
#include "ui/charts/tune_chart.h"
#include "widget_map.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ui {

bool Dashboard::startRecommend(const std::string& target, int budgetEvals) {
    Recommend& r = recommend_;
    try {
        if (!scene_.truth) throw std::runtime_error("Recommend needs ray-traced truth for this scene");
        const geometry::analysis::TuneTarget t = geometry::analysis::parseTuneTarget(target);
        r.size = sides_[0].size.width > 0 ? sides_[0].size : geometry::shadow::Viewport{640, 360};
        // The receivers of the frame shown decide the screening size (they do not depend on the settings).
        double receivers = 0;
        if (const auto* in = inspection(shownSide()); in && in->width == r.size.width)
            receivers = double(std::count(in->receiver.begin(), in->receiver.end(), uint8_t(1)));
        r.tuner = std::make_unique<geometry::analysis::Tuner>(
            state_.settings[size_t(shownSide())], geometry::analysis::defaultTuneSpace(), t,
            geometry::analysis::TuneOptions{.size = r.size, .budgetEvals = budgetEvals, .receiverPixels = receivers});
    } catch (const std::exception& e) {
        status_ = std::string("Recommend: ") + e.what();
        return false;
    }
    r.target = target;
    r.camera = scene_.file.scene.camera;
    r.light = scene_.file.scene.light;
    r.result.reset();
    r.summary.clear();
    r.running = true;
    r.showChart = true;
    return true;
}

void Dashboard::applyRecommendation(int side) {
    if (!recommend_.result) return;
    state_.settings[size_t(side)] = *recommend_.result;
    if (side == 1 && !comparing()) state_.views.compare = CompareMode::SideBySide;
    status_ = std::string("recommended settings applied to ") + (side == 0 ? "A" : "B");
}

void Dashboard::stepRecommend() {
    Recommend& r = recommend_;
    if (!r.running || !r.tuner) return;
    const auto finish = [&] {
        r.running = false;
        const auto& evals = r.tuner->evaluations();
        std::ostringstream os;
        if (const auto best = r.tuner->recommended()) {
            r.result = evals[*best].candidate;
            os << "recommended: " << evals[*best].request.label << " (cost " << evals[*best].figures.costMs
               << " ms modelled, " << evals[*best].figures.frameMs << " ms measured)";
        } else if (const auto near = r.tuner->closest()) {
            os << "nothing met " << r.target << "; closest: " << evals[*near].request.label << ", misses "
               << geometry::analysis::describeMisses(evals[*near].figures, r.tuner->target());
        }
        os << " - " << evals.size() << " evaluations, " << r.tuner->fullEvaluations() << " at full size";
        r.summary = os.str();
        status_ = r.summary;
    };
    const auto request = r.tuner->next();
    if (!request) {
        finish();
        return;
    }
    geometry::scene::Scene& scene = scene_.file.scene;
    if (!r.renderer || r.generation != sceneGeneration_) {
        r.renderer = std::make_unique<renderer::Renderer>(scene);
        r.generation = sceneGeneration_;
    }
    giveCasterLod(*r.renderer);
    try {
        // The stored llvmpipe calibration ranks here too: the dashboard issues no GL query of its own.
        r.tuner->report(renderer::measureTuneRequest(*r.renderer, *request, scene.bounds(), {{r.camera, r.light}},
                                                     *scene_.truth, 1, geometry::analysis::storedCostModel("llvmpipe"),
                                                     {.warmup = 1, .frames = 2}));
    } catch (const std::exception& e) {
        status_ = std::string("Recommend: ") + e.what();
        r.running = false;
    }
}

void Dashboard::drawRecommendControls() {
    Recommend& r = recommend_;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 14);
    ImGui::InputText("target", &r.target);
    widgetMapRecord("recommend.target");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "KEY=VALUE,...: p95 (aliasing m), interior, edge, misclassified (fractions of the receivers), soft "
            "(mean |s - v| against the sun's disk; needs light.angular_diameter_deg > 0), umbra (light in the umbra)");
    ImGui::SameLine();
    if (!r.running) {
        if (ImGui::SmallButton("Recommend")) (void)startRecommend(r.target, r.budget);
        widgetMapRecord("recommend.run");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "Searches for the cheapest settings that meet the target on this view (as `shadowscope "
                "tune`): screening at half size where the target allows, then full size; one measurement per "
                "frame");
    } else {
        const double done = r.tuner ? r.tuner->progress() : 0.0;
        ImGui::ProgressBar(float(done), ImVec2(ImGui::GetFontSize() * 8, 0));
        ImGui::SameLine();
        if (ImGui::SmallButton("Cancel##recommend")) {
            r.running = false;
            if (r.tuner) {
                if (const auto best = r.tuner->recommended()) r.result = r.tuner->evaluations()[*best].candidate;
                r.summary = "cancelled after " + std::to_string(r.tuner->evaluations().size()) + " evaluations";
            }
        }
        widgetMapRecord("recommend.cancel");
    }
    if (r.result) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Apply to A")) applyRecommendation(0);
        widgetMapRecord("recommend.apply_a");
        ImGui::SameLine();
        if (ImGui::SmallButton("Apply to B")) applyRecommendation(1);
        widgetMapRecord("recommend.apply_b");
    }
    if (r.tuner) {
        ImGui::SameLine();
        ImGui::Checkbox("tune chart", &r.showChart);
        widgetMapRecord("recommend.chart");
    }
    if (!r.summary.empty()) ImGui::TextUnformatted(r.summary.c_str());
}

charts::Chart Dashboard::recommendChart() const {
    std::vector<charts::TunePoint> points;
    const auto& tuner = *recommend_.tuner;
    const auto chosen = tuner.recommended();
    for (size_t i = 0; i < tuner.evaluations().size(); ++i) {
        const auto& e = tuner.evaluations()[i];
        points.push_back({e.request.label, e.figures.costMs, geometry::analysis::targetRatio(e.figures, tuner.target()),
                          e.request.stage == geometry::analysis::TuneStage::Full, chosen == i});
    }
    return charts::tuneChart(points, geometry::analysis::formatTuneTarget(tuner.target()));
}

} // namespace ui
