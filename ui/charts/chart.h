#pragma once
// A plain description of a 2-D line chart, with no ImGui or GL dependency: the SVG writer
// (chart_svg.cpp) and, later, the GUI's ImDrawList renderer draw the same Chart. Everything
// that decides *what* is drawn (axis ranges, ticks, tick labels, which points can be plotted,
// where a value lands on an axis) lives here as pure functions, so every renderer agrees.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ui::charts {

struct ChartAxis {
    std::string label;
    bool log = false;               // log10 scale; non-positive values are not plotted
    std::optional<double> min, max; // fixed bounds; otherwise from the data, widened to nice ticks
};

struct Rgb {
    std::uint8_t r = 0, g = 0, b = 0;
};

struct ChartPoint {
    double x = 0, y = 0;
};

enum class SeriesStyle { Lines, Markers };

struct ChartSeries {
    std::string name;
    Rgb colour;
    std::vector<ChartPoint> points; // Lines: in x order; non-plottable points break the line
    SeriesStyle style = SeriesStyle::Lines;
    float markerRadius = 3.f;        // Markers: dot radius in pixels
    std::vector<std::string> labels; // Markers: optional text beside each point (empty: none)
};

struct Chart {
    std::string title;
    ChartAxis x, y;
    std::vector<ChartSeries> series;
};

/// The value interval an axis shows.
struct AxisRange {
    double lo = 0, hi = 1;
};

/// The i-th colour of a fixed qualitative palette (cycles), for series colours.
[[nodiscard]] Rgb paletteColour(int i) noexcept;

/// A value can be drawn on an axis: finite, and positive on a log axis.
[[nodiscard]] bool plottable(double v, bool log) noexcept;

/// Tick values inside [lo, hi] at round positions, at most about `maxTicks` of them.
/// Linear: multiples of 1, 2 or 5 × 10^k. Log: powers of ten (every m-th decade when there are
/// too many), with 2× and 5× added when fewer than three decades are in range, and linear ticks
/// when the range lies inside one decade. Empty for an empty or non-finite range (or lo ≤ 0 on a log axis).
[[nodiscard]] std::vector<double> niceTicks(double lo, double hi, bool log, int maxTicks = 10);

/// [lo, hi] widened outwards to round values (linear: the nice tick step; log: whole decades,
/// or the linear rule when the data spans less than a decade),
/// so the axis starts and ends on a tick. A degenerate range is padded first.
[[nodiscard]] AxisRange niceRange(double lo, double hi, bool log, int maxTicks = 10);

/// The range an axis shows for a chart: the extent of the plottable data on that axis, made nice,
/// with the axis' fixed min/max taking precedence. A fallback range when there is no data.
[[nodiscard]] AxisRange axisRange(const Chart& chart, bool xAxis, int maxTicks = 10);

/// Where v lies on the axis, as a fraction: 0 at range.lo, 1 at range.hi (log axes in log10).
[[nodiscard]] double axisFraction(double v, const AxisRange& range, bool log) noexcept;

/// Short tick label: "0", "20", "0.05", "1e+06" style for very large or small magnitudes.
[[nodiscard]] std::string formatTick(double v);

/// The series' points split into runs of consecutive plottable points (each run is one line).
[[nodiscard]] std::vector<std::vector<ChartPoint>> plottableRuns(const ChartSeries& series, bool xLog, bool yLog);

/// Where a chart's parts go inside a panel, in pixels: shared by the SVG writer and the ImGui
/// renderer so both draw the same picture.
struct ChartTick {
    double value = 0, pixel = 0;
    std::string label;
};
struct ChartFrame {
    double left = 0, top = 0, right = 0, bottom = 0; // the plot area
    AxisRange x, y;
    std::vector<ChartTick> xTicks, yTicks;
    double legendLeft = 0, legendTop = 0; // first legend entry
    double titleX = 0, titleY = 0, xLabelY = 0, yLabelX = 0;
    [[nodiscard]] double px(double v, bool log) const noexcept {
        return left + axisFraction(v, x, log) * (right - left);
    }
    [[nodiscard]] double py(double v, bool log) const noexcept {
        return bottom - axisFraction(v, y, log) * (bottom - top);
    }
};
inline constexpr double kLegendRowHeight = 18;
/// The frame of `chart` drawn in the panel [left, right] × [top, bottom]. Compact frames (small
/// panels in the GUI) leave the title out and keep the margins tight. `scale`: the UI scale, which
/// multiplies the margins, the legend's width and the tick spacing (the GUI's text grows with it).
[[nodiscard]] ChartFrame chartFrame(const Chart& chart, double left, double top, double right, double bottom,
                                    bool compact = false, double scale = 1);
/// The smallest plot height the GUI draws a chart with, in pixels at UI scale 1 (issue 32: the
/// Recommend chart's plot was 70 px tall); the panel scrolls rather than squeezing the plot.
inline constexpr double kMinPlotHeight = 180;
/// The panel height whose frame leaves a plot `plotHeight` pixels tall.
[[nodiscard]] double chartHeightForPlot(double plotHeight, bool compact, double scale = 1);

/// Pareto-optimal points for minimising both x and y (non-dominated, plottable), sorted by x.
[[nodiscard]] std::vector<size_t> paretoFront(const std::vector<ChartPoint>& points);

/// SVG text of the chart, width × height pixels (chart_svg.cpp).
[[nodiscard]] std::string chartToSvg(const Chart& chart, int width, int height);
/// Several charts as small multiples in a grid of `columns`, each panel panelWidth × panelHeight,
/// under one overall title.
[[nodiscard]] std::string chartsToSvg(const std::string& title, const std::vector<Chart>& panels, int columns,
                                      int panelWidth, int panelHeight);
/// Writes chartToSvg(chart, width, height) to `path`; throws std::runtime_error when it cannot.
void writeSvg(const std::filesystem::path& path, const Chart& chart, int width = 800, int height = 500);
/// Writes SVG text to `path`; throws std::runtime_error when it cannot.
void writeSvgText(const std::filesystem::path& path, const std::string& svg);

} // namespace ui::charts
