#include "renderer/inspection.h"

#include <algorithm>
#include <utility>

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

geometry::analysis::Inspection inspect(Renderer& r, const geometry::shadow::ShadowPlan& plan,
                                       const geometry::analysis::GroundTruth* truth, int truthSamples) {
    geometry::analysis::FrameReadback frame = readBack(r, plan);
    if (truth && truthSamples > 1) {
        frame.samplesPerAxis = truthSamples;
        frame.sampleShadow = r.readShadowSamples(plan, truthSamples);
    }
    return geometry::analysis::makeInspection(std::move(frame), plan, truth, truthSamples);
}

} // namespace renderer
