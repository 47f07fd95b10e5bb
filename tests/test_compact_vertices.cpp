// Compact vertices (docs/design.md §2.2): the grid moves no coordinate by more than half its step, the
// GL form decodes to exactly the scene's (snapped) positions in every chunk, wide chunks keep floats,
// normals pack within a 10-bit step, and what cannot be packed is refused rather than drawn wrong.
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/chunking.h"
#include "geometry/scene/compact_vertices.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace geometry::scene;

namespace {

/// Every corner of every chunk, decoded from the compact form, is the mesh's own position bit for bit,
/// and its packed normal is the mesh's normal within one 10-bit step per component.
void expectDecodesExactly(const Mesh& m, const CompactVertices& c) {
    ASSERT_EQ(c.chunks.size(), m.chunks.size());
    ASSERT_EQ(c.indices.size(), m.indices.size());
    size_t mismatches = 0, badNormals = 0;
    for (size_t k = 0; k < m.chunks.size(); ++k) {
        const CompactChunk& cc = c.chunks[k];
        const auto& normals = cc.wide ? c.floatNormals : c.normals;
        for (size_t i = size_t(m.chunks[k].firstTriangle) * 3;
             i < (size_t(m.chunks[k].firstTriangle) + m.chunks[k].triangleCount) * 3; ++i) {
            const uint32_t v = m.indices[i];
            if (c.position(k, c.indices[i]) != m.positions[v]) ++mismatches;
            const glm::vec3 n = unpackNormal(normals[cc.firstVertex + c.indices[i]]);
            if (glm::any(glm::greaterThan(glm::abs(n - m.normals[v]), glm::vec3(1.f / 511.f)))) ++badNormals;
        }
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(badNormals, 0u);
}

/// A strip of n quads along x from `origin`, each `size` wide, with unit normals that vary.
Mesh strip(glm::vec3 origin, float size, int n) {
    Mesh m;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j < 2; ++j) {
            m.positions.push_back(origin + glm::vec3(float(i) * size, float(j) * size * 0.37f, 0.001f * float(i)));
            m.normals.push_back(glm::normalize(glm::vec3(std::sin(float(i)), 1.f, std::cos(float(j) + 0.3f))));
        }
    for (uint32_t i = 0; i < uint32_t(n); ++i) {
        const uint32_t a = 2 * i, b = a + 1, c = a + 2, d = a + 3;
        m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
    }
    return m;
}

} // namespace

TEST(CompactVertices, SnappedPositionsStayWithinHalfAStepOfTheOriginals) {
    // Far from the origin, as CAD coordinates often are, and irregular: random points in a 40 m box at
    // (12 km, 300 m, −7 km).
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.f, 40.f);
    Mesh m;
    for (int i = 0; i < 3000; ++i) {
        m.positions.push_back(glm::vec3(12000.f, 300.f, -7000.f) + glm::vec3(u(rng), u(rng), u(rng)));
        m.normals.push_back(glm::vec3(0.f, 1.f, 0.f));
    }
    for (uint32_t i = 0; i + 2 < 3000; i += 3) m.indices.insert(m.indices.end(), {i, i + 1, i + 2});
    const std::vector<glm::vec3> original = m.positions;
    chunkMesh(m, 64, 16);

    const float step = gridStep(m);
    // kGridUlps float spacings at the largest coordinate, 12 040: 2^13 · 2^-23 · 8 = 2^-7.
    EXPECT_EQ(step, std::ldexp(1.f, -7));
    float worst = 0.f;
    for (size_t i = 0; i < original.size(); ++i) {
        const glm::vec3 d = glm::abs(m.positions[i] - original[i]);
        worst = std::max({worst, d.x, d.y, d.z});
        const glm::vec3 q = m.positions[i] / step;
        EXPECT_EQ(q, glm::round(q)) << i; // on the grid
    }
    EXPECT_LE(worst, 0.5f * step);
    EXPECT_GT(worst, 0.25f * step); // random points: the bound is nearly reached, not loose

    const auto c = compactVertices(m);
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->step, step);
    EXPECT_EQ(c->maxError(), 0.5f * step);
    expectDecodesExactly(m, *c);
    // 40 m in steps of 2^-7 is 5120 counts: every chunk narrow.
    for (const CompactChunk& cc : c->chunks) EXPECT_FALSE(cc.wide);
    EXPECT_TRUE(c->floatPositions.empty());
}

// Coordinates at float's largest value stay finite: the nearest grid point, 2^128, is out of range,
// so those round towards zero, less than a step away.
TEST(CompactVertices, TheLargestFloatsStayFinite) {
    const float big = std::numeric_limits<float>::max();
    Mesh m = strip(glm::vec3(0.f), 1.f, 3);
    m.positions[0] = glm::vec3(big, -big, 1e38f);
    const std::vector<glm::vec3> original = m.positions;
    chunkMesh(m);
    const float step = gridStep(m);
    EXPECT_EQ(step, std::ldexp(1.f, 107));
    for (size_t i = 0; i < original.size(); ++i)
        for (int a = 0; a < 3; ++a) {
            ASSERT_TRUE(std::isfinite(m.positions[i][a])) << i << ' ' << a;
            EXPECT_LT(std::abs(double(m.positions[i][a]) - double(original[i][a])), double(step));
        }
    // float's largest value is (2^24 - 1) · 2^104; the grid point below it, (2^21 - 1) · 2^107.
    EXPECT_EQ(m.positions[0].x, std::ldexp(2097151.f, 107));
    EXPECT_EQ(m.positions[0].y, -std::ldexp(2097151.f, 107));
}

TEST(CompactVertices, SharedVerticesAreStoredOncePerChunkAndDecodeAlikeInEach) {
    Mesh m = strip(glm::vec3(-3.f, 1.f, 2.f), 0.25f, 200);
    chunkMesh(m, 16, 4);
    ASSERT_GT(m.chunks.size(), 10u);
    const auto c = compactVertices(m);
    ASSERT_TRUE(c.has_value());
    expectDecodesExactly(m, *c);
    // Each chunk holds the vertices it names once: 402 vertices, plus those two chunks share.
    EXPECT_GT(c->positions.size(), m.positions.size());
    EXPECT_LT(c->positions.size(), 2 * m.positions.size());
    for (size_t k = 0; k < c->chunks.size(); ++k) {
        const uint32_t end = k + 1 < c->chunks.size() ? c->chunks[k + 1].firstVertex : uint32_t(c->positions.size());
        for (size_t i = size_t(m.chunks[k].firstTriangle) * 3;
             i < (size_t(m.chunks[k].firstTriangle) + m.chunks[k].triangleCount) * 3; ++i)
            EXPECT_LT(c->chunks[k].firstVertex + c->indices[i], end);
    }
}

TEST(CompactVertices, AChunkTooWideFor16BitsKeepsFloatsOnTheSameGrid) {
    // A long thin strip (a pipe run) beside small parts: its chunk spans 4 km, 2^19 steps of 2^-7.
    Mesh m = strip(glm::vec3(-2000.f, 0.f, 0.f), 4000.f, 1);
    Mesh small = strip(glm::vec3(5.f, 2.f, 3.f), 0.01f, 40);
    const auto base = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), small.positions.begin(), small.positions.end());
    m.normals.insert(m.normals.end(), small.normals.begin(), small.normals.end());
    for (uint32_t i : small.indices) m.indices.push_back(base + i);
    chunkMesh(m, 8, 8);
    const auto c = compactVertices(m);
    ASSERT_TRUE(c.has_value());
    size_t wide = 0;
    for (const CompactChunk& cc : c->chunks) wide += cc.wide;
    EXPECT_GE(wide, 1u);
    EXPECT_LT(wide, c->chunks.size());
    EXPECT_FALSE(c->floatPositions.empty());
    expectDecodesExactly(m, *c);
}

TEST(CompactVertices, TheBuiltInScenesDecodeExactly) {
    for (const Scene& s : {makePlatformScene(), makePiperackScene()})
        for (const Mesh& m : s.meshes) {
            SCOPED_TRACE(s.name + "/" + m.name);
            const auto c = compactVertices(m);
            ASSERT_TRUE(c.has_value());
            expectDecodesExactly(m, *c);
            // 12 bytes a vertex and 2 an index in GL, where floats and 32-bit indices took 24 and 4.
            static_assert(sizeof(c->positions[0]) + sizeof(c->normals[0]) == 12);
            static_assert(sizeof(c->indices[0]) == 2);
        }
}

TEST(CompactVertices, WhatCannotBePackedIsRefused) {
    Mesh unchunked = strip(glm::vec3(0.f), 1.f, 4);
    EXPECT_FALSE(compactVertices(unchunked).has_value()); // no chunks

    Mesh gap = strip(glm::vec3(0.f), 1.f, 4);
    chunkMesh(gap, 2, 2);
    gap.chunks.pop_back(); // the chunks no longer tile the triangles
    EXPECT_FALSE(compactVertices(gap).has_value());

    Mesh outOfRange = strip(glm::vec3(0.f), 1.f, 4);
    chunkMesh(outOfRange);
    outOfRange.indices[4] = uint32_t(outOfRange.positions.size());
    EXPECT_FALSE(compactVertices(outOfRange).has_value());

    Mesh notFinite = strip(glm::vec3(0.f), 1.f, 4);
    chunkMesh(notFinite);
    notFinite.positions[notFinite.indices[0]].y = NAN;
    EXPECT_FALSE(compactVertices(notFinite).has_value());
    EXPECT_FALSE(compactStep(notFinite).has_value());

    Mesh moved = strip(glm::vec3(0.f), 1.f, 4);
    chunkMesh(moved);
    ASSERT_TRUE(compactVertices(moved).has_value());
    moved.positions[moved.indices[0]].x += 0.3f * gridStep(moved); // off the grid: not drawn compact
    EXPECT_FALSE(compactVertices(moved).has_value());

    Mesh tooMany; // one chunk naming 3 · 22 000 distinct vertices
    for (uint32_t i = 0; i < 66000; ++i) {
        tooMany.positions.push_back(glm::vec3(float(i % 100), float(i / 100), float(i % 3)));
        tooMany.normals.push_back(glm::vec3(0.f, 0.f, 1.f));
    }
    for (uint32_t i = 0; i < 66000; ++i) tooMany.indices.push_back(i);
    chunkMesh(tooMany, 22000, 22000);
    ASSERT_EQ(tooMany.chunks.size(), 1u);
    EXPECT_FALSE(compactVertices(tooMany).has_value());
}

TEST(CompactVertices, TheStepAloneIsTheStepOfTheCompactVertices) {
    // compactStep answers without building when it can: the same answer as building, whichever way.
    Mesh plain = strip(glm::vec3(0.f), 1.f, 4);
    chunkMesh(plain, 2, 2);
    Mesh spareNan = plain; // a vertex no triangle uses may be anything: the quick answer is not certain
    spareNan.positions.push_back(glm::vec3(NAN));
    spareNan.normals.push_back(glm::vec3(0.f, 0.f, 1.f));
    Mesh bigChunk = strip(glm::vec3(0.f), 1.f, 11000); // 22 000 triangles in one chunk: too many to be sure
    chunkMesh(bigChunk, 30000, 30000);
    ASSERT_EQ(bigChunk.chunks.size(), 1u);
    // Coordinates near float's smallest normal value: the step is subnormal, and 1 / step no float.
    Mesh tiny = strip(glm::vec3(0.f), 1.f, 4);
    for (glm::vec3& p : tiny.positions) p *= 1e-38f;
    chunkMesh(tiny, 2, 2);
    EXPECT_LT(gridStep(tiny), std::numeric_limits<float>::min());
    EXPECT_FALSE(std::isfinite(1.f / gridStep(tiny)));
    for (const Mesh* m : {&plain, &spareNan, &bigChunk, &tiny}) {
        const std::optional<CompactVertices> built = compactVertices(*m);
        ASSERT_TRUE(built.has_value());
        const std::optional<float> step = compactStep(*m);
        ASSERT_TRUE(step.has_value());
        EXPECT_EQ(*step, built->step);
    }
    for (const Mesh* m : {&plain, &tiny}) {
        Mesh offGrid = *m; // an unused vertex off the grid: the quick answer fails, the built one holds
        offGrid.positions.push_back(glm::vec3(0.3f * gridStep(*m)));
        offGrid.normals.push_back(glm::vec3(0.f, 0.f, 1.f));
        const std::optional<CompactVertices> built = compactVertices(offGrid);
        ASSERT_TRUE(built.has_value());
        EXPECT_EQ(compactStep(offGrid), built->step);
    }
}

TEST(CompactVertices, NormalsPackAsGlReadsThem) {
    EXPECT_EQ(unpackNormal(packNormal({1.f, -1.f, 0.f})), glm::vec3(1.f, -1.f, 0.f));
    EXPECT_EQ(unpackNormal(packNormal({NAN, INFINITY, -2.f})), glm::vec3(0.f, 0.f, -1.f));
    EXPECT_EQ(packNormal({0.f, 0.f, 0.f}), 0u);
    // −1 is stored as −511 (0x201); GL reads −512 (0x200) as −1 too.
    EXPECT_EQ(packNormal({-1.f, 0.f, 0.f}) & 0x3ffu, 0x201u);
    EXPECT_EQ(unpackNormal(0x200u).x, -1.f);
    std::mt19937 rng(3);
    std::normal_distribution<float> g;
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 n = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
        const glm::vec3 back = unpackNormal(packNormal(n));
        EXPECT_LE(glm::length(back - n), std::sqrt(3.f) * 0.5f / 511.f + 1e-6f);
    }
}
