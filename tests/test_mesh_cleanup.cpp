// cleanMesh(): every step on hand-built meshes, counted and checked.
#include "geometry/io/model_loader.h"
#include "geometry/scene/mesh_builder.h"
#include "geometry/scene/parallel_ranges.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <tuple>

using namespace geometry::scene;
using namespace geometry::io;

namespace {

Mesh makeMesh(std::vector<glm::vec3> positions, std::vector<uint32_t> indices) {
    Mesh m;
    m.positions = std::move(positions);
    m.indices = std::move(indices);
    return m;
}

/// Unit cube on 8 shared vertices, 12 triangles wound counter-clockwise seen from outside.
Mesh sharedCube() {
    std::vector<glm::vec3> p;
    for (int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? 1.f : 0.f, i & 2 ? 1.f : 0.f, i & 4 ? 1.f : 0.f);
    // Quads listed counter-clockwise from outside.
    const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    std::vector<uint32_t> idx;
    for (const auto& q : quads) idx.insert(idx.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
    return makeMesh(p, idx);
}

/// True when every triangle's normal points away from the cube's centre.
bool allOutward(const Mesh& m) {
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                        c = m.positions[m.indices[3 * t + 2]];
        if (glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.f - glm::vec3(0.5f)) <= 0) return false;
    }
    return true;
}

void expectValid(const Mesh& m) {
    ASSERT_EQ(m.normals.size(), m.positions.size());
    for (uint32_t i : m.indices) ASSERT_LT(i, m.positions.size());
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.f, 1e-4f);
    for (const glm::vec3& p : m.positions) EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
}

} // namespace

TEST(MeshCleanup, SharedEdgeWrittenTwiceMergesToFourVertices) {
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 1, 2, 3, 4, 5});
    const CleanupReport r = cleanMesh(m);
    EXPECT_EQ(r.inputVertices, 6u);
    EXPECT_EQ(r.inputFaces, 2u);
    EXPECT_EQ(r.mergedVertices, 2u);
    EXPECT_EQ(r.outputVertices, 4u);
    EXPECT_EQ(r.outputFaces, 2u);
    EXPECT_EQ(m.positions.size(), 4u);
    expectValid(m);
    for (const glm::vec3& n : m.normals) EXPECT_NEAR(n.z, 1.f, 1e-5f);
}

TEST(MeshCleanup, MergeRespectsTolerance) {
    // 1e-7 apart in a unit-sized mesh merges at the default 1e-6; 1e-3 apart does not.
    Mesh close = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1e-7f, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 1, 2, 3, 4, 5});
    EXPECT_EQ(cleanMesh(close).mergedVertices, 2u);
    Mesh far = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1e-3f, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 1, 2, 3, 4, 5});
    EXPECT_EQ(cleanMesh(far).mergedVertices, 1u);
}

TEST(MeshCleanup, TwoCloseVerticesLeftAfterCopiesMerge) {
    // A, B 2e-6 apart and A's bit-equal copy share a coarse cell (64 tolerances wide) and lie well
    // inside it: only their count makes them merge candidates. Once the copy is folded, A and B are
    // counted again on their own, in the smallest counter table there is; B must still merge into A.
    CleanupOptions o;
    o.mergeTolerance = 1e-5;
    o.creaseAngleDeg = 180;
    const glm::vec3 a(0.5f, 0.5f, 0.5f), b(0.500002f, 0.5f, 0.5f), d(0.5f, 1.5f, 0.5f), e(1.5f, 1.5f, 0.5f);
    Mesh m = makeMesh({a, b, d, a, e}, {0, 1, 2, 3, 2, 4});
    const CleanupReport r = cleanMesh(m, o);
    EXPECT_EQ(r.mergedVertices, 2u);  // the copy, and B
    EXPECT_EQ(r.degenerateFaces, 1u); // A B D, with B merged into A
    EXPECT_EQ(r.outputFaces, 1u);
    EXPECT_EQ(r.outputVertices, 3u); // A, D, E
}

TEST(MeshCleanup, NonFiniteVertexRemovesItsFaces) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {nan, 0, 0}, {1, inf, 0}}, {0, 1, 2, 1, 3, 2, 0, 4, 1});
    const CleanupReport r = cleanMesh(m);
    EXPECT_EQ(r.nonFiniteVertices, 2u);
    EXPECT_EQ(r.nonFiniteFaces, 2u);
    EXPECT_EQ(r.outputFaces, 1u);
    EXPECT_EQ(r.outputVertices, 3u);
    expectValid(m);
}

TEST(MeshCleanup, DegenerateFacesRemoved) {
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}}, {0, 1, 2,   // good
                                                                     0, 0, 1,   // repeated index
                                                                     0, 1, 3}); // collinear: zero area
    const CleanupReport r = cleanMesh(m);
    EXPECT_EQ(r.degenerateFaces, 2u);
    EXPECT_EQ(r.outputFaces, 1u);
    EXPECT_EQ(r.isolatedVertices, 1u); // vertex 3 was used by the collinear face alone
    EXPECT_EQ(r.outputVertices, 3u);
    expectValid(m);
}

TEST(MeshCleanup, IndexOutOfRangeDropsFace) {
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2, 0, 1, 7});
    const CleanupReport r = cleanMesh(m);
    EXPECT_EQ(r.outputFaces, 1u);
    EXPECT_EQ(r.degenerateFaces, 1u);
}

TEST(MeshCleanup, DuplicateFacesAnyWindingRemoved) {
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {0, 1, 2, 2, 1, 0, 1, 2, 0, 1, 3, 2});
    const CleanupReport r = cleanMesh(m);
    EXPECT_EQ(r.duplicateFaces, 2u);
    EXPECT_EQ(r.outputFaces, 2u);
    EXPECT_EQ(m.indices[0], 0u); // the first occurrence is the one kept
    EXPECT_EQ(m.indices[1], 1u);
    EXPECT_EQ(m.indices[2], 2u);
}

TEST(MeshCleanup, DuplicateFacesFoundAroundAVertexOfManyFaces) {
    // Every face of a fan has the hub as its smallest vertex: one bucket of 40 faces, compared by
    // sorting rather than pair by pair. Every third face comes again later, wound the other way.
    constexpr uint32_t rim = 30;
    std::vector<glm::vec3> p{{0, 0, 0}};
    for (uint32_t i = 0; i < rim; ++i)
        p.emplace_back(std::cos(0.2f * float(i)), std::sin(0.2f * float(i)), 0.01f * float(i));
    std::vector<uint32_t> idx;
    for (uint32_t i = 1; i < rim; ++i) idx.insert(idx.end(), {0, i, i + 1});
    std::vector<uint32_t> first = idx; // the faces that must stay, in order
    size_t copies = 0;
    for (uint32_t i = 1; i < rim; i += 3, ++copies) idx.insert(idx.end(), {i + 1, 0, i});
    for (uint32_t i = 1; i < rim; i += 3) idx.insert(idx.end(), {i, i + 1, 0}); // and once more, rotated
    copies *= 2;
    Mesh m = makeMesh(std::move(p), std::move(idx));
    CleanupOptions o;
    o.creaseAngleDeg = 180; // one output vertex per input vertex: indices compare directly
    const CleanupReport r = cleanMesh(m, o);
    EXPECT_EQ(r.duplicateFaces, copies);
    EXPECT_EQ(r.outputFaces, rim - 1);
    EXPECT_EQ(m.indices, first);
}

TEST(MeshCleanup, IsolatedVerticesRemoved) {
    Mesh m = makeMesh({{5, 5, 5}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {9, 9, 9}}, {1, 2, 3});
    const CleanupReport r = cleanMesh(m);
    EXPECT_EQ(r.isolatedVertices, 2u);
    EXPECT_EQ(r.outputVertices, 3u);
    EXPECT_EQ(m.positions[0], glm::vec3(0, 0, 0)); // order of the kept vertices preserved
    expectValid(m);
}

TEST(MeshCleanup, CubeNormalsSharpAtThirtyDegreeCrease) {
    Mesh m = sharedCube();
    CleanupOptions o;
    o.creaseAngleDeg = 30;
    const CleanupReport r = cleanMesh(m, o);
    EXPECT_EQ(r.outputVertices, 24u);
    EXPECT_EQ(r.outputFaces, 12u);
    expectValid(m);
    for (const glm::vec3& n : m.normals) // axis-aligned: one component ±1
        EXPECT_NEAR(std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)}), 1.f, 1e-5f);
    // Each triangle's corner normals equal its face normal.
    for (size_t t = 0; t < m.triangleCount(); ++t) {
        const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                        c = m.positions[m.indices[3 * t + 2]];
        const glm::vec3 fn = glm::normalize(glm::cross(b - a, c - a));
        for (int k = 0; k < 3; ++k) EXPECT_GT(glm::dot(fn, m.normals[m.indices[3 * t + k]]), 0.9999f);
    }
}

TEST(MeshCleanup, CubeNormalsSmoothAtHundredDegreeCrease) {
    Mesh m = sharedCube();
    CleanupOptions o;
    o.creaseAngleDeg = 100;
    EXPECT_EQ(cleanMesh(m, o).outputVertices, 8u);
    expectValid(m);
    for (size_t i = 0; i < m.positions.size(); ++i) // every normal points outward from the corner
        EXPECT_GT(glm::dot(m.normals[i], m.positions[i] - glm::vec3(0.5f)), 0.f);
}

TEST(MeshCleanup, FlatShadedBoxMergesThenSplitsAgain) {
    MeshBuilder mb("box", glm::vec3(1.f));
    mb.addBox(glm::vec3(0.f), glm::vec3(1.f, 2.f, 3.f));
    Mesh m = mb.build();
    ASSERT_EQ(m.positions.size(), 24u);
    const CleanupReport r = cleanMesh(m);
    EXPECT_EQ(r.mergedVertices, 16u);
    EXPECT_EQ(r.outputVertices, 24u);
    EXPECT_EQ(r.outputFaces, 12u);
    expectValid(m);
}

TEST(MeshCleanup, OrientationFixFlipsExactlyTheFlippedFaces) {
    Mesh m = sharedCube();
    const std::set<size_t> flipped{1, 4, 9};
    for (size_t t : flipped) std::swap(m.indices[3 * t + 1], m.indices[3 * t + 2]);
    ASSERT_FALSE(allOutward(m));
    CleanupOptions o;
    o.fixOrientation = true;
    const CleanupReport r = cleanMesh(m, o);
    EXPECT_EQ(r.flippedFaces, flipped.size());
    EXPECT_TRUE(allOutward(m));
    expectValid(m);
}

TEST(MeshCleanup, OrientationFixLeavesConsistentMeshAlone) {
    Mesh m = sharedCube();
    CleanupOptions o;
    o.fixOrientation = true;
    EXPECT_EQ(cleanMesh(m, o).flippedFaces, 0u);
    EXPECT_TRUE(allOutward(m));
}

TEST(MeshCleanup, OrientationOffKeepsWinding) {
    Mesh m = sharedCube();
    std::swap(m.indices[1], m.indices[2]);
    EXPECT_EQ(cleanMesh(m).flippedFaces, 0u);
    EXPECT_FALSE(allOutward(m));
}

TEST(MeshCleanup, TriangleSoupGridWeldsIntoGrid) {
    // A 60×60 grid written as an STL-style soup (three vertices per triangle).
    constexpr int n = 60;
    Mesh m;
    auto corner = [](int i, int j) { return glm::vec3(i * 0.1f, 0.f, j * 0.1f); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (const glm::vec3& p : {corner(i, j), corner(i, j + 1), corner(i + 1, j + 1), corner(i, j),
                                       corner(i + 1, j + 1), corner(i + 1, j)}) {
                m.indices.push_back(static_cast<uint32_t>(m.positions.size()));
                m.positions.push_back(p);
            }
    const CleanupReport r = cleanMesh(m);
    EXPECT_EQ(r.outputFaces, size_t(2 * n * n));
    EXPECT_EQ(r.outputVertices, size_t((n + 1) * (n + 1)));
    EXPECT_EQ(r.mergedVertices, size_t(6 * n * n - (n + 1) * (n + 1)));
    expectValid(m);
}

TEST(MeshCleanup, EmptyMeshStaysEmpty) {
    Mesh m;
    const CleanupReport r = cleanMesh(m);
    EXPECT_EQ(r.outputFaces, 0u);
    EXPECT_TRUE(m.positions.empty());
}

TEST(MeshCleanup, ReportsAdd) {
    CleanupReport a, b;
    a.inputFaces = 2;
    a.notes = {"x"};
    b.inputFaces = 3;
    b.flippedFaces = 1;
    b.notes = {"y"};
    a += b;
    EXPECT_EQ(a.inputFaces, 5u);
    EXPECT_EQ(a.flippedFaces, 1u);
    EXPECT_EQ(a.notes.size(), 2u);
}

TEST(MeshCleanup, ZeroToleranceMergesExactDuplicatesOnly) {
    Mesh m = makeMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1e-7f, 0}, {1, 1, 0}, {0, 1, 0}, {-0.f, 0, 0}},
                      {0, 1, 2, 3, 4, 5, 6, 2, 3});
    CleanupOptions o;
    o.mergeTolerance = 0;
    const CleanupReport r = cleanMesh(m, o);
    EXPECT_EQ(r.mergedVertices, 2u); // (0,1,0) twice and -0 = +0; not the 1e-7 neighbour
}

TEST(MeshCleanup, HighDegreeFanStaysFastAndSmooth) {
    // A flat disc of 5000 triangles around one centre vertex, and a shallow cone of as many:
    // the grouped path above kExactCornerDegree.
    constexpr int n = 5000;
    for (const float apex : {0.f, 0.05f}) {
        Mesh m;
        m.positions.emplace_back(0.f, 0.f, apex);
        for (int i = 0; i < n; ++i) {
            const float a = 2.f * 3.14159265f * float(i) / n;
            m.positions.emplace_back(std::cos(a), std::sin(a), 0.f);
            m.indices.insert(m.indices.end(), {0u, uint32_t(1 + i), uint32_t(1 + (i + 1) % n)});
        }
        const CleanupReport r = cleanMesh(m);
        EXPECT_EQ(r.outputFaces, size_t(n));
        expectValid(m);
        // Every face lies within the crease angle of every other: one vertex at the centre.
        EXPECT_EQ(r.outputVertices, size_t(n + 1));
        EXPECT_GT(m.normals[0].z, 0.99f);
    }
}

namespace {

/// A number in [0, 1) from splitmix64's next step: the same sequence on every machine.
double unitRandom(uint64_t& state) {
    state += 0x9E3779B97F4A7C15ull;
    uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return double((z ^ (z >> 31)) >> 11) / double(1ull << 53);
}

/// A soup of `triangles` faces whose corners are drawn from clusters: points jittered within a
/// fraction of `tol` (which must merge), others about `tol` apart (either way), many of them next
/// to the faces of the merge's coarse cells (64 tolerances wide), where the search crosses cells.
Mesh clusteredSoup(size_t triangles, double tol, uint32_t seed) {
    uint64_t state = seed;
    auto next = [&state] { return unitRandom(state); };
    const double cell = 64 * tol;
    std::vector<glm::dvec3> centres;
    for (size_t i = 0; i < triangles / 2 + 3; ++i) {
        glm::dvec3 c(next() * 2000, next() * 2000, next() * 2000); // cells, not metres
        if (i % 3 == 0) c.x = std::round(c.x);                     // on a cell face
        centres.push_back(c * cell);
    }
    Mesh m;
    for (size_t t = 0; t < triangles; ++t)
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3& c = centres[size_t(next() * double(centres.size())) % centres.size()];
            const double r = next() < 0.5 ? 0.3 * tol : 1.2 * tol; // merges / borderline
            const glm::dvec3 p = c + glm::dvec3(next() - 0.5, next() - 0.5, next() - 0.5) * r;
            m.indices.push_back(uint32_t(m.positions.size()));
            m.positions.emplace_back(p);
        }
    return m;
}

} // namespace

TEST(MeshCleanup, BitEqualCornersStayOneVertexThroughAChainOfMerges) {
    // Along x, in tolerances (cells of the merge are four wide): k at 4.0, i at 3.1 (merges into k), r
    // at 2.2 (1.8 from k, so a vertex of its own), then j at i's position, −0 for +0 in y. Searching
    // for j on its own, the merge meets r (its own cell) before k (the next): j and i, one position,
    // would be two vertices, a crack. Bit-equal corners are one vertex first, so j follows i to k.
    constexpr float t = 1e-3f;
    const std::vector<glm::vec3> corners = {
        {4.0f * t, 0.f, 0.f}, {3.1f * t, 0.f, 0.f}, {2.2f * t, 0.f, 0.f}, {3.1f * t, -0.f, 0.f}};
    std::vector<glm::vec3> p;
    std::vector<uint32_t> idx;
    for (uint32_t v = 0; v < corners.size(); ++v) p.push_back(corners[v]);
    for (uint32_t v = 0; v < corners.size(); ++v) { // a face of its own for each, far from the others
        const float y = 10.f + 5.f * float(v);
        p.emplace_back(0.f, y, 0.f);
        p.emplace_back(0.f, y, 1.f);
        idx.insert(idx.end(), {v, uint32_t(p.size() - 2), uint32_t(p.size() - 1)});
    }
    Mesh m = makeMesh(p, idx);
    CleanupOptions o;
    o.mergeTolerance = t;
    const CleanupReport r = cleanMesh(m, o);
    EXPECT_EQ(r.mergedVertices, 2u); // i into k, j with i
    ASSERT_EQ(m.triangleCount(), 4u);
    // Faces keep their order (nothing dropped): face f's first corner is corners[f]'s vertex.
    const auto firstCorner = [&](size_t f) { return m.positions[m.indices[3 * f]]; };
    EXPECT_EQ(firstCorner(1), firstCorner(0));
    EXPECT_EQ(firstCorner(3), firstCorner(0));
    EXPECT_EQ(firstCorner(2), corners[2]);
}

TEST(MeshCleanup, MergedVerticesAreFartherApartThanTheTolerance) {
    // What the greedy merge promises: every kept vertex is more than `tol` from every other kept
    // vertex (checked against all pairs), and every input corner of a kept face has a kept vertex
    // within `tol`.
    constexpr double tol = 1e-3;
    for (const bool copies : {false, true}) {
        SCOPED_TRACE(copies ? "with bit-equal copies" : "soup");
        Mesh m = clusteredSoup(1500, tol, 7);
        if (copies) // every fourth face's first corner a copy of an earlier face's, as indexed files repeat them
            for (size_t f = 4; f < m.triangleCount(); f += 4)
                m.positions[m.indices[3 * f]] = m.positions[m.indices[3 * f - 2]];
        const std::vector<glm::vec3> input = m.positions;
        CleanupOptions o;
        o.mergeTolerance = tol;
        o.creaseAngleDeg = 180; // one output vertex per merged vertex
        const CleanupReport r = cleanMesh(m, o);
        ASSERT_GT(r.mergedVertices, 1000u);
        ASSERT_GT(r.outputVertices, 300u);
        std::vector<glm::vec3> kept = m.positions;
        std::sort(kept.begin(), kept.end(), [](const glm::vec3& a, const glm::vec3& b) {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        });
        kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
        size_t tooClose = 0;
        for (size_t i = 0; i < kept.size(); ++i)
            for (size_t j = i + 1; j < kept.size() && double(kept[j].x) - double(kept[i].x) <= tol; ++j)
                tooClose += glm::distance(glm::dvec3(kept[i]), glm::dvec3(kept[j])) <= tol;
        EXPECT_EQ(tooClose, 0u);
        size_t farFromAll = 0;
        for (const glm::vec3& p : input) {
            bool near = false;
            for (const glm::vec3& q : kept) near = near || glm::distance(glm::dvec3(p), glm::dvec3(q)) <= tol;
            farFromAll += !near;
        }
        // A corner's kept vertex goes when all its faces were dropped (degenerate or duplicate).
        EXPECT_LE(farFromAll, 3 * (r.degenerateFaces + r.duplicateFaces));
    }
}

// 30 000 faces of random corners, far more than the tolerance apart: each vertex alone in its cell of
// the merge's coarse grid, so nearly every vertex that the first count meets another has met a
// collision, and the second count runs. Two corners a third of the tolerance apart in the middle of
// one cell (far from its faces) still merge: both meet in both counts.
TEST(MeshCleanup, TwoVerticesSharingACoarseCellMergeWhereTheFirstCountMostlyCollides) {
    constexpr double tol = 1e-3;
    uint64_t state = 3;
    auto next = [&state] { return unitRandom(state); };
    Mesh m;
    for (uint32_t i = 0; i < 3 * 30000; ++i) {
        m.positions.emplace_back(next() * 1000, next() * 1000, next() * 1000);
        m.indices.push_back(i);
    }
    const glm::dvec3 centre = glm::dvec3(500.5, 700.5, 300.5) * (64 * tol); // a coarse cell's centre
    m.positions[0] = glm::vec3(centre);
    m.positions[3] = glm::vec3(centre + glm::dvec3(tol / 3, 0, 0));
    CleanupOptions o;
    o.mergeTolerance = tol;
    o.creaseAngleDeg = 180;
    const CleanupReport r = cleanMesh(m, o, {}, ReadPositions::Distinct);
    EXPECT_EQ(r.mergedVertices, 1u);
    EXPECT_EQ(r.outputVertices, 3u * 30000 - 1);
}

TEST(MeshCleanup, DistinctReadPositionsCleanAsAnyOthers) {
    // A reader that welded bit-equal corners (binary STL) says so, and the merge skips looking for
    // copies: the result must be what the search would have given.
    Mesh a = clusteredSoup(3000, 1e-3, 5);
    std::vector<glm::vec3> sorted = a.positions;
    std::sort(sorted.begin(), sorted.end(),
              [](const glm::vec3& p, const glm::vec3& q) { return std::tie(p.x, p.y, p.z) < std::tie(q.x, q.y, q.z); });
    ASSERT_EQ(std::unique(sorted.begin(), sorted.end()), sorted.end()) << "the soup's positions must be distinct";
    Mesh b = a;
    CleanupOptions o;
    o.mergeTolerance = 1e-3;
    const CleanupReport ra = cleanMesh(a, o, {}, ReadPositions::MayRepeat);
    const CleanupReport rb = cleanMesh(b, o, {}, ReadPositions::Distinct);
    ASSERT_GT(ra.mergedVertices, 1000u);
    EXPECT_EQ(ra.mergedVertices, rb.mergedVertices);
    EXPECT_EQ(ra.outputVertices, rb.outputVertices);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.normals, b.normals);
}

/// A wavy height field of w × h quads, its vertices numbered row by row and its faces in the same order
/// (as a loaded model's are, about: passes that skip blocks of faces far from a thread's vertices do so
/// here), every 97th quad's first face given twice.
Mesh orderedGrid(uint32_t w, uint32_t h) {
    std::vector<glm::vec3> p;
    std::vector<uint32_t> idx;
    for (uint32_t j = 0; j <= h; ++j)
        for (uint32_t i = 0; i <= w; ++i)
            p.emplace_back(float(i), 2.f * std::sin(0.7f * float(i)) * std::cos(0.3f * float(j)), float(j));
    for (uint32_t j = 0; j < h; ++j)
        for (uint32_t i = 0; i < w; ++i) {
            const uint32_t a = j * (w + 1) + i, b = a + 1, c = a + w + 1, d = c + 1;
            idx.insert(idx.end(), {a, c, b, b, c, d});
            if ((j * w + i) % 97 == 0) idx.insert(idx.end(), {c, b, a});
        }
    return makeMesh(std::move(p), std::move(idx));
}

TEST(MeshCleanup, BadFacesCountedAlikeOnOneThreadAndOnSeveral) {
    // Faces touching a non-finite vertex or naming none are judged on every core, each range counting
    // its own: the counts and the faces kept must be those of one thread, wherever the bad ones lie.
    Mesh one = orderedGrid(500, 400);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const uint32_t v : {1000u, 100'000u, 150'300u}) one.positions[v].y = nan;
    const size_t faces = one.triangleCount();
    for (const size_t f : {size_t(5), faces / 2 + 1, faces - 2}) one.indices[3 * f + 1] = 0xffffff00u;
    size_t outOfRange = 0, nonFinite = 0;
    for (size_t f = 0; f < faces; ++f) {
        bool out = false, bad = false;
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = one.indices[3 * f + k];
            out = out || v >= one.positions.size();
            bad = bad || (v < one.positions.size() && std::isnan(one.positions[v].y));
        }
        outOfRange += out;
        nonFinite += bad && !out;
    }
    ASSERT_EQ(outOfRange, 3u);
    ASSERT_GE(nonFinite, 12u); // up to six faces a vertex
    Mesh several = one;
    const unsigned cores = rangeThreadCap().load();
    rangeThreadCap() = 1;
    const CleanupReport a = cleanMesh(one);
    rangeThreadCap() = 3;
    const CleanupReport b = cleanMesh(several);
    rangeThreadCap() = cores;
    EXPECT_EQ(a.nonFiniteVertices, 3u);
    EXPECT_EQ(a.nonFiniteFaces, nonFinite);
    EXPECT_EQ(b.nonFiniteFaces, nonFinite);
    EXPECT_EQ(a.degenerateFaces, b.degenerateFaces);
    EXPECT_GE(b.degenerateFaces, outOfRange);
    EXPECT_EQ(one.indices, several.indices);
    expectValid(several);
}

TEST(MeshCleanup, SameResultOnOneThreadAndOnSeveral) {
    // The linear passes run over vertex and face ranges on as many threads as there are cores; what
    // they write must not depend on it. 400 k faces: enough for every pass to split three ways (a face
    // pass takes a thread per 2^17 faces).
    for (const bool ordered : {false, true}) {
        Mesh one = ordered ? orderedGrid(500, 400) : clusteredSoup(400'000, 1e-3, 11), several = one;
        CleanupOptions o;
        o.mergeTolerance = 1e-3;
        o.creaseAngleDeg = 30;
        const unsigned cores = rangeThreadCap().load();
        rangeThreadCap() = 1;
        const CleanupReport a = cleanMesh(one, o);
        rangeThreadCap() = 3;
        const CleanupReport b = cleanMesh(several, o);
        rangeThreadCap() = cores;
        SCOPED_TRACE(ordered ? "ordered grid" : "clustered soup");
        EXPECT_EQ(a.mergedVertices, b.mergedVertices);
        EXPECT_EQ(a.duplicateFaces, b.duplicateFaces);
        if (ordered) {
            EXPECT_EQ(a.duplicateFaces, (500u * 400u + 96u) / 97u);
        }
        EXPECT_EQ(a.outputVertices, b.outputVertices);
        EXPECT_GT(a.outputVertices, size_t(3) << 16)
            << "too few vertices for every range of the normals to have a thread";
        EXPECT_EQ(one.indices, several.indices);
        ASSERT_EQ(one.positions.size(), several.positions.size());
        EXPECT_EQ(
            0, std::memcmp(one.positions.data(), several.positions.data(), one.positions.size() * sizeof(glm::vec3)));
        EXPECT_EQ(0, std::memcmp(one.normals.data(), several.normals.data(), one.normals.size() * sizeof(glm::vec3)));
        expectValid(several);
    }
}

TEST(MeshCleanup, VerticesOfMoreThan255NormalsKeepTheirPositions) {
    // Two cones of 256 faces (the most compared pair by pair), crease angle 0: every face of a cone
    // has a normal of its own, so each apex becomes 256 vertices, more than a byte counts, and every
    // rim vertex two. Each corner must keep its position, the second apex's too.
    constexpr uint32_t n = 256;
    Mesh m;
    for (const float x : {0.f, 5.f}) {
        const uint32_t apex = uint32_t(m.positions.size());
        m.positions.emplace_back(x, 0.f, 1.f);
        for (uint32_t i = 0; i < n; ++i) {
            const float a = 2.f * 3.14159265f * float(i) / float(n);
            m.positions.emplace_back(x + std::cos(a), std::sin(a), 0.f);
            m.indices.insert(m.indices.end(), {apex, apex + 1 + i, apex + 1 + (i + 1) % n});
        }
    }
    const Mesh input = m;
    CleanupOptions o;
    o.creaseAngleDeg = 0;
    const CleanupReport r = cleanMesh(m, o);
    ASSERT_EQ(r.outputFaces, size_t(2 * n));
    expectValid(m);
    EXPECT_EQ(r.outputVertices, size_t(2 * (n + 2 * n)));
    for (size_t c = 0; c < m.indices.size(); ++c)
        ASSERT_EQ(m.positions[m.indices[c]], input.positions[input.indices[c]]) << "corner " << c;
    size_t apexVertices = 0;
    for (const glm::vec3& p : m.positions) apexVertices += p.z == 1.f;
    EXPECT_EQ(apexVertices, size_t(2 * n));
}

TEST(MeshCleanup, CornerNormalsAverageTheFacesWithinTheCreaseAngle) {
    // Fans of n faces around an apex, its height alternating so that neighbours meet at a crease or
    // not: apex degrees either side of the 64 up to which faces within the angle are kept as a bit
    // mask (up to 256 every pair is tested; beyond, faces are grouped). Each corner's normal is checked against the
    // definition, computed here from the input alone: the area-weighted sum of the normals of the faces at its position
    // within the crease angle of its own face, the own face always counted.
    for (const int n : {5, 12, 63, 64, 65, 100}) {
        Mesh m;
        m.positions.emplace_back(0.f, 0.f, 1.f);
        for (int i = 0; i < n; ++i) {
            const float a = 2.f * 3.14159265f * float(i) / float(n), r = i % 3 == 0 ? 0.4f : 1.f;
            m.positions.emplace_back(r * std::cos(a), r * std::sin(a), i % 2 == 0 ? 0.f : 0.6f);
            m.indices.insert(m.indices.end(), {0u, uint32_t(1 + i), uint32_t(1 + (i + 1) % n)});
        }
        std::vector<glm::vec3> faceN;
        for (size_t t = 0; t < m.triangleCount(); ++t) {
            const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                            c = m.positions[m.indices[3 * t + 2]];
            faceN.push_back(glm::cross(b - a, c - a));
        }
        const Mesh input = m;
        CleanupOptions o;
        o.creaseAngleDeg = 30;
        const float cosCrease = std::cos(glm::radians(30.f));
        ASSERT_EQ(cleanMesh(m, o).outputFaces, size_t(n));
        expectValid(m);
        // Cleanup keeps the faces in order (nothing dropped) and positions exactly (nothing merged).
        for (size_t t = 0; t < m.triangleCount(); ++t)
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 p = input.positions[input.indices[3 * t + k]];
                ASSERT_EQ(m.positions[m.indices[3 * t + k]], p);
                const glm::vec3 own = glm::normalize(faceN[t]);
                glm::vec3 sum(0.f);
                for (size_t g = 0; g < faceN.size(); ++g) {
                    bool at = false;
                    for (int j = 0; j < 3; ++j) at = at || input.positions[input.indices[3 * g + j]] == p;
                    if (at && (g == t || glm::dot(own, glm::normalize(faceN[g])) >= cosCrease)) sum += faceN[g];
                }
                const glm::vec3 want = glm::normalize(sum), got = m.normals[m.indices[3 * t + k]];
                EXPECT_NEAR(glm::length(got - want), 0.f, 1e-5f) << n << " faces, face " << t << " corner " << k;
            }
        // The apex splits into as many vertices as it has distinct corner normals: more than one here.
        size_t apexVertices = 0;
        for (const glm::vec3& p : m.positions) apexVertices += p == glm::vec3(0.f, 0.f, 1.f);
        EXPECT_GT(apexVertices, 1u) << n << " faces";
    }
}
