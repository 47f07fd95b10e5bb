#include "ui/charts/label_placement.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace ui::charts {

namespace {

/// DejaVu Sans advance widths in em, ASCII 32 … 126 (read from DejaVuSans.ttf's hmtx table).
constexpr std::array<double, 95> kDejaVuAdvance{
    0.318, 0.401, 0.460, 0.838, 0.636, 0.950, 0.780, 0.275, 0.390, 0.390, 0.500, 0.838, 0.318, 0.361, 0.318, 0.337,
    0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.636, 0.337, 0.337, 0.838, 0.838, 0.838, 0.531,
    1.000, 0.684, 0.686, 0.698, 0.770, 0.632, 0.575, 0.775, 0.752, 0.295, 0.295, 0.656, 0.557, 0.863, 0.748, 0.787,
    0.603, 0.787, 0.695, 0.635, 0.611, 0.732, 0.684, 0.989, 0.685, 0.611, 0.685, 0.390, 0.337, 0.390, 0.838, 0.500,
    0.500, 0.613, 0.635, 0.550, 0.635, 0.615, 0.352, 0.635, 0.634, 0.278, 0.278, 0.579, 0.278, 0.974, 0.634, 0.612,
    0.635, 0.635, 0.411, 0.521, 0.392, 0.634, 0.592, 0.818, 0.592, 0.592, 0.525, 0.636, 0.337, 0.636, 0.838};

/// The label's box when it sits in direction (dx, dy) ∈ {−1, 0, 1}² from the point, `gap` pixels away.
LabelBox candidate(const LabelRequest& r, int dx, int dy, double gap) {
    const double left = dx > 0 ? r.x + gap : dx < 0 ? r.x - gap - r.width : r.x - r.width / 2;
    const double top = dy < 0 ? r.y - gap - r.height : dy > 0 ? r.y + gap : r.y - r.height / 2;
    return {left, top, left + r.width, top + r.height};
}

bool coversAny(const LabelBox& b, std::span<const LabelBox> boxes) {
    return std::any_of(boxes.begin(), boxes.end(), [&](const LabelBox& o) { return b.overlaps(o); });
}

} // namespace

ChartPoint PlacedLabel::leaderEnd(double x, double y) const noexcept {
    return {std::clamp(x, box.left, box.right), std::clamp(y, box.top, box.bottom)};
}

std::vector<PlacedLabel> placeLabels(std::span<const LabelRequest> requests, const LabelBox& bounds,
                                     std::span<const LabelBox> obstacles) {
    // Right-above first (where a reader looks for a point's name), then the other sides.
    static constexpr std::array<std::array<int, 2>, 8> kDirections{
        {{1, -1}, {1, 1}, {-1, -1}, {-1, 1}, {1, 0}, {-1, 0}, {0, -1}, {0, 1}}};
    std::vector<PlacedLabel> out(requests.size());
    std::vector<LabelBox> placed;
    for (size_t i = 0; i < requests.size(); ++i) {
        const LabelRequest& r = requests[i];
        if (!(r.width > 0 && r.height > 0) || !std::isfinite(r.x) || !std::isfinite(r.y)) continue;
        // Ring k's candidates, k label heights further out than ring 0: the eight directions, then
        // beside the point stacked up and down (labels of a crowd line up in a column).
        std::vector<LabelBox> candidates;
        for (int ring = 0; ring <= kLabelRings; ++ring) {
            const double gap = r.radius + 2.0 + double(ring) * r.height;
            for (const auto& [dx, dy] : kDirections) candidates.push_back(candidate(r, dx, dy, gap));
            for (int j = 1; j <= ring; ++j)
                for (const int side : {1, -1})
                    for (const int up : {-1, 1}) {
                        LabelBox b = candidate(r, side, 0, gap);
                        b.top += up * j * r.height, b.bottom += up * j * r.height;
                        candidates.push_back(b);
                    }
        }
        // Pass 0 keeps clear of the markers too; pass 1 only of the labels and the bounds.
        for (int pass = 0; pass < 2 && !out[i].shown; ++pass)
            for (size_t c = 0; c < candidates.size(); ++c) {
                const LabelBox& b = candidates[c];
                if (!b.inside(bounds) || coversAny(b, placed)) continue;
                if (pass == 0 && coversAny(b, obstacles)) continue;
                out[i] = {b, true, c >= kDirections.size()};
                placed.push_back(b);
                break;
            }
    }
    return out;
}

double estimatedTextWidth(std::string_view text, double fontSize) {
    double em = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 32 && c < 127) em += kDejaVuAdvance[c - 32];
        else if ((c & 0xC0) != 0x80) em += 1.0; // a UTF-8 lead byte: one character outside ASCII
    }
    return 1.1 * em * fontSize;
}

std::vector<ChartLabel> chartLabels(const Chart& c, const ChartFrame& f, const TextWidth& width, double fontSize,
                                    double lineHeight) {
    struct Item {
        ChartLabel label;
        double radius;
    };
    std::vector<Item> items;
    std::vector<LabelBox> markers;
    for (const ChartSeries& s : c.series) {
        if (s.style != SeriesStyle::Markers) continue;
        for (size_t i = 0; i < s.points.size(); ++i) {
            const ChartPoint& p = s.points[i];
            if (!plottable(p.x, c.x.log) || !plottable(p.y, c.y.log)) continue;
            const ChartPoint at{f.px(p.x, c.x.log), f.py(p.y, c.y.log)};
            const double r = s.markerRadius;
            markers.push_back({at.x - r, at.y - r, at.x + r, at.y + r});
            if (i < s.labels.size() && !s.labels[i].empty()) items.push_back({{s.labels[i], at, {}}, r});
        }
    }
    // Bigger markers are the highlighted series: their names get the first choice of place.
    std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.radius > b.radius; });
    std::vector<LabelRequest> requests;
    for (const Item& it : items)
        requests.push_back({it.label.at.x, it.label.at.y, it.radius, width(it.label.text, fontSize), lineHeight});
    const std::vector<PlacedLabel> placed = placeLabels(requests, {f.left, f.top, f.right, f.bottom}, markers);
    std::vector<ChartLabel> out;
    for (size_t i = 0; i < items.size(); ++i) {
        out.push_back(std::move(items[i].label));
        out.back().place = placed[i];
    }
    return out;
}

} // namespace ui::charts
