#include "renderer/shadow_block.h"

#include <algorithm>
#include <cmath>

namespace renderer {

ShadowBlock shadowBlock(const geometry::shadow::ShadowPlan& plan, int arrayResolution) noexcept {
    ShadowBlock b;
    const int count = std::min(int(plan.splits.size()), geometry::shadow::kMaxSplits);
    for (int i = 0; i < count; ++i) {
        const auto& split = plan.splits[i];
        auto& s = b.splits[i];
        s.lightViewProj = split.lightViewProj;
        s.splitFar = split.far;
        s.mapScale =
            arrayResolution > 0 ? float(std::min(split.resolution, arrayResolution)) / float(arrayResolution) : 1.f;
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
    return b;
}

} // namespace renderer
