#include "ui/charts/chart_imgui.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

namespace ui::charts {

namespace {

ImU32 col(const Rgb& c, int a = 255) { return IM_COL32(c.r, c.g, c.b, a); }
constexpr ImU32 kInk = IM_COL32(51, 51, 51, 255), kGrid = IM_COL32(228, 228, 228, 255),
                kLeader = IM_COL32(150, 150, 150, 255);

void text(ImDrawList* dl, float size, float x, float y, const std::string& s, float anchor, ImU32 colour = kInk) {
    ImFont* font = ImGui::GetFont();
    const ImVec2 extent = font->CalcTextSizeA(size, FLT_MAX, 0.f, s.c_str());
    dl->AddText(font, size, ImVec2(std::round(x - anchor * extent.x), std::round(y - extent.y * 0.75f)), colour,
                s.c_str());
}

/// Width of `s` in the current ImGui font at `size` pixels.
double textWidth(std::string_view s, double size) {
    return ImGui::GetFont()->CalcTextSizeA(float(size), FLT_MAX, 0.f, s.data(), s.data() + s.size()).x;
}

/// The frame: the title (not when compact), the grid with its tick labels, the box and the axis
/// labels; notes the texts drawn into limited room.
void drawAxes(ImDrawList* dl, const Chart& c, const ChartFrame& f, const PlotArea& area, bool compact,
              std::vector<ChartTextFit>& fits) {
    const float k = area.scale;
    if (!compact) {
        text(dl, 15.f * k, float(f.titleX), float(f.titleY), c.title, 0.5f);
        fits.push_back({"title", c.title, textWidth(c.title, 15.f * k), area.w});
    }
    for (const ChartTick& t : f.xTicks) {
        dl->AddLine(ImVec2(float(t.pixel), float(f.top)), ImVec2(float(t.pixel), float(f.bottom)), kGrid);
        dl->AddLine(ImVec2(float(t.pixel), float(f.bottom)), ImVec2(float(t.pixel), float(f.bottom + 5 * k)), kInk);
        text(dl, 12.f * k, float(t.pixel), float(f.bottom + 18 * k), t.label, 0.5f);
    }
    for (const ChartTick& t : f.yTicks) {
        dl->AddLine(ImVec2(float(f.left), float(t.pixel)), ImVec2(float(f.right), float(t.pixel)), kGrid);
        dl->AddLine(ImVec2(float(f.left - 5 * k), float(t.pixel)), ImVec2(float(f.left), float(t.pixel)), kInk);
        text(dl, 12.f * k, float(f.left - 8 * k), float(t.pixel + 4 * k), t.label, 1.f);
        fits.push_back({"y tick", t.label, textWidth(t.label, 12.f * k), f.left - 8 * k - area.x});
    }
    dl->AddRect(ImVec2(float(f.left), float(f.top)), ImVec2(float(f.right), float(f.bottom)), kInk);
    const std::string xLabel = c.x.label + (c.x.log ? " (log)" : "");
    const double centre = (f.left + f.right) / 2;
    text(dl, 13.f * k, float(centre), float(f.xLabelY), xLabel, 0.5f);
    fits.push_back(
        {"x label", xLabel, textWidth(xLabel, 13.f * k), 2 * std::min(centre - area.x, area.right() - centre)});
    // ImDrawList has no rotated text: the y label goes above the axis instead.
    const std::string yLabel = c.y.label + (c.y.log ? " (log)" : "");
    text(dl, 13.f * k, float(f.left), float(f.top - 8 * k), yLabel, 0.f);
    fits.push_back({"y label", yLabel, textWidth(yLabel, 13.f * k), area.right() - f.left});
}

/// The plotted point nearest the mouse, within 12 pixels.
struct NearestPoint {
    double distance = 12.0 * 12.0; // squared, in pixels
    const ChartSeries* series = nullptr;
    ChartPoint point;
    std::string label;

    /// Takes `p` of `s`, drawn at `q`, when it is nearer the mouse than the nearest so far.
    void consider(const ChartSeries& s, const ChartPoint& p, ImVec2 q, const std::string& pointLabel,
                  const float* mouse) {
        if (!mouse) return;
        const double d = (q.x - mouse[0]) * (q.x - mouse[0]) + (q.y - mouse[1]) * (q.y - mouse[1]);
        if (d < distance) distance = d, series = &s, point = p, label = pointLabel;
    }
};

/// Plots one series, as markers or as lines through its plottable runs, noting the point nearest the mouse.
void drawSeries(ImDrawList* dl, const Chart& c, const ChartFrame& f, const ChartSeries& s, const float* mouse,
                NearestPoint& nearest) {
    const auto px = [&](const ChartPoint& p) { return ImVec2(float(f.px(p.x, c.x.log)), float(f.py(p.y, c.y.log))); };
    if (s.style == SeriesStyle::Markers) {
        for (size_t i = 0; i < s.points.size(); ++i) {
            const ChartPoint& p = s.points[i];
            if (!plottable(p.x, c.x.log) || !plottable(p.y, c.y.log)) continue;
            dl->AddCircleFilled(px(p), s.markerRadius, col(s.colour), 16);
            nearest.consider(s, p, px(p), i < s.labels.size() ? s.labels[i] : std::string(), mouse);
        }
        return;
    }
    for (const auto& run : plottableRuns(s, c.x.log, c.y.log)) {
        std::vector<ImVec2> pts;
        for (const ChartPoint& p : run) pts.push_back(px(p)), nearest.consider(s, p, pts.back(), {}, mouse);
        if (pts.size() == 1) dl->AddCircleFilled(pts[0], 2.5f, col(s.colour));
        else dl->AddPolyline(pts.data(), int(pts.size()), col(s.colour), 0, 2.f);
    }
}

/// The point labels where label_placement.h put them, a leader line to a displaced one's point.
void drawLabels(ImDrawList* dl, const std::vector<ChartLabel>& labels, float size) {
    for (const ChartLabel& l : labels) {
        if (!l.place.shown) continue;
        if (l.place.displaced) {
            const ChartPoint end = l.place.leaderEnd(l.at.x, l.at.y);
            dl->AddLine(ImVec2(float(l.at.x), float(l.at.y)), ImVec2(float(end.x), float(end.y)), kLeader);
        }
        dl->AddText(ImGui::GetFont(), size, ImVec2(float(l.place.box.left), float(l.place.box.top)), kInk,
                    l.text.c_str());
    }
}

/// The legend: one row per series, its marker or line and its name.
void drawLegend(ImDrawList* dl, const Chart& c, const ChartFrame& f, const PlotArea& area,
                std::vector<ChartTextFit>& fits) {
    const double k = area.scale;
    double y = f.legendTop;
    for (const ChartSeries& s : c.series) {
        if (s.style == SeriesStyle::Markers)
            dl->AddCircleFilled(ImVec2(float(f.legendLeft + 11 * k), float(y)), s.markerRadius, col(s.colour), 16);
        else
            dl->AddLine(ImVec2(float(f.legendLeft), float(y)), ImVec2(float(f.legendLeft + 22 * k), float(y)),
                        col(s.colour), 3.f);
        text(dl, 13.f * float(k), float(f.legendLeft + 28 * k), float(y + 4 * k), s.name, 0.f);
        fits.push_back({"legend", s.name, textWidth(s.name, 13 * k), area.right() - (f.legendLeft + 28 * k)});
        y += kLegendRowHeight * k;
    }
}

/// The nearest point ringed, with its series, label and coordinates in a box kept inside the plot.
void drawTooltip(ImDrawList* dl, const Chart& c, const ChartFrame& f, const NearestPoint& nearest, float k) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s%s%s: x %.4g, y %.4g", nearest.series->name.c_str(),
                  nearest.label.empty() ? "" : " ", nearest.label.c_str(), nearest.point.x, nearest.point.y);
    const ImVec2 q(float(f.px(nearest.point.x, c.x.log)), float(f.py(nearest.point.y, c.y.log)));
    dl->AddCircle(q, 6.f, kInk, 16, 1.5f);
    const ImVec2 size = ImGui::GetFont()->CalcTextSizeA(13.f * k, FLT_MAX, 0.f, buf);
    const float bx = std::min(q.x + 10.f, float(f.right) - size.x - 6.f),
                by = std::max(q.y - size.y - 12.f, float(f.top) + 2.f);
    dl->AddRectFilled(ImVec2(bx - 4, by - 2), ImVec2(bx + size.x + 4, by + size.y + 2), IM_COL32(255, 255, 230, 240));
    dl->AddText(ImGui::GetFont(), 13.f * k, ImVec2(bx, by), kInk, buf);
}

} // namespace

DrawnChart drawChart(ImDrawList* dl, const Chart& c, const PlotArea& area, const float* mouse) {
    DrawnChart out;
    const float k = area.scale > 0.f ? area.scale : 1.f;
    if (area.w < 50.f * k || area.h < 50.f * k) return out;
    const bool compact = area.h < 360.f * k; // the dashboard's stats panel: every pixel for the plot
    out.frame = chartFrame(c, area.x, area.y, area.right(), area.bottom(), compact, k);
    out.drawn = true;
    const ChartFrame& f = out.frame;
    dl->AddRectFilled(ImVec2(area.x, area.y), ImVec2(area.right(), area.bottom()), IM_COL32(255, 255, 255, 255));
    drawAxes(dl, c, f, area, compact, out.texts);
    dl->PushClipRect(ImVec2(float(f.left), float(f.top)), ImVec2(float(f.right), float(f.bottom)), true);
    NearestPoint nearest;
    for (const ChartSeries& s : c.series) drawSeries(dl, c, f, s, mouse, nearest);
    dl->PopClipRect();
    // Labels are placed inside the plot by the same rule as the SVG writer's, measured in this font.
    const float labelSize = 12.f * k;
    out.labels =
        chartLabels(c, f, textWidth, labelSize, ImGui::GetFont()->CalcTextSizeA(labelSize, FLT_MAX, 0.f, "Ag").y);
    drawLabels(dl, out.labels, labelSize);
    for (const ChartLabel& l : out.labels)
        if (l.place.shown)
            out.texts.push_back({"point label", l.text, textWidth(l.text, labelSize),
                                 l.place.box.inside({f.left, f.top, f.right, f.bottom}) ? l.place.box.width() : 0.0});
    drawLegend(dl, c, f, {area.x, area.y, area.w, area.h, k}, out.texts);
    if (nearest.series) drawTooltip(dl, c, f, nearest, k);
    return out;
}

} // namespace ui::charts
