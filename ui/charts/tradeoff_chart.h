#pragma once
// The speed/accuracy trade-off chart: frame time against aliasing error, one point per
// configuration, the Pareto front drawn and labelled, ssm and paper presets highlighted. Shared by
// `bench` (SVG/PNG) and the dashboard's Charts panel.
#include "ui/charts/chart.h"

#include <string>
#include <vector>

namespace ui::charts {

struct TradeoffPoint {
    std::string label;  // e.g. "paper filter.kernel=5"
    std::string preset; // preset file stem, "" for none ("ssm" and "paper" are highlighted)
    double frameMs = 0; // x
    double p95 = 0;     // y: aliasing p95 m
};

[[nodiscard]] Chart tradeoffChart(const std::vector<TradeoffPoint>& points, const std::string& timeLabel);

} // namespace ui::charts
