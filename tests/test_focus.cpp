#include "geometry/shadow/focus.h"
#include "geometry/shadow/shadow_plan.h"

#include <gtest/gtest.h>

#include <random>

#include "random_util.h"

using namespace geometry::scene;
using namespace geometry::shadow;
using testutil::randomUnit;
using testutil::uniform;
using testutil::uniform01;

namespace {

bool insideUnitCube(const glm::mat4& m, const glm::vec3& p) { return testutil::insideUnitCube(m, p, 1e-4f); }

} // namespace

TEST(Focus, ConvexClipKeepsTheInsideOfAFrustum) {
    Camera cam;
    cam.eye = {0, 0, 0};
    cam.target = {0, 0, -1};
    cam.near = 1.f;
    cam.far = 100.f;
    Aabb S;
    S.add({-10, -10, -50});
    S.add({10, 10, 10});
    ConvexBody body = ConvexBody::fromCorners(frustumCorners(cam, 1.f, cam.near, cam.far));
    body.clip(S);
    const auto verts = body.vertices();
    ASSERT_FALSE(verts.empty());
    float maxDepth = 0.f;
    for (const auto& v : verts) {
        EXPECT_TRUE(S.contains(v, 1e-3f));
        maxDepth = std::max(maxDepth, -v.z);
    }
    EXPECT_NEAR(maxDepth, 50.f, 1e-3); // the frustum is cut where S ends
}

TEST(Focus, EmptyWhenTheFrustumMissesTheScene) {
    Camera cam;
    cam.eye = {0, 0, 0};
    cam.target = {0, 0, -1};
    Aabb S;
    S.add({100, 100, 100});
    S.add({110, 110, 110});
    const auto body = focusBody(frustumCorners(cam, 1.5f, 0.5f, 20.f), S, glm::normalize(glm::vec3(0, -1, 0.2f)));
    EXPECT_TRUE(body.empty());
    const ShadowPlan plan = planShadows({}, S, cam, Light{}, Viewport{320, 240});
    ASSERT_EQ(plan.splits.size(), 1u);
    EXPECT_TRUE(plan.splits[0].empty());
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(plan.splits[0].lightViewProj[i][j]));
}

// Every point of V ∩ S, and every point of S between it and the light, lands in the light's
// unit cube, for random cameras and lights (docs/design.md §3.1).
TEST(Focus, RandomCamerasAndLightsKeepReceiversAndCastersInTheUnitCube) {
    std::mt19937 rng(1234);
    Aabb S;
    S.add({-40, 0, -60});
    S.add({50, 25, 30});
    int checkedPoints = 0;
    for (int trial = 0; trial < 300; ++trial) {
        Camera cam;
        cam.eye = {uniform(rng, -60, 60), uniform(rng, -5, 40), uniform(rng, -70, 40)};
        cam.target = cam.eye + randomUnit(rng);
        cam.fovYDeg = uniform(rng, 20, 90);
        cam.near = uniform(rng, 0.1f, 2.f);
        cam.far = uniform(rng, 20.f, 300.f);
        Light light;
        light.direction = randomUnit(rng);
        const float aspect = uniform(rng, 0.5f, 2.5f);
        const ShadowPlan plan = planShadows({}, S, cam, light, Viewport{int(aspect * 480), 480});
        ASSERT_EQ(plan.splits.size(), 1u);
        const SplitPlan& split = plan.splits[0];
        const auto corners = frustumCorners(cam, Viewport{int(aspect * 480), 480}.aspect(), cam.near, cam.far);
        for (int k = 0; k < 200; ++k) {
            // A random point of the frustum (trilinear in its corners), kept if inside S.
            const float u = uniform01(rng), v = uniform01(rng), w = uniform01(rng);
            glm::vec3 p(0.f);
            for (int c = 0; c < 8; ++c)
                p += corners[c] * (((c & 1) ? u : 1 - u) * ((c & 2) ? v : 1 - v) * ((c & 4) ? w : 1 - w));
            if (!S.contains(p)) continue;
            ASSERT_FALSE(split.empty()) << "trial " << trial;
            EXPECT_TRUE(insideUnitCube(split.lightViewProj, p)) << "receiver, trial " << trial;
            const glm::vec3 exit = exitTowardLight(p, plan.l, S);
            const float t = uniform01(rng);
            EXPECT_TRUE(insideUnitCube(split.lightViewProj, p + t * (exit - p))) << "caster, trial " << trial;
            EXPECT_TRUE(insideUnitCube(split.lightViewProj, exit)) << "caster at S, trial " << trial;
            ++checkedPoints;
        }
        for (const auto& b : split.body) EXPECT_TRUE(insideUnitCube(split.lightViewProj, b));
    }
    EXPECT_GT(checkedPoints, 5000);
}

TEST(Focus, ExitTowardLightLeavesTheBox) {
    Aabb S;
    S.add({0, 0, 0});
    S.add({10, 10, 10});
    const glm::vec3 e = exitTowardLight({5, 2, 5}, glm::vec3(0, -1, 0), S);
    EXPECT_NEAR(e.y, 10.f, 1e-5);
    EXPECT_NEAR(e.x, 5.f, 1e-5);
    const glm::vec3 outside = exitTowardLight({50, 2, 5}, glm::vec3(0, -1, 0), S);
    EXPECT_EQ(outside, glm::vec3(50, 2, 5));
}
