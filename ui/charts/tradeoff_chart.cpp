#include "ui/charts/tradeoff_chart.h"

namespace ui::charts {

Chart tradeoffChart(const std::vector<TradeoffPoint>& points, const std::string& timeLabel) {
    Chart c;
    c.title = "Speed against accuracy (one point per configuration)";
    c.x.label = timeLabel;
    c.y.label = "aliasing p95 m (pixels per texel)";
    c.y.log = true;
    const auto highlighted = [](const TradeoffPoint& p) { return p.preset == "ssm" || p.preset == "paper"; };
    ChartSeries all{"configurations", Rgb{120, 120, 130}, {}, SeriesStyle::Markers, 4.f, {}};
    ChartSeries key{"ssm.json / paper.json", Rgb{214, 39, 40}, {}, SeriesStyle::Markers, 6.f, {}};
    std::vector<ChartPoint> xy;
    for (const TradeoffPoint& p : points) {
        xy.push_back({p.frameMs, p.p95});
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
