// ui::Chart as SVG text: what the chart shows (ranges, ticks, labels) comes from chart_axes.cpp;
// this file only lays it out in pixels.
#include "chart.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace ui {

namespace {

constexpr const char* kFont = "font-family=\"sans-serif\"";
// Pixel budget per tick label, so narrow panels get fewer ticks instead of overlapping labels.
constexpr int kPixelsPerXTick = 45, kPixelsPerYTick = 40;

std::string escapeXml(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        case '\'': out += "&apos;"; break;
        default: out += c;
        }
    }
    return out;
}

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

/// A rough text width for layout (SVG has no text metrics without a renderer): ~0.6 em per glyph.
double textWidth(const std::string& text, double fontSize) {
    size_t glyphs = 0;
    for (const unsigned char c : text) glyphs += (c & 0xC0) != 0x80; // count UTF-8 lead bytes only
    return 0.6 * fontSize * static_cast<double>(glyphs);
}

struct Box {
    double left, top, right, bottom;
    [[nodiscard]] double width() const { return right - left; }
    [[nodiscard]] double height() const { return bottom - top; }
};

std::string text(double x, double y, const std::string& s, double size, const char* anchor, const char* extra = "") {
    return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" " + kFont + " font-size=\"" + num(size) +
           "\" text-anchor=\"" + anchor + "\"" + extra + ">" + escapeXml(s) + "</text>\n";
}

std::string line(double x1, double y1, double x2, double y2, const char* stroke, double width) {
    return "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" + num(y2) +
           "\" stroke=\"" + stroke + "\" stroke-width=\"" + num(width) + "\"/>\n";
}

/// Grid lines, tick marks and tick labels of both axes.
std::string axesSvg(const Chart& c, const Box& plot, const AxisRange& xr, const AxisRange& yr, int xTicks, int yTicks) {
    std::string out;
    for (const double t : niceTicks(xr.lo, xr.hi, c.x.log, xTicks)) {
        const double x = plot.left + axisFraction(t, xr, c.x.log) * plot.width();
        out += line(x, plot.top, x, plot.bottom, "#e4e4e4", 1);
        out += line(x, plot.bottom, x, plot.bottom + 5, "#333333", 1);
        out += text(x, plot.bottom + 18, formatTick(t), 11, "middle");
    }
    for (const double t : niceTicks(yr.lo, yr.hi, c.y.log, yTicks)) {
        const double y = plot.bottom - axisFraction(t, yr, c.y.log) * plot.height();
        out += line(plot.left, y, plot.right, y, "#e4e4e4", 1);
        out += line(plot.left - 5, y, plot.left, y, "#333333", 1);
        out += text(plot.left - 8, y + 4, formatTick(t), 11, "end");
    }
    out += "<rect x=\"" + num(plot.left) + "\" y=\"" + num(plot.top) + "\" width=\"" + num(plot.width()) +
           "\" height=\"" + num(plot.height()) + "\" fill=\"none\" stroke=\"#333333\" stroke-width=\"1\"/>\n";
    return out;
}

/// One <polyline> per run of plottable points (a single point becomes a dot), clipped to the plot.
std::string seriesSvg(const Chart& c, const Box& plot, const AxisRange& xr, const AxisRange& yr, const std::string& clipId) {
    std::string out = "<g clip-path=\"url(#" + clipId + ")\" fill=\"none\" stroke-width=\"2\" stroke-linejoin=\"round\">\n";
    for (const ChartSeries& s : c.series) {
        const std::string stroke = colour(s.colour);
        for (const auto& run : plottableRuns(s, c.x.log, c.y.log)) {
            const auto px = [&](const ChartPoint& p) { return plot.left + axisFraction(p.x, xr, c.x.log) * plot.width(); };
            const auto py = [&](const ChartPoint& p) { return plot.bottom - axisFraction(p.y, yr, c.y.log) * plot.height(); };
            if (run.size() == 1) {
                out += "<circle cx=\"" + num(px(run[0])) + "\" cy=\"" + num(py(run[0])) + "\" r=\"2.5\" fill=\"" +
                       stroke + "\" stroke=\"none\"/>\n";
                continue;
            }
            out += "<polyline class=\"series\" stroke=\"" + stroke + "\" points=\"";
            for (const ChartPoint& p : run) out += num(px(p)) + "," + num(py(p)) + " ";
            out.back() = '"';
            out += "><title>" + escapeXml(s.name) + "</title></polyline>\n";
        }
    }
    return out + "</g>\n";
}

std::string legendSvg(const Chart& c, double left, double top) {
    std::string out;
    double y = top;
    for (const ChartSeries& s : c.series) {
        out += line(left, y, left + 22, y, colour(s.colour).c_str(), 3);
        out += text(left + 28, y + 4, s.name, 12, "start");
        y += 18;
    }
    return out;
}

double legendWidth(const Chart& c, double panelWidth) {
    double widest = 0;
    for (const ChartSeries& s : c.series) widest = std::max(widest, textWidth(s.name, 12));
    return c.series.empty() ? 0 : std::clamp(widest + 40, 70.0, panelWidth / 3);
}

/// The whole chart inside `panel` (pixels of the enclosing SVG); `id` keeps clip ids unique.
std::string panelSvg(const Chart& c, const Box& panel, const std::string& id) {
    const double legend = legendWidth(c, panel.width());
    const Box plot{panel.left + 68, panel.top + 40, panel.right - legend - 18, panel.bottom - 50};
    const int xTicks = std::max(2, static_cast<int>(plot.width()) / kPixelsPerXTick);
    const int yTicks = std::max(2, static_cast<int>(plot.height()) / kPixelsPerYTick);
    const AxisRange xr = axisRange(c, true, xTicks), yr = axisRange(c, false, yTicks);
    const std::string clipId = "plot-" + id;

    std::string out = "<g>\n<clipPath id=\"" + clipId + "\"><rect x=\"" + num(plot.left) + "\" y=\"" + num(plot.top) +
                      "\" width=\"" + num(plot.width()) + "\" height=\"" + num(plot.height()) + "\"/></clipPath>\n";
    out += text((panel.left + panel.right) / 2, panel.top + 24, c.title, 14, "middle", " font-weight=\"bold\"");
    out += axesSvg(c, plot, xr, yr, xTicks, yTicks);
    out += seriesSvg(c, plot, xr, yr, clipId);
    out += text((plot.left + plot.right) / 2, plot.bottom + 38, c.x.label + (c.x.log ? " (log)" : ""), 12, "middle");
    const double yx = panel.left + 16, yy = (plot.top + plot.bottom) / 2;
    out += text(yx, yy, c.y.label + (c.y.log ? " (log)" : ""), 12, "middle",
                (" transform=\"rotate(-90 " + num(yx) + " " + num(yy) + ")\"").c_str());
    out += legendSvg(c, plot.right + 14, plot.top + 8);
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

} // namespace ui
