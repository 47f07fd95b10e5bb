#pragma once
// ui::charts::Chart drawn with ImGui's draw list (the Charts panel; ui/chart_image.h renders it to PNG):
// the same frame (ticks, ranges, legend place) as the SVG writer, plus a hover readout.
#include "ui/charts/chart.h"

struct ImDrawList;

namespace ui::charts {

/// Where a chart goes on screen (pixels, top-left corner and size).
struct PlotArea {
    float x = 0, y = 0, w = 0, h = 0;
    [[nodiscard]] float right() const noexcept { return x + w; }
    [[nodiscard]] float bottom() const noexcept { return y + h; }
};

/// Draws `chart` into `area` (screen pixels). With `mouse` inside the plot, shows the nearest
/// point's series and values. Returns nothing; pure drawing.
void drawChart(ImDrawList* drawList, const Chart& chart, const PlotArea& area, const float* mouse = nullptr);

} // namespace ui::charts
