#include "renderer/shadow_map_key.h"

namespace renderer {

ShadowMapKey shadowMapKey(const geometry::shadow::ShadowPlan& plan) {
    ShadowMapKey k;
    shadowMapKey(plan, k);
    return k;
}

void shadowMapKey(const geometry::shadow::ShadowPlan& plan, ShadowMapKey& k) {
    k.splits.clear();
    for (const auto& s : plan.splits)
        k.splits.push_back(
            {s.lightViewProj, s.resolution, s.empty(), {s.linearDepthRange.x, s.linearDepthScale}, s.dualDepthCap});
    k.l = plan.l;
    k.polygonOffset = plan.polygonOffset;
    k.linearZ = plan.linearDepth;
    k.lodEye = plan.casterLodTexels > 0.f ? plan.eye : glm::vec3(0.f);
    k.mapSettings.clear();
    const auto& rows = geometry::shadow::settingsDeclaration();
    for (size_t i = 0; i < rows.size(); ++i)
        if (rows[i].drawsMaps(plan.settings)) k.mapSettings.emplace_back(int(i), rows[i].get(plan.settings));
}

} // namespace renderer
