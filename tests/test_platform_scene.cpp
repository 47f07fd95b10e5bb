// The "platform" built-in scene: deterministic, on its triangle budget, well formed.
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/chunking.h"
#include "scene_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace geometry::scene;
using testutil::sameGeometry;
using testutil::toWorld;

namespace {

/// Built once: the default scene is used by several tests and costs tens of milliseconds.
const Scene& defaultScene() {
    static const Scene scene = makePlatformScene();
    return scene;
}

TEST(PlatformScene, SameSeedGivesIdenticalScene) {
    const Scene a = makePlatformScene({100'000, 7});
    const Scene b = makePlatformScene({100'000, 7});
    EXPECT_TRUE(sameGeometry(a, b));
}

TEST(PlatformScene, DifferentSeedGivesDifferentScene) {
    const Scene a = makePlatformScene({100'000, 7});
    const Scene b = makePlatformScene({100'000, 8});
    EXPECT_FALSE(sameGeometry(a, b));
}

TEST(PlatformScene, NameAndBuiltinLookup) {
    EXPECT_EQ(defaultScene().name, "platform");
    EXPECT_EQ(makeBuiltinScene("platform").triangleCount(), defaultScene().triangleCount());
}

class PlatformTriangleBudget : public ::testing::TestWithParam<uint32_t> {};

TEST_P(PlatformTriangleBudget, WithinTenPercentOfTarget) {
    const uint32_t target = GetParam();
    const Scene scene = makePlatformScene({target, 1});
    const double count = static_cast<double>(scene.triangleCount());
    EXPECT_NEAR(count, target, 0.1 * target) << "target " << target;
}

INSTANTIATE_TEST_SUITE_P(Targets, PlatformTriangleBudget, ::testing::Values(20'000u, 100'000u, 250'000u, 1'000'000u));

TEST(PlatformScene, BoundsContainEveryVertex) {
    const Scene& scene = defaultScene();
    const Aabb bounds = scene.bounds();
    ASSERT_FALSE(bounds.empty());
    for (const Mesh& m : scene.meshes)
        for (const glm::vec3& p : m.positions) ASSERT_TRUE(bounds.contains(toWorld(m, p), 1e-3f)) << m.name;
}

TEST(PlatformScene, SeaSpansAtLeastTwoKilometres) {
    const Scene& scene = defaultScene();
    const Mesh* sea = nullptr;
    for (const Mesh& m : scene.meshes)
        if (m.name == "sea") sea = &m;
    ASSERT_NE(sea, nullptr);
    const Aabb b = sea->worldBounds();
    EXPECT_GE(b.extent().x, 2000.f);
    EXPECT_GE(b.extent().z, 2000.f);
    EXPECT_FLOAT_EQ(b.lo.y, 0.f);
    EXPECT_FLOAT_EQ(b.hi.y, 0.f);
    // The structure rises well above the sea.
    EXPECT_GT(scene.bounds().hi.y, 50.f);
}

TEST(PlatformScene, ChunksCoverEveryTriangleOnceWithinBounds) {
    testutil::expectChunksCoverEveryTriangleOnce(defaultScene());
}

TEST(PlatformScene, IndicesInRange) { testutil::expectIndicesInRange(defaultScene()); }

TEST(PlatformScene, CameraHasHugeDepthRange) {
    const Camera& c = defaultScene().camera;
    EXPECT_FLOAT_EQ(c.near, 0.5f);
    EXPECT_GE(c.far, 1000.f);
    EXPECT_FLOAT_EQ(c.fovYDeg, 60.f);
    // Standing above the sea, looking slightly down.
    EXPECT_GT(c.eye.y, 0.f);
    EXPECT_LT(c.viewDir().y, 0.f);
    EXPECT_GT(c.viewDir().y, -0.5f);
}

TEST(PlatformScene, LightIsAnElevatedSun) {
    const glm::vec3 l = defaultScene().lights[0].l();
    const float elevationDeg = glm::degrees(std::asin(-l.y));
    EXPECT_GE(elevationDeg, 35.f);
    EXPECT_LE(elevationDeg, 55.f);
}

TEST(PlatformScene, PositionsFiniteAndNormalsUnit) { testutil::expectFinitePositionsAndUnitNormals(defaultScene()); }

} // namespace
