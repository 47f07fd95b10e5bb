#include "ui/charts/chart_imgui.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

namespace ui::charts {

namespace {

ImU32 col(const Rgb& c, int a = 255) { return IM_COL32(c.r, c.g, c.b, a); }
constexpr ImU32 kInk = IM_COL32(51, 51, 51, 255), kGrid = IM_COL32(228, 228, 228, 255);

void text(ImDrawList* dl, float size, float x, float y, const std::string& s, float anchor, ImU32 colour = kInk) {
    ImFont* font = ImGui::GetFont();
    const ImVec2 extent = font->CalcTextSizeA(size, FLT_MAX, 0.f, s.c_str());
    dl->AddText(font, size, ImVec2(std::round(x - anchor * extent.x), std::round(y - extent.y * 0.75f)), colour,
                s.c_str());
}

/// The frame: the title (not when compact), the grid with its tick labels, the box and the axis labels.
void drawAxes(ImDrawList* dl, const Chart& c, const ChartFrame& f, bool compact) {
    if (!compact) text(dl, 15.f, float(f.titleX), float(f.titleY), c.title, 0.5f);
    for (const ChartTick& t : f.xTicks) {
        dl->AddLine(ImVec2(float(t.pixel), float(f.top)), ImVec2(float(t.pixel), float(f.bottom)), kGrid);
        dl->AddLine(ImVec2(float(t.pixel), float(f.bottom)), ImVec2(float(t.pixel), float(f.bottom + 5)), kInk);
        text(dl, 12.f, float(t.pixel), float(f.bottom + 18), t.label, 0.5f);
    }
    for (const ChartTick& t : f.yTicks) {
        dl->AddLine(ImVec2(float(f.left), float(t.pixel)), ImVec2(float(f.right), float(t.pixel)), kGrid);
        dl->AddLine(ImVec2(float(f.left - 5), float(t.pixel)), ImVec2(float(f.left), float(t.pixel)), kInk);
        text(dl, 12.f, float(f.left - 8), float(t.pixel + 4), t.label, 1.f);
    }
    dl->AddRect(ImVec2(float(f.left), float(f.top)), ImVec2(float(f.right), float(f.bottom)), kInk);
    text(dl, 13.f, float((f.left + f.right) / 2), float(f.xLabelY), c.x.label + (c.x.log ? " (log)" : ""), 0.5f);
    // ImDrawList has no rotated text: the y label goes above the axis instead.
    text(dl, 13.f, float(f.left), float(f.top - 8), c.y.label + (c.y.log ? " (log)" : ""), 0.f);
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

/// Plots one series, as labelled markers or as lines through its plottable runs, noting the point nearest the mouse.
void drawSeries(ImDrawList* dl, const Chart& c, const ChartFrame& f, const ChartSeries& s, const float* mouse,
                NearestPoint& nearest) {
    const auto px = [&](const ChartPoint& p) { return ImVec2(float(f.px(p.x, c.x.log)), float(f.py(p.y, c.y.log))); };
    if (s.style == SeriesStyle::Markers) {
        for (size_t i = 0; i < s.points.size(); ++i) {
            const ChartPoint& p = s.points[i];
            if (!plottable(p.x, c.x.log) || !plottable(p.y, c.y.log)) continue;
            dl->AddCircleFilled(px(p), s.markerRadius, col(s.colour), 16);
            const std::string label = i < s.labels.size() ? s.labels[i] : std::string();
            if (!label.empty()) text(dl, 12.f, px(p).x + s.markerRadius + 3, px(p).y - s.markerRadius - 2, label, 0.f);
            nearest.consider(s, p, px(p), label, mouse);
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

/// The legend: one row per series, its marker or line and its name.
void drawLegend(ImDrawList* dl, const Chart& c, const ChartFrame& f) {
    double y = f.legendTop;
    for (const ChartSeries& s : c.series) {
        if (s.style == SeriesStyle::Markers)
            dl->AddCircleFilled(ImVec2(float(f.legendLeft + 11), float(y)), s.markerRadius, col(s.colour), 16);
        else
            dl->AddLine(ImVec2(float(f.legendLeft), float(y)), ImVec2(float(f.legendLeft + 22), float(y)),
                        col(s.colour), 3.f);
        text(dl, 13.f, float(f.legendLeft + 28), float(y + 4), s.name, 0.f);
        y += kLegendRowHeight;
    }
}

/// The nearest point ringed, with its series, label and coordinates in a box kept inside the plot.
void drawTooltip(ImDrawList* dl, const Chart& c, const ChartFrame& f, const NearestPoint& nearest) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s%s%s: x %.4g, y %.4g", nearest.series->name.c_str(),
                  nearest.label.empty() ? "" : " ", nearest.label.c_str(), nearest.point.x, nearest.point.y);
    const ImVec2 q(float(f.px(nearest.point.x, c.x.log)), float(f.py(nearest.point.y, c.y.log)));
    dl->AddCircle(q, 6.f, kInk, 16, 1.5f);
    const ImVec2 size = ImGui::GetFont()->CalcTextSizeA(13.f, FLT_MAX, 0.f, buf);
    const float bx = std::min(q.x + 10.f, float(f.right) - size.x - 6.f),
                by = std::max(q.y - size.y - 12.f, float(f.top) + 2.f);
    dl->AddRectFilled(ImVec2(bx - 4, by - 2), ImVec2(bx + size.x + 4, by + size.y + 2), IM_COL32(255, 255, 230, 240));
    dl->AddText(ImGui::GetFont(), 13.f, ImVec2(bx, by), kInk, buf);
}

} // namespace

void drawChart(ImDrawList* dl, const Chart& c, const PlotArea& area, const float* mouse) {
    if (area.w < 50.f || area.h < 50.f) return;
    const bool compact = area.h < 360.f; // the dashboard's stats panel: every pixel for the plot
    const ChartFrame f = chartFrame(c, area.x, area.y, area.right(), area.bottom(), compact);
    dl->AddRectFilled(ImVec2(area.x, area.y), ImVec2(area.right(), area.bottom()), IM_COL32(255, 255, 255, 255));
    drawAxes(dl, c, f, compact);
    dl->PushClipRect(ImVec2(float(f.left), float(f.top)), ImVec2(float(f.right), float(f.bottom)), true);
    NearestPoint nearest;
    for (const ChartSeries& s : c.series) drawSeries(dl, c, f, s, mouse, nearest);
    dl->PopClipRect();
    drawLegend(dl, c, f);
    if (nearest.series) drawTooltip(dl, c, f, nearest);
}

} // namespace ui::charts
