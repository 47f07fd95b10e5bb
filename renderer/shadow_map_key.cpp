#include "renderer/shadow_map_key.h"

namespace renderer {

ShadowMapKey shadowMapKey(const geometry::shadow::ShadowPlan& plan) {
    using geometry::shadow::FilterType;
    ShadowMapKey k;
    k.splits.reserve(plan.splits.size());
    for (const auto& s : plan.splits)
        k.splits.push_back(
            {s.lightViewProj, s.resolution, s.empty(), {s.linearDepthRange.x, s.linearDepthScale}, s.dualDepthCap});
    k.l = plan.l;
    k.polygonOffset = plan.polygonOffset;
    k.biasType = static_cast<int>(plan.bias.type);
    k.linearZ = plan.bias.linearZ;
    k.moments = plan.filter.type == FilterType::Vsm;
    k.momentsKernel = k.moments ? plan.filter.kernel : 0;
    k.casterLodTexels = plan.casterLodTexels;
    if (plan.casterLodTexels > 0.f) k.lodEye = plan.eye;
    return k;
}

} // namespace renderer
