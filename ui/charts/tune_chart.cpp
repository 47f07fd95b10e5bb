#include "ui/charts/tune_chart.h"

#include <algorithm>
#include <cmath>

namespace ui::charts {

Chart tuneChart(const std::vector<TunePoint>& points, const std::string& target) {
    Chart c;
    c.title = "tune: frame time against the target " + target + " (below 1 meets it)";
    c.x.label = "modelled cost (ms; screened at a quarter of the pixels where the target allows)";
    c.y.label = "worst figure / target";
    c.y.log = true;
    ChartSeries screened{"screened (half size)", Rgb{150, 150, 160}, {}, SeriesStyle::Markers, 3.f, {}};
    ChartSeries full{"full size", Rgb{31, 119, 180}, {}, SeriesStyle::Markers, 5.f, {}};
    ChartSeries chosen{"recommended", Rgb{214, 39, 40}, {}, SeriesStyle::Markers, 8.f, {}};
    std::vector<ChartPoint> fullXy;
    std::vector<size_t> fullIndex;
    double xMin = INFINITY, xMax = -INFINITY;
    for (size_t i = 0; i < points.size(); ++i) {
        const TunePoint& p = points[i];
        const ChartPoint xy{p.costMs, std::max(p.ratio, 1e-3)};
        if (plottable(xy.x, false)) {
            xMin = std::min(xMin, xy.x);
            xMax = std::max(xMax, xy.x);
        }
        if (p.chosen) {
            chosen.points.push_back(xy);
            chosen.labels.push_back(p.label);
        }
        if (p.full) {
            full.points.push_back(xy);
            full.labels.push_back(""); // long labels of close points overlap: the choice alone is named
            fullXy.push_back(xy);
            fullIndex.push_back(i);
        } else {
            screened.points.push_back(xy);
        }
    }
    ChartSeries front{"Pareto front (full size)", Rgb{31, 119, 180}, {}, SeriesStyle::Lines, 3.f, {}};
    for (size_t i : paretoFront(fullXy)) front.points.push_back(fullXy[i]);
    ChartSeries line{"target", Rgb{44, 160, 44}, {}, SeriesStyle::Lines, 3.f, {}};
    if (xMin <= xMax) line.points = {{xMin, 1.0}, {xMax, 1.0}};
    c.series = {screened, full, front, line, chosen};
    return c;
}

} // namespace ui::charts
