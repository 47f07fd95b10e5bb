#include "geometry/lod/caster_lod.h"
#include "geometry/scene/chunking.h"
#include "geometry/scene/mesh_builder.h"
#include "lod_test_meshes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

using namespace geometry;
using geometry::lod::LodRange;
using geometry::lod::MeshLod;

namespace {

constexpr float kRadius = 0.5f, kLength = 2.f;
constexpr int kSegments = 64, kRings = 20;

scene::Scene sceneOf(scene::Mesh mesh, uint32_t maxChunk = scene::kMaxChunkTriangles) {
    scene::chunkMesh(mesh, maxChunk);
    scene::Scene s;
    s.meshes.push_back(std::move(mesh));
    return s;
}

/// The 64 × 20 tube of radius 0.5 along z from the origin, in one chunk.
scene::Mesh tube(const glm::mat4& transform = glm::mat4(1.f), bool seamCopies = false) {
    scene::Mesh m;
    m.twoSided = false;
    testutil::addTube(m, glm::vec3(0.f), glm::vec3(0, 0, 1), kRadius, kLength, kSegments, kRings, seamCopies);
    m.transform = transform;
    return m;
}

/// A level's triangles as world-space corner triples.
std::vector<std::array<glm::vec3, 3>> levelTriangles(const MeshLod& lod, const LodRange& r, const glm::mat4& m) {
    std::vector<std::array<glm::vec3, 3>> out;
    for (uint32_t t = r.firstTriangle; t < r.firstTriangle + r.triangleCount; ++t) {
        std::array<glm::vec3, 3> tri{};
        for (int k = 0; k < 3; ++k) tri[k] = glm::vec3(m * glm::vec4(lod.positions[lod.indices[3 * t + k]], 1.f));
        out.push_back(tri);
    }
    return out;
}

float distanceToSegment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.f ? std::clamp(glm::dot(p - a, ab) / len2, 0.f, 1.f) : 0.f;
    return glm::length(a + t * ab - p);
}

float distanceToTriangle(const glm::vec3& p, const std::array<glm::vec3, 3>& t) {
    const glm::vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
    if (glm::dot(n, n) > 0.f) {
        bool inside = true;
        for (int k = 0; k < 3; ++k) inside &= glm::dot(glm::cross(t[(k + 1) % 3] - t[k], p - t[k]), n) >= 0.f;
        if (inside) return std::abs(glm::dot(p - t[0], n)) / glm::length(n);
    }
    return std::min(
        {distanceToSegment(p, t[0], t[1]), distanceToSegment(p, t[1], t[2]), distanceToSegment(p, t[2], t[0])});
}

/// Points spread over a triangle: its barycentric grid with n steps a side.
std::vector<glm::vec3> samples(const std::array<glm::vec3, 3>& t, int n = 6) {
    std::vector<glm::vec3> out;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const float a = float(i) / float(n), b = float(j) / float(n);
            out.push_back(t[0] + a * (t[1] - t[0]) + b * (t[2] - t[0]));
        }
    return out;
}

std::vector<std::array<glm::vec3, 3>> meshTriangles(const scene::Mesh& m) {
    std::vector<std::array<glm::vec3, 3>> out;
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        std::array<glm::vec3, 3> tri{};
        for (int k = 0; k < 3; ++k) tri[k] = glm::vec3(m.transform * glm::vec4(m.positions[m.indices[3 * t + k]], 1.f));
        out.push_back(tri);
    }
    return out;
}

float distanceToSet(const glm::vec3& p, const std::vector<std::array<glm::vec3, 3>>& set) {
    float d = std::numeric_limits<float>::infinity();
    for (const auto& t : set) d = std::min(d, distanceToTriangle(p, t));
    return d;
}

/// The bound the builder guarantees: the farthest vertex or edge midpoint of `from` from `to`.
float farthestVertexOrMidpoint(const std::vector<std::array<glm::vec3, 3>>& from,
                               const std::vector<std::array<glm::vec3, 3>>& to) {
    float farthest = 0.f;
    for (const auto& t : from)
        for (int k = 0; k < 3; ++k)
            farthest = std::max({farthest, distanceToSet(t[k], to), distanceToSet(0.5f * (t[k] + t[(k + 1) % 3]), to)});
    return farthest;
}

/// How far the level strays from the original, sampled (measured, not guaranteed).
float farthestSample(const std::vector<std::array<glm::vec3, 3>>& level,
                     const std::vector<std::array<glm::vec3, 3>>& original) {
    float farthest = 0.f;
    for (const auto& t : level)
        for (const glm::vec3& p : samples(t, 4)) farthest = std::max(farthest, distanceToSet(p, original));
    return farthest;
}

bool allFinite(const MeshLod& lod) {
    for (const auto* v : {&lod.positions, &lod.normals})
        for (const glm::vec3& p : *v)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    for (uint32_t i : lod.indices)
        if (i >= lod.positions.size()) return false;
    return lod.positions.size() == lod.normals.size();
}

} // namespace

// (1) A finely tessellated cylinder gets levels of strictly fewer triangles, the coarsest at most half.
TEST(CasterLod, TessellatedCylinderSimplifies) {
    const scene::Scene s = sceneOf(tube());
    ASSERT_EQ(s.meshes[0].chunks.size(), 1u);
    const uint32_t original = s.meshes[0].chunks[0].triangleCount;
    ASSERT_EQ(original, uint32_t(2 * kSegments * kRings));

    const lod::SceneLod lod = lod::buildCasterLod(s);
    ASSERT_EQ(lod.meshes.size(), 1u);
    ASSERT_EQ(lod.meshes[0].chunkLevels.size(), 1u);
    const auto& levels = lod.meshes[0].chunkLevels[0];
    ASSERT_FALSE(levels.empty());
    EXPECT_EQ(lod.sourceTriangles, original);
    uint32_t previous = original;
    float previousError = 0.f;
    uint64_t total = 0;
    for (const LodRange& r : levels) {
        EXPECT_LE(double(r.triangleCount), 0.9 * previous); // each level is worth a draw
        EXPECT_GT(r.error, previousError);
        previous = r.triangleCount;
        previousError = r.error;
        total += r.triangleCount;
    }
    EXPECT_LE(levels.back().triangleCount, original / 2);
    EXPECT_EQ(lod.lodTriangles, total);
    EXPECT_TRUE(allFinite(lod.meshes[0]));
    // The error is the relative error × the chunk's world diagonal.
    const float diagonal = glm::length(s.meshes[0].chunks[0].bounds.extent());
    EXPECT_NEAR(levels.back().error, diagonal / 32.f, 1e-5f);
}

// Welding: the same tube as a triangle soup (no vertex shared) decimates as well.
TEST(CasterLod, WeldsDuplicatedVertices) {
    scene::Mesh m = tube(glm::mat4(1.f), true), soup;
    for (uint32_t i : m.indices) {
        soup.positions.push_back(m.positions[i]);
        soup.normals.push_back(m.normals[i]);
        soup.indices.push_back(uint32_t(soup.indices.size()));
    }
    const lod::SceneLod lod = lod::buildCasterLod(sceneOf(std::move(soup)));
    const auto& levels = lod.meshes[0].chunkLevels[0];
    ASSERT_FALSE(levels.empty());
    EXPECT_LE(levels.back().triangleCount, uint32_t(kSegments * kRings)); // ≤ 50 %
}

// (2) Every level stays within its error of the original, both ways, in world units.
class CasterLodBound : public ::testing::TestWithParam<int> {};

TEST_P(CasterLodBound, LevelsStayWithinTheirErrorAndDoNotShrink) {
    const glm::mat4 transform = GetParam() == 0
                                    ? glm::mat4(1.f)
                                    : glm::translate(glm::mat4(1.f), glm::vec3(300.f, -20.f, 5.f)) *
                                          glm::rotate(glm::mat4(1.f), 0.7f, glm::normalize(glm::vec3(1, 2, 3))) *
                                          glm::scale(glm::mat4(1.f), glm::vec3(3.f));
    const float scale = GetParam() == 0 ? 1.f : 3.f;
    const scene::Scene s = sceneOf(tube(transform));
    const lod::SceneLod lod = lod::buildCasterLod(s);
    const auto& levels = lod.meshes[0].chunkLevels[0];
    ASSERT_GE(levels.size(), 2u);

    // World-space axis and radius of the original; the original's inner radius is its facets'.
    const glm::vec3 a = glm::vec3(transform * glm::vec4(0, 0, 0, 1)),
                    b = glm::vec3(transform * glm::vec4(0, 0, kLength, 1));
    const float r = scale * kRadius, rInner = r * std::cos(glm::pi<float>() / kSegments);
    auto axisDistance = [&](const glm::vec3& p) {
        const glm::vec3 d = glm::normalize(b - a);
        return glm::length((p - a) - glm::dot(p - a, d) * d);
    };
    const float eps = GetParam() == 0 ? 1e-5f : 2e-4f; // float rounding of world positions ~300 m out
    const auto original = meshTriangles(s.meshes[0]);
    for (const LodRange& level : levels) {
        const auto tris = levelTriangles(lod.meshes[0], level, transform);
        for (const auto& t : tris)
            for (const glm::vec3& p : t) EXPECT_LE(std::abs(axisDistance(p) - r), level.error + eps);
        float closest = std::numeric_limits<float>::infinity();
        for (const auto& t : tris)
            for (const glm::vec3& p : samples(t)) closest = std::min(closest, axisDistance(p));
        EXPECT_GE(closest, rInner - level.error - eps) << "error " << level.error;
        // The bound the builder guarantees: every original vertex and edge midpoint within `error`.
        const float farthest = farthestVertexOrMidpoint(original, tris);
        EXPECT_LE(farthest, level.error + eps);
        EXPECT_GT(farthest, 0.25f * level.error) << "the level uses little of its error";
    }
}

INSTANTIATE_TEST_SUITE_P(IdentityAndScaled, CasterLodBound, ::testing::Values(0, 1));

// Creases: a flange (a short capped cylinder, caps with their own vertices as CAD exports them)
// keeps its rims within the error; vertices alone would let a level cut across a long rim edge.
TEST(CasterLod, CreasesStayWithinError) {
    scene::MeshBuilder mb("flange", glm::vec3(1.f));
    mb.addCylinder(glm::vec3(0.f), glm::vec3(0.f, 0.4f, 0.f), 1.f, 96);
    const scene::Scene s = sceneOf(mb.build());
    const lod::SceneLod lod = lod::buildCasterLod(s);
    const auto& levels = lod.meshes[0].chunkLevels[0];
    ASSERT_GE(levels.size(), 2u);
    EXPECT_LE(levels.back().triangleCount, s.meshes[0].chunks[0].triangleCount / 4);
    const auto original = meshTriangles(s.meshes[0]);
    for (const LodRange& level : levels) {
        const auto tris = levelTriangles(lod.meshes[0], level, glm::mat4(1.f));
        EXPECT_LE(farthestVertexOrMidpoint(original, tris), level.error + 1e-5f);
        EXPECT_LE(farthestSample(tris, original), level.error + 1e-5f) << "measured on this model, not guaranteed";
    }
}

// Long creases: braces as the platform has them (16 sides, caps, no rows along their 10 m). A
// level must not cut a rim or a cap across, which no vertex of the original would notice.
TEST(CasterLod, LongCreasesStayWithinError) {
    scene::MeshBuilder mb("braces", glm::vec3(1.f));
    for (int i = 0; i < 8; ++i)
        mb.addCylinder(glm::vec3(3.f * float(i), 0.f, 0.f), glm::vec3(3.f * float(i) + 2.f, 10.f, 1.f), 0.5f, 16);
    const scene::Scene s = sceneOf(mb.build());
    const lod::SceneLod lod = lod::buildCasterLod(s);
    const auto original = meshTriangles(s.meshes[0]);
    size_t levels = 0;
    for (const auto& chunkLevels : lod.meshes[0].chunkLevels)
        for (const LodRange& level : chunkLevels) {
            const auto tris = levelTriangles(lod.meshes[0], level, glm::mat4(1.f));
            EXPECT_LE(farthestVertexOrMidpoint(original, tris), level.error + 1e-5f);
            EXPECT_LE(farthestSample(tris, original), level.error + 1e-5f) << "measured on this model, not guaranteed";
            ++levels;
        }
    EXPECT_GT(levels, 0u);
}

// A flat open sheet is thin only by its width: a wide grid simplifies, a narrow strip stays exact.
TEST(CasterLod, SheetsAreThinByTheirWidth) {
    scene::MeshBuilder mb("deck", glm::vec3(1.f));
    mb.addGroundGrid(glm::vec3(0.f), 10.f, 40); // 3200 triangles
    scene::Mesh m = mb.build();
    const auto stripFirst = uint32_t(m.positions.size());
    for (int i = 0; i <= 50; ++i) // a 2 cm × 10 m strip at y = 1, 100 triangles
        for (float z : {0.f, 0.02f}) {
            m.positions.push_back({-5.f + 0.2f * float(i), 1.f, z});
            m.normals.push_back({0, 1, 0});
        }
    for (uint32_t i = 0; i < 50; ++i) {
        const uint32_t p = stripFirst + 2 * i;
        m.indices.insert(m.indices.end(), {p, p + 1, p + 3, p, p + 3, p + 2});
    }
    const scene::Scene s = sceneOf(m);
    ASSERT_EQ(s.meshes[0].chunks.size(), 1u);
    const lod::SceneLod lod = lod::buildCasterLod(s);
    const auto& levels = lod.meshes[0].chunkLevels[0];
    ASSERT_FALSE(levels.empty());
    for (const LodRange& r : levels) {
        uint32_t strip = 0, grid = 0;
        for (const auto& t : levelTriangles(lod.meshes[0], r, glm::mat4(1.f))) (t[0].y == 1.f ? strip : grid) += 1;
        EXPECT_EQ(strip, 100u);
        EXPECT_LE(grid, 3200u / 20);
    }
}

// (3) A 2.4 cm bar sharing a chunk with a large tube stays exact in every level; without the
// thin rule it would be decimated (the control that this test can fail): it is straight, so
// collapses along it cost nothing, and 2.4 cm is within the coarser errors.
TEST(CasterLod, ThinBarStaysExact) {
    scene::Mesh m;
    testutil::addTube(m, glm::vec3(0.f), glm::vec3(0, 0, 1), 1.f, 10.f, 48, 30);
    const auto barFirst = uint32_t(m.indices.size() / 3);
    testutil::addBar(m, glm::vec3(3.f, 0.f, 0.f), glm::vec3(0, 0, 1), 0.024f, 10.f, 50);
    const auto barTriangles = uint32_t(m.indices.size() / 3) - barFirst;
    m.twoSided = false;
    const scene::Scene s = sceneOf(m);
    ASSERT_EQ(s.meshes[0].chunks.size(), 1u);

    auto sortedCorners = [](std::array<glm::vec3, 3> t) {
        std::sort(t.begin(), t.end(), [](const glm::vec3& p, const glm::vec3& q) {
            return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z);
        });
        return std::array<float, 9>{t[0].x, t[0].y, t[0].z, t[1].x, t[1].y, t[1].z, t[2].x, t[2].y, t[2].z};
    };
    std::multiset<std::array<float, 9>> bar; // as the scene holds it: chunked, on its grid (snapToGrid)
    const scene::Mesh& held = s.meshes[0];
    for (uint32_t t = 0; t < held.triangleCount(); ++t) {
        const std::array<glm::vec3, 3> corners{held.positions[held.indices[3 * t]],
                                               held.positions[held.indices[3 * t + 1]],
                                               held.positions[held.indices[3 * t + 2]]};
        if (corners[0].x > 2.f) bar.insert(sortedCorners(corners));
    }
    ASSERT_EQ(bar.size(), barTriangles);
    auto barInLevel = [&](const MeshLod& lod, const LodRange& r) {
        std::multiset<std::array<float, 9>> found;
        for (const auto& t : levelTriangles(lod, r, glm::mat4(1.f)))
            if (t[0].x > 2.f) found.insert(sortedCorners(t)); // the tube lies within x ≤ 1
        return found;
    };

    const lod::SceneLod lod = lod::buildCasterLod(s);
    const auto& levels = lod.meshes[0].chunkLevels[0];
    ASSERT_FALSE(levels.empty());
    for (const LodRange& r : levels) EXPECT_EQ(barInLevel(lod.meshes[0], r), bar);

    lod::LodOptions noThinRule;
    noThinRule.thinFactor = 0.f;
    const lod::SceneLod control = lod::buildCasterLod(s, noThinRule);
    ASSERT_FALSE(control.meshes[0].chunkLevels[0].empty());
    EXPECT_LT(barInLevel(control.meshes[0], control.meshes[0].chunkLevels[0].back()).size(), barTriangles / 2);
}

// (4) Vertices shared by two chunks stay, at identical positions, in every level of both.
TEST(CasterLod, ChunkSeamsStayClosed) {
    // Two halves of the tube with their own copies of the middle ring, as a CAD export may have.
    scene::Mesh m;
    testutil::addTube(m, glm::vec3(0.f), glm::vec3(0, 0, 1), kRadius, 1.f, kSegments, kRings / 2);
    testutil::addTube(m, glm::vec3(0, 0, 1), glm::vec3(0, 0, 1), kRadius, 1.f, kSegments, kRings / 2);
    m.twoSided = false;
    const uint32_t half = uint32_t(m.indices.size() / 6);
    for (uint32_t c = 0; c < 2; ++c) {
        scene::Chunk chunk;
        chunk.firstTriangle = c * half;
        chunk.triangleCount = half;
        for (uint32_t i = 3 * chunk.firstTriangle; i < 3 * (chunk.firstTriangle + half); ++i)
            chunk.bounds.add(m.positions[m.indices[i]]);
        m.chunks.push_back(chunk);
    }
    std::vector<glm::vec3> seam;
    for (const glm::vec3& p : m.positions)
        if (p.z == 1.f) seam.push_back(p);
    ASSERT_EQ(seam.size(), size_t(2 * kSegments));

    scene::Scene s;
    s.meshes.push_back(m);
    const lod::SceneLod lod = lod::buildCasterLod(s);
    const MeshLod& ml = lod.meshes[0];
    ASSERT_EQ(ml.chunkLevels.size(), 2u);
    for (const auto& levels : ml.chunkLevels) {
        ASSERT_FALSE(levels.empty());
        for (const LodRange& r : levels) {
            std::set<std::array<float, 3>> present;
            for (const auto& t : levelTriangles(ml, r, glm::mat4(1.f)))
                for (const glm::vec3& p : t) present.insert({p.x, p.y, p.z});
            for (const glm::vec3& p : seam) EXPECT_TRUE(present.count({p.x, p.y, p.z})) << p.x << " " << p.y;
            EXPECT_LT(r.triangleCount, half);
        }
    }
}

// (5) Degenerate input: no crash, no NaN, the bad chunks without levels.
TEST(CasterLod, DegenerateInputIsHarmless) {
    EXPECT_TRUE(lod::buildCasterLod(scene::Scene{}).meshes.empty());

    scene::Scene s;
    s.meshes.emplace_back(); // empty mesh
    {
        scene::Mesh nan = tube(); // a NaN position
        nan.positions[5].y = std::numeric_limits<float>::quiet_NaN();
        s.meshes.push_back(sceneOf(nan).meshes[0]);
    }
    {
        scene::Mesh flat; // zero-area triangles only: a repeated vertex, collinear corners
        flat.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 0}};
        flat.normals.assign(4, glm::vec3(0, 1, 0));
        flat.indices = {0, 1, 3, 0, 1, 2, 2, 2, 2};
        s.meshes.push_back(sceneOf(flat).meshes[0]);
    }
    {
        scene::Mesh fan = tube(); // three fins on an inner edge of the tube: a non-manifold edge
        const uint32_t t = 2 * kSegments * kRings / 2, a = fan.indices[3 * t], b = fan.indices[3 * t + 1];
        for (int i = 0; i < 3; ++i) {
            fan.positions.push_back(glm::vec3(0.f, 0.f, 0.3f * float(i + 1)));
            fan.normals.push_back(glm::vec3(0, 1, 0));
            fan.indices.insert(fan.indices.end(), {a, b, uint32_t(fan.positions.size() - 1)});
        }
        s.meshes.push_back(sceneOf(fan).meshes[0]);
    }
    {
        scene::Mesh bad = sceneOf(tube()).meshes[0]; // an index out of range, a chunk past the index buffer
        bad.indices[7] = 1u << 30;
        bad.chunks.push_back({{bad.chunks[0].firstTriangle + 10, 1u << 20, bad.chunks[0].bounds}});
        s.meshes.push_back(bad);
    }
    {
        scene::Mesh squashed = tube(glm::scale(glm::mat4(1.f), glm::vec3(0.f))); // a zero transform
        s.meshes.push_back(sceneOf(squashed).meshes[0]);
    }

    const lod::SceneLod lod = lod::buildCasterLod(s);
    ASSERT_EQ(lod.meshes.size(), s.meshes.size());
    for (size_t m = 0; m < s.meshes.size(); ++m) {
        EXPECT_EQ(lod.meshes[m].chunkLevels.size(), s.meshes[m].chunks.size());
        EXPECT_TRUE(allFinite(lod.meshes[m])) << "mesh " << m;
    }
    EXPECT_TRUE(lod.meshes[1].chunkLevels[0].empty()); // NaN
    EXPECT_TRUE(lod.meshes[2].chunkLevels[0].empty()); // nothing with area
    for (const auto& levels : lod.meshes[5].chunkLevels) EXPECT_TRUE(levels.empty());
    EXPECT_TRUE(lod.meshes[4].chunkLevels[0].empty()); // bad index
    EXPECT_TRUE(lod.meshes[4].chunkLevels[1].empty()); // bad range

    // The fins are refused by OpenMesh; they go verbatim into every level, which still simplifies.
    const scene::Mesh& fan = s.meshes[3];
    const auto& fanLevels = lod.meshes[3].chunkLevels[0];
    ASSERT_FALSE(fanLevels.empty());
    EXPECT_LE(fanLevels.back().triangleCount, fan.chunks[0].triangleCount / 2);
    for (const LodRange& r : fanLevels) {
        int fins = 0;
        for (const auto& t : levelTriangles(lod.meshes[3], r, glm::mat4(1.f)))
            for (const glm::vec3& p : t) fins += p.x == 0.f && p.y == 0.f;
        EXPECT_EQ(fins, 3);
    }
}

// (6) Picking a level.
TEST(CasterLod, CoarsestLevelWithin) {
    const std::vector<LodRange> levels = {{0, 10, 0.1f}, {10, 5, 0.4f}, {15, 2, 1.6f}};
    EXPECT_EQ(lod::coarsestLevelWithin(levels, 0.05f), -1);
    EXPECT_EQ(lod::coarsestLevelWithin(levels, 0.1f), 0);
    EXPECT_EQ(lod::coarsestLevelWithin(levels, 0.5f), 1);
    EXPECT_EQ(lod::coarsestLevelWithin(levels, 2.f), 2);
    EXPECT_EQ(lod::coarsestLevelWithin(levels, std::numeric_limits<float>::infinity()), 2);
    EXPECT_EQ(lod::coarsestLevelWithin(levels, -std::numeric_limits<float>::infinity()), -1);
    EXPECT_EQ(lod::coarsestLevelWithin(levels, std::numeric_limits<float>::quiet_NaN()), -1);
    EXPECT_EQ(lod::coarsestLevelWithin({}, 1.f), -1);
    static_assert(noexcept(lod::coarsestLevelWithin(levels, 1.f)));
}

// (7) Progress runs from 0 to 1; returning false cancels, and the result is empty.
TEST(CasterLod, ProgressAndCancel) {
    const scene::Scene s = sceneOf(tube());
    std::vector<float> seen;
    const lod::SceneLod done = lod::buildCasterLod(s, {}, [&](float f) {
        seen.push_back(f);
        return true;
    });
    ASSERT_GE(seen.size(), 2u);
    EXPECT_EQ(seen.front(), 0.f);
    EXPECT_EQ(seen.back(), 1.f);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_FALSE(done.meshes[0].chunkLevels[0].empty());

    for (int allowedCalls : {0, 1}) {
        int calls = 0;
        const lod::SceneLod cancelled = lod::buildCasterLod(s, {}, [&](float) { return calls++ < allowedCalls; });
        EXPECT_TRUE(cancelled.meshes.empty());
        EXPECT_EQ(cancelled.sourceTriangles, 0u);
    }
}

// Many chunks: the same levels whatever the number of threads, and every level worth a draw
// (at least 10 % fewer triangles than the one before it, or than the original).
TEST(CasterLod, ManyChunksDeterministicAndEachLevelWorthADraw) {
    scene::Mesh m;
    for (int i = 0; i < 6; ++i)
        testutil::addTube(m, glm::vec3(2.f * float(i), 0.f, 0.f), glm::vec3(0, 0, 1), 0.3f, 5.f, 32, 40);
    const scene::Scene s = sceneOf(m);
    ASSERT_GT(s.meshes[0].chunks.size(), 2u);
    lod::LodOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const lod::SceneLod a = lod::buildCasterLod(s, one), b = lod::buildCasterLod(s, two);
    EXPECT_EQ(a.meshes[0].positions, b.meshes[0].positions);
    EXPECT_EQ(a.meshes[0].indices, b.meshes[0].indices);
    ASSERT_EQ(a.meshes[0].chunkLevels.size(), b.meshes[0].chunkLevels.size());
    size_t dropped = 0;
    for (size_t c = 0; c < a.meshes[0].chunkLevels.size(); ++c) {
        const auto& levels = a.meshes[0].chunkLevels[c];
        ASSERT_EQ(levels.size(), b.meshes[0].chunkLevels[c].size());
        uint32_t previous = s.meshes[0].chunks[c].triangleCount;
        for (size_t k = 0; k < levels.size(); ++k) {
            EXPECT_EQ(levels[k].triangleCount, b.meshes[0].chunkLevels[c][k].triangleCount);
            EXPECT_LE(double(levels[k].triangleCount), 0.9 * double(previous));
            previous = levels[k].triangleCount;
        }
        dropped += 3 - levels.size();
    }
    EXPECT_GT(dropped, 0u); // the coarser levels of a tube cut at both ends have little left to remove
    EXPECT_LT(a.lodTriangles, a.sourceTriangles / 2);
}
