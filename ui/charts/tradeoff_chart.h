#pragma once
// The speed/accuracy trade-off chart: a cost (frame time or memory) against an accuracy figure, one
// point per configuration, the Pareto front of that pair drawn and labelled, ssm and paper presets
// highlighted. Shared by `bench` (SVG/PNG) and the dashboard's Charts panel.
#include "ui/charts/chart.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ui::charts {

/// The x axis: a cost. The y axis: an accuracy figure (lower is better for both).
enum class TradeoffX { GpuMs, CpuMs, MemoryMiB };
enum class TradeoffY { P95, Interior, Edge, Misclassified, Flicker, Soft, Umbra };

/// Axis names as `--x` / `--y` spell them: gpu_ms, cpu_ms, memory_mib; p95, interior, edge,
/// misclassified, flicker, soft (soft_mean_abs against the sun's disk), umbra (umbra_light).
[[nodiscard]] const std::vector<std::string>& tradeoffXNames();
[[nodiscard]] const std::vector<std::string>& tradeoffYNames();
[[nodiscard]] std::optional<TradeoffX> parseTradeoffX(std::string_view name) noexcept;
[[nodiscard]] std::optional<TradeoffY> parseTradeoffY(std::string_view name) noexcept;
[[nodiscard]] std::string tradeoffXLabel(TradeoffX x);
[[nodiscard]] std::string tradeoffYLabel(TradeoffY y);

struct TradeoffPoint {
    std::string label;  // e.g. "paper filter.kernel=5"
    std::string preset; // preset file stem, "" for none ("ssm" and "paper" are highlighted)
    double x = 0;       // the cost
    double y = 0;       // the accuracy figure
};

[[nodiscard]] Chart tradeoffChart(const std::vector<TradeoffPoint>& points, TradeoffX x, TradeoffY y);

} // namespace ui::charts
