// Users' files that loaded wrongly, each test made from its repro (issue 31): ASCII STL line ends,
// a merge tolerance that one far-away triangle widened, transforms that reach infinity, and saved
// files that must read back bit for bit.
#include "geometry/io/model_loader.h"

#include "loader_test_util.h"
#include "temp_dir_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace geometry::scene;
using namespace geometry::io;

namespace {

class UserFiles : public testutil::TempDirTest {
protected:
    UserFiles() : TempDirTest("shadowscope_userfiles_") {}
};

using Corners = std::array<glm::vec3, 3>;

/// Every triangle's corner positions, in order (cleanup keeps the order of the faces it keeps).
std::vector<Corners> corners(const Mesh& m) {
    std::vector<Corners> out(m.triangleCount());
    for (size_t t = 0; t < out.size(); ++t)
        for (int k = 0; k < 3; ++k) out[t][k] = m.positions[m.indices[3 * t + k]];
    return out;
}

bool sameBits(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::string asciiFacet(const Corners& c, const char* eol) {
    std::string s = std::string("facet normal 0 0 1") + eol + "outer loop" + eol;
    for (const glm::vec3& p : c)
        s += "vertex " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + eol;
    return s + "endloop" + eol + "endfacet" + eol;
}

/// A cube of side `side` at `origin`, 12 triangles, as binary STL facets.
std::vector<Corners> cube(glm::vec3 origin, float side) {
    std::vector<Corners> tris;
    const auto corner = [&](int i) { return origin + side * glm::vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1); };
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        tris.push_back({corner(q[0]), corner(q[1]), corner(q[2])});
        tris.push_back({corner(q[0]), corner(q[2]), corner(q[3])});
    }
    return tris;
}

std::string binaryStl(const std::vector<Corners>& tris) {
    std::string s(80, ' ');
    const auto n = static_cast<uint32_t>(tris.size());
    s.append(reinterpret_cast<const char*>(&n), 4);
    for (const Corners& c : tris) {
        s.append(12, '\0');
        for (const glm::vec3& p : c) s.append(reinterpret_cast<const char*>(&p), 12);
        s.append(2, '\0');
    }
    return s;
}

} // namespace

// ---- ASCII STL line ends ----------------------------------------------------------------------

TEST_F(UserFiles, AsciiStlWithCrLfLoads) { // the issue's repro, which failed with "control character 0x0d"
    const std::string path = write("c.stl", "solid t\r\nfacet normal 0 0 1\r\nouter loop\r\nvertex 0 0 0\r\nvertex 1 0 "
                                            "0\r\nvertex 0 1 0\r\nendloop\r\nendfacet\r\nendsolid t\r\n");
    const LoadedModel m = loadModel(path);
    ASSERT_EQ(m.meshes.size(), 1u);
    EXPECT_EQ(m.meshes[0].triangleCount(), 1u);
}

TEST_F(UserFiles, AsciiStlLineEndsAndTabsGiveTheSameTriangles) {
    const std::vector<Corners> tris = cube(glm::vec3(1, 2, 3), 2.f);
    std::vector<std::vector<Corners>> loaded;
    for (const char* eol : {"\n", "\r\n", "\r"}) {
        std::string s = std::string("solid\tpart one\t(exported)") + eol;
        for (const Corners& c : tris) s += asciiFacet(c, eol);
        s += std::string("endsolid\tpart one") + eol;
        const LoadedModel m = loadModel(write("eol.stl", s));
        ASSERT_EQ(m.meshes.size(), 1u);
        EXPECT_EQ(m.meshes[0].triangleCount(), 12u) << "line end " << int(eol[0]) << " " << s.size();
        loaded.push_back(corners(m.meshes[0]));
    }
    ASSERT_EQ(loaded[0].size(), 12u);
    for (size_t i = 1; i < loaded.size(); ++i)
        for (size_t t = 0; t < 12; ++t)
            for (int k = 0; k < 3; ++k) EXPECT_TRUE(sameBits(loaded[i][t][k], loaded[0][t][k]));
}

TEST_F(UserFiles, AsciiStlStillRefusesOtherControlBytes) {
    testutil::expectLoadRejected(write("ctl.stl", "solid a\x01name\nendsolid\n"), "line 1: control character 0x01");
    // A CR-only file counts its lines too.
    testutil::expectLoadRejected(write("cr.stl", "solid a\rfacet normal 0 0 1\router loop\rvertex 0 0 x\r"), "line 4:");
}

// ---- Merge tolerance in model units --------------------------------------------------------------

TEST_F(UserFiles, AFarAwayTriangleNoLongerMergesASmallPart) {
    // A 1 cm cube beside one triangle 100 km away: a tolerance relative to the diagonal became
    // 0.1 m and left 1 triangle; in model units (1e-5 by default) all 13 stay.
    std::vector<Corners> tris = cube(glm::vec3(0.f), 0.01f);
    tris.push_back({glm::vec3(1e5f, 0, 0), glm::vec3(1e5f + 1, 0, 0), glm::vec3(1e5f, 1, 0)});
    const std::string path = write("far.stl", binaryStl(tris));
    const LoadedModel m = loadModel(path);
    EXPECT_EQ(m.meshes[0].triangleCount(), 13u);
    EXPECT_EQ(m.report.mergeTolerance, kDefaultMergeTolerance);

    CleanupOptions relative;
    relative.mergeTolerance = 1e-6;
    relative.mergeToleranceOfDiagonal = true; // still there when asked, with its known weakness
    const LoadedModel r = loadModel(path, relative);
    EXPECT_LT(r.meshes[0].triangleCount(), 13u);
    EXPECT_NEAR(r.report.mergeTolerance, 1e-6 * 1e5, 1.0);
}

TEST_F(UserFiles, TheToleranceMergesNearDuplicatesWithinIt) {
    // Two triangles sharing an edge whose shared corners differ by 4e-6 (text rounding): merged
    // into 4 vertices by default, kept apart (6) with a tolerance of 0.
    const std::vector<Corners> tris = {{glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)},
                                       {glm::vec3(1.000004f, 0, 0), glm::vec3(1, 1, 0), glm::vec3(0, 1.000004f, 0)}};
    const std::string path = write("near.stl", binaryStl(tris));
    CleanupOptions sharp;
    sharp.creaseAngleDeg = 0; // normals never split vertices: the counts are the merge's
    const LoadedModel merged = loadModel(path, sharp);
    EXPECT_EQ(merged.report.mergedVertices, 2u);
    sharp.mergeTolerance = 0;
    const LoadedModel apart = loadModel(path, sharp);
    EXPECT_EQ(apart.report.mergedVertices, 0u);
}

TEST_F(UserFiles, AModelSmallerThanTheToleranceSaysSo) {
    // A 4e-7 triangle (a part in metres this small is rare, but possible): every corner within
    // 1e-5 of the others merges; the error names the tolerance, and a tolerance of 0 keeps it.
    const std::string path =
        write("tiny.stl", binaryStl({{glm::vec3(0, 0, 0), glm::vec3(4e-7f, 0, 0), glm::vec3(0, 4e-7f, 0)}}));
    testutil::expectLoadRejected(path, "1 faces lie within the merge tolerance, 1e-05 model units");
    CleanupOptions exact;
    exact.mergeTolerance = 0;
    EXPECT_EQ(loadModel(path, exact).meshes[0].triangleCount(), 1u);
}

// ---- Transforms beyond the float range --------------------------------------------------------

TEST_F(UserFiles, ANodeTransformReachingInfinityIsRefused) {
    // glTF node: scale 1e38, translation 3e38 on a unit triangle (the issue's repro): every
    // number is finite, their product is not.
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    write("tri.bin", std::string(reinterpret_cast<const char*>(pos), sizeof pos));
    const std::string gltf = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
        "nodes":[{"mesh":0,"scale":[1e38,1e38,1e38],"translation":[3e38,0,0]}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
        "bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"uri":"tri.bin","byteLength":36}]})";
    testutil::expectLoadRejected(write("inf.gltf", gltf), "beyond the float range");
}

// ---- Saved files read back bit for bit ----------------------------------------------------------

namespace {

/// A coordinate of up to 20 significant bits in [-0.5, 0.5]: a multiple of 2^-21, which is the grid
/// that loading snaps a mesh of this size to (docs/design.md §2.1 "Compact vertices"), so a loaded
/// mesh keeps the values exactly and any loss is the file's. Six decimals lose the small ones
/// (3·2^-21 = 1.4e-6), six significant digits the long ones (0.7654319...).
float gridValue(std::mt19937& rng) {
    return std::ldexp(float(std::uniform_int_distribution<int>(-(1 << 20), 1 << 20)(rng)), -21);
}

/// 200 triangles of every size down to a few grid steps, corners on the grid and below 1 (the
/// largest coordinate sets the grid: 8 float spacings at it).
Mesh gridTriangles() {
    std::mt19937 rng(31);
    Mesh m;
    for (uint32_t t = 0; t < 200; ++t) {
        const glm::vec3 a(gridValue(rng), gridValue(rng), gridValue(rng));
        const int shift = std::uniform_int_distribution<int>(0, 17)(rng); // edges of 3·2^-21 to 7·2^-4
        const float e = std::ldexp(float(std::uniform_int_distribution<int>(3, 7)(rng)), shift - 21);
        const glm::vec3 b = a + glm::vec3(e, 0, 0), c = a + glm::vec3(0, e, e);
        m.positions.insert(m.positions.end(), {a, b, c});
        m.indices.insert(m.indices.end(), {3 * t, 3 * t + 1, 3 * t + 2});
    }
    return m;
}

CleanupOptions exactOptions() {
    CleanupOptions o;
    o.mergeTolerance = 0; // nothing merged, no face too small: every triangle comes back
    return o;
}

void expectSameTriangles(const std::vector<Corners>& got, const std::vector<Corners>& expected) {
    ASSERT_EQ(got.size(), expected.size());
    size_t differing = 0;
    for (size_t t = 0; t < got.size(); ++t)
        for (int k = 0; k < 3; ++k) differing += !sameBits(got[t][k], expected[t][k]);
    EXPECT_EQ(differing, 0u);
}

} // namespace

TEST_F(UserFiles, SavedFilesReadBackBitForBit) {
    const Mesh source = gridTriangles();
    for (const char* ext : {"obj", "off", "ply", "stl"}) {
        SCOPED_TRACE(ext);
        const std::string path = (dir / (std::string("exact.") + ext)).string();
        saveMesh(path, source);
        const LoadedModel m = loadModel(path, exactOptions(), {}, UpAxis::Y);
        ASSERT_EQ(m.meshes.size(), 1u);
        expectSameTriangles(corners(m.meshes[0]), corners(source));
    }
}

TEST_F(UserFiles, ObjCleanLoadRoundTripIsBitExact) {
    // OBJ → load and clean → save (`mesh clean`) → load: the second load gives the first one's
    // triangles, and both the file's numbers.
    const Mesh source = gridTriangles();
    std::string obj;
    char line[128];
    for (const glm::vec3& p : source.positions) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
        obj += line;
    }
    for (size_t t = 0; t < source.triangleCount(); ++t)
        obj +=
            "f " + std::to_string(3 * t + 1) + " " + std::to_string(3 * t + 2) + " " + std::to_string(3 * t + 3) + "\n";
    const LoadedModel first = loadModel(write("in.obj", obj), exactOptions(), {}, UpAxis::Y);
    ASSERT_EQ(first.meshes.size(), 1u);
    expectSameTriangles(corners(first.meshes[0]), corners(source));
    const std::string out = (dir / "out.obj").string();
    saveMesh(out, first.meshes[0]);
    const LoadedModel second = loadModel(out, exactOptions(), {}, UpAxis::Y);
    ASSERT_EQ(second.meshes.size(), 1u);
    expectSameTriangles(corners(second.meshes[0]), corners(first.meshes[0]));
}
