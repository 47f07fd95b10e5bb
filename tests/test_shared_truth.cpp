// Ground truth traced from the scene's own arrays (GroundTruth::borrowing: Embree shared buffers,
// instances for meshes with a transform) answers as the world-space copy does: the same hits, normals,
// meshes and occlusion on the platform with some of its meshes moved, turned and scaled.
#include "geometry/analysis/ground_truth.h"
#include "geometry/scene/builtin_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace geometry::scene;
using namespace geometry::analysis;

namespace {

/// The platform with every third mesh under a transform (turned, moved, scaled unevenly), so
/// that both the identity path and the instance path are traced.
Scene transformedPlatform() {
    Scene scene = makePlatformScene({60'000});
    const glm::mat4 t = glm::scale(glm::rotate(glm::translate(glm::mat4(1.f), glm::vec3(3.f, 0.5f, -2.f)), 0.3f,
                                               glm::normalize(glm::vec3(0.2f, 1.f, 0.1f))),
                                   glm::vec3(1.f, 1.3f, 0.9f));
    for (size_t i = 0; i < scene.meshes.size(); i += 3) scene.meshes[i].transform = t * scene.meshes[i].transform;
    for (Mesh& m : scene.meshes) m.positions.reserve(m.positions.size() + 1); // room for Embree's last load
    return scene;
}

bool same(const glm::vec3& a, const glm::vec3& b, float tol) {
    const bool nanA = std::isnan(a.x), nanB = std::isnan(b.x);
    if (nanA || nanB) return nanA == nanB;
    return glm::length(a - b) <= tol * std::max(1.f, glm::length(a));
}

TEST(SharedTruth, AnswersAsTheCopyDoes) {
    const Scene scene = transformedPlatform();
    const GroundTruth copy(scene);
    const GroundTruth shared = GroundTruth::borrowing(scene);
    ASSERT_EQ(shared.triangleCount(), copy.triangleCount());
    EXPECT_EQ(shared.sharedTriangleCount(), shared.triangleCount());
    EXPECT_EQ(copy.sharedTriangleCount(), 0u);

    constexpr int kW = 160, kH = 90;
    const PrimaryHits a = copy.primaryHits(scene.camera, kW, kH), b = shared.primaryHits(scene.camera, kW, kH);
    ASSERT_GT(a.hitCount(), size_t(kW * kH / 2));
    EXPECT_EQ(a.hitCount(), b.hitCount());
    size_t pointsApart = 0, normalsApart = 0;
    for (size_t i = 0; i < a.points.size(); ++i) {
        pointsApart += !same(a.points[i], b.points[i], 1e-4f);
        normalsApart += !same(a.normals[i], b.normals[i], 1e-3f);
    }
    // An instance transforms the ray, not the vertices: the last bits differ, a pixel on an
    // edge may pick the neighbouring triangle (8 of 14 400 would be 0.06 %).
    EXPECT_LE(pointsApart, 8u);
    EXPECT_LE(normalsApart, 8u);

    std::vector<int> meshesA, meshesB;
    const std::vector<glm::vec3> nA = copy.surfaceNormals(scene.camera.eye, a.points, a.normals, 0, &meshesA);
    const std::vector<glm::vec3> nB = shared.surfaceNormals(scene.camera.eye, a.points, a.normals, 0, &meshesB);
    size_t meshesApart = 0, surfaceApart = 0, onTransformed = 0;
    for (size_t i = 0; i < meshesA.size(); ++i) {
        meshesApart += meshesA[i] != meshesB[i];
        surfaceApart += !same(nA[i], nB[i], 1e-3f);
        onTransformed += meshesA[i] >= 0 && meshesA[i] % 3 == 0;
    }
    EXPECT_GT(onTransformed, size_t(kW * kH / 20)); // the instance path is really traced
    EXPECT_LE(meshesApart, 8u);
    EXPECT_LE(surfaceApart, 8u);

    for (const glm::vec3 l : {glm::vec3(-0.4f, -1.f, -0.3f), glm::vec3(0.7f, -0.3f, 0.2f)}) {
        const std::vector<uint8_t> occA = copy.occluded(a.points, nA, l), occB = shared.occluded(a.points, nA, l);
        size_t shadowed = 0, apart = 0;
        for (size_t i = 0; i < occA.size(); ++i) {
            shadowed += occA[i];
            apart += occA[i] != occB[i];
        }
        EXPECT_GT(shadowed, size_t(kW * kH / 50)) << "light " << l.x;
        EXPECT_LE(apart, 8u) << "light " << l.x << ": " << apart << " receivers judged apart";
    }
}

TEST(SharedTruth, AFullArrayIsCopiedNotOverread) {
    Scene scene = transformedPlatform();
    scene.meshes[1].positions.shrink_to_fit(); // no spare capacity for Embree's 16-byte load
    const GroundTruth shared = GroundTruth::borrowing(scene);
    EXPECT_EQ(shared.triangleCount(), GroundTruth(scene).triangleCount());
    EXPECT_EQ(shared.sharedTriangleCount(), shared.triangleCount() - scene.meshes[1].triangleCount());
}

} // namespace
