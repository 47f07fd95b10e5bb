// Axis ranges, ticks and labels for ui::Chart: pure functions shared by every chart renderer.
#include "ui/charts/chart.h"
#include "ui/charts/label_placement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ui::charts {

namespace {

// Relative slack when deciding whether a computed tick lies on a range end (ticks are computed
// by division and pow, so an end value like 90 or 100 may come back a few ULPs off).
constexpr double kSlack = 1e-9;

/// m × 10^e, computed so that negative exponents divide by an exact power of ten: 3 × 10^-1
/// becomes 3 / 10 = 0.3 rather than 3 × 0.1 = 0.30000000000000004.
double scaled(double m, int e) { return e >= 0 ? m * std::pow(10.0, e) : m / std::pow(10.0, -e); }

/// A nice linear step (1, 2 or 5 × 10^e) for [lo, hi], as (mantissa, exponent): the smallest step
/// giving at most maxTicks ticks. `widened` counts the ticks of the range widened outwards to the
/// step (what niceRange() produces), so a nice range never holds more than maxTicks ticks;
/// otherwise only the ticks inside [lo, hi] count (a fixed 0..90 axis may then use step 20).
struct Step {
    double mantissa = 1;
    int exponent = 0;
    [[nodiscard]] double value() const { return scaled(mantissa, exponent); }
};

Step linearStep(double lo, double hi, int maxTicks, bool widened) {
    const double span = hi - lo;
    int e = static_cast<int>(std::floor(std::log10(span / maxTicks)));
    for (;; ++e) {
        for (const double m : {1.0, 2.0, 5.0}) {
            const double step = scaled(m, e);
            const double count = widened ? std::ceil(hi / step - kSlack) - std::floor(lo / step + kSlack) + 1
                                         : std::floor(hi / step + kSlack) - std::ceil(lo / step - kSlack) + 1;
            if (count <= maxTicks) return {m, e};
        }
    }
}

/// i × step without accumulating rounding error; −0 becomes 0.
double tickAt(long long i, const Step& s) {
    const double v = scaled(static_cast<double>(i) * s.mantissa, s.exponent);
    return v == 0.0 ? 0.0 : v;
}

bool validRange(double lo, double hi, bool log) {
    return std::isfinite(lo) && std::isfinite(hi) && lo <= hi && (!log || lo > 0.0);
}

std::vector<double> linearTicks(double lo, double hi, int maxTicks) {
    if (hi == lo) return {lo};
    const Step s = linearStep(lo, hi, maxTicks, false);
    const double step = s.value();
    std::vector<double> ticks;
    const auto first = static_cast<long long>(std::ceil(lo / step - kSlack));
    const auto last = static_cast<long long>(std::floor(hi / step + kSlack));
    for (long long i = first; i <= last; ++i) ticks.push_back(tickAt(i, s));
    return ticks;
}

bool insideLog(double v, double lo, double hi) { return v >= lo * (1 - kSlack) && v <= hi * (1 + kSlack); }

std::vector<double> logTicks(double lo, double hi, int maxTicks) {
    const int d0 = static_cast<int>(std::ceil(std::log10(lo) - kSlack));
    const int d1 = static_cast<int>(std::floor(std::log10(hi) + kSlack));
    const int decades = d1 - d0 + 1;
    std::vector<double> ticks;
    if (decades >= 3) {
        // Every stride-th decade, aligned to multiples of the stride so labels read 1, 100, 10^4 …
        const int stride = (decades + maxTicks - 1) / maxTicks;
        const int start = static_cast<int>(std::ceil(static_cast<double>(d0) / stride)) * stride;
        for (int d = start; d <= d1; d += stride) ticks.push_back(scaled(1.0, d));
        return ticks;
    }
    // Fewer than three decades: 1-2-5 ticks give enough labels.
    const int e0 = static_cast<int>(std::floor(std::log10(lo))), e1 = static_cast<int>(std::ceil(std::log10(hi)));
    for (int e = e0; e <= e1; ++e)
        for (const double m : {1.0, 2.0, 5.0})
            if (const double v = scaled(m, e); insideLog(v, lo, hi)) ticks.push_back(v);
    if (ticks.size() > static_cast<size_t>(maxTicks)) {
        std::erase_if(ticks, [](double v) {
            const double l = std::log10(v);
            return std::abs(l - std::round(l)) > 1e-9;
        });
    }
    // Inside one decade (e.g. 2..5) the 1-2-5 ticks are too sparse: plain linear ticks read better.
    if (ticks.size() < 2) return linearTicks(lo, hi, maxTicks);
    return ticks;
}

} // namespace

Rgb paletteColour(int i) noexcept {
    // Tableau 10: distinguishable, and readable on white.
    static constexpr std::array<Rgb, 10> kPalette{{{0x4e, 0x79, 0xa7},
                                                   {0xf2, 0x8e, 0x2b},
                                                   {0xe1, 0x57, 0x59},
                                                   {0x76, 0xb7, 0xb2},
                                                   {0x59, 0xa1, 0x4f},
                                                   {0xed, 0xc9, 0x48},
                                                   {0xb0, 0x7a, 0xa1},
                                                   {0xff, 0x9d, 0xa7},
                                                   {0x9c, 0x75, 0x5f},
                                                   {0xba, 0xb0, 0xac}}};
    const int n = static_cast<int>(kPalette.size());
    return kPalette[static_cast<size_t>(((i % n) + n) % n)];
}

bool plottable(double v, bool log) noexcept { return std::isfinite(v) && (!log || v > 0.0); }

std::vector<double> niceTicks(double lo, double hi, bool log, int maxTicks) {
    if (!validRange(lo, hi, log)) return {};
    maxTicks = std::max(2, maxTicks);
    return log ? logTicks(lo, hi, maxTicks) : linearTicks(lo, hi, maxTicks);
}

AxisRange niceRange(double lo, double hi, bool log, int maxTicks) {
    if (!validRange(lo, hi, log)) return log ? AxisRange{1, 10} : AxisRange{0, 1};
    maxTicks = std::max(2, maxTicks);
    if (log) {
        if (hi == lo) return {lo / 10.0, hi * 10.0};
        // Inside one decade, widening to whole decades would squeeze the data into a sliver.
        if (hi / lo < 10.0) {
            if (const AxisRange r = niceRange(lo, hi, false, maxTicks); r.lo > 0.0) return r;
        }
        return {scaled(1.0, static_cast<int>(std::floor(std::log10(lo) + kSlack))),
                scaled(1.0, static_cast<int>(std::ceil(std::log10(hi) - kSlack)))};
    }
    if (hi == lo) {
        const double pad = lo == 0.0 ? 1.0 : std::abs(lo) * 0.1;
        lo -= pad;
        hi += pad;
    }
    const Step s = linearStep(lo, hi, maxTicks, true);
    const double step = s.value();
    return {tickAt(static_cast<long long>(std::floor(lo / step + kSlack)), s),
            tickAt(static_cast<long long>(std::ceil(hi / step - kSlack)), s)};
}

AxisRange axisRange(const Chart& chart, bool xAxis, int maxTicks) {
    const ChartAxis& axis = xAxis ? chart.x : chart.y;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    // Only points that are drawn count: one that is off the other axis (e.g. y = ∞) is skipped.
    for (const ChartSeries& s : chart.series)
        for (const ChartPoint& p : s.points)
            if (plottable(p.x, chart.x.log) && plottable(p.y, chart.y.log)) {
                const double v = xAxis ? p.x : p.y;
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
    if (axis.min && plottable(*axis.min, axis.log)) lo = std::isfinite(lo) ? lo : *axis.min;
    if (axis.max && plottable(*axis.max, axis.log)) hi = std::isfinite(hi) ? hi : *axis.max;
    AxisRange r = niceRange(lo, hi, axis.log, maxTicks);
    if (axis.min && plottable(*axis.min, axis.log)) r.lo = *axis.min;
    if (axis.max && plottable(*axis.max, axis.log)) r.hi = *axis.max;
    if (!(r.hi > r.lo)) r = niceRange(r.lo, r.lo, axis.log, maxTicks); // fixed bounds crossed the data
    return r;
}

double axisFraction(double v, const AxisRange& r, bool log) noexcept {
    const double a = log ? std::log10(r.lo) : r.lo, b = log ? std::log10(r.hi) : r.hi;
    const double x = log ? std::log10(v) : v;
    return b > a ? (x - a) / (b - a) : 0.5;
}

std::string formatTick(double v) {
    if (v == 0.0) return "0";
    char buf[32];
    const double a = std::abs(v);
    if (a >= 1e5 || a < 1e-3) {
        std::snprintf(buf, sizeof buf, "%.3g", v); // e.g. "1e+06"
        std::string s(buf);
        // "1e+06" → "1e6", "2.5e-05" → "2.5e-5": shorter labels on a crowded log axis.
        if (const auto e = s.find('e'); e != std::string::npos) {
            std::string exp = s.substr(e + 1);
            const bool negative = !exp.empty() && exp[0] == '-';
            if (!exp.empty() && (exp[0] == '+' || exp[0] == '-')) exp.erase(0, 1);
            exp.erase(0, std::min(exp.find_first_not_of('0'), exp.size() - 1));
            s = s.substr(0, e + 1) + (negative ? "-" : "") + exp;
        }
        return s;
    }
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::vector<std::vector<ChartPoint>> plottableRuns(const ChartSeries& series, bool xLog, bool yLog) {
    std::vector<std::vector<ChartPoint>> runs;
    bool open = false;
    for (const ChartPoint& p : series.points) {
        if (!plottable(p.x, xLog) || !plottable(p.y, yLog)) {
            open = false;
            continue;
        }
        if (!open) runs.emplace_back();
        runs.back().push_back(p);
        open = true;
    }
    return runs;
}

namespace {
constexpr int kPixelsPerXTick = 45, kPixelsPerYTick = 40;
// The frame's margins at scale 1: above the plot (title, y label), below it (tick labels, x label).
constexpr double kTopMargin = 52, kTopMarginCompact = 22, kBottomMargin = 50, kBottomMarginCompact = 40;
} // namespace

double chartHeightForPlot(double plotHeight, bool compact, double scale) {
    return plotHeight + scale * (compact ? kTopMarginCompact + kBottomMarginCompact : kTopMargin + kBottomMargin);
}

ChartFrame chartFrame(const Chart& c, double left, double top, double right, double bottom, bool compact,
                      double scale) {
    const double k = scale > 0 && std::isfinite(scale) ? scale : 1.0;
    double widest = 0; // the legend's names, at the larger of the renderers' legend fonts
    for (const ChartSeries& s : c.series) widest = std::max(widest, estimatedTextWidth(s.name, 13 * k));
    const double legend = c.series.empty() ? 0 : std::clamp(widest + 40 * k, 70 * k, (right - left) / 3);
    ChartFrame f;
    f.left = left + 68 * k;
    // The title and, in ImGui (no rotated text), the y label above the plot.
    f.top = top + k * (compact ? kTopMarginCompact : kTopMargin);
    f.right = std::max(f.left + 1, right - legend - 18 * k);
    f.bottom = std::max(f.top + 1, bottom - k * (compact ? kBottomMarginCompact : kBottomMargin));
    const int xTicks = std::max(2, static_cast<int>((f.right - f.left) / (kPixelsPerXTick * k)));
    const int yTicks = std::max(2, static_cast<int>((f.bottom - f.top) / (kPixelsPerYTick * k)));
    f.x = axisRange(c, true, xTicks);
    f.y = axisRange(c, false, yTicks);
    for (const double t : niceTicks(f.x.lo, f.x.hi, c.x.log, xTicks))
        f.xTicks.push_back({t, f.px(t, c.x.log), formatTick(t)});
    for (const double t : niceTicks(f.y.lo, f.y.hi, c.y.log, yTicks))
        f.yTicks.push_back({t, f.py(t, c.y.log), formatTick(t)});
    f.legendLeft = f.right + 14 * k;
    f.legendTop = f.top + 8 * k;
    f.titleX = (left + right) / 2;
    f.titleY = top + 22 * k;
    f.xLabelY = f.bottom + k * (compact ? 32 : 38);
    f.yLabelX = left + 16 * k;
    return f;
}

std::vector<size_t> paretoFront(const std::vector<ChartPoint>& points) {
    std::vector<size_t> order;
    for (size_t i = 0; i < points.size(); ++i)
        if (std::isfinite(points[i].x) && std::isfinite(points[i].y)) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return points[a].x != points[b].x ? points[a].x < points[b].x : points[a].y < points[b].y;
    });
    std::vector<size_t> front;
    double bestY = std::numeric_limits<double>::infinity();
    for (size_t i : order)
        if (points[i].y < bestY) { // strictly better error than every faster point
            front.push_back(i);
            bestY = points[i].y;
        }
    return front;
}

} // namespace ui::charts
