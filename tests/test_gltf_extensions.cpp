// glTF data that tinygltf hands over raw: sparse accessors, KHR_mesh_quantization,
// EXT_meshopt_compression; and the choice of scene and tinygltf's reasons for refusing a file.
// One plain indexed part is written in several encodings, each of which must load to the same
// triangles and bounds; the hostile variants are small edits of a valid twin.
#include "geometry/io/gltf_loader.h"
#include "gltf_test_util.h"

#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace {

using geometry::io::LoadedModel;
using nlohmann::json;
using namespace gltftest;

// ---------------------------------------------------------------------------------------------
// The part

/// A bent 7 x 6 grid (42 vertices, 60 triangles) on an integer lattice in [0, 255]^3, placed at
/// kOffset + kStep * lattice: every quantized twin then holds the plain twin's coordinates exactly.
constexpr int kColumns = 7, kRows = 6, kVertices = kColumns * kRows, kIndices = (kColumns - 1) * (kRows - 1) * 6;
constexpr std::array<double, 3> kOffset{-3.25, 1.5, 0.75};
constexpr double kStep = 0.0173;

struct Part {
    std::vector<std::array<int, 3>> lattice;
    std::vector<uint16_t> indices;

    [[nodiscard]] std::vector<float> positions() const {
        std::vector<float> out;
        for (const auto& p : lattice)
            for (int k = 0; k < 3; ++k) out.push_back(float(kOffset[size_t(k)] + kStep * p[size_t(k)]));
        return out;
    }
    [[nodiscard]] std::vector<uint32_t> indices32() const { return {indices.begin(), indices.end()}; }
};

Part makePart() {
    Part part;
    for (int j = 0; j < kRows; ++j)
        for (int i = 0; i < kColumns; ++i) {
            const int u = 10 + 37 * i, v = 5 + 45 * j;
            part.lattice.push_back({u, v, 60 + (u * v) % 97});
        }
    for (int j = 0; j + 1 < kRows; ++j)
        for (int i = 0; i + 1 < kColumns; ++i) {
            const auto v = uint16_t(j * kColumns + i);
            part.indices.insert(part.indices.end(), {v, uint16_t(v + 1), uint16_t(v + kColumns)});
            part.indices.insert(part.indices.end(),
                                {uint16_t(v + 1), uint16_t(v + kColumns + 1), uint16_t(v + kColumns)});
        }
    return part;
}

/// A one-mesh, one-node, one-scene document: POSITION accessor 0, indices accessor 1.
json document(json buffers, json views, json accessors, json node = json::object()) {
    node["mesh"] = 0;
    return {
        {"asset", {{"version", "2.0"}}},
        {"buffers", std::move(buffers)},
        {"bufferViews", std::move(views)},
        {"accessors", std::move(accessors)},
        {"meshes", json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}})}}})},
        {"nodes", json::array({node})},
        {"scenes", json::array({{{"nodes", json::array({0})}}})},
        {"scene", 0},
    };
}

json view(size_t offset, size_t length, size_t stride = 0) {
    json v = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}};
    if (stride) v["byteStride"] = stride;
    return v;
}

json indexAccessor(int bufferView) {
    return {{"bufferView", bufferView}, {"componentType", kUShort}, {"count", kIndices}, {"type", "SCALAR"}};
}

json plainDoc(const Part& part) {
    Bin bin;
    bin.add(part.positions());
    const size_t indexOffset = bin.add(part.indices);
    return document(json::array({{{"byteLength", bin.bytes.size()}, {"uri", dataUri(bin.bytes)}}}),
                    json::array({view(0, kVertices * 12), view(indexOffset, kIndices * 2)}),
                    json::array({{{"bufferView", 0}, {"componentType", kFloat}, {"count", kVertices}, {"type", "VEC3"}},
                                 indexAccessor(1)}));
}

geometry::scene::Aabb worldBounds(const LoadedModel& model) {
    geometry::scene::Aabb box;
    for (const auto& mesh : model.meshes)
        for (size_t i = 0; i < mesh.placementCount(); ++i) box.add(mesh.placementBounds(i));
    return box;
}

size_t triangles(const LoadedModel& model) {
    size_t n = 0;
    for (const auto& mesh : model.meshes) n += mesh.placedTriangleCount();
    return n;
}

class GltfExtensionsTest : public GltfFileTest {
protected:
    GltfExtensionsTest() : GltfFileTest("shadowscope_gltfx_") {}

    void SetUp() override {
        GltfFileTest::SetUp();
        part_ = makePart();
        plain_ = geometry::io::loadGltf(writeDoc("plain.gltf", plainDoc(part_)));
    }

    /// The acceptance: the plain twin's triangle count, and its bounds within 1e-5 of
    /// their diagonal.
    void expectPlainTwin(const std::string& path) const {
        SCOPED_TRACE(path);
        const LoadedModel model = geometry::io::loadGltf(path);
        ASSERT_EQ(triangles(plain_), size_t(kIndices / 3));
        EXPECT_EQ(triangles(model), triangles(plain_));
        const geometry::scene::Aabb box = worldBounds(model), expected = worldBounds(plain_);
        const float tolerance = 1e-5f * glm::length(expected.hi - expected.lo);
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(box.lo[a], expected.lo[a], tolerance) << "axis " << a;
            EXPECT_NEAR(box.hi[a], expected.hi[a], tolerance) << "axis " << a;
        }
    }

    /// Expects loadGltf to throw a one-line message naming the file, and returns it.
    static std::string expectFailure(const std::string& path) {
        const std::string message = loadFailure(path);
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message;
    }
    static void expectFailure(const std::string& path, const std::string& words) {
        const std::string message = expectFailure(path);
        EXPECT_NE(message.find(words), std::string::npos) << message;
    }

    Part part_;
    LoadedModel plain_;
};

TEST_F(GltfExtensionsTest, PlainTwinIsTheLattice) {
    const geometry::scene::Aabb box = worldBounds(plain_);
    EXPECT_NEAR(box.lo.x, kOffset[0] + 10 * kStep, 1e-5);
    EXPECT_NEAR(box.hi.x, kOffset[0] + 232 * kStep, 1e-5);
    EXPECT_NEAR(box.hi.y, kOffset[1] + 230 * kStep, 1e-5);
    EXPECT_GT(box.hi.z - box.lo.z, 50 * kStep); // bent: no flat axis
}

// ---------------------------------------------------------------------------------------------
// Sparse accessors

TEST_F(GltfExtensionsTest, SparseWithoutBufferViewCoversEveryVertex) {
    std::vector<uint16_t> all(kVertices);
    for (size_t i = 0; i < all.size(); ++i) all[i] = uint16_t(i);
    Bin bin;
    const size_t at = bin.add(all), values = bin.add(part_.positions()), indices = bin.add(part_.indices);
    json position = {{"componentType", kFloat},
                     {"count", kVertices},
                     {"type", "VEC3"},
                     {"sparse",
                      {{"count", kVertices},
                       {"indices", {{"bufferView", 0}, {"componentType", kUShort}}},
                       {"values", {{"bufferView", 1}}}}}};
    const json doc =
        document(json::array({{{"byteLength", bin.bytes.size()}, {"uri", dataUri(bin.bytes)}}}),
                 json::array({view(at, kVertices * 2), view(values, kVertices * 12), view(indices, kIndices * 2)}),
                 json::array({position, indexAccessor(2)}));
    expectPlainTwin(writeDoc("zeros.gltf", doc));
}

/// Base data with a few wrong vertices and indices, put right by sparse substitutions: were one
/// missed, a vertex would lie a kilometre off or an index would be out of range.
TEST_F(GltfExtensionsTest, SparseSubstitutesIntoBaseViews) {
    const std::vector<uint8_t> vertexAt{3, 17, 41};
    const std::vector<uint32_t> indexAt{0, 50, kIndices - 1};
    std::vector<float> base = part_.positions(), values;
    for (uint8_t v : vertexAt)
        for (int k = 0; k < 3; ++k) {
            values.push_back(base[size_t(v) * 3 + size_t(k)]);
            base[size_t(v) * 3 + size_t(k)] = k == 1 ? -1000.f : 1000.f;
        }
    std::vector<uint16_t> baseIndices = part_.indices, indexValues;
    for (uint32_t i : indexAt) {
        indexValues.push_back(baseIndices[i]);
        baseIndices[i] = 9999;
    }
    Bin bin;
    const size_t positions = bin.add(base), indices = bin.add(baseIndices);
    // Sparse data after 4 bytes of padding in each view: the byteOffsets are honoured.
    const size_t vertexAtView = bin.add(std::vector<uint8_t>{7, 7, 7, 7, 3, 17, 41});
    const size_t valuesView = bin.add(std::vector<float>{0.f}); // padding, then the values
    bin.add(values);
    const size_t indexAtView = bin.add(std::vector<uint32_t>{7});
    bin.add(indexAt);
    const size_t indexValuesView = bin.add(std::vector<uint16_t>{7, 7});
    bin.add(indexValues);
    json position = {{"bufferView", 0},
                     {"componentType", kFloat},
                     {"count", kVertices},
                     {"type", "VEC3"},
                     {"sparse",
                      {{"count", 3},
                       {"indices", {{"bufferView", 2}, {"byteOffset", 4}, {"componentType", kUByte}}},
                       {"values", {{"bufferView", 3}, {"byteOffset", 4}}}}}};
    json index = indexAccessor(1);
    index["sparse"] = {{"count", 3},
                       {"indices", {{"bufferView", 4}, {"byteOffset", 4}, {"componentType", kUInt}}},
                       {"values", {{"bufferView", 5}, {"byteOffset", 4}}}};
    const json doc =
        document(json::array({{{"byteLength", bin.bytes.size()}, {"uri", dataUri(bin.bytes)}}}),
                 json::array({view(positions, kVertices * 12), view(indices, kIndices * 2), view(vertexAtView, 7),
                              view(valuesView, 4 + 36), view(indexAtView, 16), view(indexValuesView, 4 + 6)}),
                 json::array({position, index}));
    expectPlainTwin(writeDoc("substituted.gltf", doc));
    expectPlainTwin(writeBytes("substituted.glb", makeGlb(doc.dump(), {})));
}

/// tinygltf refuses indices without a bufferView; the loader lends one and reads zeros.
TEST_F(GltfExtensionsTest, SparseIndicesWithoutBufferView) {
    std::vector<uint16_t> all(kIndices);
    for (size_t i = 0; i < all.size(); ++i) all[i] = uint16_t(i);
    Bin bin;
    const size_t positions = bin.add(part_.positions()), at = bin.add(all), values = bin.add(part_.indices);
    json index = {{"componentType", kUShort},
                  {"count", kIndices},
                  {"type", "SCALAR"},
                  {"sparse",
                   {{"count", kIndices},
                    {"indices", {{"bufferView", 1}, {"componentType", kUShort}}},
                    {"values", {{"bufferView", 2}}}}}};
    const json doc = document(
        json::array({{{"byteLength", bin.bytes.size()}, {"uri", dataUri(bin.bytes)}}}),
        json::array({view(positions, kVertices * 12), view(at, kIndices * 2), view(values, kIndices * 2)}),
        json::array({{{"bufferView", 0}, {"componentType", kFloat}, {"count", kVertices}, {"type", "VEC3"}}, index}));
    expectPlainTwin(writeDoc("zeroindices.gltf", doc));
}

/// Khronos' glTF-Sample-Models 2.0/SimpleSparseAccessor (glTF-Embedded), its JSON and data as
/// published: 14 vertices of a 6 x 1 strip, three of them lifted by a sparse accessor.
TEST_F(GltfExtensionsTest, KhronosSimpleSparseAccessor) {
    const std::string data =
        "data:application/"
        "gltf-buffer;base64,AAAIAAcAAAABAAgAAQAJAAgAAQACAAkAAgAKAAkAAgADAAoAAwALAAoAAwAEAAsABAAMAAsABAA"
        "FAAwABQANAAwABQAGAA0AAAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAQAAAAAAAAAAAAABAQAAAAAAAAAAAAACAQAAAAAAAAAAAAACgQAAA"
        "AAAAAAAAAADAQAAAAAAAAAAAAAAAAAAAgD8AAAAAAACAPwAAgD8AAAAAAAAAQAAAgD8AAAAAAABAQAAAgD8AAAAAAACAQAAAgD8AAAAAAACgQA"
        "AAgD8AAAAAAADAQAAAgD8AAAAACAAKAAwAAAAAAIA/AAAAQAAAAAAAAEBAAABAQAAAAAAAAKBAAACAQAAAAAA=";
    const json doc = {
        {"scene", 0},
        {"scenes", json::array({{{"nodes", {0}}}})},
        {"nodes", json::array({{{"mesh", 0}}})},
        {"meshes", json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 1}}}, {"indices", 0}}})}}})},
        {"buffers", json::array({{{"uri", data}, {"byteLength", 284}}})},
        {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 72}, {"target", 34963}},
                                     {{"buffer", 0}, {"byteOffset", 72}, {"byteLength", 168}},
                                     {{"buffer", 0}, {"byteOffset", 240}, {"byteLength", 6}},
                                     {{"buffer", 0}, {"byteOffset", 248}, {"byteLength", 36}}})},
        {"accessors", json::array({{{"bufferView", 0},
                                    {"byteOffset", 0},
                                    {"componentType", kUShort},
                                    {"count", 36},
                                    {"type", "SCALAR"},
                                    {"max", {13}},
                                    {"min", {0}}},
                                   {{"bufferView", 1},
                                    {"byteOffset", 0},
                                    {"componentType", kFloat},
                                    {"count", 14},
                                    {"type", "VEC3"},
                                    {"max", {6.0, 4.0, 0.0}},
                                    {"min", {0.0, 0.0, 0.0}},
                                    {"sparse",
                                     {{"count", 3},
                                      {"indices", {{"bufferView", 2}, {"byteOffset", 0}, {"componentType", kUShort}}},
                                      {"values", {{"bufferView", 3}, {"byteOffset", 0}}}}}}})},
        {"asset", {{"version", "2.0"}}},
    };
    const LoadedModel model = geometry::io::loadGltf(writeDoc("SimpleSparseAccessor.gltf", doc));
    EXPECT_EQ(triangles(model), 12u);
    const geometry::scene::Aabb box = worldBounds(model);
    // The accessor's min and max: without the substitutions the strip would be 1 high, not 4.
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(box.lo[a], 0.0, 1e-6) << "axis " << a;
        EXPECT_NEAR(box.hi[a], (std::array<double, 3>{6, 4, 0})[size_t(a)], 1e-6) << "axis " << a;
    }
}

TEST_F(GltfExtensionsTest, HostileSparseAccessors) {
    // A valid base: positions substituted at 1 and 2 from views 2 (indices) and 3 (values).
    Bin bin;
    const size_t positions = bin.add(part_.positions()), indices = bin.add(part_.indices);
    const size_t at = bin.add(std::vector<uint16_t>{1, 2});
    const size_t values = bin.add(std::vector<float>{0.5f, 0.5f, 0.5f, 0.7f, -0.2f, 0.9f});
    const json valid = document(
        json::array({{{"byteLength", bin.bytes.size()}, {"uri", dataUri(bin.bytes)}}}),
        json::array({view(positions, kVertices * 12), view(indices, kIndices * 2), view(at, 4), view(values, 24)}),
        json::array({{{"bufferView", 0},
                      {"componentType", kFloat},
                      {"count", kVertices},
                      {"type", "VEC3"},
                      {"sparse",
                       {{"count", 2},
                        {"indices", {{"bufferView", 2}, {"componentType", kUShort}}},
                        {"values", {{"bufferView", 3}}}}}},
                     indexAccessor(1)}));
    EXPECT_EQ(triangles(geometry::io::loadGltf(writeDoc("valid.gltf", valid))), size_t(kIndices / 3));
    const auto sparse = [](json& doc) -> json& { return doc["accessors"][0]["sparse"]; };

    json doc = valid;
    doc["accessors"][0]["count"] = 1; // 2 substitutions in 1 element (and index 2 beyond it)
    doc["meshes"][0]["primitives"][0].erase("indices");
    expectFailure(writeDoc("count.gltf", doc), "accessor 0: sparse count 2 is not within 1 to its 1 elements");
    doc = valid;
    sparse(doc)["count"] = 0;
    expectFailure(writeDoc("zero.gltf", doc), "sparse count 0");
    doc = valid;
    sparse(doc)["count"] = 3; // 6 bytes of indices in a 4-byte view
    expectFailure(writeDoc("indexview.gltf", doc), "sparse indices (6 bytes at offset 0) exceed buffer view 2");
    doc = valid;
    sparse(doc)["values"]["byteOffset"] = 4; // 24 bytes of values at 4 in a 24-byte view
    expectFailure(writeDoc("valueview.gltf", doc), "sparse values (24 bytes at offset 4) exceed buffer view 3");
    doc = valid;
    sparse(doc)["indices"]["byteOffset"] = -4;
    expectFailure(writeDoc("negative.gltf", doc), "sparse indices");
    doc = valid;
    sparse(doc)["indices"]["componentType"] = kFloat;
    expectFailure(writeDoc("floatindex.gltf", doc), "sparse indices must be unsigned integers, not FLOAT");
    doc = valid;
    sparse(doc)["indices"]["bufferView"] = 9;
    expectFailure(writeDoc("noview.gltf", doc), "buffer view 9 does not exist");

    Bytes edited = bin.bytes; // index 2 → kVertices: out of range
    edited[at + 2] = uint8_t(kVertices);
    doc = valid;
    doc["buffers"][0]["uri"] = dataUri(edited);
    expectFailure(writeDoc("range.gltf", doc), "accessor 0: sparse index 42 out of range (42 elements)");
    edited = bin.bytes; // 1, 1: not increasing
    edited[at + 2] = 1;
    doc["buffers"][0]["uri"] = dataUri(edited);
    expectFailure(writeDoc("repeated.gltf", doc), "sparse indices not strictly increasing (1 then 1)");
    edited = bin.bytes; // 2, 1
    std::swap(edited[at], edited[at + 2]);
    doc["buffers"][0]["uri"] = dataUri(edited);
    expectFailure(writeDoc("decreasing.gltf", doc), "sparse indices not strictly increasing (2 then 1)");

    // Zeros cost the file nothing: a count beyond 32-bit indices is refused, one within them
    // is held to the decode budget before anything is allocated.
    doc = valid;
    doc["accessors"][0].erase("bufferView");
    doc["accessors"][0]["count"] = 1000000000000ull;
    expectFailure(writeDoc("zeros.gltf", doc), "over the 2^32 - 1 limit");
    doc["accessors"][0]["count"] = 4000000000ull;
    doc["meshes"][0]["primitives"][0].erase("indices");
    expectFailure(writeDoc("budget.gltf", doc), "MiB");
}

// ---------------------------------------------------------------------------------------------
// KHR_mesh_quantization

/// The part's lattice as integer components, stride 4 or 8 as the spec aligns vertex attributes.
template <typename T> Bytes latticeBytes(const Part& part, int shift, int scale) {
    std::vector<T> values;
    for (const auto& p : part.lattice) {
        for (int k = 0; k < 3; ++k) values.push_back(T((p[size_t(k)] + shift) * scale));
        values.push_back(0);
    }
    Bin bin;
    bin.add(values);
    return bin.bytes;
}

json quantizedDoc(const Part& part, const Bytes& positions, int componentType, bool normalized,
                  const std::array<double, 3>& translation, double scale) {
    Bin bin;
    bin.bytes = positions;
    const size_t stride = positions.size() / kVertices;
    const size_t indices = bin.add(part.indices);
    json node = {{"translation", translation}, {"scale", {scale, scale, scale}}};
    json doc = document(
        json::array({{{"byteLength", bin.bytes.size()}, {"uri", dataUri(bin.bytes)}}}),
        json::array({view(0, positions.size(), stride), view(indices, kIndices * 2)}),
        json::array({{{"bufferView", 0}, {"componentType", componentType}, {"count", kVertices}, {"type", "VEC3"}},
                     indexAccessor(1)}),
        node);
    if (normalized) doc["accessors"][0]["normalized"] = true;
    doc["extensionsUsed"] = {"KHR_mesh_quantization"};
    doc["extensionsRequired"] = {"KHR_mesh_quantization"};
    return doc;
}

TEST_F(GltfExtensionsTest, QuantizedShortNormalizedPositions) {
    // q = (lattice - 128) * 128 in [-16384, 16256]; q / 32767 * s + t = kOffset + kStep * lattice.
    const double s = kStep * 32767 / 128;
    const std::array<double, 3> t{kOffset[0] + 128 * kStep, kOffset[1] + 128 * kStep, kOffset[2] + 128 * kStep};
    expectPlainTwin(
        writeDoc("short.gltf", quantizedDoc(part_, latticeBytes<int16_t>(part_, -128, 128), kShort, true, t, s)));
}

TEST_F(GltfExtensionsTest, QuantizedUnsignedBytePositions) {
    expectPlainTwin(
        writeDoc("ubyte.gltf", quantizedDoc(part_, latticeBytes<uint8_t>(part_, 0, 1), kUByte, false, kOffset, kStep)));
}

TEST_F(GltfExtensionsTest, QuantizedNormalizedMappingOfTheSpec) {
    // BYTE normalized: max(c / 127, -1), so -128 and -127 both give -1; UNSIGNED_SHORT: c / 65535.
    Bin bin;
    bin.add(std::vector<int8_t>{-128, 0, 0, 0, 127, 0, 0, 0, 0, -127, 64, 0});
    const size_t indices = bin.add(std::vector<uint16_t>{0, 1, 2});
    json doc = document(
        json::array({{{"byteLength", bin.bytes.size()}, {"uri", dataUri(bin.bytes)}}}),
        json::array({view(0, 12, 4), view(indices, 6)}),
        json::array(
            {{{"bufferView", 0}, {"componentType", kByte}, {"normalized", true}, {"count", 3}, {"type", "VEC3"}},
             {{"bufferView", 1}, {"componentType", kUShort}, {"count", 3}, {"type", "SCALAR"}}}));
    geometry::scene::Aabb box = worldBounds(geometry::io::loadGltf(writeDoc("byte.gltf", doc)));
    EXPECT_NEAR(box.lo.x, -1.f, 1e-6);
    EXPECT_NEAR(box.hi.x, 1.f, 1e-6);
    EXPECT_NEAR(box.lo.y, -1.f, 1e-6);
    EXPECT_NEAR(box.hi.z, 64.f / 127.f, 1e-6);

    Bin wide;
    wide.add(std::vector<uint16_t>{0, 0, 0, 0, 65535, 0, 0, 0, 0, 13107, 0, 0});
    wide.add(std::vector<uint16_t>{0, 1, 2});
    doc["buffers"][0] = {{"byteLength", wide.bytes.size()}, {"uri", dataUri(wide.bytes)}};
    doc["bufferViews"] = json::array({view(0, 24, 8), view(24, 6)});
    doc["accessors"][0]["componentType"] = kUShort;
    box = worldBounds(geometry::io::loadGltf(writeDoc("ushort.gltf", doc)));
    EXPECT_NEAR(box.hi.x, 1.f, 1e-6);
    EXPECT_NEAR(box.hi.y, 0.2f, 1e-6);
}

TEST_F(GltfExtensionsTest, IntegerPositionsOutsideQuantizationRefused) {
    json doc = quantizedDoc(part_, latticeBytes<uint8_t>(part_, 0, 1), kUByte, false, kOffset, kStep);
    doc["accessors"][0]["componentType"] = kUInt; // 16 bytes a vertex: 42 of them fit the view
    doc["accessors"][0]["count"] = 10;
    doc["bufferViews"][0]["byteStride"] = 16;
    expectFailure(writeDoc("uint.gltf", doc), "POSITION must be VEC3 of FLOAT");
}

// ---------------------------------------------------------------------------------------------
// EXT_meshopt_compression

Bytes encodeVertices(const void* data, size_t count, size_t stride) {
    Bytes out(meshopt_encodeVertexBufferBound(count, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, count, stride));
    return out;
}

/// Compressed views of the part: positions (view 0, FLOAT, stride 12) and TRIANGLES indices
/// (view 1, UNSIGNED_SHORT); the compressed bytes in buffer 0, the views' own buffer 1 a fallback
/// without data. `glb`: buffer 0 is the BIN chunk, buffer 1 untagged (no URI: no data either).
struct Meshopt {
    Bytes compressed;
    json doc;
};

Meshopt meshoptPart(const Part& part, bool glb) {
    const std::vector<float> positions = part.positions();
    const std::vector<uint32_t> indices = part.indices32();
    Bin bin;
    const Bytes vertices = encodeVertices(positions.data(), kVertices, 12);
    Bytes triangles(meshopt_encodeIndexBufferBound(kIndices, kVertices));
    triangles.resize(meshopt_encodeIndexBuffer(triangles.data(), triangles.size(), indices.data(), kIndices));
    const size_t vertexOffset = bin.add(vertices), indexOffset = bin.add(triangles);
    json fallback = {{"byteLength", kVertices * 12 + kIndices * 2}};
    if (!glb) fallback["extensions"] = {{"EXT_meshopt_compression", {{"fallback", true}}}};
    json compressed = {{"byteLength", bin.bytes.size()}};
    if (!glb) compressed["uri"] = dataUri(bin.bytes);
    auto ext = [](size_t offset, size_t length, size_t stride, size_t count, const char* mode) {
        return json{{"EXT_meshopt_compression",
                     {{"buffer", 0},
                      {"byteOffset", offset},
                      {"byteLength", length},
                      {"byteStride", stride},
                      {"count", count},
                      {"mode", mode}}}};
    };
    json views = json::array({{{"buffer", 1},
                               {"byteLength", kVertices * 12},
                               {"byteStride", 12},
                               {"extensions", ext(vertexOffset, vertices.size(), 12, kVertices, "ATTRIBUTES")}},
                              {{"buffer", 1},
                               {"byteOffset", kVertices * 12},
                               {"byteLength", kIndices * 2},
                               {"extensions", ext(indexOffset, triangles.size(), 2, kIndices, "TRIANGLES")}}});
    json doc =
        document(json::array({compressed, fallback}), views,
                 json::array({{{"bufferView", 0}, {"componentType", kFloat}, {"count", kVertices}, {"type", "VEC3"}},
                              indexAccessor(1)}));
    doc["extensionsUsed"] = {"EXT_meshopt_compression"};
    doc["extensionsRequired"] = {"EXT_meshopt_compression"};
    return {bin.bytes, doc};
}

TEST_F(GltfExtensionsTest, MeshoptCompressedWithFallbackBufferWithoutData) {
    expectPlainTwin(writeDoc("meshopt.gltf", meshoptPart(part_, false).doc));
    const Meshopt glb = meshoptPart(part_, true);
    expectPlainTwin(writeBytes("meshopt.glb", makeGlb(glb.doc.dump(), glb.compressed)));
}

/// Filters and the other index mode: positions EXPONENTIAL (23-bit mantissas), normals
/// OCTAHEDRAL (BYTE, normalized, stride 4), indices as an INDICES sequence of UNSIGNED_INT.
TEST_F(GltfExtensionsTest, MeshoptFiltersAndIndexSequence) {
    const std::vector<float> positions = part_.positions();
    std::vector<uint32_t> exp(positions.size());
    meshopt_encodeFilterExp(exp.data(), kVertices, 12, 23, positions.data());
    std::vector<float> normals;
    for (int i = 0; i < kVertices; ++i) {
        const glm::vec3 n = glm::normalize(glm::vec3(0.1f * float(i % 5), -0.2f, 1.f));
        normals.insert(normals.end(), {n.x, n.y, n.z, 0.f});
    }
    std::vector<int8_t> oct(size_t(kVertices) * 4);
    meshopt_encodeFilterOct(oct.data(), kVertices, 4, 8, normals.data());
    const std::vector<uint32_t> indices = part_.indices32();
    Bytes sequence(meshopt_encodeIndexSequenceBound(kIndices, kVertices));
    sequence.resize(meshopt_encodeIndexSequence(sequence.data(), sequence.size(), indices.data(), kIndices));

    Bin bin;
    const Bytes p = encodeVertices(exp.data(), kVertices, 12), n = encodeVertices(oct.data(), kVertices, 4);
    const size_t po = bin.add(p), no = bin.add(n), so = bin.add(sequence);
    auto compressedView = [](size_t fallbackOffset, size_t stride, size_t count, size_t offset, size_t length,
                             const char* mode, const char* filter) {
        json v = {{"buffer", 1},
                  {"byteOffset", fallbackOffset},
                  {"byteLength", stride * count},
                  {"extensions",
                   {{"EXT_meshopt_compression",
                     {{"buffer", 0},
                      {"byteOffset", offset},
                      {"byteLength", length},
                      {"byteStride", stride},
                      {"count", count},
                      {"mode", mode},
                      {"filter", filter}}}}}};
        if (std::string(mode) == "ATTRIBUTES") v["byteStride"] = stride;
        return v;
    };
    json doc =
        document(json::array({{{"byteLength", bin.bytes.size()}, {"uri", dataUri(bin.bytes)}}, {{"byteLength", 1392}}}),
                 json::array({compressedView(0, 12, kVertices, po, p.size(), "ATTRIBUTES", "EXPONENTIAL"),
                              compressedView(504, 4, kVertices, no, n.size(), "ATTRIBUTES", "OCTAHEDRAL"),
                              compressedView(672, 4, kIndices, so, sequence.size(), "INDICES", "NONE")}),
                 json::array({{{"bufferView", 0}, {"componentType", kFloat}, {"count", kVertices}, {"type", "VEC3"}},
                              {{"bufferView", 2}, {"componentType", kUInt}, {"count", kIndices}, {"type", "SCALAR"}},
                              {{"bufferView", 1},
                               {"componentType", kByte},
                               {"normalized", true},
                               {"count", kVertices},
                               {"type", "VEC3"}}}));
    doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
    doc["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    const std::string path = writeDoc("filters.gltf", doc);
    expectPlainTwin(path);
    EXPECT_FALSE(hasNote(geometry::io::loadGltf(path), "NORMAL")); // read, though cleanup recomputes them
}

TEST_F(GltfExtensionsTest, HostileMeshopt) {
    const Meshopt valid = meshoptPart(part_, false);
    const auto ext = [](json& doc, int view) -> json& {
        return doc["bufferViews"][view]["extensions"]["EXT_meshopt_compression"];
    };
    json doc = valid.doc;
    ext(doc, 0)["byteLength"] = valid.compressed.size() + 100; // beyond the compressed buffer
    expectFailure(writeDoc("length.gltf", doc), "exceeds buffer 0");
    doc = valid.doc;
    ext(doc, 1)["byteOffset"] = 1u << 30;
    expectFailure(writeDoc("offset.gltf", doc), "exceeds buffer 0");
    // Decoded sizes no stream of that length can hold are refused before allocating.
    doc = valid.doc;
    ext(doc, 0)["count"] = 1u << 31;
    doc["bufferViews"][0]["byteLength"] = (uint64_t{1} << 31) * 12;
    expectFailure(writeDoc("huge.gltf", doc), "cannot come from");
    ext(doc, 0)["count"] = uint64_t{1} << 33;
    expectFailure(writeDoc("count.gltf", doc), "over the 2^32 - 1");
    ext(doc, 0)["count"] = 1e15;
    expectFailure(writeDoc("float.gltf", doc), "count must be an integer");
    // The spec's rules, which meshoptimizer asserts.
    doc = valid.doc;
    ext(doc, 0)["byteStride"] = 6;
    expectFailure(writeDoc("stride.gltf", doc), "ATTRIBUTES byteStride 6");
    doc = valid.doc;
    ext(doc, 1)["byteStride"] = 3;
    expectFailure(writeDoc("indexstride.gltf", doc), "index byteStride 3");
    doc = valid.doc;
    ext(doc, 1)["count"] = kIndices - 1;
    expectFailure(writeDoc("triangles.gltf", doc), "not a multiple of 3");
    doc = valid.doc;
    ext(doc, 1)["filter"] = "OCTAHEDRAL";
    expectFailure(writeDoc("indexfilter.gltf", doc), "index data cannot have a filter");
    doc = valid.doc;
    ext(doc, 0)["filter"] = "QUATERNION";
    expectFailure(writeDoc("quaternion.gltf", doc), "QUATERNION byteStride 12");
    doc = valid.doc;
    ext(doc, 0)["mode"] = "VERTICES";
    expectFailure(writeDoc("mode.gltf", doc), "mode must be");
    doc = valid.doc;
    ext(doc, 0)["buffer"] = 5;
    expectFailure(writeDoc("buffer.gltf", doc), "names no existing buffer");
    doc = valid.doc;
    doc["bufferViews"][0]["byteLength"] = kVertices * 12 - 4;
    expectFailure(writeDoc("viewlength.gltf", doc), "not count * byteStride");
    // Corrupt streams: the decoder's error, not a crash.
    Bytes corrupt = valid.compressed;
    std::fill(corrupt.begin(), corrupt.begin() + 8, 0x55);
    doc = valid.doc;
    doc["buffers"][0]["uri"] = dataUri(corrupt);
    expectFailure(writeDoc("corrupt.gltf", doc), "cannot be decoded");
    // A plain view on the data-less fallback buffer.
    doc = valid.doc;
    doc["bufferViews"][0].erase("extensions");
    expectFailure(writeDoc("plainview.gltf", doc), "buffer view 0 reads buffer 1, an EXT_meshopt_compression fallback");
}

// ---------------------------------------------------------------------------------------------
// Scenes and tinygltf's reasons

TEST_F(GltfExtensionsTest, WithoutDefaultSceneSceneZeroIsShown) {
    json doc = plainDoc(part_);
    doc.erase("scene");
    doc["nodes"] = json::array({{{"mesh", 0}}, {{"mesh", 0}, {"translation", {100, 0, 0}}}, {{"mesh", 0}}});
    doc["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {1, 2}}}, {{"nodes", {1}}}});
    const LoadedModel model = geometry::io::loadGltf(writeDoc("scenes.gltf", doc));
    EXPECT_EQ(triangles(model), triangles(plain_)); // scene 0: one placement, not three
    EXPECT_NEAR(worldBounds(model).hi.x, worldBounds(plain_).hi.x, 1e-5);
    EXPECT_TRUE(hasNote(model, "no default scene: scene 0 of 3 shown"));

    doc["scene"] = 1; // named: that scene, no note
    const LoadedModel second = geometry::io::loadGltf(writeDoc("scene1.gltf", doc));
    EXPECT_EQ(triangles(second), 2 * triangles(plain_));
    EXPECT_FALSE(hasNote(second, "default scene"));
    doc["scene"] = 3;
    expectFailure(writeDoc("scene3.gltf", doc), "default scene 3 does not exist");
    doc["scene"] = -2;
    expectFailure(writeDoc("negative.gltf", doc), "default scene -2 does not exist");
}

TEST_F(GltfExtensionsTest, TinygltfReasonIsOneBoundedLine) {
    std::string message =
        expectFailure(writeText("broken.gltf", "{\"asset\": {\"version\": \"2.0\"},\n\"nodes\": [\n"));
    EXPECT_NE(message.find("tinygltf could not load the file: "), std::string::npos) << message;
    EXPECT_NE(message.find("parse error"), std::string::npos) << message;
    // A long first line (tinygltf quotes the data URI it could not decode) is cut.
    json doc = plainDoc(part_);
    doc["buffers"][0]["byteLength"] = 5;
    const std::string path = writeDoc("longreason.gltf", doc);
    message = expectFailure(path);
    EXPECT_NE(message.find("tinygltf could not load the file: "), std::string::npos) << message;
    EXPECT_LT(message.size(), path.size() + 260) << message;
    EXPECT_TRUE(message.ends_with("...")) << message;
}

} // namespace
