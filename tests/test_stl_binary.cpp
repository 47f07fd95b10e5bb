// Binary STL read from a mapped file and welded while read (geometry/io/stl_binary.h): bit-equal
// corners become one vertex in order of first use, −0 with +0, non-finite corners never; any number
// of threads gives the same mesh; and loading it gives what the ASCII twin of the file gives
// (read corner by corner and merged by cleanup alone).
#include "geometry/io/model_loader.h"
#include "geometry/io/stl_binary.h"
#include "geometry/scene/scratch_pages.h"

#include "temp_dir_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using geometry::io::CleanupReport;
using Triangle = std::array<glm::vec3, 3>;

namespace {

class StlBinaryTest : public testutil::TempDirTest {
protected:
    StlBinaryTest() : TempDirTest("shadowscope_stl_binary_") {}
};

std::string binaryStl(const std::vector<Triangle>& tris) {
    std::string s(80, ' ');
    const auto n = uint32_t(tris.size());
    s.append(reinterpret_cast<const char*>(&n), 4);
    for (const Triangle& t : tris) {
        s.append(12, '\0'); // facet normal: ignored
        for (const glm::vec3& p : t) s.append(reinterpret_cast<const char*>(&p), 12);
        s.append(2, '\0');
    }
    return s;
}

/// The same triangles as ASCII STL, every float written round-trip exact (%.9g).
std::string asciiStl(const std::vector<Triangle>& tris) {
    std::string s = "solid twin\n";
    char line[128];
    for (const Triangle& t : tris) {
        s += "facet normal 0 0 0\nouter loop\n";
        for (const glm::vec3& p : t) {
            std::snprintf(line, sizeof line, "vertex %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
            s += line;
        }
        s += "endloop\nendfacet\n";
    }
    return s + "endsolid twin\n";
}

/// A wavy grid of n × n quads (two facets each, every inner corner shared by six), facets shuffled.
std::vector<Triangle> shuffledGrid(int n, uint32_t seed) {
    std::vector<Triangle> tris;
    const auto at = [n](int i, int j) {
        return glm::vec3(float(i) / float(n), 0.1f * std::sin(float(i * j) * 0.37f), float(j) / float(n));
    };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            tris.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            tris.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    std::mt19937 rng(seed);
    std::shuffle(tris.begin(), tris.end(), rng);
    return tris;
}

} // namespace

TEST_F(StlBinaryTest, WeldsBitEqualCornersInOrderOfFirstUse) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<Triangle> tris = {
        {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)},
        {glm::vec3(1, 0, 0), glm::vec3(-0.f, 0, 0), glm::vec3(0, 0, 1)},  // −0 is the first corner
        {glm::vec3(nan, 0, 0), glm::vec3(nan, 0, 0), glm::vec3(0, 1, 0)}, // NaNs stay apart
    };
    const std::string path = write("w.stl", binaryStl(tris));
    CleanupReport counts;
    const geometry::scene::Mesh m = geometry::io::detail::readBinaryStl(path, 84 + 50 * tris.size(), counts, 1);
    ASSERT_EQ(m.positions.size(), 6u); // (0,0,0) (1,0,0) (0,1,0) (0,0,1) NaN NaN
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 1, 0, 3, 4, 5, 2}));
    EXPECT_EQ(counts.inputVertices, 9u);
    EXPECT_EQ(counts.mergedVertices, 3u);
    EXPECT_FALSE(std::signbit(m.positions[0].x));
    EXPECT_GT(m.positions.capacity(), m.positions.size()) << "spare room for Embree's last load";
}

// A header with no facets (84 bytes): nothing to weld, nothing copied (UBSan, in the checked build,
// caught a memcpy from the empty key array that the fuzzer found).
TEST_F(StlBinaryTest, NoFacetsGiveAnEmptyMesh) {
    const std::string path = write("empty.stl", binaryStl({}));
    CleanupReport counts;
    const geometry::scene::Mesh m = geometry::io::detail::readBinaryStl(path, 84, counts, 2);
    EXPECT_TRUE(m.positions.empty());
    EXPECT_TRUE(m.indices.empty());
    EXPECT_EQ(counts.inputVertices, 0u);
}

TEST_F(StlBinaryTest, AnyThreadCountGivesTheSameMesh) {
    const std::vector<Triangle> tris = shuffledGrid(60, 5);
    const std::string path = write("g.stl", binaryStl(tris));
    CleanupReport one;
    const geometry::scene::Mesh a = geometry::io::detail::readBinaryStl(path, 84 + 50 * tris.size(), one, 1);
    EXPECT_EQ(a.positions.size(), 61u * 61u);
    EXPECT_EQ(one.mergedVertices, 3 * tris.size() - 61 * 61);
    for (const unsigned threads : {2u, 3u, 7u}) {
        CleanupReport counts;
        const geometry::scene::Mesh b =
            geometry::io::detail::readBinaryStl(path, 84 + 50 * tris.size(), counts, threads);
        EXPECT_EQ(b.indices, a.indices) << threads;
        ASSERT_EQ(b.positions.size(), a.positions.size()) << threads;
        EXPECT_EQ(0, std::memcmp(b.positions.data(), a.positions.data(), a.positions.size() * sizeof(glm::vec3)));
        EXPECT_EQ(counts.mergedVertices, one.mergedVertices);
    }
}

// Large enough that the last range's lookups and numbering run in two parts (each part's new
// vertices numbered after the parts before it).
TEST_F(StlBinaryTest, TwoThreadsGiveOnesMeshWhenTheLastRangeIsSplitInParts) {
    const std::vector<Triangle> tris = shuffledGrid(400, 3);
    const std::string path = write("big.stl", binaryStl(tris));
    CleanupReport one, two;
    const geometry::scene::Mesh a = geometry::io::detail::readBinaryStl(path, 84 + 50 * tris.size(), one, 1);
    const geometry::scene::Mesh b = geometry::io::detail::readBinaryStl(path, 84 + 50 * tris.size(), two, 2);
    ASSERT_EQ(a.positions.size(), 401u * 401u);
    EXPECT_EQ(b.indices, a.indices);
    ASSERT_EQ(b.positions.size(), a.positions.size());
    EXPECT_EQ(0, std::memcmp(b.positions.data(), a.positions.data(), a.positions.size() * sizeof(glm::vec3)));
    EXPECT_EQ(two.mergedVertices, one.mergedVertices);
}

TEST_F(StlBinaryTest, LoadsAsItsAsciiTwinDoes) {
    const std::vector<Triangle> tris = shuffledGrid(40, 9);
    const geometry::io::LoadedModel bin = geometry::io::loadModel(write("b.stl", binaryStl(tris)));
    const geometry::io::LoadedModel text = geometry::io::loadModel(write("a.stl", asciiStl(tris)));
    ASSERT_EQ(bin.meshes.size(), 1u);
    ASSERT_EQ(text.meshes.size(), 1u);
    EXPECT_EQ(bin.meshes[0].indices, text.meshes[0].indices);
    EXPECT_EQ(bin.meshes[0].positions, text.meshes[0].positions);
    EXPECT_EQ(bin.meshes[0].normals, text.meshes[0].normals);
    EXPECT_EQ(bin.report.inputVertices, text.report.inputVertices);
    EXPECT_EQ(bin.report.mergedVertices, text.report.mergedVertices);
    EXPECT_EQ(bin.report.outputVertices, text.report.outputVertices);
    EXPECT_EQ(bin.report.outputFaces, tris.size());
    // No slack left resident: one spare vertex for Embree's last load, not the growth of cleanup.
    const geometry::scene::Mesh& m = bin.meshes[0];
    EXPECT_GT(m.positions.capacity(), m.positions.size());
    EXPECT_LE(m.positions.capacity(), m.positions.size() + 1 + m.positions.size() / 16);
    EXPECT_LE(m.normals.capacity(), m.normals.size() + m.normals.size() / 16);
    EXPECT_EQ(m.indices.capacity(), m.indices.size());
}

TEST_F(StlBinaryTest, PagesLeftByEarlierWorkChangeNothing) {
    // 180 k facets: the load's arrays are MiBs, scratch pages (geometry/scene/scratch_pages.h). Kept
    // pages hold what was last written in them, unlike fresh ones: a pass that read an element
    // before writing it would see 0xff here and zero in the first load.
    namespace scratch = geometry::scene::scratch;
    const std::vector<Triangle> tris = shuffledGrid(300, 3);
    const std::string path = write("big.stl", binaryStl(tris));
    const geometry::io::LoadedModel first = geometry::io::loadModel(path);
    EXPECT_EQ(scratch::keptBytes(), 0u); // the load gave its pages back
    geometry::io::LoadedModel again;
    {
        const geometry::scene::ScratchScope outer; // keeps these for the load to take first
        for (const size_t mib : {1, 2, 8, 32}) {
            void* block = scratch::allocate(mib << 20);
            std::memset(block, 0xff, mib << 20);
            scratch::release(block, mib << 20);
        }
        EXPECT_EQ(scratch::keptBytes(), size_t(32) << 20); // each block took the one before it; all 0xff
        again = geometry::io::loadModel(path);
        EXPECT_EQ(scratch::keptBytes(), 0u); // chunking gives back what is left once its temporaries go
    }
    EXPECT_EQ(scratch::keptBytes(), 0u);
    ASSERT_EQ(first.meshes.size(), 1u);
    ASSERT_EQ(again.meshes.size(), 1u);
    const geometry::scene::Mesh &a = first.meshes[0], &b = again.meshes[0];
    EXPECT_EQ(a.triangleCount(), tris.size());
    EXPECT_EQ(b.indices, a.indices);
    EXPECT_EQ(b.positions, a.positions);
    EXPECT_EQ(b.normals, a.normals);
    ASSERT_EQ(b.chunks.size(), a.chunks.size());
    for (size_t c = 0; c < a.chunks.size(); ++c) {
        EXPECT_EQ(b.chunks[c].firstTriangle, a.chunks[c].firstTriangle);
        EXPECT_EQ(b.chunks[c].triangleCount, a.chunks[c].triangleCount);
    }
}
