#include "geometry/analysis/tune_space.h"

#include "geometry/analysis/tune_target.h"

#include <algorithm>
#include <stdexcept>

namespace geometry::analysis {

using shadow::BiasType;
using shadow::FilterType;
using shadow::ShadowSettings;
using shadow::SplitScheme;
using shadow::WarpMethod;

std::vector<TuneAxis> defaultTuneSpace() {
    // The strongest levers first: coordinate descent takes the axes in this order.
    return {
        {"technique", {"maps", "virtual"}},
        {"virtual.pool_pages", {"1024", "4096"}}, // 64 or 256 MiB: whether the finest levels fit
        {"bias.type", {"constant", "slope", "slope_normal_offset"}},
        {"filter.type", {"hw2x2", "pcf", "pcss", "evsm4", "msm"}},
        {"shadow_map.resolution", {"1024", "2048", "4096"}},
        {"warp.method", {"uniform", "lispsm", "glispsm"}},
        {"splits.count", {"1", "2", "3", "4"}},
        {"splits.scheme", {"practical", "adaptive"}},
        {"splits.alpha", {"2", "4"}},
        {"bias.constant", {"0.02", "0.05", "0.1"}},
        {"bias.slope", {"1", "2", "4"}},
        {"bias.normal_offset", {"0.5", "1", "2"}},
        {"filter.kernel", {"3", "5"}},
        {"bias.tangent_plane", {"false", "true"}},
    };
}

void overrideTuneAxis(std::vector<TuneAxis>& space, std::string_view spec) {
    const size_t eq = spec.find('=');
    if (eq == std::string_view::npos || eq == 0 || eq + 1 == spec.size())
        throw std::invalid_argument("--space " + std::string(spec) + ": expected KEY=v1,v2,...");
    TuneAxis axis{std::string(spec.substr(0, eq)), {}};
    ShadowSettings probe;
    for (std::string_view v : splitCommas(spec.substr(eq + 1))) {
        try {
            shadow::applySetting(probe, axis.key, v);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("--space " + std::string(spec) + ": " + e.what());
        }
        if (std::find(axis.values.begin(), axis.values.end(), v) == axis.values.end()) axis.values.emplace_back(v);
    }
    const auto it = std::find_if(space.begin(), space.end(), [&](const TuneAxis& a) { return a.key == axis.key; });
    if (it != space.end()) *it = std::move(axis);
    else space.push_back(std::move(axis));
}

double tuneSpaceSize(const std::vector<TuneAxis>& space) noexcept {
    double n = space.empty() ? 0.0 : 1.0;
    for (const TuneAxis& a : space) n *= double(std::max<size_t>(a.values.size(), 1));
    return n;
}

} // namespace geometry::analysis
