#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/chunking.h"
#include "geometry/scene/mesh_builder.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <vector>

using namespace geometry::scene;

TEST(PlaneScene, IsDeterministicWithPolesAndBounds) {
    const Scene a = makePlaneScene(), b = makePlaneScene();
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (size_t i = 0; i < a.meshes.size(); ++i) {
        EXPECT_EQ(a.meshes[i].positions, b.meshes[i].positions);
        EXPECT_EQ(a.meshes[i].indices, b.meshes[i].indices);
    }
    const Aabb S = a.bounds();
    EXPECT_NEAR(S.lo.x, -kPlaneSceneHalfSize, 1e-4);
    EXPECT_NEAR(S.hi.x, kPlaneSceneHalfSize, 1e-4);
    EXPECT_NEAR(S.lo.y, 0.f, 1e-4);
    float tallest = 0.f;
    for (const auto& p : planeScenePoles()) tallest = std::max(tallest, p.height);
    EXPECT_NEAR(S.hi.y, tallest, 1e-4);
}

TEST(Chunking, ChunksCoverEveryTriangleOnceWithinLimitAndBounds) {
    MeshBuilder mb("grid", glm::vec3(1.f));
    mb.addGroundGrid({0, 0, 0}, 100.f, 100); // 20000 triangles
    const Mesh m = mb.build();
    ASSERT_EQ(m.triangleCount(), 20000u);
    uint32_t next = 0;
    for (const auto& c : m.chunks) {
        EXPECT_EQ(c.firstTriangle, next);
        EXPECT_LE(c.triangleCount, kMaxChunkTriangles);
        EXPECT_GT(c.triangleCount, 0u);
        for (uint32_t t = c.firstTriangle; t < c.firstTriangle + c.triangleCount; ++t)
            for (int k = 0; k < 3; ++k) EXPECT_TRUE(c.bounds.contains(m.positions[m.indices[3 * t + k]], 1e-4f));
        next += c.triangleCount;
    }
    EXPECT_EQ(next, 20000u);
    // Spatial coherence: chunks of a flat grid cover roughly 1/N of its area each.
    const float area = 100.f * 100.f;
    for (const auto& c : m.chunks) EXPECT_LT(c.bounds.extent().x * c.bounds.extent().z, area / 2.f);
}

// A run's box is Aabb::add's over its vertices, bit for bit (−0 counted as +0, as a transform's product
// leaves it), an index past the positions left out, the last position read without reading past it.
TEST(Chunking, RunBoxesAreTheirVerticesBoxesBitForBit) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-5.f, 5.f);
    Mesh m;
    for (int i = 0; i < 3001; ++i) m.positions.emplace_back(u(rng), u(rng), u(rng));
    m.positions[17] = glm::vec3(-0.f, -0.f, -0.f);
    m.positions.shrink_to_fit(); // no spare capacity after the last position
    for (int i = 0; i < 3 * 1000; ++i) m.indices.push_back(uint32_t(rng() % m.positions.size()));
    m.indices[0] = m.indices[1] = m.indices[2] = m.indices[5] = 17; // the first part: −0 alone
    m.indices[3 * 999 + 2] = uint32_t(m.positions.size() - 1);
    m.indices[3 * 998 + 1] = uint32_t(m.positions.size()); // out of range
    m.parts = {{0, 1, {}}, {1, 401, {}}, {402, 598, {}}};
    m.chunks = {Chunk{{0, 1000, {}}, 0, 3}};
    reboundRuns(m);
    const auto bits = [](const glm::vec3& v) {
        uint32_t b[3];
        std::memcpy(b, &v, sizeof b);
        return std::vector<uint32_t>(b, b + 3);
    };
    for (const TriangleRun& r : m.parts) {
        Aabb expected;
        for (uint32_t i = 3 * r.firstTriangle; i < 3 * (r.firstTriangle + r.triangleCount); ++i)
            if (m.indices[i] < m.positions.size()) expected.add(m.positions[m.indices[i]] + glm::vec3(0.f));
        EXPECT_EQ(bits(r.bounds.lo), bits(expected.lo)) << r.firstTriangle;
        EXPECT_EQ(bits(r.bounds.hi), bits(expected.hi)) << r.firstTriangle;
    }
}

// Each chunk's parts tile it in order, hold at most kMaxPartTriangles each, and their boxes hold
// their triangles (and lie in the chunk's, which is their union); after a transform change
// reboundRuns makes all boxes hold the moved triangles again.
TEST(Chunking, PartsTileEachChunkInOrderWithinLimitAndBounds) {
    MeshBuilder mb("grid", glm::vec3(1.f));
    mb.addGroundGrid({0, 0, 0}, 100.f, 100); // 20000 triangles: chunks of ≤ 4096, parts of ≤ 256
    Mesh m = mb.build();
    const auto holdsItsTriangles = [&](const TriangleRun& r) {
        for (uint32_t t = r.firstTriangle; t < r.firstTriangle + r.triangleCount; ++t)
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 p(m.transform * glm::vec4(m.positions[m.indices[3 * t + k]], 1.f));
                if (!r.bounds.contains(p, 1e-3f)) return false;
            }
        return true;
    };
    const auto check = [&] {
        size_t parts = 0;
        for (const Chunk& c : m.chunks) {
            ASSERT_GT(c.partCount, 1u) << "a chunk of " << c.triangleCount << " triangles is split further";
            ASSERT_LE(size_t(c.firstPart) + c.partCount, m.parts.size());
            uint32_t next = c.firstTriangle;
            Aabb united;
            for (uint32_t k = c.firstPart; k < c.firstPart + c.partCount; ++k) {
                const TriangleRun& p = m.parts[k];
                EXPECT_EQ(p.firstTriangle, next);
                EXPECT_GT(p.triangleCount, 0u);
                EXPECT_LE(p.triangleCount, kMaxPartTriangles);
                EXPECT_TRUE(holdsItsTriangles(p));
                EXPECT_LT(p.bounds.extent().x * p.bounds.extent().z, c.bounds.extent().x * c.bounds.extent().z / 8.f)
                    << "parts are spatially coherent";
                united.add(p.bounds);
                next += p.triangleCount;
            }
            EXPECT_EQ(next, c.firstTriangle + c.triangleCount);
            EXPECT_EQ(united.lo, c.bounds.lo);
            EXPECT_EQ(united.hi, c.bounds.hi);
            EXPECT_TRUE(holdsItsTriangles(c));
            parts += c.partCount;
        }
        EXPECT_EQ(parts, m.parts.size());
    };
    check();
    m.transform = glm::rotate(glm::translate(glm::mat4(1.f), {5.f, 2.f, -3.f}), 0.7f, glm::vec3(0, 1, 0));
    reboundRuns(m);
    check();
    // A chunk that is one part keeps none.
    MeshBuilder small("small", glm::vec3(1.f));
    small.addGroundGrid({0, 0, 0}, 10.f, 10); // 200 triangles
    const Mesh one = small.build();
    ASSERT_EQ(one.chunks.size(), 1u);
    EXPECT_EQ(one.chunks[0].partCount, 0u);
    EXPECT_TRUE(one.parts.empty());
}

TEST(Gamma, AngleBetweenLightAndView) {
    EXPECT_NEAR(gammaDeg({0, 0, -1}, {0, -1, 0}), 90.f, 1e-4);
    EXPECT_NEAR(gammaDeg({0, 0, -1}, {0, 0, -1}), 0.f, 1e-3);
    EXPECT_NEAR(gammaDeg({0, 0, -1}, {0, 0, 1}), 0.f, 1e-3); // γ folds facing light onto [0, 90]
    EXPECT_NEAR(lightViewAngleDeg({0, 0, -1}, {0, 0, 1}), 180.f, 1e-3);
    EXPECT_NEAR(lightViewAngleDeg({0, 0, -1}, {0, 0, -1}), 0.f, 1e-3);
    EXPECT_NEAR(gammaDeg({0, 0, -1}, glm::normalize(glm::vec3(0, -1, -1))), 45.f, 1e-3);
    EXPECT_EQ(gammaDeg({0, 0, 0}, {0, -1, 0}), 0.f);
    EXPECT_EQ(gammaDeg({NAN, 0, 0}, {0, -1, 0}), 0.f);
}

TEST(MeshBuilder, NormalsPointOutOfClosedSolids) {
    MeshBuilder mb("solids", glm::vec3(1.f));
    mb.addBox({1, 2, 3}, {0.5f, 1.f, 2.f});
    mb.addBeam({0, 0, 0}, {3, 4, 5}, 0.2f);
    mb.addCylinder({0, 0, 0}, {0, 5, 0}, 0.5f, 12);
    const Mesh m = mb.build();
    // For each triangle the face normal agrees with the winding and points away from its solid's axis.
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                        c = m.positions[m.indices[3 * t + 2]];
        const glm::vec3 wound = glm::cross(b - a, c - a);
        const glm::vec3 n = m.normals[m.indices[3 * t]];
        EXPECT_GT(glm::dot(wound, n), 0.f) << "triangle " << t;
    }
}

namespace {

/// Signed volume enclosed by a mesh (divergence theorem): the solid's volume when it is closed
/// and wound outwards, whether or not its faces share vertices.
double signedVolume(const Mesh& m) {
    double v = 0.0;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const glm::dvec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                         c = m.positions[m.indices[3 * t + 2]];
        v += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return v;
}

/// Every triangle's winding agrees with its first vertex's normal.
void expectWoundLikeNormals(const Mesh& m) {
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                        c = m.positions[m.indices[3 * t + 2]];
        ASSERT_GT(glm::dot(glm::cross(b - a, c - a), m.normals[m.indices[3 * t]]), 0.f) << m.name << " triangle " << t;
    }
}

/// Area of a regular `sides`-gon inscribed in a circle of radius r.
double polygonArea(double r, int sides) { return 0.5 * sides * r * r * std::sin(2.0 * std::numbers::pi / sides); }

} // namespace

TEST(MeshBuilder, SweptSolidsAreClosedOutwardAndCountedExactly) {
    const int sides = 24;
    {
        // Straight tube with a ring at every metre, along a tilted axis.
        MeshBuilder mb("tube", glm::vec3(1.f));
        std::vector<glm::vec3> path;
        const glm::vec3 dir = glm::normalize(glm::vec3(1, 2, -1));
        for (int i = 0; i <= 4; ++i) path.push_back(glm::vec3(3, 1, 2) + static_cast<float>(i) * dir);
        mb.addTube(path, 0.5f, sides);
        EXPECT_EQ(mb.triangleCount(), MeshBuilder::tubeTriangles(path.size(), sides, true));
        const Mesh m = mb.build();
        expectWoundLikeNormals(m);
        EXPECT_NEAR(signedVolume(m), polygonArea(0.5, sides) * 4.0, 1e-3);
        EXPECT_LT(m.positions.size(), m.triangleCount()); // rings shared between steps
    }
    {
        // Quarter elbow, capped: a quarter of the torus's volume (Pappus, for the polygonal section).
        MeshBuilder mb("elbow", glm::vec3(1.f));
        mb.addTorus({1, 2, 3}, {0, 0, 1}, {0, -1, 0}, 2.f, 0.4f, 0.5f * std::numbers::pi_v<float>, 64, sides);
        EXPECT_EQ(mb.triangleCount(), MeshBuilder::torusTriangles(0.5f * std::numbers::pi_v<float>, 64, sides, true));
        const Mesh m = mb.build();
        expectWoundLikeNormals(m);
        EXPECT_NEAR(signedVolume(m), polygonArea(0.4, sides) * 2.0 * std::numbers::pi * 2.0 / 4.0, 0.01);
    }
    {
        // A full turn closes on itself without caps (a handwheel rim).
        MeshBuilder mb("rim", glm::vec3(1.f));
        mb.addTorus({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, 1.f, 0.1f, 2.f * std::numbers::pi_v<float>, 96, sides);
        EXPECT_EQ(mb.triangleCount(), MeshBuilder::torusTriangles(2.f * std::numbers::pi_v<float>, 96, sides, true));
        EXPECT_EQ(mb.triangleCount(), 2u * 96u * sides);
        const Mesh m = mb.build();
        expectWoundLikeNormals(m);
        EXPECT_NEAR(signedVolume(m), polygonArea(0.1, sides) * 2.0 * std::numbers::pi, 2e-3);
    }
    {
        MeshBuilder mb("flange", glm::vec3(1.f));
        mb.addRing({0, 1, 0}, {0.2f, 1, 0}, 0.3f, 0.5f, sides);
        EXPECT_EQ(mb.triangleCount(), MeshBuilder::ringTriangles(sides));
        const Mesh m = mb.build();
        expectWoundLikeNormals(m);
        EXPECT_NEAR(signedVolume(m), (polygonArea(0.5, sides) - polygonArea(0.3, sides)) * 0.2, 1e-4);
    }
    MeshBuilder mb("cylinder", glm::vec3(1.f));
    mb.addCylinder({0, 0, 0}, {0, 1, 0}, 0.5f, sides, false);
    EXPECT_EQ(mb.triangleCount(), MeshBuilder::cylinderTriangles(sides, false));
    mb.addCylinder({2, 0, 0}, {2, 1, 0}, 0.5f, sides, true);
    EXPECT_EQ(mb.triangleCount(),
              MeshBuilder::cylinderTriangles(sides, false) + MeshBuilder::cylinderTriangles(sides, true));
}
