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

using Frame = testutil::TracedFrame;

/// The platform's default view at w × h as the eye pass would read it back: positions, normals and
/// splits from the truth's primary rays, s from its verdict with every 97th pixel flipped (so
/// some pixels disagree), and m varying from pixel to pixel.
Frame platformFrame(int w, int h) {
    const Scene& scene = platformScene();
    const ShadowPlan plan =
        planShadows(ShadowSettings{}, scene.bounds(), scene.camera, scene.lights[0], Viewport{w, h});
    const PrimaryHits hits = platformTruth().primaryHits(scene.camera, w, h);
    const auto occ = platformTruth().occluded(hits.points, hits.normals, plan.l);
    return testutil::tracedFrame(scene.camera, platformTruth(), plan, w, h, [&](size_t i, const glm::vec3&) {
        return glm::vec2((occ[i] != 0) != (i % 97 == 0) ? 0.f : 1.f, 0.25f + 0.5f * float(i % 7));
    });
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
