#include "renderer/shadow_block.h"

#include "geometry/scene/invariant.h"

#include <algorithm>
#include <cmath>

namespace renderer {

ShadowBlock shadowBlock(const geometry::shadow::ShadowPlan& plan, int arrayResolution) noexcept {
    // The plan holds at most kMaxSplits (settings validation refuses more); the block has no room
    // for another, and dropping one would shade its pixels with the wrong map.
    SHADOWSCOPE_EXPECTS(plan.splits.size() <= size_t(geometry::shadow::kMaxSplits));
    SHADOWSCOPE_EXPECTS(arrayResolution > 0);
    ShadowBlock b;
    const int count = int(plan.splits.size());
    for (int i = 0; i < count; ++i) {
        const auto& split = plan.splits[i];
        auto& s = b.splits[i];
        s.lightViewProj = split.lightViewProj;
        s.splitFar = split.far;
        s.mapScale = float(std::min(split.resolution, arrayResolution)) / float(arrayResolution);
        s.linearLo = split.linearDepthRange.x;
        s.linearScale = split.linearDepthScale;
        s.dualDepthCap = split.dualDepthCap;
        s.lookupShiftX = split.lookupShift.x;
        s.lookupShiftY = split.lookupShift.y;
        s.blendStart = split.blendStart;
    }
    b.lightDir = plan.l;
    b.splitCount = count;
    b.eye = glm::vec3(glm::inverse(plan.eyeView)[3]); // where the eye matrices put the camera
    b.arrayResolution = arrayResolution;
    b.viewDir = plan.v;
    b.receiverOffset = plan.receiverOffset;
    b.normalOffset = plan.normalOffsetTexels;
    b.linearDepth = plan.linearDepth ? 1 : 0;
    b.slopeBias = plan.polygonOffset;
    b.sunTanHalfAngle = float(std::tan(glm::radians(double(plan.settings.light.angularDiameterDeg)) * 0.5));
    const geometry::scene::Light& light = plan.light;
    b.lightType = int(light.type);
    b.lightPos = light.position;
    b.lightRange = light.range;
    b.lightRadius = light.radius;
    b.spotCosOuter = b.spotCosInner = -2.f;
    if (light.type == geometry::scene::LightType::Spot) {
        // A smooth edge over the outer 5 % of the half angle (at least 0.5°), inside the cone.
        const double half = 0.5 * double(light.coneDeg), edge = std::max(0.05 * half, 0.5);
        b.spotCosOuter = float(std::cos(glm::radians(half)));
        b.spotCosInner = float(std::cos(glm::radians(std::max(half - edge, 0.0))));
    }
    return b;
}

} // namespace renderer
