#pragma once
// The platform scene and its ray-tracing BVH, built once per test binary (inline statics: one copy
// for every file of the binary that includes this).
#include "geometry/analysis/ground_truth.h"
#include "geometry/analysis/inspection.h"
#include "geometry/scene/builtin_scenes.h"
#include "geometry/shadow/shadow_plan.h"

#include <cmath>
#include <functional>

namespace testutil {

inline const geometry::scene::Scene& platformScene() {
    static const geometry::scene::Scene scene = geometry::scene::makePlatformScene();
    return scene;
}

inline const geometry::analysis::GroundTruth& platformTruth() {
    static const geometry::analysis::GroundTruth truth(platformScene());
    return truth;
}

/// A frame as the eye pass would read it back, made without GL from the truth's primary rays:
/// positions, normals and each pixel's split from the hits of `plan`'s camera; s and m of pixel i at
/// p from `shade(i, p)` as (s, m). Pixels that see nothing are sky (split −1, s 1).
struct TracedFrame {
    geometry::analysis::FrameReadback readback;
    geometry::shadow::ShadowPlan plan;
};

inline TracedFrame tracedFrame(const geometry::scene::Camera& camera, const geometry::analysis::GroundTruth& truth,
                               geometry::shadow::ShadowPlan plan, int w, int h,
                               const std::function<glm::vec2(size_t, const glm::vec3&)>& shade) {
    TracedFrame f{{}, std::move(plan)};
    const geometry::analysis::PrimaryHits hits = truth.primaryHits(camera, w, h);
    geometry::analysis::FrameReadback& r = f.readback;
    r.width = w;
    for (size_t i = 0; i < hits.points.size(); ++i) {
        const glm::vec3 p = hits.points[i], n = hits.normals[i];
        if (!std::isfinite(p.x)) {
            r.positions.emplace_back(0.f);
            r.normals.emplace_back(0.f);
            r.aux.emplace_back(0.f, 0.f, -1.f, 0.f);
            r.shadow.push_back(1.f);
            continue;
        }
        const float depth = glm::dot(p - f.plan.eye, f.plan.v);
        int split = 0;
        while (split + 1 < int(f.plan.splits.size()) && depth > f.plan.splits[size_t(split)].far) ++split;
        const glm::vec2 sm = shade(i, p);
        r.positions.emplace_back(p, sm.y);
        r.normals.emplace_back(n, glm::dot(n, -f.plan.l));
        r.aux.emplace_back(0.5f, 0.5f, float(split), 0.5f);
        r.shadow.push_back(sm.x);
    }
    for (const auto& s : f.plan.splits) r.resolutions.push_back(s.resolution);
    return f;
}

} // namespace testutil
