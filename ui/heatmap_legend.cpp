#include "heatmap_legend.h"

#include "text_fit.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <string>
#include <vector>

namespace ui {

namespace {

ImU32 colour(const glm::vec3& c, int alpha = 255) {
    const auto byte = [](float v) { return int(std::clamp(v, 0.f, 1.f) * 255.f + 0.5f); };
    return IM_COL32(byte(c.r), byte(c.g), byte(c.b), alpha);
}

/// One text of the legend: where it goes and the width it wraps at.
struct Line {
    std::string text;
    ImVec2 pos;
    float wrap = 0;
};

} // namespace

void drawHeatmapLegend(const geometry::analysis::Legend& legend, const Rect& area) {
    if (legend.empty() || area.w < 1.f || area.h < 1.f) return;
    ImFont* font = ImGui::GetFont();
    const float size = ImGui::GetFontSize(), pad = 0.4f * size, margin = 0.5f * size, gap = 0.3f * size;
    const float swatch = 0.8f * size;
    // The widest box the panel has room for; the bar as wide as the ticks' labels need, at most that.
    const float room = std::max(area.w - 2.f * margin - 2.f * pad, 4.f * size);
    const auto extent = [&](const std::string& s, float wrap) {
        return font->CalcTextSizeA(size, FLT_MAX, wrap, s.c_str());
    };
    float tickWidth = 0;
    for (const auto& t : legend.ticks) tickWidth = std::max(tickWidth, extent(t.label, 0.f).x);
    const float barW = std::min(room - tickWidth, std::max(11.f * size, 1.5f * tickWidth * float(legend.ticks.size())));
    const float barH = 0.7f * size;

    // Lay out top to bottom from y = 0, then move the box to the panel's bottom-left corner.
    std::vector<Line> lines;
    float y = 0, contentW = 0;
    if (!legend.title.empty()) {
        const ImVec2 e = extent(legend.title, room);
        lines.push_back({legend.title, {0.f, y}, room});
        contentW = std::max(contentW, e.x);
        y += e.y + gap;
    }
    const float barX = legend.ticks.empty() ? 0.f : 0.5f * tickWidth, barY = y;
    if (legend.bar) {
        contentW = std::max(contentW, barX + barW + (legend.ticks.empty() ? 0.f : 0.5f * tickWidth));
        y += barH;
        for (const auto& t : legend.ticks) {
            const float w = extent(t.label, 0.f).x;
            lines.push_back(
                {t.label, {barX + std::clamp(t.position, 0.f, 1.f) * barW - 0.5f * w, y + 0.2f * size}, 0.f});
        }
        y += (legend.ticks.empty() ? 0.f : 0.2f * size + size) + gap;
    }
    const float labelX = swatch + gap, labelRoom = std::max(room - labelX, size);
    std::vector<float> swatchY;
    for (const auto& e : legend.entries) {
        const ImVec2 ext = extent(e.label, labelRoom);
        swatchY.push_back(y + 0.5f * (size - swatch));
        lines.push_back({e.label, {labelX, y}, labelRoom});
        contentW = std::max(contentW, labelX + ext.x);
        y += ext.y + 0.15f * size;
    }
    const float boxW = contentW + 2.f * pad, boxH = y - (legend.entries.empty() ? gap : 0.15f * size) + 2.f * pad;
    const ImVec2 origin(area.x + margin, area.y + area.h - margin - boxH); // the box's top-left
    const ImVec2 o(origin.x + pad, origin.y + pad);                        // the content's

    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(ImVec2(area.x, area.y), ImVec2(area.x + area.w, area.y + area.h), true);
    dl->AddRectFilled(origin, ImVec2(origin.x + boxW, origin.y + boxH), IM_COL32(10, 10, 13, 190), 3.f);
    if (legend.bar) {
        const int steps = std::max(2, int(barW));
        for (int i = 0; i < steps; ++i) {
            const float x0 = o.x + barX + barW * float(i) / float(steps),
                        x1 = o.x + barX + barW * float(i + 1) / float(steps);
            dl->AddRectFilled(ImVec2(x0, o.y + barY), ImVec2(x1 + 0.5f, o.y + barY + barH),
                              colour(legend.bar((float(i) + 0.5f) / float(steps))));
        }
        for (const auto& t : legend.ticks) {
            const float x = o.x + barX + std::clamp(t.position, 0.f, 1.f) * barW;
            dl->AddLine(ImVec2(x, o.y + barY + barH), ImVec2(x, o.y + barY + barH + 0.2f * size),
                        IM_COL32(245, 245, 245, 255));
        }
    }
    for (size_t i = 0; i < legend.entries.size(); ++i) {
        const ImVec2 a(o.x, o.y + swatchY[i]), b(o.x + swatch, o.y + swatchY[i] + swatch);
        dl->AddRectFilled(a, b, colour(legend.entries[i].colour));
        dl->AddRect(a, b, IM_COL32(155, 155, 155, 255)); // keeps dark swatches visible on the dark box
    }
    const float boxRight = area.x + area.w - margin - pad;
    for (const Line& l : lines) {
        const ImVec2 at(o.x + l.pos.x, o.y + l.pos.y);
        dl->AddText(font, size, at, IM_COL32(245, 245, 245, 255), l.text.c_str(), nullptr, l.wrap);
        // The room a line has: to its wrap width, and never past the panel's right edge.
        const float box = std::min(l.wrap > 0.f ? l.wrap : FLT_MAX, boxRight - at.x);
        if (textFitEnabled())
            textFitRecord("legend:" + l.text, l.text, extent(l.text, l.wrap).x, at.x >= area.x ? box : 0.f);
    }
    dl->PopClipRect();
}

} // namespace ui
