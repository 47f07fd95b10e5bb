#include "renderer/shadow_map_key.h"

namespace renderer {

ShadowMapKey shadowMapKey(const geometry::shadow::ShadowPlan& plan) {
    ShadowMapKey k;
    k.splits.reserve(plan.splits.size());
    for (const auto& s : plan.splits)
        k.splits.push_back(
            {s.lightViewProj, s.resolution, s.empty(), {s.linearDepthRange.x, s.linearDepthScale}, s.dualDepthCap});
    k.l = plan.l;
    k.polygonOffset = plan.polygonOffset;
    k.biasType = static_cast<int>(plan.bias.type);
    k.linearZ = plan.linearDepth;
    if (geometry::shadow::isMomentFilter(plan.filter.type)) {
        k.momentFilter = static_cast<int>(plan.filter.type);
        k.momentsKernel = plan.filter.kernel;
        k.momentExponents = {plan.filter.esmExponent, plan.filter.evsmPositive, plan.filter.evsmNegative};
    }
    k.casterLodTexels = plan.casterLodTexels;
    if (plan.casterLodTexels > 0.f) k.lodEye = plan.eye;
    return k;
}

} // namespace renderer
