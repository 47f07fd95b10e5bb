// The inspection's ground truth (addTruth, makeInspection) cancelled through a std::stop_token, as
// the dashboard's worker does: no GL, a frame read-back made up from the truth's own primary rays.
#include "geometry/analysis/ground_truth.h"
#include "geometry/analysis/inspection.h"
#include "geometry/scene/builtin_scenes.h"
#include "geometry/shadow/shadow_plan.h"

#include "cancel_test_util.h"
#include "truth_test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

using namespace geometry::scene;
using namespace geometry::shadow;
using namespace geometry::analysis;

namespace {

using testutil::platformScene;
using testutil::platformTruth;

struct Frame {
    FrameReadback readback;
    ShadowPlan plan;
};

/// The platform's default view at w × h as the eye pass would read it back: positions, normals and
/// splits from the truth's primary rays, s from its verdict with every 97th pixel flipped (so
/// some pixels disagree), and m varying from pixel to pixel.
Frame platformFrame(int w, int h) {
    const Scene& scene = platformScene();
    Frame f;
    f.plan = planShadows(ShadowSettings{}, scene.bounds(), scene.camera, scene.light, Viewport{w, h});
    const PrimaryHits hits = platformTruth().primaryHits(scene.camera, w, h);
    const auto occ = platformTruth().occluded(hits.points, hits.normals, f.plan.l);
    FrameReadback& r = f.readback;
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
        r.positions.emplace_back(p, 0.25f + 0.5f * float(i % 7));
        r.normals.emplace_back(n, glm::dot(n, -f.plan.l));
        r.aux.emplace_back(0.5f, 0.5f, float(split), 0.5f);
        r.shadow.push_back((occ[i] != 0) != (i % 97 == 0) ? 0.f : 1.f);
    }
    for (const SplitPlan& s : f.plan.splits) r.resolutions.push_back(s.resolution);
    return f;
}

std::stop_token stopped() {
    std::stop_source source;
    source.request_stop();
    return source.get_token();
}

TEST(InspectionTruthCancel, AStopRequestedBeforeTheCallThrowsCancelled) {
    const Frame f = platformFrame(64, 36);
    const GroundTruth& truth = platformTruth();
    EXPECT_THROW((void)makeInspection(f.readback, f.plan, &truth, 1, stopped()), Cancelled);
    EXPECT_THROW((void)makeInspection(f.readback, f.plan, nullptr, 1, stopped()), Cancelled);
    Inspection in = makeInspection(f.readback, f.plan, nullptr);
    EXPECT_THROW(addTruth(in, f.plan, truth, 2, stopped()), Cancelled);
    EXPECT_THROW(addTruth(in, f.plan, truth, 0, stopped()), std::invalid_argument); // bad input first
    EXPECT_THROW((void)truthOcclusion(in, f.plan.eye, f.plan.l, truth, stopped()), Cancelled);
}

// makeInspection passes the token on to the truth: a stop ~20 ms into an inspection with 8 × 8
// truth samples per pixel (two cores: coverage() dominates) ends it long before it would finish.
TEST(InspectionTruthCancel, AStopFromAnotherThreadEndsMakeInspectionEarly) {
    const Frame f = platformFrame(320, 180);
    const GroundTruth& truth = platformTruth();
    bool classes = false;
    const testutil::CancelTiming t = testutil::timeCancellation([&](std::stop_token stop) {
        classes = makeInspection(f.readback, f.plan, &truth, 8, stop).truthClasses.has_value();
    });
    ASSERT_TRUE(classes);
    testutil::expectCancelledEarly(t);
}

// A token that is never stopped changes nothing: the same fields, bit for bit, and the same metrics.
TEST(InspectionTruthCancel, ANeverStoppedTokenGivesTheSameInspection) {
    const Frame f = platformFrame(160, 90);
    const GroundTruth& truth = platformTruth();
    const std::stop_source source; // can be stopped, never is
    const Inspection a = makeInspection(f.readback, f.plan, &truth, 2);
    const Inspection b = makeInspection(f.readback, f.plan, &truth, 2, source.get_token());
    ASSERT_TRUE(a.truthClasses.has_value());
    EXPECT_GT(a.truthClasses->count, 1000u);
    EXPECT_EQ(b.occluded, a.occluded);
    EXPECT_EQ(b.geometricNormals, a.geometricNormals);
    EXPECT_EQ(b.mesh, a.mesh);
    EXPECT_EQ(b.coverage, a.coverage); // no NaN left: addTruth falls back to the centre verdict
    EXPECT_EQ(b.ambiguity, a.ambiguity);
    EXPECT_EQ(b.classes, a.classes);
    nlohmann::json ja, jb;
    addInspectionMetrics(ja, a);
    addInspectionMetrics(jb, b);
    EXPECT_EQ(jb.dump(), ja.dump());
}

} // namespace
