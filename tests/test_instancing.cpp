// Instanced meshes (docs/design.md §2 "Instances"): placements, bounds and counts; the scene
// flattened into one mesh per placement has the same bounds; and the truth traced through Embree
// instances of one shared mesh answers exactly as the flattened scene's does.
#include "geometry/analysis/ground_truth.h"
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/chunking.h"
#include "geometry/scene/instancing.h"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace geometry::scene;
using namespace geometry::analysis;

namespace {

/// The plane scene with its poles placed three times: as they are, moved, and turned and stretched.
Scene instancedPlane() {
    Scene s = makePlaneScene();
    Mesh& poles = s.meshes.back();
    const glm::mat4 turned = glm::scale(glm::rotate(glm::translate(glm::mat4(1.f), glm::vec3(-5.f, 0.f, 4.f)),
                                                    glm::radians(30.f), glm::vec3(0.f, 1.f, 0.f)),
                                        glm::vec3(1.f, 1.5f, 1.f));
    poles.instances = {glm::mat4(1.f), glm::translate(glm::mat4(1.f), glm::vec3(6.f, 0.f, 3.f)), turned};
    return s;
}

bool sameBox(const Aabb& a, const Aabb& b) { return a.lo == b.lo && a.hi == b.hi; }

/// Equal as numbers (an identity normal matrix turns −0 into +0), NaN (a miss) equal to NaN.
bool equal(const glm::vec3& a, const glm::vec3& b) {
    for (int k = 0; k < 3; ++k)
        if (!(a[k] == b[k] || (std::isnan(a[k]) && std::isnan(b[k])))) return false;
    return true;
}

} // namespace

TEST(Instancing, GridPlacesXFastest) {
    const std::vector<glm::mat4> g = gridInstances({2, 3, 2}, {1.f, 2.f, 3.f}, {10.f, 0.f, 0.f});
    ASSERT_EQ(g.size(), 12u);
    EXPECT_EQ(glm::vec3(g[0][3]), glm::vec3(10.f, 0.f, 0.f));
    EXPECT_EQ(glm::vec3(g[1][3]), glm::vec3(11.f, 0.f, 0.f));
    EXPECT_EQ(glm::vec3(g[2][3]), glm::vec3(10.f, 2.f, 0.f));
    EXPECT_EQ(glm::vec3(g[11][3]), glm::vec3(11.f, 4.f, 3.f));
    EXPECT_TRUE(gridInstances({0, 5, 5}, glm::vec3(1.f)).empty());
}

TEST(Instancing, CountsAndBoundsCoverEveryPlacement) {
    const Scene s = instancedPlane();
    const Mesh& poles = s.meshes.back();
    EXPECT_EQ(poles.placementCount(), 3u);
    EXPECT_EQ(s.triangleCount(), makePlaneScene().triangleCount());
    EXPECT_EQ(s.placedTriangleCount(), s.triangleCount() + 2 * poles.triangleCount());
    // The moved placement is the first one shifted by (6, 0, 3), exactly.
    const Aabb first = poles.placementBounds(0), moved = poles.placementBounds(1);
    EXPECT_EQ(moved.lo, first.lo + glm::vec3(6.f, 0.f, 3.f));
    EXPECT_EQ(moved.hi, first.hi + glm::vec3(6.f, 0.f, 3.f));
    // Stretched 1.5× in y: the tallest pole reaches 1.5× as high.
    EXPECT_NEAR(poles.placementBounds(2).hi.y, 1.5f * first.hi.y, 1e-4f * first.hi.y);
    Aabb all;
    for (size_t i = 0; i < 3; ++i) all.add(poles.placementBounds(i));
    all.add(s.meshes.front().placementBounds(0));
    EXPECT_TRUE(sameBox(all, s.bounds()));
}

TEST(Instancing, FlattenedSceneHasOneMeshPerPlacementAndTheSameBounds) {
    const Scene s = instancedPlane();
    const Scene flat = flattenInstances(s);
    ASSERT_EQ(flat.meshes.size(), s.meshes.size() + 2);
    EXPECT_EQ(flat.triangleCount(), s.placedTriangleCount());
    EXPECT_EQ(flat.placedTriangleCount(), s.placedTriangleCount());
    EXPECT_TRUE(sameBox(flat.bounds(), s.bounds()));
    const Mesh& poles = s.meshes.back();
    for (size_t i = 0; i < 3; ++i) {
        const Mesh& m = flat.meshes[s.meshes.size() - 1 + i];
        EXPECT_FALSE(m.instanced());
        EXPECT_EQ(m.transform, poles.placement(i));
        EXPECT_TRUE(sameBox(m.placementBounds(0), poles.placementBounds(i))) << i;
        EXPECT_GT(m.positions.capacity(), m.positions.size()) << "spare room for Embree's last load";
    }
}

// One Embree scene of the poles placed by three instances against three meshes of their own (each
// an instance of its own arrays, as borrowing() traces a transformed mesh): the same hits, the same
// occlusion, value for value, whether the instanced truth borrows the arrays or copies them.
TEST(Instancing, TruthThroughInstancesEqualsTheFlattenedScene) {
    Scene s = instancedPlane();
    for (Mesh& m : s.meshes) reserveSpareVertex(m);
    const Scene flat = flattenInstances(s);
    for (const bool borrow : {true, false}) {
        const GroundTruth a = borrow ? GroundTruth::borrowing(s) : GroundTruth(s);
        const GroundTruth b = GroundTruth::borrowing(flat);
        EXPECT_EQ(a.triangleCount(), s.triangleCount());
        EXPECT_EQ(a.placedTriangleCount(), s.placedTriangleCount());
        EXPECT_EQ(b.triangleCount(), s.placedTriangleCount());
        constexpr int kW = 192, kH = 108;
        const PrimaryHits ha = a.primaryHits(s.camera, kW, kH, 1), hb = b.primaryHits(s.camera, kW, kH, 1);
        ASSERT_GT(ha.hitCount(), size_t(kW * kH / 3));
        ASSERT_EQ(ha.points.size(), hb.points.size());
        size_t apart = 0;
        for (size_t i = 0; i < ha.points.size(); ++i)
            apart += !equal(ha.points[i], hb.points[i]) || !equal(ha.normals[i], hb.normals[i]);
        EXPECT_EQ(apart, 0u);
        std::vector<glm::vec3> points, normals;
        for (size_t i = 0; i < ha.points.size(); ++i)
            if (!std::isnan(ha.points[i].x)) {
                points.push_back(ha.points[i]);
                normals.push_back(ha.normals[i]);
            }
        const TruthLight light(s.lights[0]);
        const std::vector<uint8_t> oa = a.occluded(points, normals, light, 1),
                                   ob = b.occluded(points, normals, light, 1);
        EXPECT_EQ(oa, ob);
        size_t shadowed = 0;
        for (uint8_t o : oa) shadowed += o;
        EXPECT_GT(shadowed, points.size() / 100) << "the poles cast shadows on the ground";
    }
}

// The plant: three module types held once, placed on a grid to reach the target; un-instanced, the
// same placements as meshes of their own (the same bounds, every triangle held).
TEST(PlantScene, HoldsAFewModulesAndPlacesTheTarget) {
    const Scene plant = makePlantScene({1'200'000, 1, true});
    EXPECT_EQ(plant.name, "plant");
    EXPECT_EQ(plant.meshes.front().name, "ground");
    size_t instanced = 0;
    for (const Mesh& m : plant.meshes) instanced += m.instanced();
    EXPECT_EQ(instanced, plant.meshes.size() - 1); // 3 types × 5 part classes, the ground once
    // Modules of 1.2M / 16 = 75k: about 16 placements of about 75k each.
    EXPECT_LE(plant.triangleCount(), 3 * 80'000u + plant.meshes.front().triangleCount());
    EXPECT_NEAR(double(plant.placedTriangleCount()), 1.2e6, 0.1 * 1.2e6);
    // The camera looks into the first module, as the piperack's does.
    EXPECT_TRUE(plant.bounds().contains(plant.camera.eye));

    const Scene flat = makePlantScene({1'200'000, 1, false});
    EXPECT_EQ(flat.triangleCount(), plant.placedTriangleCount());
    EXPECT_TRUE(sameBox(flat.bounds(), plant.bounds()));
}
