// glTF loading: hierarchy, materials, modes, buffers, and hostile files. Fixtures are generated
// into a temporary folder (JSON via nlohmann, GLB assembled byte by byte) so every malformed
// variant is a small, visible edit of one valid document.
#include "geometry/io/gltf_loader.h"
#include "geometry/scene/scene.h"
#include "gltf_test_util.h"

#include <draco/compression/encode.h>
#include <draco/core/encoder_buffer.h>
#include <draco/mesh/mesh.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <iterator>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using geometry::io::LoadedModel;
using nlohmann::json;
using namespace gltftest;

/// The unit triangle (0,0,0) (1,0,0) (0,1,0): POSITION accessor 0, UNSIGNED_SHORT indices 1.
Bin triangleBin() {
    Bin bin;
    bin.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
    bin.add(std::vector<uint16_t>{0, 1, 2});
    return bin;
}

json triangleDoc(const Bytes& bin, const std::string& uri) {
    json buffer = {{"byteLength", bin.size()}};
    if (!uri.empty()) buffer["uri"] = uri;
    return {
        {"asset", {{"version", "2.0"}}},
        {"buffers", json::array({buffer})},
        {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                                     {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}})},
        {"accessors", json::array({{{"bufferView", 0}, {"componentType", kFloat}, {"count", 3}, {"type", "VEC3"}},
                                   {{"bufferView", 1}, {"componentType", kUShort}, {"count", 3}, {"type", "SCALAR"}}})},
        {"meshes", json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}})}}})},
        {"nodes", json::array({{{"mesh", 0}}})},
        {"scenes", json::array({{{"nodes", json::array({0})}}})},
        {"scene", 0},
    };
}

/// The triangle document with its buffer embedded as a data URI.
json embeddedTriangle() {
    const Bytes bin = triangleBin().bytes;
    return triangleDoc(bin, dataUri(bin));
}

json primitive(int position, int indices, int mode = 4, int material = -1) {
    json p = {{"attributes", {{"POSITION", position}}}, {"mode", mode}};
    if (indices >= 0) p["indices"] = indices;
    if (material >= 0) p["material"] = material;
    return p;
}

class GltfTest : public gltftest::GltfFileTest {
protected:
    GltfTest() : GltfFileTest("shadowscope_gltf_") {}

    /// Expects loadGltf to throw, fast, a one-line message naming the file; returns it.
    static std::string expectFailure(const std::string& path) {
        const auto start = std::chrono::steady_clock::now();
        const std::string message = loadFailure(path);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_LT(seconds, 10.0) << "a hang guard, not a speed goal: " << message;
        EXPECT_NE(message.find(fs::path(path).filename().string()), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message;
    }
};

bool near(const glm::vec3& a, const glm::vec3& b) { return glm::all(glm::lessThan(glm::abs(a - b), glm::vec3(1e-4f))); }

// ---------------------------------------------------------------------------------------------
// Valid files

TEST_F(GltfTest, EmbeddedDataUriTriangle) {
    const LoadedModel model = geometry::io::loadGltf(writeDoc("triangle.gltf", embeddedTriangle()));
    EXPECT_EQ(model.format, "gltf");
    ASSERT_EQ(model.meshes.size(), 1u);
    const geometry::scene::Mesh& mesh = model.meshes[0];
    EXPECT_EQ(mesh.triangleCount(), 1u);
    EXPECT_EQ(mesh.positions.size(), 3u);
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size()); // computed by cleanMesh
    EXPECT_TRUE(near(mesh.color, glm::vec3(0.8f)));
    EXPECT_TRUE(mesh.twoSided);
    EXPECT_FALSE(mesh.chunks.empty());
    EXPECT_EQ(model.report.inputFaces, 1u);
    EXPECT_EQ(model.report.outputFaces, 1u);
}

TEST_F(GltfTest, ChildTransformComposesWithParents) {
    json doc = embeddedTriangle();
    const double s = std::sqrt(0.5);
    doc["nodes"] = json::array({
        // matrix form, column-major: translate z by 5
        {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}, {"children", {1}}},
        {{"translation", {10, 0, 0}}, {"children", {2}}},
        // 90° about +z, then uniform scale 2 (T * R * S inside the node)
        {{"rotation", {0, 0, s, s}}, {"scale", {2, 2, 2}}, {"mesh", 0}},
        {{"mesh", 0}}, // a second root, untransformed
    });
    doc["scenes"] = json::array({{{"nodes", {0, 3}}}});
    const LoadedModel model = geometry::io::loadGltf(writeDoc("hierarchy.gltf", doc));
    // Two nodes use mesh 0: one mesh, held once, placed twice (instancing).
    ASSERT_EQ(model.meshes.size(), 1u);
    const geometry::scene::Mesh& mesh = model.meshes[0];
    ASSERT_EQ(mesh.instances.size(), 2u);
    EXPECT_EQ(mesh.placedTriangleCount(), 2u);
    // (0,0) (1,0) (0,1) → ×2 → rotated to (0,0) (0,2) (−2,0) → +(10,0,5)
    const geometry::scene::Aabb child = mesh.placementBounds(0);
    EXPECT_TRUE(near(child.lo, {8, 0, 5})) << child.lo.x << " " << child.lo.y << " " << child.lo.z;
    EXPECT_TRUE(near(child.hi, {10, 2, 5})) << child.hi.x << " " << child.hi.y << " " << child.hi.z;
    const geometry::scene::Aabb root = mesh.placementBounds(1);
    EXPECT_TRUE(near(root.lo, {0, 0, 0}));
    EXPECT_TRUE(near(root.hi, {1, 1, 0}));
    EXPECT_EQ(model.report.outputFaces, 1u); // the faces held, counted once
}

TEST_F(GltfTest, WithoutDefaultSceneAllRootsLoad) {
    json doc = embeddedTriangle();
    doc.erase("scene");
    doc.erase("scenes");
    doc["nodes"] = json::array({{{"children", {1}}, {"translation", {0, 3, 0}}}, {{"mesh", 0}}, {{"mesh", 0}}});
    const LoadedModel model = geometry::io::loadGltf(writeDoc("noscene.gltf", doc));
    ASSERT_EQ(model.meshes.size(), 1u);
    ASSERT_EQ(model.meshes[0].instances.size(), 2u);
    EXPECT_TRUE(near(model.meshes[0].placementBounds(0).lo, {0, 3, 0}));
    EXPECT_TRUE(near(model.meshes[0].placementBounds(1).lo, {0, 0, 0}));
}

TEST_F(GltfTest, BaseColourPerPrimitive) {
    json doc = embeddedTriangle();
    doc["materials"] = json::array({
        {{"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}},
        {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0.5, 1, 1}}}}, {"doubleSided", true}},
    });
    doc["meshes"][0]["primitives"] = json::array({primitive(0, 1, 4, 0), primitive(0, 1, 4, 1), primitive(0, 1)});
    const LoadedModel model = geometry::io::loadGltf(writeDoc("colours.gltf", doc));
    ASSERT_EQ(model.meshes.size(), 3u);
    EXPECT_TRUE(near(model.meshes[0].color, {1, 0, 0}));
    EXPECT_TRUE(near(model.meshes[1].color, {0, 0.5f, 1}));
    EXPECT_TRUE(near(model.meshes[2].color, glm::vec3(0.8f)));
    for (const auto& mesh : model.meshes) EXPECT_TRUE(mesh.twoSided);
}

TEST_F(GltfTest, LinesPrimitiveSkippedWithNote) {
    json doc = embeddedTriangle();
    doc["meshes"][0]["primitives"] = json::array({primitive(0, 1), primitive(0, -1, 1)});
    const LoadedModel model = geometry::io::loadGltf(writeDoc("lines.gltf", doc));
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_TRUE(hasNote(model, "mesh 0 primitive 1: mode LINES skipped"));
}

TEST_F(GltfTest, StripAndFanAreUnrolled) {
    Bin bin;
    bin.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
    json doc = triangleDoc(bin.bytes, dataUri(bin.bytes));
    doc["bufferViews"] = json::array({{{"buffer", 0}, {"byteLength", 48}}});
    doc["accessors"] = json::array({{{"bufferView", 0}, {"componentType", kFloat}, {"count", 4}, {"type", "VEC3"}}});
    doc["meshes"][0]["primitives"] = json::array({primitive(0, -1, 5), primitive(0, -1, 6)});
    const LoadedModel model = geometry::io::loadGltf(writeDoc("strip.gltf", doc));
    ASSERT_EQ(model.meshes.size(), 2u);
    EXPECT_EQ(model.meshes[0].triangleCount(), 2u);
    EXPECT_EQ(model.meshes[1].triangleCount(), 2u);
}

TEST_F(GltfTest, ExternalBinBuffer) {
    const Bytes bin = triangleBin().bytes;
    writeBytes("triangle.bin", bin);
    const LoadedModel model = geometry::io::loadGltf(writeDoc("external.gltf", triangleDoc(bin, "triangle.bin")));
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.meshes[0].triangleCount(), 1u);
}

TEST_F(GltfTest, GlbWithBinChunk) {
    const Bytes bin = triangleBin().bytes;
    const LoadedModel model =
        geometry::io::loadGltf(writeBytes("triangle.glb", makeGlb(triangleDoc(bin, "").dump(), bin)));
    EXPECT_EQ(model.format, "glb");
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.meshes[0].triangleCount(), 1u);
}

TEST_F(GltfTest, GlbBinChunkReadInPlaceGivesWhatTinygltfsCopyGives) {
    // The loader reads a GLB's BIN chunk where it lies in the file, telling tinygltf that buffer 0
    // holds 4 bytes, through a JSON rewritten in place of the file's own (compact: it fits; pretty:
    // it fits with room to spare). Where the rewrite would not fit (numbers written shorter than
    // the rewrite writes them), tinygltf copies the chunk as before. All three load alike, and the
    // file itself is never written. Two primitives: the second is read after the first's cleanup
    // dropped the chunk's pages from memory.
    Bin bin;
    bin.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.5f, 2, 0, 0});
    bin.add(std::vector<uint16_t>{0, 1, 2, 1, 3, 2, 1, 4, 3});
    json doc = triangleDoc(bin.bytes, "");
    doc["bufferViews"] = json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 60}},
                                      {{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 18}}});
    doc["accessors"][0]["count"] = 5;
    doc["accessors"][1]["count"] = 9;
    doc["meshes"][0]["primitives"].push_back(doc["meshes"][0]["primitives"][0]);
    std::string longer = doc.dump();
    longer.insert(longer.size() - 1, ",\"extras\":[1E5,2E5,3E5,4E5,5E5,6E5,7E5,8E5]"); // 100000.0 when rewritten
    std::vector<geometry::scene::Mesh> meshes;
    for (const std::string& text : {doc.dump(), doc.dump(4), longer}) {
        const Bytes glb = makeGlb(text, bin.bytes);
        const std::string path = writeBytes("in_place" + std::to_string(meshes.size()) + ".glb", glb);
        const LoadedModel model = geometry::io::loadGltf(path);
        ASSERT_EQ(model.meshes.size(), 2u);
        EXPECT_EQ(model.meshes[1].positions, model.meshes[0].positions);
        EXPECT_EQ(model.meshes[1].indices, model.meshes[0].indices);
        meshes.push_back(model.meshes[0]);
        std::ifstream in(path, std::ios::binary);
        EXPECT_EQ(Bytes(std::istreambuf_iterator<char>(in), {}), glb) << "the file was written";
    }
    EXPECT_EQ(meshes[0].triangleCount(), 3u);
    geometry::scene::Aabb box;
    for (const glm::vec3& p : meshes[0].positions) box.add(p);
    EXPECT_TRUE(near(box.lo, {0, 0, 0}));
    EXPECT_TRUE(near(box.hi, {2, 1, 0.5f}));
    for (size_t i = 1; i < meshes.size(); ++i) {
        EXPECT_EQ(meshes[i].positions, meshes[0].positions) << i;
        EXPECT_EQ(meshes[i].normals, meshes[0].normals) << i;
        EXPECT_EQ(meshes[i].indices, meshes[0].indices) << i;
    }
}

TEST_F(GltfTest, GlbBufferLongerThanItsBinChunkRefused) {
    const Bytes bin = triangleBin().bytes; // 42 bytes, padded to 44 in the chunk
    json doc = triangleDoc(bin, "");
    doc["buffers"][0]["byteLength"] = 48;
    const std::string message = expectFailure(writeBytes("long_buffer.glb", makeGlb(doc.dump(), bin)));
    EXPECT_NE(message.find("byteLength"), std::string::npos) << message;
}

TEST_F(GltfTest, PrimitivesReadTheVerticesTheyUseDenselyOrSparsely) {
    // One accessor of 64 grid points shared by a primitive that uses all of them (numbered by a table
    // over the accessor) and one that uses three (numbered by sorting): both read exactly their
    // triangles' corners.
    std::vector<float> grid;
    for (int k = 0; k < 64; ++k) grid.insert(grid.end(), {float(k % 8), float(k / 8), 0.f});
    std::vector<uint32_t> dense;
    for (uint32_t j = 0; j < 7; ++j)
        for (uint32_t i = 0; i < 7; ++i) {
            const uint32_t a = 8 * j + i;
            dense.insert(dense.end(), {a, a + 1, a + 9, a, a + 9, a + 8});
        }
    const std::vector<uint32_t> sparse = {50, 7, 33};
    Bin bin;
    const size_t gridAt = bin.add(grid), denseAt = bin.add(dense), sparseAt = bin.add(sparse);
    json doc = triangleDoc(bin.bytes, "");
    doc["bufferViews"] = json::array({{{"buffer", 0}, {"byteOffset", gridAt}, {"byteLength", grid.size() * 4}},
                                      {{"buffer", 0}, {"byteOffset", denseAt}, {"byteLength", dense.size() * 4}},
                                      {{"buffer", 0}, {"byteOffset", sparseAt}, {"byteLength", sparse.size() * 4}}});
    doc["accessors"] =
        json::array({{{"bufferView", 0}, {"componentType", kFloat}, {"count", 64}, {"type", "VEC3"}},
                     {{"bufferView", 1}, {"componentType", kUInt}, {"count", dense.size()}, {"type", "SCALAR"}},
                     {{"bufferView", 2}, {"componentType", kUInt}, {"count", sparse.size()}, {"type", "SCALAR"}}});
    doc["meshes"][0]["primitives"] = json::array({primitive(0, 1), primitive(0, 2)});
    const LoadedModel model = geometry::io::loadGltf(writeBytes("shared.glb", makeGlb(doc.dump(), bin.bytes)));
    ASSERT_EQ(model.meshes.size(), 2u);
    const auto corners = [](const geometry::scene::Mesh& m) {
        std::multiset<std::array<float, 3>> out;
        for (const uint32_t i : m.indices) out.insert({m.positions[i].x, m.positions[i].y, m.positions[i].z});
        return out;
    };
    const auto expected = [&](const std::vector<uint32_t>& indices) {
        std::multiset<std::array<float, 3>> out;
        for (const uint32_t i : indices) out.insert({grid[3 * i], grid[3 * i + 1], grid[3 * i + 2]});
        return out;
    };
    EXPECT_EQ(corners(model.meshes[0]), expected(dense));
    EXPECT_EQ(corners(model.meshes[1]), expected(sparse));
}

TEST_F(GltfTest, NonFinitePositionsAreCleanedNotFatal) {
    Bin bin;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    bin.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, nan, 0, 0});
    bin.add(std::vector<uint8_t>{0, 1, 2, 0, 1, 3});
    json doc = triangleDoc(bin.bytes, dataUri(bin.bytes));
    doc["bufferViews"] =
        json::array({{{"buffer", 0}, {"byteLength", 48}}, {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 6}}});
    doc["accessors"][0]["count"] = 4;
    doc["accessors"][1] = {{"bufferView", 1}, {"componentType", kUByte}, {"count", 6}, {"type", "SCALAR"}};
    const LoadedModel model = geometry::io::loadGltf(writeDoc("nan.gltf", doc));
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.meshes[0].triangleCount(), 1u);
    EXPECT_EQ(model.report.nonFiniteVertices, 1u);
}

TEST_F(GltfTest, ProgressStartsWithReadingThenReportsPrimitives) {
    json doc = embeddedTriangle();
    doc["meshes"][0]["primitives"] = json::array({primitive(0, 1), primitive(0, 1)});
    std::vector<std::string> stages;
    (void)geometry::io::loadGltf(writeDoc("progress.gltf", doc), {}, [&](float fraction, std::string_view stage) {
        EXPECT_GE(fraction, 0.f);
        EXPECT_LE(fraction, 1.f);
        stages.emplace_back(stage);
    });
    ASSERT_FALSE(stages.empty());
    EXPECT_EQ(stages.front(), "reading");
    EXPECT_EQ(std::count(stages.begin(), stages.end(), "cleaning"), 2);
}

// ---------------------------------------------------------------------------------------------
// Hostile files: each a one-line "PATH: problem", fast

TEST_F(GltfTest, MissingFile) {
    EXPECT_NE(expectFailure((dir / "absent.gltf").string()).find("not found"), std::string::npos);
}

TEST_F(GltfTest, NotJsonAtAll) {
    expectFailure(writeText("garbage.gltf", "solid cube\nfacet normal 0 0 1\n"));
    expectFailure(writeText("broken.gltf", "{ \"asset\": { \"version\": \"2.0\" }, \"nodes\": [ {"));
    expectFailure(writeText("empty.glb", ""));
}

TEST_F(GltfTest, TruncatedGlb) {
    const Bytes bin = triangleBin().bytes;
    const Bytes glb = makeGlb(triangleDoc(bin, "").dump(), bin);
    for (size_t keep : {size_t(10), size_t(24), glb.size() / 2, glb.size() - 4})
        expectFailure(
            writeBytes("truncated" + std::to_string(keep) + ".glb", Bytes(glb.begin(), glb.begin() + long(keep))));
}

TEST_F(GltfTest, NodeCycle) {
    json doc = embeddedTriangle();
    doc["nodes"] = json::array({{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}});
    EXPECT_NE(expectFailure(writeDoc("cycle.gltf", doc)).find("cycle"), std::string::npos);
    doc["nodes"][0]["children"] = {0}; // its own child
    expectFailure(writeDoc("selfchild.gltf", doc));
    doc.erase("scene"); // no default scene: every node has a parent
    doc["nodes"] = json::array({{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}});
    EXPECT_NE(expectFailure(writeDoc("rootless.gltf", doc)).find("cycle"), std::string::npos);
}

TEST_F(GltfTest, DeepAndExponentialHierarchies) {
    json doc = embeddedTriangle();
    json chain = json::array();
    for (int i = 0; i < 100; ++i) chain.push_back({{"children", {i + 1}}});
    chain.push_back({{"mesh", 0}});
    doc["nodes"] = chain;
    expectFailure(writeDoc("deep.gltf", doc));

    // No cycle, but every node lists its successor twice: 2^40 instances.
    json dag = json::array();
    for (int i = 0; i < 40; ++i) dag.push_back({{"children", {i + 1, i + 1}}});
    dag.push_back({{"mesh", 0}});
    doc["nodes"] = dag;
    expectFailure(writeDoc("exponential.gltf", doc));
}

TEST_F(GltfTest, MissingMeshAndNode) {
    json doc = embeddedTriangle();
    doc["nodes"][0]["mesh"] = 5;
    EXPECT_NE(expectFailure(writeDoc("nomesh.gltf", doc)).find("mesh 5"), std::string::npos);
    doc = embeddedTriangle();
    doc["nodes"][0]["children"] = {7};
    expectFailure(writeDoc("nochild.gltf", doc));
}

TEST_F(GltfTest, MissingBinBuffer) {
    const Bytes bin = triangleBin().bytes;
    expectFailure(writeDoc("missingbin.gltf", triangleDoc(bin, "absent.bin")));
    fs::create_directories(dir / "folder.bin");
    expectFailure(writeDoc("dirbin.gltf", triangleDoc(bin, "folder.bin")));
}

TEST_F(GltfTest, AccessorOutOfRange) {
    json doc = embeddedTriangle();
    doc["accessors"][0]["count"] = 4; // 48 bytes in a 36-byte view
    EXPECT_NE(expectFailure(writeDoc("count.gltf", doc)).find("accessor 0"), std::string::npos);
    doc = embeddedTriangle();
    doc["accessors"][0]["byteOffset"] = 4;
    expectFailure(writeDoc("offset.gltf", doc));
    doc = embeddedTriangle();
    doc["bufferViews"][0]["byteLength"] = 1000; // view past the buffer
    expectFailure(writeDoc("view.gltf", doc));
    doc = embeddedTriangle();
    doc["accessors"][0]["bufferView"] = 9;
    expectFailure(writeDoc("noview.gltf", doc));
}

TEST_F(GltfTest, AbsurdCountClaim) {
    json doc = embeddedTriangle();
    doc["accessors"][0]["count"] = 1000000000000ull;
    expectFailure(writeDoc("huge.gltf", doc));
    doc = embeddedTriangle();
    doc["accessors"][1]["count"] = 1000000000000ull;
    expectFailure(writeDoc("hugeindices.gltf", doc));
}

TEST_F(GltfTest, IndexOutOfRange) {
    Bin bin = triangleBin();
    bin.bytes[36 + 4] = 7; // third index: 7 with 3 vertices
    const std::string message = expectFailure(writeDoc("index.gltf", triangleDoc(bin.bytes, dataUri(bin.bytes))));
    EXPECT_NE(message.find("index 7"), std::string::npos) << message;
}

// A grid of 400 × 400 vertices and 955 k indices: read on every core (the decode's passes split at
// 65 536 elements). It loads whole; with two indices out of range, in different halves, the message
// names the first, as one thread reading front to back would.
TEST_F(GltfTest, LargeAccessorsReadOnEveryCoreAsInOrder) {
    constexpr uint32_t kSide = 400;
    std::vector<float> positions;
    for (uint32_t y = 0; y < kSide; ++y)
        for (uint32_t x = 0; x < kSide; ++x) positions.insert(positions.end(), {float(x), 0.f, float(y)});
    std::vector<uint32_t> indices;
    for (uint32_t y = 0; y + 1 < kSide; ++y)
        for (uint32_t x = 0; x + 1 < kSide; ++x) {
            const uint32_t a = y * kSide + x, b = a + 1, c = a + kSide, d = c + 1;
            indices.insert(indices.end(), {a, c, b, b, c, d});
        }
    const auto glb = [&](const std::vector<uint32_t>& idx) {
        Bin bin;
        bin.add(positions);
        bin.add(idx);
        json doc = triangleDoc(bin.bytes, "");
        doc["bufferViews"][0]["byteLength"] = positions.size() * 4;
        doc["bufferViews"][1]["byteOffset"] = positions.size() * 4;
        doc["bufferViews"][1]["byteLength"] = idx.size() * 4;
        doc["accessors"][0]["count"] = kSide * kSide;
        doc["accessors"][1]["count"] = idx.size();
        doc["accessors"][1]["componentType"] = kUInt;
        return makeGlb(doc.dump(), bin.bytes);
    };
    const LoadedModel model = geometry::io::loadGltf(writeBytes("grid.glb", glb(indices)));
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.meshes[0].triangleCount(), 2u * (kSide - 1) * (kSide - 1));
    EXPECT_EQ(model.meshes[0].positions.size(), size_t(kSide) * kSide);
    std::vector<uint32_t> bad = indices;
    bad[100000] = 7777777;
    bad[900000] = 9999999;
    const std::string message = expectFailure(writeBytes("badgrid.glb", glb(bad)));
    EXPECT_NE(message.find("index 7777777 out of range (160000 vertices)"), std::string::npos) << message;
}

TEST_F(GltfTest, WrongAccessorTypes) {
    json doc = embeddedTriangle();
    doc["accessors"][0]["componentType"] = kUInt; // not a KHR_mesh_quantization type
    EXPECT_NE(expectFailure(writeDoc("uintpos.gltf", doc)).find("POSITION"), std::string::npos);
    doc = embeddedTriangle();
    doc["accessors"][0]["type"] = "VEC2";
    expectFailure(writeDoc("vec2pos.gltf", doc));
    doc = embeddedTriangle();
    doc["accessors"][1]["componentType"] = kFloat;
    doc["accessors"][1]["count"] = 1;
    expectFailure(writeDoc("floatindex.gltf", doc));
}

TEST_F(GltfTest, SharedAccessorAmplificationRefused) {
    // 120 KB of vertices referenced by 400 primitives: each accessor fits, the sum would not.
    Bin bin;
    bin.add(std::vector<float>(30000, 0.f));
    json doc = triangleDoc(bin.bytes, "");
    doc["bufferViews"] = json::array({{{"buffer", 0}, {"byteLength", bin.bytes.size()}}});
    doc["accessors"] =
        json::array({{{"bufferView", 0}, {"componentType", kFloat}, {"count", 10000}, {"type", "VEC3"}}});
    doc["meshes"][0]["primitives"] = json::array();
    for (int i = 0; i < 400; ++i) doc["meshes"][0]["primitives"].push_back(primitive(0, -1));
    const std::string message = expectFailure(writeBytes("amplified.glb", makeGlb(doc.dump(), bin.bytes)));
    EXPECT_NE(message.find("MiB"), std::string::npos) << message;
}

TEST_F(GltfTest, DeeplyNestedJsonRefused) {
    json doc = embeddedTriangle();
    const std::string text = doc.dump();
    const std::string nested = std::string(100000, '[') + std::string(100000, ']');
    expectFailure(writeText("nested.gltf", text.substr(0, text.size() - 1) + ",\"extras\":" + nested + "}"));
}

TEST_F(GltfTest, NoTriangles) {
    json doc = embeddedTriangle();
    doc["meshes"][0]["primitives"] = json::array({primitive(0, -1, 1), primitive(0, -1, 0)});
    EXPECT_NE(expectFailure(writeDoc("linesonly.gltf", doc)).find("no triangles"), std::string::npos);
    doc = embeddedTriangle();
    doc["nodes"] = json::array({json::object()});
    expectFailure(writeDoc("nomeshes.gltf", doc));
}

// ---------------------------------------------------------------------------------------------
// Draco, unsupported versions and extensions

/// A 10x10 grid of quads over [0,2]x[-1,1], bent in z so no box axis is degenerate.
struct Grid {
    std::vector<float> positions; // xyz per vertex
    std::vector<uint16_t> indices;
};

Grid makeGrid() {
    Grid g;
    constexpr int n = 10;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float x = 2.f * float(i) / n, y = -1.f + 2.f * float(j) / n;
            g.positions.insert(g.positions.end(), {x, y, 0.25f * x * y});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const auto v = uint16_t(j * (n + 1) + i);
            g.indices.insert(g.indices.end(), {v, uint16_t(v + 1), uint16_t(v + n + 1)});
            g.indices.insert(g.indices.end(), {uint16_t(v + 1), uint16_t(v + n + 2), uint16_t(v + n + 1)});
        }
    return g;
}

/// The grid compressed with the Draco library itself (no fixture files): returns the encoded
/// bytes and the POSITION attribute's unique id, which the glTF extension refers to.
std::pair<Bytes, int> dracoEncode(const Grid& g) {
    draco::Mesh mesh;
    const auto points = uint32_t(g.positions.size() / 3);
    mesh.set_num_points(points);
    draco::GeometryAttribute position;
    position.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false, 3 * sizeof(float), 0);
    const int att = mesh.AddAttribute(position, true, points);
    for (uint32_t i = 0; i < points; ++i)
        mesh.attribute(att)->SetAttributeValue(draco::AttributeValueIndex(i), &g.positions[3 * i]);
    for (size_t f = 0; f < g.indices.size(); f += 3)
        mesh.AddFace({draco::PointIndex(g.indices[f]), draco::PointIndex(g.indices[f + 1]),
                      draco::PointIndex(g.indices[f + 2])});
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
    draco::EncoderBuffer buffer;
    const draco::Status status = encoder.EncodeMeshToBuffer(mesh, &buffer);
    EXPECT_TRUE(status.ok()) << status.error_msg_string();
    const auto* data = reinterpret_cast<const unsigned char*>(buffer.data());
    return {Bytes(data, data + buffer.size()), int(mesh.attribute(att)->unique_id())};
}

/// The grid uncompressed: POSITION accessor 0, UNSIGNED_SHORT indices accessor 1.
json gridDoc(const Grid& g) {
    Bin bin;
    bin.add(g.positions);
    const size_t indexOffset = bin.add(g.indices);
    json doc = triangleDoc(bin.bytes, dataUri(bin.bytes));
    doc["bufferViews"][0]["byteLength"] = g.positions.size() * sizeof(float);
    doc["bufferViews"][1] = {{"buffer", 0}, {"byteOffset", indexOffset}, {"byteLength", g.indices.size() * 2}};
    doc["accessors"][0]["count"] = g.positions.size() / 3;
    doc["accessors"][1]["count"] = g.indices.size();
    return doc;
}

/// The same grid as KHR_draco_mesh_compression (required): the accessors have no bufferView,
/// the extension points at the compressed bytes. `uri` empty: the GLB's BIN chunk.
json dracoGridDoc(const Grid& g, const Bytes& encoded, int positionId, const std::string& uri) {
    json buffer = {{"byteLength", encoded.size()}};
    if (!uri.empty()) buffer["uri"] = uri;
    json prim = {{"attributes", {{"POSITION", 0}}},
                 {"indices", 1},
                 {"mode", 4},
                 {"extensions",
                  {{"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", positionId}}}}}}}};
    return {
        {"asset", {{"version", "2.0"}}},
        {"extensionsUsed", {"KHR_draco_mesh_compression"}},
        {"extensionsRequired", {"KHR_draco_mesh_compression"}},
        {"buffers", json::array({buffer})},
        {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", encoded.size()}}})},
        {"accessors", json::array({{{"componentType", kFloat}, {"count", g.positions.size() / 3}, {"type", "VEC3"}},
                                   {{"componentType", kUShort}, {"count", g.indices.size()}, {"type", "SCALAR"}}})},
        {"meshes", json::array({{{"primitives", json::array({prim})}}})},
        {"nodes", json::array({{{"mesh", 0}}})},
        {"scenes", json::array({{{"nodes", json::array({0})}}})},
        {"scene", 0},
    };
}

geometry::scene::Aabb worldBounds(const LoadedModel& model) {
    geometry::scene::Aabb box;
    for (const auto& mesh : model.meshes) box.add(mesh.worldBounds());
    return box;
}

size_t triangles(const LoadedModel& model) {
    size_t n = 0;
    for (const auto& mesh : model.meshes) n += mesh.triangleCount();
    return n;
}

TEST_F(GltfTest, DracoCompressedMatchesUncompressedTwin) {
    const Grid grid = makeGrid();
    const auto [encoded, positionId] = dracoEncode(grid);
    ASSERT_FALSE(encoded.empty());
    const LoadedModel twin = geometry::io::loadGltf(writeDoc("twin.gltf", gridDoc(grid)));
    ASSERT_EQ(triangles(twin), 200u);
    const geometry::scene::Aabb expected = worldBounds(twin);

    const json embedded = dracoGridDoc(grid, encoded, positionId, dataUri(encoded));
    const json binary = dracoGridDoc(grid, encoded, positionId, "");
    for (const std::string& path :
         {writeDoc("draco.gltf", embedded), writeBytes("draco.glb", makeGlb(binary.dump(), encoded))}) {
        SCOPED_TRACE(path);
        const LoadedModel model = geometry::io::loadGltf(path);
        EXPECT_EQ(triangles(model), triangles(twin));
        const geometry::scene::Aabb box = worldBounds(model);
        // 14-bit quantization over a 2-unit range: steps of about 1.2e-4.
        EXPECT_TRUE(glm::all(glm::lessThan(glm::abs(box.lo - expected.lo), glm::vec3(1e-3f))));
        EXPECT_TRUE(glm::all(glm::lessThan(glm::abs(box.hi - expected.hi), glm::vec3(1e-3f))));
    }
}

TEST_F(GltfTest, DracoReferencesAreCheckedBeforeDecoding) {
    const Grid grid = makeGrid();
    const auto [encoded, positionId] = dracoEncode(grid);
    const json valid = dracoGridDoc(grid, encoded, positionId, dataUri(encoded));
    const auto ext = [](json& doc) -> json& {
        return doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"];
    };
    json doc = valid;
    ext(doc)["bufferView"] = 7;
    EXPECT_NE(expectFailure(writeDoc("view.gltf", doc)).find("KHR_draco_mesh_compression"), std::string::npos);
    doc = valid;
    doc["bufferViews"][0]["byteLength"] = encoded.size() + 1;
    expectFailure(writeDoc("length.gltf", doc));
    doc = valid;
    doc["meshes"][0]["primitives"][0]["indices"] = 9;
    expectFailure(writeDoc("indices.gltf", doc));
    doc = valid;
    doc["accessors"][1]["componentType"] = 1;
    expectFailure(writeDoc("indextype.gltf", doc));
    doc = valid;
    ext(doc)["attributes"]["NORMAL"] = 1;
    expectFailure(writeDoc("attribute.gltf", doc));
    doc = valid;
    doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 5;
    expectFailure(writeDoc("accessor.gltf", doc));
    // Checked by decoding: tinygltf would dereference a missing attribute.
    doc = valid;
    ext(doc)["attributes"]["POSITION"] = positionId + 7;
    EXPECT_NE(expectFailure(writeDoc("uid.gltf", doc)).find("names no Draco attribute"), std::string::npos);
    Bytes corrupt = encoded;
    std::fill(corrupt.begin() + std::ptrdiff_t(corrupt.size() / 4), corrupt.end(), 0xFF);
    expectFailure(writeDoc("corrupt.gltf", dracoGridDoc(grid, corrupt, positionId, dataUri(corrupt))));
}

TEST_F(GltfTest, DracoStreamSharedByPrimitivesDecodesOnce) {
    const Grid grid = makeGrid();
    const auto [encoded, positionId] = dracoEncode(grid);
    json doc = dracoGridDoc(grid, encoded, positionId, dataUri(encoded));
    json& prims = doc["meshes"][0]["primitives"];
    for (int i = 0; i < 200; ++i) prims.push_back(prims[0]);
    EXPECT_EQ(triangles(geometry::io::loadGltf(writeDoc("shared.gltf", doc))), 201u * 200u);
}

TEST_F(GltfTest, DracoInExternalBin) {
    const Grid grid = makeGrid();
    const auto [encoded, positionId] = dracoEncode(grid);
    writeBytes("grid draco.bin", encoded);
    const LoadedModel model =
        geometry::io::loadGltf(writeDoc("external.gltf", dracoGridDoc(grid, encoded, positionId, "grid%20draco.bin")));
    EXPECT_EQ(triangles(model), 200u);
}

/// Expects exactly `PATH: problem`, one line.
void expectMessage(const std::string& path, const std::string& problem) {
    try {
        (void)geometry::io::loadGltf(path);
        ADD_FAILURE() << path << " loaded without error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), path + ": " + problem);
    }
}

TEST_F(GltfTest, Gltf1IsRefusedByName) {
    json doc = embeddedTriangle();
    doc["asset"]["version"] = "1.0";
    expectMessage(writeDoc("v1.gltf", doc), "glTF 1.0 is not supported (convert to glTF 2.0)");
    // The 1.0 layout: top-level collections are objects keyed by id, and no asset.version.
    doc = embeddedTriangle();
    doc.erase("asset");
    doc["meshes"] = {{"mesh_0", doc["meshes"][0]}};
    expectMessage(writeDoc("v1layout.gltf", doc), "glTF 1.0 is not supported (convert to glTF 2.0)");
    expectMessage(writeBytes("v1.glb", makeGlb(doc.dump(), {})), "glTF 1.0 is not supported (convert to glTF 2.0)");
    // A KHR_binary_glTF container (GLB version 1), whatever its JSON says.
    Bytes glb1 = makeGlb(embeddedTriangle().dump(), {});
    glb1[4] = 1;
    expectMessage(writeBytes("binary1.glb", glb1), "glTF 1.0 is not supported (convert to glTF 2.0)");
}

TEST_F(GltfTest, UnsupportedRequiredExtensionIsNamed) {
    json doc = embeddedTriangle();
    doc["extensionsUsed"] = {"KHR_materials_unlit", "EXT_mesh_gpu_instancing"};
    doc["extensionsRequired"] = {"KHR_materials_unlit", "EXT_mesh_gpu_instancing"};
    expectMessage(writeDoc("instancing.gltf", doc), "requires the unsupported glTF extension EXT_mesh_gpu_instancing");
    doc["extensionsRequired"] = {"KHR_mesh_quantization", "EXT_meshopt_compression", "MSFT_lod"};
    expectMessage(writeDoc("lod.gltf", doc), "requires the unsupported glTF extension MSFT_lod");
    // Only used, not required: loads (a viewer may ignore it).
    doc.erase("extensionsRequired");
    EXPECT_EQ(triangles(geometry::io::loadGltf(writeDoc("used.gltf", doc))), 1u);
}

TEST_F(GltfTest, NoTrianglesAtAllIsOneClearLine) {
    json doc = embeddedTriangle();
    doc["meshes"][0]["primitives"] = json::array({primitive(0, -1, 0)}); // points only
    expectMessage(writeDoc("points.gltf", doc), "the file has no triangles");
    doc["meshes"][0]["primitives"] = json::array({primitive(0, -1, 1), primitive(0, -1, 3)}); // lines
    expectMessage(writeBytes("lines.glb", makeGlb(doc.dump(), {})), "the file has no triangles");
    doc = embeddedTriangle();
    doc.erase("meshes");
    doc["nodes"] = json::array({json::object()});
    expectMessage(writeDoc("nomeshes.gltf", doc), "the file has no triangles");
}

// ---------------------------------------------------------------------------------------------
// Bounds

/// A rotated, translated child under a rotated parent, holding a mesh whose local box is far from
/// its rotated box; the expected box is computed from the transformed vertices themselves.
class RotatedHierarchy : public GltfTest {
protected:
    void SetUp() override {
        GltfTest::SetUp();
        grid_ = makeGrid();
        json doc = gridDoc(grid_);
        const float half = glm::radians(45.f) / 2.f, parentHalf = glm::radians(30.f) / 2.f;
        doc["nodes"] = json::array({
            {{"rotation", {std::sin(parentHalf), 0, 0, std::cos(parentHalf)}}, {"children", {1}}}, // 30° about x
            {{"rotation", {0, 0, std::sin(half), std::cos(half)}}, {"translation", {3, -2, 1}}, {"mesh", 0}},
        });
        model_ = geometry::io::loadGltf(writeDoc("rotated.gltf", doc));
        const glm::mat4 parent = glm::mat4_cast(glm::angleAxis(glm::radians(30.f), glm::vec3(1, 0, 0)));
        const glm::mat4 child = glm::translate(glm::mat4(1.f), glm::vec3(3, -2, 1)) *
                                glm::mat4_cast(glm::angleAxis(glm::radians(45.f), glm::vec3(0, 0, 1)));
        for (size_t i = 0; i < grid_.positions.size(); i += 3)
            expected_.add(glm::vec3(parent * child *
                                    glm::vec4(grid_.positions[i], grid_.positions[i + 1], grid_.positions[i + 2], 1)));
    }

    static void expectBox(const geometry::scene::Aabb& box, const geometry::scene::Aabb& expected) {
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(box.lo[a], expected.lo[a], 1e-5) << "axis " << a;
            EXPECT_NEAR(box.hi[a], expected.hi[a], 1e-5) << "axis " << a;
        }
    }

    Grid grid_;
    LoadedModel model_;
    geometry::scene::Aabb expected_;
};

TEST_F(RotatedHierarchy, MeshWorldBoundsAreTheBoxOfTransformedVertices) {
    ASSERT_EQ(triangles(model_), 200u);
    expectBox(worldBounds(model_), expected_);
}

TEST_F(RotatedHierarchy, SceneBoundsAreTheBoxOfTransformedVertices) {
    geometry::scene::Scene scene;
    scene.meshes = model_.meshes;
    expectBox(scene.bounds(), expected_);
}

} // namespace
