#include "ui/charts/tradeoff_chart.h"

namespace ui::charts {

const std::vector<std::string>& tradeoffXNames() {
    static const std::vector<std::string> names{"gpu_ms", "cpu_ms", "memory_mib"};
    return names;
}

const std::vector<std::string>& tradeoffYNames() {
    static const std::vector<std::string> names{"p95", "interior", "edge", "misclassified", "flicker", "soft", "umbra"};
    return names;
}

std::optional<TradeoffX> parseTradeoffX(std::string_view name) noexcept {
    for (size_t i = 0; i < tradeoffXNames().size(); ++i)
        if (tradeoffXNames()[i] == name) return TradeoffX(i);
    return std::nullopt;
}

std::optional<TradeoffY> parseTradeoffY(std::string_view name) noexcept {
    for (size_t i = 0; i < tradeoffYNames().size(); ++i)
        if (tradeoffYNames()[i] == name) return TradeoffY(i);
    return std::nullopt;
}

std::string tradeoffXLabel(TradeoffX x) {
    switch (x) {
    case TradeoffX::GpuMs: return "frame time, GPU median (ms)";
    case TradeoffX::CpuMs: return "frame time, CPU median (ms)";
    case TradeoffX::MemoryMiB: return "shadow-map memory (MiB)";
    }
    return "";
}

std::string tradeoffYLabel(TradeoffY y) {
    switch (y) {
    case TradeoffY::P95: return "aliasing p95 m (pixels per texel)";
    case TradeoffY::Interior: return "interior false shadow + false lit (fraction)";
    case TradeoffY::Edge: return "edge error (fraction)";
    case TradeoffY::Misclassified: return "misclassified (fraction)";
    case TradeoffY::Flicker: return "world-space flicker, mean over the path (fraction)";
    case TradeoffY::Soft: return "mean |s - v| against the sun's disk (soft_mean_abs)";
    case TradeoffY::Umbra: return "light in the umbra, mean s (umbra_light)";
    }
    return "";
}

Chart tradeoffChart(const std::vector<TradeoffPoint>& points, TradeoffX xAxis, TradeoffY yAxis) {
    Chart c;
    c.title = std::string(xAxis == TradeoffX::MemoryMiB ? "Memory" : "Speed") +
              " against accuracy (one point per configuration)";
    c.x.label = tradeoffXLabel(xAxis);
    c.y.label = tradeoffYLabel(yAxis);
    c.y.log = yAxis == TradeoffY::P95; // the fractions can be 0
    if (!c.y.log) c.y.min = 0.0;
    const auto highlighted = [](const TradeoffPoint& p) { return p.preset == "ssm" || p.preset == "paper"; };
    ChartSeries all{"configurations", Rgb{120, 120, 130}, {}, SeriesStyle::Markers, 4.f, {}};
    ChartSeries key{"ssm.json / paper.json", Rgb{214, 39, 40}, {}, SeriesStyle::Markers, 6.f, {}};
    std::vector<ChartPoint> xy;
    for (const TradeoffPoint& p : points) {
        xy.push_back({p.x, p.y});
        ChartSeries& s = highlighted(p) ? key : all;
        s.points.push_back(xy.back());
        s.labels.push_back(highlighted(p) || points.size() <= 12 ? p.label : "");
    }
    ChartSeries front{"Pareto front", Rgb{31, 119, 180}, {}, SeriesStyle::Lines, 3.f, {}};
    ChartSeries optimal{"Pareto-optimal", Rgb{31, 119, 180}, {}, SeriesStyle::Markers, 3.f, {}};
    for (size_t i : paretoFront(xy)) {
        front.points.push_back(xy[i]);
        optimal.points.push_back(xy[i]);
        // Labelled when no other series already names the point.
        optimal.labels.push_back(highlighted(points[i]) || points.size() <= 12 ? "" : points[i].label);
    }
    c.series = {all, key, front, optimal};
    return c;
}

} // namespace ui::charts
