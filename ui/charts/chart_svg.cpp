// ui::Chart as SVG text: what the chart shows (ranges, ticks, labels) comes from chart_axes.cpp;
// this file only lays it out in pixels.
#include "ui/charts/chart.h"
#include "ui/charts/label_placement.h"
#include "ui/charts/xml_text.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace ui::charts {

namespace {

constexpr const char* kFont = "font-family=\"sans-serif\"";

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

std::string colour(const Rgb& c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
    return buf;
}

struct Box {
    double left, top, right, bottom;
    [[nodiscard]] double width() const { return right - left; }
    [[nodiscard]] double height() const { return bottom - top; }
};

std::string text(double x, double y, const std::string& s, double size, const char* anchor, const char* extra = "") {
    return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" " + kFont + " font-size=\"" + num(size) +
           "\" text-anchor=\"" + anchor + "\"" + extra + ">" + xmlEscape(s) + "</text>\n";
}

std::string line(double x1, double y1, double x2, double y2, const char* stroke, double width) {
    return "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" + num(y2) +
           "\" stroke=\"" + stroke + "\" stroke-width=\"" + num(width) + "\"/>\n";
}

/// Grid lines, tick marks and tick labels of both axes.
std::string axesSvg(const ChartFrame& f) {
    std::string out;
    for (const ChartTick& t : f.xTicks) {
        out += line(t.pixel, f.top, t.pixel, f.bottom, "#e4e4e4", 1);
        out += line(t.pixel, f.bottom, t.pixel, f.bottom + 5, "#333333", 1);
        out += text(t.pixel, f.bottom + 18, t.label, 11, "middle");
    }
    for (const ChartTick& t : f.yTicks) {
        out += line(f.left, t.pixel, f.right, t.pixel, "#e4e4e4", 1);
        out += line(f.left - 5, t.pixel, f.left, t.pixel, "#333333", 1);
        out += text(f.left - 8, t.pixel + 4, t.label, 11, "end");
    }
    out += "<rect x=\"" + num(f.left) + "\" y=\"" + num(f.top) + "\" width=\"" + num(f.right - f.left) +
           "\" height=\"" + num(f.bottom - f.top) + "\" fill=\"none\" stroke=\"#333333\" stroke-width=\"1\"/>\n";
    return out;
}

/// One <polyline> per run of plottable points (a single point becomes a dot), or one dot per point
/// for marker series, clipped to the plot.
std::string seriesSvg(const Chart& c, const ChartFrame& f, const std::string& clipId) {
    std::string out =
        "<g clip-path=\"url(#" + clipId + ")\" fill=\"none\" stroke-width=\"2\" stroke-linejoin=\"round\">\n";
    for (const ChartSeries& s : c.series) {
        const std::string stroke = colour(s.colour);
        const auto px = [&](const ChartPoint& p) { return f.px(p.x, c.x.log); };
        const auto py = [&](const ChartPoint& p) { return f.py(p.y, c.y.log); };
        if (s.style == SeriesStyle::Markers) {
            for (size_t i = 0; i < s.points.size(); ++i) {
                const ChartPoint& p = s.points[i];
                if (!plottable(p.x, c.x.log) || !plottable(p.y, c.y.log)) continue;
                out += "<circle cx=\"" + num(px(p)) + "\" cy=\"" + num(py(p)) + "\" r=\"" + num(s.markerRadius) +
                       "\" fill=\"" + stroke + "\" stroke=\"none\"><title>" + xmlEscape(s.name) + "</title></circle>\n";
            }
            continue;
        }
        for (const auto& run : plottableRuns(s, c.x.log, c.y.log)) {
            if (run.size() == 1) {
                out += "<circle cx=\"" + num(px(run[0])) + "\" cy=\"" + num(py(run[0])) + "\" r=\"2.5\" fill=\"" +
                       stroke + "\" stroke=\"none\"/>\n";
                continue;
            }
            out += "<polyline class=\"series\" stroke=\"" + stroke + "\" points=\"";
            for (const ChartPoint& p : run) out += num(px(p)) + "," + num(py(p)) + " ";
            out.back() = '"';
            out += "><title>" + xmlEscape(s.name) + "</title></polyline>\n";
        }
    }
    return out + "</g>\n";
}

/// The point labels, placed inside the plot by label_placement.h with this writer's conservative
/// width estimate; a leader line to a displaced label's point. The text's baseline sits 0.95 em
/// below its box's top, the box 1.25 em tall (DejaVu Sans: ascent 0.93 em, descent 0.24 em).
std::string labelsSvg(const Chart& c, const ChartFrame& f) {
    constexpr double kSize = 11;
    std::string out;
    for (const ChartLabel& l : chartLabels(c, f, estimatedTextWidth, kSize, kLabelLineHeight * kSize)) {
        if (!l.place.shown) continue;
        if (l.place.displaced) {
            const ChartPoint end = l.place.leaderEnd(l.at.x, l.at.y);
            out += line(l.at.x, l.at.y, end.x, end.y, "#999999", 0.8);
        }
        out += text(l.place.box.left, l.place.box.top + kLabelBaseline * kSize, l.text, kSize, "start",
                    " class=\"point-label\"");
    }
    return out;
}

std::string legendSvg(const Chart& c, const ChartFrame& f) {
    std::string out;
    double y = f.legendTop;
    for (const ChartSeries& s : c.series) {
        if (s.style == SeriesStyle::Markers)
            out += "<circle cx=\"" + num(f.legendLeft + 11) + "\" cy=\"" + num(y) + "\" r=\"" + num(s.markerRadius) +
                   "\" fill=\"" + colour(s.colour) + "\"/>\n";
        else out += line(f.legendLeft, y, f.legendLeft + 22, y, colour(s.colour).c_str(), 3);
        out += text(f.legendLeft + 28, y + 4, s.name, 12, "start");
        y += kLegendRowHeight;
    }
    return out;
}

/// The whole chart inside `panel` (pixels of the enclosing SVG); `id` keeps clip ids unique.
std::string panelSvg(const Chart& c, const Box& panel, const std::string& id) {
    const ChartFrame f = chartFrame(c, panel.left, panel.top, panel.right, panel.bottom);
    const std::string clipId = "plot-" + id;
    std::string out = "<g>\n<clipPath id=\"" + clipId + "\"><rect x=\"" + num(f.left) + "\" y=\"" + num(f.top) +
                      "\" width=\"" + num(f.right - f.left) + "\" height=\"" + num(f.bottom - f.top) +
                      "\"/></clipPath>\n";
    out += text(f.titleX, f.titleY, c.title, 14, "middle", " font-weight=\"bold\"");
    out += axesSvg(f);
    out += seriesSvg(c, f, clipId);
    out += labelsSvg(c, f);
    out += text((f.left + f.right) / 2, f.xLabelY, c.x.label + (c.x.log ? " (log)" : ""), 12, "middle");
    const double yy = (f.top + f.bottom) / 2;
    out += text(f.yLabelX, yy, c.y.label + (c.y.log ? " (log)" : ""), 12, "middle",
                (" transform=\"rotate(-90 " + num(f.yLabelX) + " " + num(yy) + ")\"").c_str());
    out += legendSvg(c, f);
    return out + "</g>\n";
}

std::string svgOpen(int width, int height) {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) + "\" height=\"" +
           std::to_string(height) + "\" viewBox=\"0 0 " + std::to_string(width) + " " + std::to_string(height) +
           "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

} // namespace

std::string chartToSvg(const Chart& chart, int width, int height) {
    width = std::max(width, 200);
    height = std::max(height, 150);
    return svgOpen(width, height) + panelSvg(chart, {0, 0, double(width), double(height)}, "0") + "</svg>\n";
}

std::string chartsToSvg(const std::string& title, const std::vector<Chart>& panels, int columns, int panelWidth,
                        int panelHeight) {
    columns = std::clamp(columns, 1, std::max(1, static_cast<int>(panels.size())));
    panelWidth = std::max(panelWidth, 200);
    panelHeight = std::max(panelHeight, 150);
    const int rows = (static_cast<int>(panels.size()) + columns - 1) / columns;
    const double header = title.empty() ? 0 : 36;
    const int width = columns * panelWidth, height = static_cast<int>(header) + std::max(rows, 1) * panelHeight;
    std::string out = svgOpen(width, height);
    if (!title.empty()) out += text(width / 2.0, 24, title, 16, "middle", " font-weight=\"bold\"");
    for (size_t i = 0; i < panels.size(); ++i) {
        const double left = static_cast<double>(static_cast<int>(i) % columns * panelWidth);
        const double top = header + static_cast<double>(static_cast<int>(i) / columns * panelHeight);
        out += panelSvg(panels[i], {left, top, left + panelWidth, top + panelHeight}, std::to_string(i));
    }
    return out + "</svg>\n";
}

void writeSvgText(const std::filesystem::path& path, const std::string& svg) {
    std::ofstream out(path, std::ios::binary);
    out << svg;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

void writeSvg(const std::filesystem::path& path, const Chart& chart, int width, int height) {
    writeSvgText(path, chartToSvg(chart, width, height));
}

} // namespace ui::charts
