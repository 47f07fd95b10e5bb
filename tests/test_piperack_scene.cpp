// The "piperack" built-in scene: deterministic, on its triangle budget, mostly curved surfaces,
// well formed, and in view of its own camera.
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/chunking.h"
#include "scene_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace geometry::scene;
using testutil::sameGeometry;
using testutil::toWorld;

namespace {

/// Built once: the default scene is used by several tests.
const Scene& defaultScene() {
    static const Scene scene = makePiperackScene();
    return scene;
}

bool isCurvedPart(const Mesh& m) {
    return m.name == "pipes" || m.name == "elbows" || m.name == "flanges" || m.name == "valves";
}

const Mesh& meshNamed(const Scene& s, const std::string& name) {
    const auto it = std::find_if(s.meshes.begin(), s.meshes.end(), [&](const Mesh& m) { return m.name == name; });
    if (it == s.meshes.end()) throw std::runtime_error("no mesh " + name);
    return *it;
}

/// Bounds of the rack itself: everything but the ground.
Aabb rackBounds(const Scene& s) {
    Aabb b;
    for (const Mesh& m : s.meshes)
        if (m.name != "ground") b.add(m.worldBounds());
    return b;
}

TEST(PiperackScene, SameSeedGivesIdenticalScene) {
    const Scene a = makePiperackScene({100'000, 7});
    const Scene b = makePiperackScene({100'000, 7});
    EXPECT_TRUE(sameGeometry(a, b));
}

TEST(PiperackScene, DifferentSeedGivesDifferentScene) {
    const Scene a = makePiperackScene({100'000, 7});
    const Scene b = makePiperackScene({100'000, 8});
    EXPECT_FALSE(sameGeometry(a, b));
}

TEST(PiperackScene, NameAndBuiltinLookup) {
    EXPECT_EQ(defaultScene().name, "piperack");
    const auto& names = builtinSceneNames();
    EXPECT_NE(std::find(names.begin(), names.end(), "piperack"), names.end());
    EXPECT_EQ(makeBuiltinScene("piperack").triangleCount(), defaultScene().triangleCount());
}

TEST(PiperackScene, OneMeshPerPartClassSolidsOneSided) {
    std::vector<std::string> names;
    for (const Mesh& m : defaultScene().meshes) {
        names.push_back(m.name);
        EXPECT_EQ(m.twoSided, m.name == "ground") << m.name; // only the ground is an open surface
    }
    EXPECT_EQ(names, (std::vector<std::string>{"ground", "steel", "pipes", "elbows", "flanges", "valves"}));
}

class PiperackTriangleBudget : public ::testing::TestWithParam<uint32_t> {};

TEST_P(PiperackTriangleBudget, OnTargetAndMostlyCurved) {
    const uint32_t target = GetParam();
    const Scene scene = makePiperackScene({target, 1});
    const size_t count = scene.triangleCount();
    // Below 50k the steel and the fittings' coarsest tessellation may exceed the target.
    if (target >= 50'000) {
        EXPECT_NEAR(static_cast<double>(count), target, 0.1 * target) << "target " << target;
    }
    size_t curved = 0;
    for (const Mesh& m : scene.meshes)
        if (isCurvedPart(m)) curved += m.triangleCount();
    EXPECT_GE(static_cast<double>(curved), 0.8 * static_cast<double>(count)) << "target " << target;
}

INSTANTIATE_TEST_SUITE_P(Targets, PiperackTriangleBudget, ::testing::Values(20'000u, 100'000u, 1'000'000u));

TEST(PiperackScene, CurvedSurfacesShareVertices) {
    // Smooth indexed surfaces, as a decimator needs them: a ring of vertices serves two steps.
    for (const char* name : {"pipes", "elbows"}) {
        const Mesh& m = meshNamed(defaultScene(), name);
        EXPECT_LT(static_cast<double>(m.positions.size()), 0.7 * static_cast<double>(m.triangleCount())) << name;
    }
}

TEST(PiperackScene, RackIsSizedLikeAPlantRack) {
    const Scene& scene = defaultScene();
    const Aabb steel = meshNamed(scene, "steel").worldBounds();
    EXPECT_NEAR(steel.extent().x, 144.f, 1.f); // 20 bays (120 m) at the default size, outriggers 12 m past each end
    EXPECT_GE(steel.extent().z, 6.f);
    EXPECT_LE(steel.extent().z, 8.f);
    EXPECT_NEAR(steel.hi.y, 9.f, 1e-3f);
    const Aabb rack = rackBounds(scene);
    EXPECT_GE(rack.lo.y, -1e-3f);
    EXPECT_LT(rack.hi.y, 12.f);
    EXPECT_LT(rack.extent().z, 20.f);
    EXPECT_LT(rack.extent().x, 170.f);
    const Aabb ground = meshNamed(scene, "ground").worldBounds();
    EXPECT_GE(ground.extent().x, 1000.f);
    EXPECT_GE(ground.extent().z, 1000.f);
    EXPECT_FLOAT_EQ(ground.hi.y, 0.f);
}

TEST(PiperackScene, BoundsContainEveryVertex) {
    const Scene& scene = defaultScene();
    const Aabb bounds = scene.bounds();
    ASSERT_FALSE(bounds.empty());
    for (const Mesh& m : scene.meshes)
        for (const glm::vec3& p : m.positions) ASSERT_TRUE(bounds.contains(toWorld(m, p), 1e-3f)) << m.name;
}

TEST(PiperackScene, ChunksCoverEveryTriangleOnceWithinBounds) {
    testutil::expectChunksCoverEveryTriangleOnce(defaultScene());
}

TEST(PiperackScene, IndicesInRange) { testutil::expectIndicesInRange(defaultScene()); }

TEST(PiperackScene, PositionsFiniteAndNormalsUnit) { testutil::expectFinitePositionsAndUnitNormals(defaultScene()); }

TEST(PiperackScene, TrianglesWoundLikeTheirNormals) {
    // One-sided solids cast from their front faces: a triangle wound against its normals would
    // drop out of the shadow pass.
    for (const Mesh& m : defaultScene().meshes) {
        size_t against = 0;
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                            c = m.positions[m.indices[3 * t + 2]];
            const glm::vec3 n =
                m.normals[m.indices[3 * t]] + m.normals[m.indices[3 * t + 1]] + m.normals[m.indices[3 * t + 2]];
            if (glm::dot(glm::cross(b - a, c - a), n) <= 0.f) ++against;
        }
        EXPECT_EQ(against, 0u) << m.name;
    }
}

TEST(PiperackScene, CameraLooksAlongTheRackWithHugeDepthRange) {
    const Scene& scene = defaultScene();
    const Camera& c = scene.camera;
    EXPECT_FLOAT_EQ(c.near, 0.5f);
    EXPECT_GE(c.far, 1000.f);
    EXPECT_GT(c.eye.y, 1.f); // eye height, on the ground
    EXPECT_LT(c.eye.y, 2.5f);
    // The rack's centre lies ahead, inside the view frustum, and the far plane reaches the ground's corners.
    const Aabb rack = rackBounds(scene);
    const glm::vec4 q = c.projection(16.f / 9.f) * c.view() * glm::vec4(rack.center(), 1.f);
    ASSERT_GT(q.w, 0.f);
    EXPECT_LT(std::abs(q.x), q.w);
    EXPECT_LT(std::abs(q.y), q.w);
    EXPECT_LT(std::abs(q.z), q.w);
    EXPECT_GT(std::abs(c.viewDir().x), 0.9f); // along the rack
    for (const glm::vec3& corner : meshNamed(scene, "ground").worldBounds().corners())
        EXPECT_LT(glm::length(corner - c.eye), c.far);
}

TEST(PiperackScene, LightIsASunFromTheSide) {
    const glm::vec3 l = defaultScene().lights[0].l();
    const float elevationDeg = glm::degrees(std::asin(-l.y));
    EXPECT_GE(elevationDeg, 35.f);
    EXPECT_LE(elevationDeg, 55.f);
    EXPECT_GT(std::abs(l.z), std::abs(l.x)); // across the rack rather than along it
}

} // namespace
