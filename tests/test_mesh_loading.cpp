// loadModel()/saveMesh() for OBJ, STL, OFF, PLY: fixtures are written by the tests into a
// temporary folder, good and hostile alike.
#include "geometry/io/mesh_limits.h"
#include "geometry/io/model_loader.h"
#include "geometry/scene/mesh_builder.h"

#include "temp_dir_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <unistd.h>

using namespace geometry::scene;
using namespace geometry::io;
namespace fs = std::filesystem;

namespace {

class MeshLoading : public testutil::TempDirTest {
protected:
    MeshLoading() : TempDirTest("shadowscope_meshio_") {}

    /// loadModel must throw a one-line runtime_error naming the file (and `needle`, if given).
    static void expectRejected(const std::string& path, const std::string& needle = {}) {
        try {
            (void)loadModel(path);
            ADD_FAILURE() << path << " was accepted";
        } catch (const std::runtime_error& e) {
            const std::string msg = e.what();
            EXPECT_NE(msg.find(fs::path(path).filename().string()), std::string::npos) << msg;
            EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
            if (!needle.empty()) {
                EXPECT_NE(msg.find(needle), std::string::npos) << msg;
            }
        }
    }
};

void put32(std::string& s, uint32_t v) {
    for (int i = 0; i < 4; ++i) s.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}
void putFloat(std::string& s, float f) {
    uint32_t v;
    std::memcpy(&v, &f, 4);
    put32(s, v);
}

using Triangle = std::array<glm::vec3, 3>;

/// Tetrahedron, outward winding.
std::vector<Triangle> tetra() {
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0), d(0, 0, 1);
    return {{a, c, b}, {a, b, d}, {a, d, c}, {b, c, d}};
}

std::string binaryStl(const std::vector<Triangle>& tris, uint32_t claimed) {
    std::string s(80, ' ');
    std::memcpy(s.data(), "binary stl from shadowscope tests", 33);
    put32(s, claimed);
    for (const Triangle& t : tris) {
        for (int k = 0; k < 3; ++k) putFloat(s, 0.f);
        for (const glm::vec3& p : t)
            for (int k = 0; k < 3; ++k) putFloat(s, p[k]);
        s += std::string(2, '\0');
    }
    return s;
}
std::string binaryStl(const std::vector<Triangle>& tris) { return binaryStl(tris, static_cast<uint32_t>(tris.size())); }

std::string asciiStl(const std::vector<Triangle>& tris) {
    std::string s = "solid tetra\n";
    for (const Triangle& t : tris) {
        s += "  facet normal 0 0 0\n    outer loop\n";
        for (const glm::vec3& p : t)
            s += "      vertex " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
        s += "    endloop\n  endfacet\n";
    }
    return s + "endsolid tetra\n";
}

const char* kCubeObj = "# unit cube, quads\n"
                       "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                       "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

const char* kCubeOff = "OFF\n8 6 12\n"
                       "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                       "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 3 7 6 2\n4 0 4 7 3\n4 1 2 6 5\n";

const char* kTetraPly = "ply\nformat ascii 1.0\ncomment tetra\nelement vertex 4\nproperty float x\n"
                        "property float y\nproperty float z\nelement face 4\n"
                        "property list uchar int vertex_indices\nend_header\n"
                        "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

std::string binaryPlyHeader(uint64_t vertices, uint64_t faces, const char* countType = "uchar") {
    return "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(vertices) +
           "\nproperty float x\nproperty float y\nproperty float z\nelement face " + std::to_string(faces) +
           "\nproperty list " + countType + " int vertex_indices\nend_header\n";
}

std::string binaryTetraPly(float firstX = 0.f) {
    std::string s = binaryPlyHeader(4, 4);
    const float v[4][3] = {{firstX, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const auto& p : v)
        for (float f : p) putFloat(s, f);
    const uint32_t f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (const auto& t : f) {
        s.push_back(3);
        for (uint32_t i : t) put32(s, i);
    }
    return s;
}

void expectClosedTetra(const LoadedModel& m) {
    ASSERT_EQ(m.meshes.size(), 1u);
    const Mesh& mesh = m.meshes[0];
    EXPECT_EQ(mesh.triangleCount(), 4u);
    EXPECT_EQ(mesh.positions.size(), 12u); // every edge sharper than 30°: split per face
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
    EXPECT_TRUE(mesh.twoSided);
    EXPECT_FALSE(mesh.chunks.empty());
    EXPECT_EQ(m.report.outputFaces, 4u);
}

} // namespace

TEST_F(MeshLoading, AsciiStl) {
    const LoadedModel m = loadModel(write("tetra.stl", asciiStl(tetra())));
    EXPECT_EQ(m.format, "stl");
    expectClosedTetra(m);
    EXPECT_EQ(m.meshes[0].name, "tetra");
}

TEST_F(MeshLoading, BinaryStl) {
    const LoadedModel m = loadModel(write("tetra.stl", binaryStl(tetra())));
    expectClosedTetra(m);
}

TEST_F(MeshLoading, ExtensionIsCaseInsensitive) {
    expectClosedTetra(loadModel(write("TETRA.STL", binaryStl(tetra()))));
    EXPECT_TRUE(isModelFile("a/b/PART.Obj"));
    EXPECT_TRUE(isModelFile("x.glb"));
    EXPECT_FALSE(isModelFile("x.step"));
    EXPECT_FALSE(isModelFile("obj"));
}

TEST_F(MeshLoading, ObjQuadsAreTriangulated) {
    const LoadedModel m = loadModel(write("cube.obj", kCubeObj));
    EXPECT_EQ(m.format, "obj");
    ASSERT_EQ(m.meshes.size(), 1u);
    EXPECT_EQ(m.meshes[0].triangleCount(), 12u);
    EXPECT_EQ(m.meshes[0].positions.size(), 24u);
}

TEST_F(MeshLoading, ObjNegativeIndices) {
    const LoadedModel m = loadModel(write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"));
    EXPECT_EQ(m.meshes[0].triangleCount(), 1u);
}

TEST_F(MeshLoading, OffQuads) {
    const LoadedModel m = loadModel(write("cube.off", kCubeOff));
    EXPECT_EQ(m.format, "off");
    EXPECT_EQ(m.meshes[0].triangleCount(), 12u);
}

TEST_F(MeshLoading, AsciiPly) {
    const LoadedModel m = loadModel(write("tetra.ply", kTetraPly));
    EXPECT_EQ(m.format, "ply");
    expectClosedTetra(m);
}

TEST_F(MeshLoading, BinaryPly) { expectClosedTetra(loadModel(write("tetra.ply", binaryTetraPly()))); }

TEST_F(MeshLoading, ProgressReportsEveryStage) {
    std::vector<std::string> stages;
    float cleaned = 0.f; // cleanup's fraction only grows, stage by stage
    (void)loadModel(write("tetra.stl", binaryStl(tetra())), {}, [&](float f, std::string_view stage) {
        EXPECT_GE(f, 0.f);
        EXPECT_LE(f, 1.f);
        if (stage.starts_with("cleaning")) {
            EXPECT_GE(f, cleaned) << stage;
            cleaned = f;
        }
        if (stages.empty() || stages.back() != stage) stages.emplace_back(stage);
    });
    EXPECT_EQ(stages,
              (std::vector<std::string>{"reading", "cleaning: non-finite vertices", "cleaning: merging vertices",
                                        "cleaning: degenerate and duplicate faces", "cleaning: normals",
                                        "cleaning: done", "chunking"}));
    EXPECT_EQ(cleaned, 1.f);
}

TEST_F(MeshLoading, RoundTripEveryFormat) {
    MeshBuilder mb("parts", glm::vec3(1.f));
    mb.addBox(glm::vec3(0.f), glm::vec3(1.f, 2.f, 3.f));
    mb.addCylinder(glm::vec3(5, 0, 0), glm::vec3(5, 4, 0), 1.f, 16);
    const Mesh source = mb.build();
    for (const char* ext : {"obj", "stl", "off", "ply"}) {
        SCOPED_TRACE(ext);
        const std::string path = (dir / (std::string("parts.") + ext)).string();
        saveMesh(path, source);
        const LoadedModel m = loadModel(path);
        ASSERT_EQ(m.meshes.size(), 1u);
        EXPECT_EQ(m.meshes[0].triangleCount(), source.triangleCount());
        EXPECT_EQ(m.format, ext);
        Aabb a, b;
        for (const glm::vec3& p : source.positions) a.add(p);
        for (const glm::vec3& p : m.meshes[0].positions) b.add(p);
        EXPECT_NEAR(glm::length(a.lo - b.lo), 0.f, 1e-5f);
        EXPECT_NEAR(glm::length(a.hi - b.hi), 0.f, 1e-5f);
    }
}

TEST_F(MeshLoading, SaveNonManifoldKeepsEveryTriangle) {
    // Three triangles on one edge: a halfedge mesh refuses the third; saveMesh must not lose it.
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    m.indices = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    const std::string path = (dir / "fin.obj").string();
    saveMesh(path, m);
    EXPECT_EQ(loadModel(path).meshes[0].triangleCount(), 3u);
}

TEST_F(MeshLoading, SaveRejectsUnknownExtension) {
    Mesh m;
    try {
        saveMesh((dir / "x.step").string(), m);
        ADD_FAILURE();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("x.step"), std::string::npos);
    }
}

// ---- hostile and broken input ------------------------------------------------------------------

TEST_F(MeshLoading, MissingFile) { expectRejected((dir / "nope.stl").string(), "not found"); }

TEST_F(MeshLoading, DirectoryIsNotAFile) {
    fs::create_directories(dir / "folder.obj");
    expectRejected((dir / "folder.obj").string());
}

TEST_F(MeshLoading, EmptyFiles) {
    for (const char* name : {"e.obj", "e.stl", "e.off", "e.ply"}) expectRejected(write(name, ""), "empty");
}

TEST_F(MeshLoading, UnknownExtensionListsSupported) {
    expectRejected(write("part.step", "ISO-10303-21;"), ".obj, .stl, .off, .ply, .gltf, .glb");
    expectRejected(write("noext", "x"), ".stl");
}

TEST_F(MeshLoading, BinaryStlCountDisagreesWithSize) {
    expectRejected(write("short.stl", binaryStl(tetra(), 5)), "5 triangles");
    std::string truncated = binaryStl(tetra());
    truncated.resize(truncated.size() - 20);
    expectRejected(write("truncated.stl", truncated), "truncated");
    expectRejected(write("tiny.stl", std::string(40, '\x01')), "too small");
}

// How fast these are refused is bench_meshio's BM_RejectAbsurdFiles (no wall clock in unit tests).
TEST_F(MeshLoading, AbsurdBinaryStlCountFailsAtOnce) {
    // The count field is 32 bits: 0xFFFFFFFF is the largest claim (4.3e9 triangles, 214 GB).
    expectRejected(write("huge.stl", binaryStl(tetra(), 0xFFFFFFFFu)), "4294967295 triangles");
}

TEST_F(MeshLoading, BinaryStlWithSolidHeaderAndWrongCount) {
    std::string s = binaryStl(tetra(), 99);
    std::memcpy(s.data(), "solid but binary", 16);
    expectRejected(write("solid.stl", s), "99 triangles");
}

TEST_F(MeshLoading, AsciiStlWithoutFacetsHasNoTriangles) {
    expectRejected(write("nofacets.stl", "solid x\nendsolid x\n"), "no triangles");
}

TEST_F(MeshLoading, NonFiniteStlVerticesAreCleaned) {
    std::vector<Triangle> tris = tetra();
    tris[1][1].x = std::numeric_limits<float>::quiet_NaN();
    const LoadedModel m = loadModel(write("nan.stl", binaryStl(tris)));
    EXPECT_EQ(m.meshes[0].triangleCount(), 3u);
    EXPECT_EQ(m.report.nonFiniteFaces, 1u);
    for (const glm::vec3& p : m.meshes[0].positions) EXPECT_TRUE(std::isfinite(p.x));
}

TEST_F(MeshLoading, AllNonFiniteLeavesNothing) {
    std::vector<Triangle> tris = tetra();
    for (Triangle& t : tris) t[0].y = std::numeric_limits<float>::infinity();
    expectRejected(write("inf.stl", binaryStl(tris)), "no triangles left after cleanup");
}

TEST_F(MeshLoading, NonFinitePlyVertexIsCleaned) {
    const LoadedModel m = loadModel(write("nan.ply", binaryTetraPly(std::numeric_limits<float>::quiet_NaN())));
    EXPECT_EQ(m.report.nonFiniteVertices, 1u);
    EXPECT_EQ(m.meshes[0].triangleCount(), 1u); // vertex 0 is in three of the four faces
}

TEST_F(MeshLoading, ObjIndexOutOfRange) {
    expectRejected(write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"), "vertex");
    expectRejected(write("neg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -7\n"), "vertex");
}

TEST_F(MeshLoading, ObjWithoutFaces) { expectRejected(write("points.obj", "v 0 0 0\nv 1 0 0\n"), "no triangles"); }

TEST_F(MeshLoading, GarbageFiles) {
    std::string noise;
    for (int i = 0; i < 4000; ++i) noise.push_back(static_cast<char>((i * 7919 + 13) % 251));
    for (const char* name : {"g.stl", "g.off", "g.ply"}) expectRejected(write(name, noise));
    // OBJ has no header: noise parses as nothing.
    expectRejected(write("g.obj", noise));
}

TEST_F(MeshLoading, OffCountsTooLargeForFile) {
    expectRejected(write("big.off", "OFF\n1000000 2000000 0\n0 0 0\n"), "cannot fit");
    // Not a fixed count: the memory 4e9 vertices and triangles need, against what is available.
    expectRejected(write("cap.off", "OFF\n4000000000 4000000000 0\n"), "GiB to load, but");
}

TEST_F(MeshLoading, OffTruncated) {
    std::string s = kCubeOff;
    s.resize(s.find("4 0 1 5 4"));
    expectRejected(write("cut.off", s), "truncated");
}

TEST_F(MeshLoading, OffIndexOutOfRange) {
    expectRejected(write("idx.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), "references vertex 3");
}

TEST_F(MeshLoading, OffHugeValence) {
    expectRejected(write("valence.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n"));
}

TEST_F(MeshLoading, OffBadHeader) {
    expectRejected(write("hdr.off", "FOO\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "header");
    expectRejected(write("bin.off", "OFF BINARY\n"), "binary");
}

TEST_F(MeshLoading, PlyCountsTooLargeForFile) {
    // 1e8 vertices fit in memory (no fixed count any more) but not in an empty body.
    expectRejected(write("big.ply", binaryPlyHeader(100000000, 1)), "cannot fit");
    expectRejected(write("huge.ply", binaryPlyHeader(5000000000ull, 1)), "32-bit indices");
    expectRejected(write("fit.ply", binaryPlyHeader(1000, 1000) + std::string(100, '\0')), "cannot fit");
}

TEST_F(MeshLoading, PlyIndexOutOfRange) {
    std::string s = kTetraPly;
    s.replace(s.rfind("3 1 2 3"), 7, "3 1 2 4");
    expectRejected(write("idx.ply", s), "references vertex 4");
    std::string b = binaryTetraPly();
    b[b.size() - 4] = 9; // last index of the last face
    expectRejected(write("idxb.ply", b), "references vertex 9");
}

TEST_F(MeshLoading, PlyHugeListCount) {
    std::string s = binaryPlyHeader(3, 1, "int");
    for (int i = 0; i < 9; ++i) putFloat(s, float(i % 2));
    put32(s, 0x7fffffffu);
    put32(s, 0);
    expectRejected(write("list.ply", s), "list");
}

TEST_F(MeshLoading, PlyTruncatedAndBadHeader) {
    std::string b = binaryTetraPly();
    b.resize(b.size() - 6);
    expectRejected(write("cut.ply", b), "truncated");
    expectRejected(write("nohdr.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"), "end_header");
    expectRejected(write("magic.ply", "plx\n"), "magic");
}

TEST_F(MeshLoading, OffStrayValueWouldShiftFaces) {
    // OpenMesh would read the stray 4000000000 as the next face's vertex count.
    expectRejected(write("stray.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 4000000000\n3 0 2 1\n"), "COFF");
    expectRejected(write("counts.off", "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "counts");
}

TEST_F(MeshLoading, CoffFaceColoursAccepted) {
    const LoadedModel m = loadModel(write("c.off", "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 255 0 0 255\n"
                                                   "0 1 0 255 0 0 255\n3 0 1 2 0 255 0\n"));
    EXPECT_EQ(m.meshes[0].triangleCount(), 1u);
}

TEST_F(MeshLoading, PlyAsciiStrayValue) {
    std::string s = kTetraPly;
    s.replace(s.find("3 0 1 3"), 7, "3 0 1 3 9");
    expectRejected(write("stray.ply", s), "more values");
}

TEST_F(MeshLoading, CorruptedFixturesNeverCrashOrHang) {
    // Every prefix length (sampled) and single-byte corruptions of each good fixture either
    // loads or throws std::runtime_error (a hang is ctest's timeout; speed is bench_meshio's).
    const std::vector<std::pair<std::string, std::string>> fixtures = {
        {"a.stl", asciiStl(tetra())}, {"b.stl", binaryStl(tetra())}, {"c.obj", kCubeObj},
        {"d.off", kCubeOff},          {"e.ply", kTetraPly},          {"f.ply", binaryTetraPly()}};
    int loaded = 0, rejected = 0;
    auto attempt = [&](const std::string& name, const std::string& bytes) {
        try {
            (void)loadModel(write(name, bytes));
            ++loaded;
        } catch (const std::runtime_error& e) {
            ++rejected;
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        }
    };
    for (const auto& [name, bytes] : fixtures) {
        for (size_t len = 0; len < bytes.size(); len += 1 + bytes.size() / 40) attempt(name, bytes.substr(0, len));
        for (size_t i = 0; i < bytes.size(); i += 1 + bytes.size() / 60) {
            for (const char c : {'\0', '\xff', '9', '-', '\n'}) {
                std::string b = bytes;
                b[i] = c;
                attempt(name, b);
            }
        }
    }
    EXPECT_GT(loaded, 0);
    EXPECT_GT(rejected, 0);
}

TEST_F(MeshLoading, HeaderWithoutTrailingNewline) {
    expectRejected(write("end.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                                    "property float y\nproperty float z\nend_header"),
                   "cannot fit");
    expectRejected(write("end.off", "OFF\n0 0 0"), "no triangles");
}

// ---- OBJ pre-validation: OpenMesh's OBJ reader trusts its input ----------------------------------

namespace {

const std::string kObjTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

std::string readSourceFile(const std::string& relative) {
    std::ifstream in(std::string(SHADOWSCOPE_SOURCE_DIR) + "/" + relative, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

} // namespace

TEST_F(MeshLoading, ObjFuzzAssertInputsAreRejected) {
    // libFuzzer found these (OpenMesh asserts on a face corner without a vertex index, "/130").
    // Corpus files start with the fuzz target's format byte: 0 selects .obj.
    const std::pair<const char*, const char*> cases[] = {
        {"regression_obj_fuzz_assert.obj", "line 1: control character 0x16"},
        {"regression_obj_corner_without_vertex.obj", "line 4: bad face vertex '/1'"}};
    for (const auto& [name, problem] : cases) {
        SCOPED_TRACE(name);
        const std::string bytes = readSourceFile(std::string("tests/fuzz/corpus/mesh/") + name);
        ASSERT_FALSE(bytes.empty());
        ASSERT_EQ(bytes[0] % 4, 0);
        expectRejected(write(name, bytes.substr(1)), problem);
    }
}

TEST_F(MeshLoading, EveryFuzzRegressionInputIsRejected) {
    static const char* const kExtensions[] = {".obj", ".stl", ".off", ".ply"}; // as fuzz_mesh.cpp
    int checked = 0;
    for (const fs::directory_entry& entry :
         fs::directory_iterator(fs::path(SHADOWSCOPE_SOURCE_DIR) / "tests/fuzz/corpus/mesh")) {
        const std::string name = entry.path().filename().string();
        if (!name.starts_with("regression_")) continue;
        SCOPED_TRACE(name);
        const std::string bytes = readSourceFile("tests/fuzz/corpus/mesh/" + name);
        ASSERT_FALSE(bytes.empty());
        expectRejected(write(entry.path().stem().string() + kExtensions[static_cast<unsigned char>(bytes[0]) % 4],
                             bytes.substr(1)));
        ++checked;
    }
    EXPECT_GE(checked, 4);
}

TEST_F(MeshLoading, ObjMalformedLinesNameTheLineAndProblem) {
    const std::string& tri = kObjTriangle;
    const std::vector<std::pair<std::string, std::string>> cases = {
        {tri + "f /1 2 3\n", "line 4: bad face vertex '/1' (expected v, v/vt, v//vn or v/vt/vn)"},
        {tri + "f 1/ 2 3\n", "bad face vertex '1/'"},
        {tri + "f 1/1/1/1 2 3\n", "bad face vertex '1/1/1/1'"},
        {tri + "f 1 2 x\n", "bad face vertex index 'x' (not an integer)"},
        {tri + "f 1 2 +3\n", "bad face vertex index '+3' (not an integer)"},
        {tri + "f 1 2 --3\n", "bad face vertex index '--3'"},
        {tri + "f 1 2 3.0\n", "bad face vertex index '3.0'"},
        {tri + "f 1 2 3 # comment\n", "bad face vertex index '#'"},
        {tri + "f 1 2\n", "line 4: face has 2 vertices, needs at least 3"},
        {tri + "f\n", "face has 0 vertices"},
        {tri + "f 1 2 0\n", "face vertex index 0 (OBJ indices start at 1)"},
        {tri + "f 1 2 4\n", "line 4: face vertex index 4 out of range (3 vertices)"},
        {tri + "f 1 2 3\nf 1 2 7\nf 3 2 1\n", "line 5: face vertex index 7 out of range (3 vertices)"},
        {tri + "f 1 2 -4\n", "face vertex index -4 out of range (3 vertices before this line)"},
        {"f -1 -2 -3\n" + tri, "line 1: face vertex index -1 out of range (0 vertices before this line)"},
        {tri + "f 1 2 99999999999999999999999\n", "face vertex index 99999999999999999999... out of range"},
        {tri + "f 1/1 2/1 3/1\n", "face texture index 1 out of range (0 texture coordinates)"},
        {tri + "vn 0 0 1\nf 1//2 2//2 3//2\n", "face normal index 2 out of range (1 normal)"},
        {tri + "f 1 2 \\\n3\n", "line continuation"},
        {"v 0 0\n", "line 1: vertex has 2 numbers, needs 3"},
        {"v 0 0 zero\n", "vertex coordinate 'zero' is not a number"},
        {"v 0 0 1,5\n", "vertex coordinate '1,5' is not a number"},
        {"v 0 0 0x1p3\n", "is not a number"},
        {"v 0 0 +-1\n", "vertex coordinate '+-1' is not a number"},
        {"v 0 0 1e\n", "vertex coordinate '1e' is not a number"},
        {"v 0 0 infinity\n", "is not finite"},
        {"v 0 0 nan\n", "vertex coordinate 'nan' is not finite"},
        {"v 0 -Inf 0\n", "is not finite"},
        {"v 1e39 0 0\n", "vertex coordinate '1e39' is out of float range"},
        {"vt 0.5\n", "texture coordinate has 1 number, needs 2"},
        {tri + std::string("f 1 2 3\0\n", 9), "line 4: NUL byte"},
        {"# comment \x01\nv 0 0 0\n", "line 1: control character 0x01"},
        {"v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r", "carriage return inside a line"},
        {"\xEF\xBB\xBFv 0 0 0\n", "byte order mark"},
        {tri + "mtllib\n", "mtllib without a file name"},
        {tri + "mtllib .\n", "material library '.' is not a regular file"},
        {tri + "mtllib ../../../../../../../../../../dev/zero\n", "is not a regular file"},
    };
    for (size_t i = 0; i < cases.size(); ++i) {
        SCOPED_TRACE(cases[i].second);
        expectRejected(write("bad" + std::to_string(i) + ".obj", cases[i].first), cases[i].second);
    }
}

TEST_F(MeshLoading, ObjEmptyMaterialLibraryIsRejected) {
    // procfs files report size 0 whatever they hold, so an empty one is refused too.
    write("empty.mtl", "");
    expectRejected(write("part.obj", "mtllib empty.mtl\n" + kObjTriangle + "f 1 2 3\n"),
                   "line 1: material library 'empty.mtl' is empty");
}

TEST_F(MeshLoading, ObjAbsurdSizesFailFast) {
    expectRejected(write("longline.obj", kObjTriangle + "# " + std::string(3 << 20, 'x') + "\nf 1 2 3\n"),
                   "line 4: line longer than 1048576 bytes");
    std::string bigFace = kObjTriangle + "f";
    for (int i = 0; i < 40000; ++i) bigFace += " 1";
    expectRejected(write("bigface.obj", bigFace + "\n"), "line 4: face has more than 32768 vertices");
    // OpenMesh removes repeated polygon corners in quadratic time: large polygons are capped in total.
    std::string polygon = "f";
    for (int i = 0; i < 30000; ++i) polygon += " " + std::to_string(i % 3 + 1);
    expectRejected(write("polygons.obj", kObjTriangle + polygon + "\n" + polygon + "\n" + polygon + "\n"),
                   "line 6: too many large polygons");
}

TEST_F(MeshLoading, ObjTypicalCadExportLoads) {
    // CRLF, tabs, comments, objects/groups/smoothing/materials, v/vt/vn corners, negative indices,
    // vertex colours, a forward reference and an underflowing coordinate (reads as 0).
    write("part.mtl", "newmtl steel\r\nKd 0.5 0.5 0.5\r\n");
    const std::string obj = "# exported by a CAD tool\r\n"
                            "mtllib part.mtl\r\n"
                            "mtllib missing.mtl\r\n"
                            "o part\r\n"
                            "v 0 0 0\r\nv 1 0 0 0.5 0.5 0.5\r\nv\t1\t1\t0\r\nv 0 1 1e-50\r\n"
                            "v 0 0 1\r\nv 1 0 1\r\nv 1 1 1\r\nv 0 1 1\r\n"
                            "\r\n"
                            "vt 0 0\r\nvt 1 0\r\nvt 1 1 0\r\nvt 0 1\r\n"
                            "vn 0 0 -1\r\nvn 0 0 1\r\nvn 0 -1 0\r\n"
                            "g bottom top\r\nusemtl steel\r\ns 1\r\n"
                            "f 1/1/1 4/4/1 3/3/1 2/2/1\r\n"
                            "f 5//2 6//2 7//2 8//2   \r\n"
                            "g sides\r\ns off\r\n"
                            "f -8/-4/-1 -7/-3/-1 -3/-2/-1 -4/-1/-1\r\n"
                            "f -5/1 -1/2 -2/3 -6/4\r\n"
                            "f 1 5 8 4\r\n"
                            "f 2 3 7 6\r\n"
                            "# end\r\n";
    const LoadedModel m = loadModel(write("part.obj", obj));
    ASSERT_EQ(m.meshes.size(), 1u);
    EXPECT_EQ(m.meshes[0].triangleCount(), 12u);
    EXPECT_EQ(m.report.inputVertices, 8u);
    Aabb box;
    for (const glm::vec3& p : m.meshes[0].positions) box.add(p);
    EXPECT_EQ(box.lo, glm::vec3(0.f));
    EXPECT_EQ(box.hi, glm::vec3(1.f));

    // Faces may come before the vertices they use (OpenMesh reads every vertex first).
    EXPECT_EQ(loadModel(write("forward.obj", "f 1 2 3\n" + kObjTriangle)).meshes[0].triangleCount(), 1u);
    // LF without a final newline.
    EXPECT_EQ(loadModel(write("last.obj", kObjTriangle + "f 1 2 3")).meshes[0].triangleCount(), 1u);
}

// The limit is the memory a load needs, estimated from the counts, against what the machine has left
// (geometry/io/mesh_limits.h): the same file loads or is refused with one line as the memory allows.
TEST(MeshLimits, TheEstimateAndItsMessage) {
    using namespace geometry::io::detail;
    EXPECT_EQ(loadBytesEstimate(1000, 2000), 1000 * kLoadBytesPerVertex + 2000 * kLoadBytesPerTriangle);
    EXPECT_EQ(loadBytesEstimate(UINT64_MAX, 1), UINT64_MAX); // saturates, never wraps
    EXPECT_EQ(meshMemoryProblem(1000, 2000, 1 << 20), "");
    const std::string tight = meshMemoryProblem(1'000'000, 2'000'000, 100u << 20);
    EXPECT_NE(tight.find("need about 267 MiB to load, but 100 MiB is available"), std::string::npos) << tight;
    EXPECT_NE(meshMemoryProblem(1ull << 32, 1, UINT64_MAX).find("32-bit"), std::string::npos);
    EXPECT_GT(availableMemory(), 0u);
}

TEST_F(MeshLoading, AMeshThatCannotFitTheMemoryLeftIsRefusedBeforeLoading) {
    std::vector<Triangle> tris;
    for (int i = 0; i < 1000; ++i) {
        const float x = float(i);
        tris.push_back(Triangle{glm::vec3(x, 0, 0), glm::vec3(x + 1, 0, 0), glm::vec3(x, 1, 0)});
    }
    const std::string file = write("thousand.stl", binaryStl(tris));
    // 3000 vertices and 1000 triangles: 40 · 3000 + 120 · 1000 = 240 000 bytes.
    ::setenv("SHADOWSCOPE_MEMORY_BYTES", "200000", 1);
    expectRejected(file, "binary STL header claims 3000 vertices and 1000 triangles need about 234 KiB to load, "
                         "but 195 KiB is available");
    ::setenv("SHADOWSCOPE_MEMORY_BYTES", "300000", 1);
    size_t triangles = 0;
    for (const auto& m : loadModel(file).meshes) triangles += m.triangleCount();
    EXPECT_EQ(triangles, 1000u);
    ::unsetenv("SHADOWSCOPE_MEMORY_BYTES");
}
