#include "geometry/shadow/memory_budget.h"

#include <algorithm>

namespace geometry::shadow {

double shadowBytesPerTexel(const ShadowSettings& s) noexcept {
    const int moments = momentCount(s.filter.type);
    if (moments > 0) return 4.0 + 2.0 * 4.0 * moments;
    const bool peeling = s.bias.type == BiasType::Midpoint || s.bias.type == BiasType::DualDepth;
    return peeling ? 12.0 : 4.0;
}

double shadowMapBytes(const ShadowSettings& s, int resolution) noexcept {
    return double(resolution) * double(resolution) * double(std::max(s.splits.count, 1)) * shadowBytesPerTexel(s);
}

int budgetedResolution(const ShadowSettings& s, double budget) noexcept {
    int resolution = std::max(s.resolution, 16);
    while (resolution > 16 && !(shadowMapBytes(s, resolution) <= budget)) resolution /= 2;
    return resolution;
}

} // namespace geometry::shadow
