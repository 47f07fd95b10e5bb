#pragma once
// Where the dashboard's panels go, as a pure function of the window size, the user's splitter
// positions and the UI scale. The GUI and the headless `render --views dashboard` both place
// their panels with it, so both show the same layout for the same size; tests check it alone.
//
//   +----------+------------------+------------------+------------------+
//   | controls | eye view         | light view       | heatmap          |
//   |          |                  |                  |                  |
//   |          +------------------+------------------+------------------+
//   |          | stats                                                  |
//   +----------+--------------------------------------------------------+
//   | status bar: the pixel under the cursor                            |
//   +-------------------------------------------------------------------+
#include <array>

namespace ui {

struct Rect {
    float x = 0, y = 0, w = 0, h = 0;
    [[nodiscard]] bool contains(float px, float py) const noexcept {
        return px >= x && py >= y && px < x + w && py < y + h;
    }
    [[nodiscard]] float right() const noexcept { return x + w; }
    [[nodiscard]] float bottom() const noexcept { return y + h; }
};

/// The splitter positions the user drags (persisted with the window layout).
struct LayoutFractions {
    float controlsWidth = 340.f; // pixels at UI scale 1
    float eyeEnd = 0.40f;        // where the eye view ends, as a fraction of the views' width
    float lightEnd = 0.70f;      // where the light view ends
    float statsHeight = 0.27f;   // the stats panel's share of the height below the top edge
};

/// Fractions clamped to usable ranges (NaN → default): every panel keeps some room.
[[nodiscard]] LayoutFractions clampFractions(LayoutFractions f) noexcept;

enum class Splitter { Controls, EyeLight, LightHeatmap, Stats, Count };

struct DashboardRects {
    Rect controls, eye, light, heatmap, stats, status;
    std::array<Rect, static_cast<int>(Splitter::Count)> splitters; // grab handles between panels
};

/// Thickness of a splitter handle and height of the status bar, in pixels at UI scale 1.
inline constexpr float kSplitterWidth = 6.f;
inline constexpr float kStatusBarHeight = 22.f;

/// Panel rectangles for a width × height window. Sizes are whole pixels, never negative; a
/// zero or non-finite window gives empty rectangles.
[[nodiscard]] DashboardRects layoutDashboard(float width, float height, const LayoutFractions& fractions,
                                             float uiScale) noexcept;

/// The fractions after dragging `splitter` by (dx, dy) pixels in a width × height window.
[[nodiscard]] LayoutFractions dragSplitter(LayoutFractions f, Splitter splitter, float dx, float dy, float width,
                                           float height, float uiScale) noexcept;

} // namespace ui
