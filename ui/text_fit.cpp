#include "text_fit.h"

#include <imgui.h>

namespace ui {

namespace {
struct FitState {
    bool on = false;
    int frame = -1; // the ImGui frame the records belong to
    std::vector<TextFit> fits;
};
FitState& state() {
    static FitState s;
    return s;
}
} // namespace

void textFitEnable(bool on) {
    state() = FitState{};
    state().on = on;
}

bool textFitEnabled() noexcept { return state().on; }

void textFitRecord(std::string_view id, std::string_view text, float width, float box) {
    FitState& s = state();
    if (!s.on) return;
    // No ImGui context (the SVG writer, a PNG export made outside a frame): frame -1.
    const int frame = ImGui::GetCurrentContext() ? ImGui::GetFrameCount() : -1;
    if (frame != s.frame) s.fits.clear(), s.frame = frame;
    s.fits.push_back({std::string(id), std::string(text), width, box});
}

void textFitRecordText(std::string_view id, std::string_view text, float box) {
    if (!state().on) return;
    textFitRecord(id, text, ImGui::CalcTextSize(text.data(), text.data() + text.size()).x, box);
}

const std::vector<TextFit>& textFits() { return state().fits; }

} // namespace ui
