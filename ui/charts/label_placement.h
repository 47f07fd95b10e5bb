#pragma once
// Where the point labels of a chart go (issue 32: labels of bench's tradeoff.png overlapped and one
// was cut at the edge): a pure, greedy placement shared by the SVG writer and the ImDrawList
// renderer. Each renderer measures its text with its own font metrics and passes the extents in.
#include "ui/charts/chart.h"

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ui::charts {

struct LabelBox {
    double left = 0, top = 0, right = 0, bottom = 0;
    [[nodiscard]] double width() const noexcept { return right - left; }
    [[nodiscard]] double height() const noexcept { return bottom - top; }
    /// The interiors meet (touching edges do not count).
    [[nodiscard]] bool overlaps(const LabelBox& o) const noexcept {
        return left < o.right && o.left < right && top < o.bottom && o.top < bottom;
    }
    [[nodiscard]] bool inside(const LabelBox& outer) const noexcept {
        return left >= outer.left && right <= outer.right && top >= outer.top && bottom <= outer.bottom;
    }
};

/// A label to place: the point it names, its marker's radius and the text's extent.
struct LabelRequest {
    double x = 0, y = 0;
    double radius = 0;
    double width = 0, height = 0;
};

/// Where a label went. `displaced`: not beside its point (the renderer draws a leader line from
/// the point to leaderEnd()); not `shown`: no free place within reach (the hover readout still names it).
struct PlacedLabel {
    LabelBox box;
    bool shown = false, displaced = false;
    /// The point of the box nearest the label's point.
    [[nodiscard]] ChartPoint leaderEnd(double x, double y) const noexcept;
};

/// How far out placeLabels() looks: this many rings of one label height beyond the nearest places.
inline constexpr int kLabelRings = 8;

/// Places labels in order (put the important ones first): for each, the first candidate that lies
/// inside `bounds` and overlaps no label placed before it, trying the eight places around the point
/// (right-above first), then rings one label height further out each (the eight directions, and
/// beside the point stacked up and down); candidates that cover no `obstacles` (the other markers)
/// are preferred. A label that cannot be placed is not shown. Shown boxes never overlap each other
/// and always lie inside `bounds`.
[[nodiscard]] std::vector<PlacedLabel> placeLabels(std::span<const LabelRequest> requests, const LabelBox& bounds,
                                                   std::span<const LabelBox> obstacles = {});

/// A text width in pixels at a font size: each renderer measures with its own font.
using TextWidth = std::function<double(std::string_view text, double fontSize)>;

/// The SVG writer's width of `text`: the viewer picks the font, so this is a conservative estimate:
/// DejaVu Sans's advance widths (the UI font, among the widest sans-serif faces) plus 10 %, 1 em
/// for a character outside ASCII.
[[nodiscard]] double estimatedTextWidth(std::string_view text, double fontSize);

/// The SVG writer's point labels: a box 1.25 em tall per line, the baseline 0.95 em below its top.
inline constexpr double kLabelLineHeight = 1.25, kLabelBaseline = 0.95;

/// A marker series' point label, placed.
struct ChartLabel {
    std::string text;
    ChartPoint at; // the point's pixel position
    PlacedLabel place;
};

/// The point labels of `chart` in `frame`, placed inside the plot: highlighted series (bigger
/// markers) first, the markers as obstacles. `width` measures at `fontSize`; `lineHeight` is the
/// box height of one line.
[[nodiscard]] std::vector<ChartLabel> chartLabels(const Chart& chart, const ChartFrame& frame, const TextWidth& width,
                                                  double fontSize, double lineHeight);

} // namespace ui::charts
