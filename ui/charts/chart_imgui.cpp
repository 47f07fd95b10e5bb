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

} // namespace

void drawChart(ImDrawList* dl, const Chart& c, const PlotArea& area, const float* mouse) {
    if (area.w < 50.f || area.h < 50.f) return;
    const bool compact = area.h < 360.f; // the dashboard's stats panel: every pixel for the plot
    const ChartFrame f = chartFrame(c, area.x, area.y, area.right(), area.bottom(), compact);
    dl->AddRectFilled(ImVec2(area.x, area.y), ImVec2(area.right(), area.bottom()), IM_COL32(255, 255, 255, 255));
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

    dl->PushClipRect(ImVec2(float(f.left), float(f.top)), ImVec2(float(f.right), float(f.bottom)), true);
    double bestDistance = 12.0 * 12.0;
    const ChartSeries* bestSeries = nullptr;
    ChartPoint bestPoint;
    std::string bestLabel;
    for (const ChartSeries& s : c.series) {
        const auto px = [&](const ChartPoint& p) {
            return ImVec2(float(f.px(p.x, c.x.log)), float(f.py(p.y, c.y.log)));
        };
        const auto consider = [&](const ChartPoint& p, const std::string& label) {
            if (!mouse) return;
            const ImVec2 q = px(p);
            const double d = (q.x - mouse[0]) * (q.x - mouse[0]) + (q.y - mouse[1]) * (q.y - mouse[1]);
            if (d < bestDistance) bestDistance = d, bestSeries = &s, bestPoint = p, bestLabel = label;
        };
        if (s.style == SeriesStyle::Markers) {
            for (size_t i = 0; i < s.points.size(); ++i) {
                const ChartPoint& p = s.points[i];
                if (!plottable(p.x, c.x.log) || !plottable(p.y, c.y.log)) continue;
                dl->AddCircleFilled(px(p), s.markerRadius, col(s.colour), 16);
                const std::string label = i < s.labels.size() ? s.labels[i] : std::string();
                if (!label.empty())
                    text(dl, 12.f, px(p).x + s.markerRadius + 3, px(p).y - s.markerRadius - 2, label, 0.f);
                consider(p, label);
            }
            continue;
        }
        for (const auto& run : plottableRuns(s, c.x.log, c.y.log)) {
            std::vector<ImVec2> pts;
            for (const ChartPoint& p : run) pts.push_back(px(p)), consider(p, {});
            if (pts.size() == 1) dl->AddCircleFilled(pts[0], 2.5f, col(s.colour));
            else dl->AddPolyline(pts.data(), int(pts.size()), col(s.colour), 0, 2.f);
        }
    }
    dl->PopClipRect();

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

    if (bestSeries) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "%s%s%s: x %.4g, y %.4g", bestSeries->name.c_str(), bestLabel.empty() ? "" : " ",
                      bestLabel.c_str(), bestPoint.x, bestPoint.y);
        const ImVec2 q(float(f.px(bestPoint.x, c.x.log)), float(f.py(bestPoint.y, c.y.log)));
        dl->AddCircle(q, 6.f, kInk, 16, 1.5f);
        const ImVec2 size = ImGui::GetFont()->CalcTextSizeA(13.f, FLT_MAX, 0.f, buf);
        const float bx = std::min(q.x + 10.f, float(f.right) - size.x - 6.f),
                    by = std::max(q.y - size.y - 12.f, float(f.top) + 2.f);
        dl->AddRectFilled(ImVec2(bx - 4, by - 2), ImVec2(bx + size.x + 4, by + size.y + 2),
                          IM_COL32(255, 255, 230, 240));
        dl->AddText(ImGui::GetFont(), 13.f, ImVec2(bx, by), kInk, buf);
    }
}

} // namespace ui::charts
