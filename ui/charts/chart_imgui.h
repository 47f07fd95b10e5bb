#pragma once
// ui::charts::Chart drawn with ImGui's draw list (the Charts panel; ui/chart_image.h renders it to PNG):
// the same frame (ticks, ranges, legend place) and point-label placement (label_placement.h) as the
// SVG writer, plus a hover readout.
#include "ui/charts/chart.h"
#include "ui/charts/label_placement.h"

#include <string>
#include <vector>

struct ImDrawList;

namespace ui::charts {

/// Where a chart goes on screen (pixels, top-left corner and size) and the UI scale its text and
/// margins follow.
struct PlotArea {
    float x = 0, y = 0, w = 0, h = 0;
    float scale = 1.f;
    [[nodiscard]] float right() const noexcept { return x + w; }
    [[nodiscard]] float bottom() const noexcept { return y + h; }
};

/// A text the chart drew into limited room: its width and the width it had (legibility checks).
struct ChartTextFit {
    std::string what, text;
    double width = 0, box = 0;
};

/// What drawChart() drew.
struct DrawnChart {
    ChartFrame frame;
    bool drawn = false; // false: the area was too small
    std::vector<ChartLabel> labels;
    std::vector<ChartTextFit> texts;
};

/// Draws `chart` into `area` (screen pixels) with the current ImGui font. With `mouse` inside the
/// plot, shows the nearest point's series and values.
DrawnChart drawChart(ImDrawList* drawList, const Chart& chart, const PlotArea& area, const float* mouse = nullptr);

} // namespace ui::charts
