#pragma once
// The chart `tune` writes and the dashboard's Recommend shows: every evaluated configuration's
// modelled cost (cost_model.h, what tune ranks by) against how far it is from the target (the worst figure / target
// ratio; ≤ 1 meets), the screened and full-size evaluations apart, the Pareto front of the full-size ones and the
// choice.
#include "ui/charts/chart.h"

#include <string>
#include <vector>

namespace ui::charts {

struct TunePoint {
    std::string label;
    double costMs = 0; // x: the modelled cost
    double ratio = 0;  // y: worst figure / target (geometry::analysis::targetRatio)
    bool full = false; // measured at full size (else screened)
    bool chosen = false;
};

[[nodiscard]] Chart tuneChart(const std::vector<TunePoint>& points, const std::string& target);

} // namespace ui::charts
