#pragma once
// The platform scene and its ray-tracing BVH, built once per test binary (inline statics: one copy
// for every file of the binary that includes this).
#include "geometry/analysis/ground_truth.h"
#include "geometry/scene/builtin_scenes.h"

namespace testutil {

inline const geometry::scene::Scene& platformScene() {
    static const geometry::scene::Scene scene = geometry::scene::makePlatformScene();
    return scene;
}

inline const geometry::analysis::GroundTruth& platformTruth() {
    static const geometry::analysis::GroundTruth truth(platformScene());
    return truth;
}

} // namespace testutil
