#pragma once
// A test hook for legibility (issue 32): the places that draw text into a box of fixed width
// (settings rows, stats cells, legend lines, chart labels) record the text's width and the width
// it was given, so a test can render the dashboard at any size and scale and check that no label
// is cut. Off unless a test turns it on; then the records of the last ImGui frame are kept.
#include <string>
#include <string_view>
#include <vector>

namespace ui {

struct TextFit {
    std::string id;   // where: "settings:filter.kernel", "stats:passes drawn/A", "chart:label 3" …
    std::string text; // what was drawn
    float width = 0;  // the text's extent, pixels
    float box = 0;    // the width available to it, pixels
    [[nodiscard]] bool fits() const noexcept { return width <= box + 0.5f; }
};

/// Starts (true) or stops recording; starting clears what was recorded. Callers skip building a
/// record (its id string, a text extent) when recording is off.
void textFitEnable(bool on);
[[nodiscard]] bool textFitEnabled() noexcept;
/// Records one text. Records of an earlier ImGui frame are dropped first, so the list always
/// describes one frame.
void textFitRecord(std::string_view id, std::string_view text, float width, float box);
/// Records `text` at the current ImGui font: its width against `box`.
void textFitRecordText(std::string_view id, std::string_view text, float box);
/// The records of the last frame that recorded any.
[[nodiscard]] const std::vector<TextFit>& textFits();

} // namespace ui
