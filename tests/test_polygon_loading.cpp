// Polygon faces (ear clipping: concave, ring and non-planar faces in OBJ, OFF and PLY) and
// the strict ASCII STL reader (junk rejected the same way every time, degenerate facets
// counted, the same triangles as the binary twin). Fixtures are written into a temporary folder.
//
// Index
//   [SECTION] Fixture and helpers ........ PolygonLoading, shoelace, polygonObj, expectTiles
//   [SECTION] Polygons ................... concave, star, ring, OFF/PLY, non-planar, fallback, spiral
//   [SECTION] ASCII STL .................. junk, degenerate facets, binary twin
#include "geometry/io/model_loader.h"
#include "geometry/io/polygon_triangulation.h"

#include "temp_dir_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <unistd.h>

using namespace geometry::io;
namespace fs = std::filesystem;

namespace {

// ---- [SECTION] Fixture and helpers ----------------------------------------------------------

class PolygonLoading : public testutil::TempDirTest {
protected:
    PolygonLoading() : TempDirTest("shadowscope_polygons_") {}
};

/// Points in the z = 0 plane, rounded to float as the loaders store them.
std::vector<glm::dvec2> toFloat(std::vector<glm::dvec2> pts) {
    for (glm::dvec2& p : pts) p = glm::dvec2(static_cast<float>(p.x), static_cast<float>(p.y));
    return pts;
}

/// The exact signed area of a closed outline (zero-width bridges add nothing).
double shoelace(const std::vector<glm::dvec2>& pts, const std::vector<uint32_t>& outline) {
    double a = 0;
    for (size_t i = 0; i < outline.size(); ++i) {
        const glm::dvec2 &p = pts[outline[i]], &q = pts[outline[(i + 1) % outline.size()]];
        a += p.x * q.y - q.x * p.y;
    }
    return a / 2;
}

std::string num(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

/// One OBJ polygon face over `pts` (z = 0) with 0-based `outline`.
std::string polygonObj(const std::vector<glm::dvec2>& pts, const std::vector<uint32_t>& outline) {
    std::string s = "# one polygon\n";
    for (const glm::dvec2& p : pts) s += "v " + num(p.x) + " " + num(p.y) + " 0\n";
    s += "f";
    for (uint32_t i : outline) s += " " + std::to_string(i + 1);
    return s + "\n";
}

/// The loaded triangles tile the polygon: their areas (all facing +z, none flipped) add up to
/// `area`, to 1e-6 relative.
void expectTiles(const LoadedModel& m, double area) {
    ASSERT_EQ(m.meshes.size(), 1u);
    const auto& mesh = m.meshes[0];
    double sum = 0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]), b(mesh.positions[mesh.indices[3 * t + 1]]),
            c(mesh.positions[mesh.indices[3 * t + 2]]);
        const double z = glm::cross(b - a, c - a).z / 2;
        EXPECT_GT(z, 0) << "triangle " << t << " is flipped against the polygon's normal";
        sum += z;
    }
    EXPECT_NEAR(sum, area, 1e-6 * area);
}

std::vector<glm::dvec2> lShape() { return toFloat({{3, 1}, {1, 1}, {1, 3}, {0, 3}, {0, 0}, {3, 0}}); }

/// A ten-pointed star, counter-clockwise, starting at a tip (a fan from there overlaps).
std::vector<glm::dvec2> star() {
    std::vector<glm::dvec2> pts;
    for (int i = 0; i < 10; ++i) {
        const double angle = i * std::numbers::pi / 5, r = i % 2 ? 0.7 : 2.0;
        pts.push_back({r * std::cos(angle), r * std::sin(angle)});
    }
    return toFloat(pts);
}

std::vector<uint32_t> iota(uint32_t n) {
    std::vector<uint32_t> v(n);
    for (uint32_t i = 0; i < n; ++i) v[i] = i;
    return v;
}

} // namespace

// ---- [SECTION] Polygons ---------------------------------------------------------------------

TEST_F(PolygonLoading, ConcaveLKeepsItsArea) {
    const auto pts = lShape();
    const LoadedModel m = loadModel(write("l.obj", polygonObj(pts, iota(6))));
    expectTiles(m, shoelace(pts, iota(6)));
    EXPECT_DOUBLE_EQ(shoelace(pts, iota(6)), 5.0);
    EXPECT_EQ(m.report.polygonsTriangulated, 1u);
    EXPECT_EQ(m.report.nonPlanarFaces, 0u);
    EXPECT_EQ(m.report.earClipFallbacks, 0u);
    EXPECT_EQ(m.meshes[0].triangleCount(), 4u);
}

TEST_F(PolygonLoading, StarKeepsItsArea) {
    const auto pts = star();
    const LoadedModel m = loadModel(write("star.obj", polygonObj(pts, iota(10))));
    expectTiles(m, shoelace(pts, iota(10)));
    EXPECT_EQ(m.report.earClipFallbacks, 0u);
}

TEST_F(PolygonLoading, SquareRingThroughABridge) {
    // Outer square counter-clockwise, the bridge to the hole, the hole clockwise, back again.
    const auto pts = toFloat({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {1, 3}, {3, 3}, {3, 1}});
    const std::vector<uint32_t> outline{0, 1, 2, 3, 0, 4, 5, 6, 7, 4};
    ASSERT_DOUBLE_EQ(shoelace(pts, outline), 12.0);
    const LoadedModel m = loadModel(write("ring.obj", polygonObj(pts, outline)));
    expectTiles(m, 12.0);
    EXPECT_EQ(m.report.earClipFallbacks, 0u);
}

TEST_F(PolygonLoading, CircleRingThroughABridge) {
    std::vector<glm::dvec2> raw;
    for (int i = 0; i < 32; ++i)
        raw.push_back({5 * std::cos(i * std::numbers::pi / 16), 5 * std::sin(i * std::numbers::pi / 16)});
    for (int i = 0; i < 32; ++i)
        raw.push_back({2 * std::cos(i * std::numbers::pi / 16), 2 * std::sin(i * std::numbers::pi / 16)});
    const auto pts = toFloat(raw);
    std::vector<uint32_t> outline = iota(32);
    outline.push_back(0);
    for (uint32_t i = 0; i <= 32; ++i) outline.push_back(32 + (32 - i) % 32); // the hole, clockwise
    const double area = shoelace(pts, outline);
    ASSERT_NEAR(area, 16 * (25 - 4) * std::sin(std::numbers::pi / 16), 1e-5);
    const LoadedModel m = loadModel(write("circle_ring.obj", polygonObj(pts, outline)));
    expectTiles(m, area);
    EXPECT_EQ(m.report.earClipFallbacks, 0u);
}

TEST_F(PolygonLoading, BridgeWithCopiedVertices) {
    // The same ring with the bridge's ends written twice (distinct indices, equal positions).
    const auto pts = toFloat({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}});
    const LoadedModel m = loadModel(write("ring_copies.obj", polygonObj(pts, iota(10))));
    expectTiles(m, 12.0);
}

TEST_F(PolygonLoading, OffAndPlyConcaveAndRingFaces) {
    const auto l = lShape();
    std::string off = "OFF\n6 1 0\n", ply = "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\n"
                                            "property float y\nproperty float z\nelement face 1\n"
                                            "property list uchar int vertex_indices\nend_header\n";
    for (const glm::dvec2& p : l) {
        off += num(p.x) + " " + num(p.y) + " 0\n";
        ply += num(p.x) + " " + num(p.y) + " 0\n";
    }
    off += "6 0 1 2 3 4 5\n";
    ply += "6 0 1 2 3 4 5\n";
    for (const std::string& path : {write("l.off", off), write("l.ply", ply)}) {
        SCOPED_TRACE(path);
        const LoadedModel m = loadModel(path);
        expectTiles(m, 5.0);
        EXPECT_EQ(m.report.polygonsTriangulated, 1u);
    }
    const LoadedModel ring = loadModel(write(
        "ring.off", "OFF\n8 1 0\n0 0 0\n4 0 0\n4 4 0\n0 4 0\n1 1 0\n1 3 0\n3 3 0\n3 1 0\n10 0 1 2 3 0 4 5 6 7 4\n"));
    expectTiles(ring, 12.0);
}

TEST_F(PolygonLoading, ConvexQuadGivesTwoTriangles) {
    const LoadedModel m = loadModel(write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"));
    EXPECT_EQ(m.meshes[0].triangleCount(), 2u);
    EXPECT_EQ(m.report.polygonsTriangulated, 1u);
    EXPECT_EQ(m.report.nonPlanarFaces, 0u);
    expectTiles(m, 1.0);
}

TEST_F(PolygonLoading, NonPlanarQuadIsCounted) {
    const LoadedModel m = loadModel(write("warped.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0.2\nv 0 1 0\nf 1 2 3 4\n"));
    EXPECT_EQ(m.meshes[0].triangleCount(), 2u);
    EXPECT_EQ(m.report.nonPlanarFaces, 1u);
    // A warp well below 1e-3 of the diameter is planar.
    const LoadedModel flat = loadModel(write("flat.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0.0001\nv 0 1 0\nf 1 2 3 4\n"));
    EXPECT_EQ(flat.report.nonPlanarFaces, 0u);
}

TEST(PolygonTriangulation, SelfCancellingBowTieFallsBackAndIsCounted) {
    const std::vector<glm::vec3> pts{{0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<uint32_t> idx{0, 1, 2, 3};
    PolygonStats stats;
    const auto tris = triangulatePolygon(pts, idx, stats);
    EXPECT_EQ(tris.size(), 2u);
    EXPECT_EQ(stats.polygons, 1u);
    EXPECT_EQ(stats.fallbacks, 1u);
}

TEST(PolygonTriangulation, TiltedConcavePolygonKeepsWinding) {
    // The L in a tilted plane: every triangle faces the way the polygon does.
    const glm::dvec3 u = glm::normalize(glm::dvec3(1, 2, 0.5)), w = glm::normalize(glm::cross(u, glm::dvec3(0, 0, 1)));
    std::vector<glm::vec3> pts;
    for (const glm::dvec2& p : lShape()) pts.push_back(glm::vec3(p.x * u + p.y * w));
    PolygonStats stats;
    const auto tris = triangulatePolygon(pts, iota(6), stats);
    ASSERT_EQ(tris.size(), 4u);
    const glm::dvec3 n = glm::cross(u, w);
    double area = 0;
    for (const auto& t : tris) {
        const glm::dvec3 c = glm::cross(glm::dvec3(pts[t[1]] - pts[t[0]]), glm::dvec3(pts[t[2]] - pts[t[0]]));
        EXPECT_GT(glm::dot(c, n), 0);
        area += glm::dot(c, n) / 2;
    }
    EXPECT_NEAR(area, 5.0, 1e-5);
    EXPECT_EQ(stats.nonPlanar, 0u);
    EXPECT_EQ(stats.fallbacks, 0u);
}

namespace {

/// A band wound `turns` times around a spiral, n corners (out along the outer edge, back along
/// the inner): ears only at its two ends, the worst case of ear clipping (O(n³)).
std::vector<glm::vec3> spiralBand(int n, double turns) {
    const int m = n / 2;
    std::vector<glm::vec3> pts(static_cast<size_t>(n));
    for (int k = 0; k < m; ++k) {
        const double t = turns * 2 * std::numbers::pi * k / (m - 1), r = 1 + t / (2 * std::numbers::pi);
        pts[static_cast<size_t>(k)] = glm::vec3((r + 0.5) * std::cos(t), (r + 0.5) * std::sin(t), 0);
        pts[static_cast<size_t>(n - 1 - k)] = glm::vec3(r * std::cos(t), r * std::sin(t), 0);
    }
    return pts;
}

} // namespace

TEST(PolygonTriangulation, HostileSpiralIsFannedWithinItsStepBudget) {
    // 1000 corners over 100 turns clip exactly; 4000 would need ~6·10⁹ steps (seconds; tens
    // under ASan): the budget gives up, fans the rest and counts one fallback.
    PolygonStats small;
    const auto exact = triangulatePolygon(spiralBand(1000, 100), iota(1000), small);
    EXPECT_EQ(exact.size(), 998u);
    EXPECT_EQ(small.fallbacks, 0u);
    PolygonStats large;
    const auto fanned = triangulatePolygon(spiralBand(4000, 100), iota(4000), large);
    EXPECT_EQ(fanned.size(), 3998u);
    EXPECT_EQ(large.polygons, 1u);
    EXPECT_EQ(large.fallbacks, 1u);
}

// ---- [SECTION] ASCII STL --------------------------------------------------------------------

namespace {

std::string facet(const std::string& v1, const std::string& v2, const std::string& v3) {
    return "  facet normal 0 0 1\n    outer loop\n      vertex " + v1 + "\n      vertex " + v2 + "\n      vertex " +
           v3 + "\n    endloop\n  endfacet\n";
}

/// The message loadModel throws for `path` (empty if it loaded).
std::string rejection(const std::string& path) {
    try {
        (void)loadModel(path);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return {};
}

} // namespace

TEST_F(PolygonLoading, JunkAsciiStlIsRejectedNamingTheLineEveryTime) {
    const std::string good = facet("0 0 0", "1 0 0", "0 1 0");
    struct Case {
        const char* name;
        std::string text;
        std::string expected; // after "PATH: "
    };
    const std::vector<Case> cases{
        {"blah.stl", "solid junk\n" + good + facet("0 0 0", "1 blah 0", "0 1 0") + "endsolid junk\n",
         "line 12: expected a number after 'vertex', got 'blah'"},
        {"control.stl", "solid junk\n" + facet("0 0 0", std::string("1.\x01") + "5 0 0", "0 1 0") + "endsolid junk\n",
         "line 5: control character 0x01 (not ASCII STL text)"},
        {"noendloop.stl",
         "solid junk\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
         "      vertex 0 1 0\n  endfacet\nendsolid junk\n",
         "line 7: expected 'endloop' after 3 vertices, got 'endfacet'"},
        {"four.stl",
         "solid junk\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n"
         "      vertex 0 1 0\n      vertex 1 1 0\n    endloop\n  endfacet\nendsolid junk\n",
         "line 7: facet has more than 3 vertices (expected 'endloop')"},
        {"twonumbers.stl", "solid junk\n" + facet("0 0 0", "1 0", "0 1 0") + "endsolid junk\n",
         "line 6: expected a number after 'vertex', got 'vertex'"},
        {"noend.stl", "solid junk\n" + good, "line 8: expected 'facet' or 'endsolid', got end of file"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string path = write(c.name, c.text);
        const std::string expected = path + ": " + c.expected;
        for (int run = 0; run < 20; ++run) ASSERT_EQ(rejection(path), expected) << "run " << run;
    }
}

TEST_F(PolygonLoading, AsciiStlDegenerateFacetsAreCounted) {
    const std::string text = "solid d\n" + facet("0 0 0", "1 0 0", "0 1 0") + facet("0 0 0", "0 0 0", "1 1 1") +
                             facet("0 0 0", "1 1 1", "2 2 2") + facet("0 0 1", "1 0 1", "0 1 1") + "endsolid d\n";
    const LoadedModel m = loadModel(write("degenerate.stl", text));
    EXPECT_EQ(m.report.inputFaces, 4u);
    EXPECT_EQ(m.report.degenerateFaces, 2u);
    EXPECT_EQ(m.report.outputFaces, 2u);
}

TEST_F(PolygonLoading, BinaryStlDegenerateFacetsAreCounted) {
    // OpenMesh's binary reader dropped these silently; now cleanup sees and counts them.
    std::string s(80, ' ');
    const float tris[3][9] = {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 0, 0, 1, 1, 1}, {0, 0, 1, 1, 0, 1, 0, 1, 1}};
    const uint32_t n = 3;
    s.append(reinterpret_cast<const char*>(&n), 4);
    for (const auto& t : tris) {
        s.append(12, '\0');
        s.append(reinterpret_cast<const char*>(t), 36);
        s.append(2, '\0');
    }
    const LoadedModel m = loadModel(write("degenerate_binary.stl", s));
    EXPECT_EQ(m.report.inputFaces, 3u);
    EXPECT_EQ(m.report.degenerateFaces, 1u);
    EXPECT_EQ(m.report.outputFaces, 2u);
}

TEST_F(PolygonLoading, AsciiStlLoadsTheSameTrianglesAsItsBinaryTwin) {
    const std::vector<std::array<float, 9>> tris{{0.1f, 0.2f, 0.3f, 1.5f, -0.25f, 0.f, 0.3f, 1.1f, 0.7f},
                                                 {0.1f, 0.2f, 0.3f, 0.3f, 1.1f, 0.7f, -2.f, 0.5f, 1e-3f},
                                                 {1.5f, -0.25f, 0.f, 0.3f, 1.1f, 0.7f, 3.25f, 2.f, -1.f}};
    std::string ascii = "SOLID twin\n", binary(80, ' ');
    const uint32_t n = static_cast<uint32_t>(tris.size());
    binary.append(reinterpret_cast<const char*>(&n), 4);
    for (const auto& t : tris) {
        ascii += "facet normal 0 0 0\nouter loop\n";
        for (int v = 0; v < 3; ++v)
            ascii += "vertex " + num(t[3 * v]) + " " + num(t[3 * v + 1]) + " " + num(t[3 * v + 2]) + "\n";
        ascii += "endloop\nendfacet\n";
        binary.append(12, '\0');
        binary.append(reinterpret_cast<const char*>(t.data()), 36);
        binary.append(2, '\0');
    }
    ascii += "endsolid twin\n";
    const LoadedModel a = loadModel(write("twin_ascii.stl", ascii)), b = loadModel(write("twin_binary.stl", binary));
    ASSERT_EQ(a.meshes.size(), 1u);
    ASSERT_EQ(b.meshes.size(), 1u);
    EXPECT_EQ(a.meshes[0].positions, b.meshes[0].positions);
    EXPECT_EQ(a.meshes[0].indices, b.meshes[0].indices);
    EXPECT_EQ(a.report.outputFaces, 3u);
    EXPECT_EQ(a.report.mergedVertices, b.report.mergedVertices);
}
