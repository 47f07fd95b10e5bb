// The Trade-off tab's "Recommend" controls: target, progress, Cancel, the tune chart and "Apply to A"
// / "Apply to B"; the search itself runs in recommend_ (recommend_job.h), one measurement a frame.
#include "dashboard.h"

#include "widget_map.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>

namespace ui {

bool Dashboard::startRecommend(const std::string& target, int budgetEvals) {
    try {
        if (!scene_.truth) throw std::runtime_error("Recommend needs ray-traced truth for this scene");
        const geometry::analysis::TuneTarget t = geometry::analysis::parseTuneTarget(target);
        const geometry::shadow::Viewport size =
            sides_[0].size.width > 0 ? sides_[0].size : geometry::shadow::Viewport{640, 360};
        // The receivers of the frame shown decide the screening size (they do not depend on the settings).
        double receivers = 0;
        if (const auto* in = inspection(shownSide()); in && in->width == size.width)
            receivers = double(std::count(in->receiver.begin(), in->receiver.end(), uint8_t(1)));
        recommend_.start(
            std::make_unique<geometry::analysis::Tuner>(
                state_.settings[size_t(shownSide())], geometry::analysis::defaultTuneSpace(), t,
                geometry::analysis::TuneOptions{.size = size, .budgetEvals = budgetEvals, .receiverPixels = receivers}),
            scene_.file.scene.camera, scene_.file.scene.lights[0]);
    } catch (const std::exception& e) {
        status_ = std::string("Recommend: ") + e.what();
        return false;
    }
    recommend_.target = target;
    return true;
}

void Dashboard::applyRecommendation(int side) {
    if (!recommend_.result()) return;
    state_.settings[size_t(side)] = *recommend_.result();
    if (side == 1 && !comparing()) state_.views.compare = CompareMode::SideBySide;
    status_ = std::string("recommended settings applied to ") + (side == 0 ? "A" : "B");
}

void Dashboard::drawRecommendControls() {
    RecommendJob& r = recommend_;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 14);
    ImGui::InputText("target", &r.target);
    widgetMapRecord("recommend.target");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "KEY=VALUE,...: p95 (aliasing m), interior, edge, misclassified (fractions of the receivers), soft "
            "(mean |s - v| against the sun's disk; needs light.angular_diameter_deg > 0), umbra (light in the umbra)");
    ImGui::SameLine();
    if (!r.running()) {
        if (ImGui::SmallButton("Recommend")) (void)startRecommend(r.target, r.budget);
        widgetMapRecord("recommend.run");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "Searches for the cheapest settings that meet the target on this view (as `shadowscope "
                "tune`): screening at half size where the target allows, then full size; one measurement per "
                "frame");
    } else {
        ImGui::ProgressBar(float(r.progress()), ImVec2(ImGui::GetFontSize() * 8, 0));
        ImGui::SameLine();
        if (ImGui::SmallButton("Cancel##recommend")) r.cancel();
        widgetMapRecord("recommend.cancel");
    }
    if (r.result()) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Apply to A")) applyRecommendation(0);
        widgetMapRecord("recommend.apply_a");
        ImGui::SameLine();
        if (ImGui::SmallButton("Apply to B")) applyRecommendation(1);
        widgetMapRecord("recommend.apply_b");
    }
    if (r.started()) {
        ImGui::SameLine();
        ImGui::Checkbox("tune chart", &r.showChart);
        widgetMapRecord("recommend.chart");
    }
    if (!r.summary().empty()) { // wrapped: a long summary must not run past the panel's edge
        ImGui::PushTextWrapPos(0.f);
        ImGui::TextUnformatted(r.summary().c_str());
        ImGui::PopTextWrapPos();
    }
}

} // namespace ui
