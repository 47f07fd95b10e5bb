#pragma once
// A chart rendered to an image through the same ImDrawList drawing as the Charts panel: the PNG
// export of a chart (ui/charts/chart_imgui.h).
#include "geometry/analysis/image.h"
#include "ui/charts/chart.h"

namespace ui {

/// The chart rendered to an image (needs a current GL context; makes its own ImGui context).
[[nodiscard]] geometry::analysis::Image renderChartImage(const charts::Chart& chart, int width, int height);

} // namespace ui
