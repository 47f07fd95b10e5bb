#pragma once
// The heatmap's legend drawn over the heatmap panel in the UI font at the UI scale (issue 32: it
// was a tiny bitmap font baked into the image, cut at the image's edge). Lines wrap to the panel's
// width. Files (the screenshot's heatmap.png, `render`) keep the baked legend (heatmap.h).
#include "dashboard_layout.h"
#include "geometry/analysis/heatmap.h"

namespace ui {

/// Draws `legend` in a translucent box at the bottom-left corner of `area` (screen pixels) with
/// the current ImGui window's draw list; records its texts for the legibility check (text_fit.h).
/// Nothing for an empty legend.
void drawHeatmapLegend(const geometry::analysis::Legend& legend, const Rect& area);

} // namespace ui
