#include "renderer/inspection.h"

#include <algorithm>

namespace renderer {

geometry::analysis::FrameReadback readBack(const Renderer& r, const geometry::shadow::ShadowPlan& plan) {
    geometry::analysis::FrameReadback frame;
    frame.width = int(r.stats().eyeWidth);
    frame.shadow = r.readShadowMask();
    frame.aux = r.readAux();
    frame.positions = r.readPositions();
    frame.normals = r.readNormals();
    for (const auto& split : plan.splits)
        frame.resolutions.push_back(std::min(split.resolution, r.stats().shadowResolution));
    return frame;
}

geometry::analysis::Inspection inspect(const Renderer& r, const geometry::shadow::ShadowPlan& plan,
                                       const geometry::analysis::GroundTruth* truth, int truthSamples) {
    return geometry::analysis::makeInspection(readBack(r, plan), plan, truth, truthSamples);
}

} // namespace renderer
