#pragma once
// ui::Chart drawn with ImGui's draw list (the Charts panel, and PNG exports of the same chart):
// the same frame (ticks, ranges, legend place) as the SVG writer, plus a hover readout.
#include "chart.h"
#include "dashboard_layout.h"
#include "renderer/image.h"

struct ImDrawList;

namespace ui {

/// Draws `chart` into `area` (screen pixels). With `mouse` inside the plot, shows the nearest
/// point's series and values. Returns nothing; pure drawing.
void drawChart(ImDrawList* drawList, const Chart& chart, const Rect& area, const float* mouse = nullptr);

/// The chart rendered to an image (needs a current GL context; makes its own ImGui context):
/// the PNG export of a chart.
[[nodiscard]] renderer::Image renderChartImage(const Chart& chart, int width, int height);

} // namespace ui
