#pragma once
// glTF accessor data for gltf_loader.cpp, read where tinygltf 2.7 leaves it raw: dense views
// bounds-checked against their buffers, sparse accessors (base values or zeros, then substitutions),
// KHR_mesh_quantization component types, and bufferViews compressed with EXT_meshopt_compression
// (decoded once, on first use, into a copy that accessors read). Internal to shadowscope_io.
#include <tiny_gltf.h>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace geometry::io::gltf {

/// A problem with the file's content; loadGltf() prefixes the path.
struct GltfError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string str(size_t n);
std::string componentName(int componentType);
std::string typeName(int type);

/// `object[key]`, or null when `object` is no object or lacks the key.
const nlohmann::json& member(const nlohmann::json& object, const char* key);
/// The JSON index `value` when it is an integer naming one of `array`'s elements.
std::optional<size_t> indexInto(const nlohmann::json& value, const nlohmann::json& array);

// ---------------------------------------------------------------------------------------------
// EXT_meshopt_compression, read from the JSON before tinygltf parses it

enum class MeshoptMode { Attributes, Triangles, Indices };
enum class MeshoptFilter { None, Octahedral, Quaternion, Exponential };

/// One bufferView's extension object, validated against the spec's rules.
struct MeshoptView {
    size_t buffer = 0, byteOffset = 0, byteLength = 0; // the compressed bytes
    size_t byteStride = 0, count = 0;                  // the decoded layout: count * byteStride bytes
    MeshoptMode mode = MeshoptMode::Attributes;
    MeshoptFilter filter = MeshoptFilter::None;
};

/// bufferView index → its compression.
using MeshoptViews = std::map<size_t, MeshoptView>;

/// The compressed bufferViews of `doc`, read from the JSON itself: tinygltf keeps extension
/// numbers as int, which would truncate lengths and counts. Throws GltfError for anything the
/// spec forbids or a decoded size that no compressed stream of that length can hold.
MeshoptViews readMeshoptViews(const nlohmann::json& doc);

/// Replaces in `doc` the buffers whose bytes are never read (tagged fallback, or without a URI
/// outside a GLB's BIN chunk and parent of compressed views) by a one-byte data URI: tinygltf
/// refuses a buffer it cannot load. Returns the buffers replaced.
std::set<size_t> replaceFallbackBuffers(nlohmann::json& doc, bool binary, const MeshoptViews& views);

/// tinygltf refuses a primitive whose indices accessor has no bufferView, which a sparse accessor
/// (zeros, then substitutions) may lack: such accessors get bufferView 0 in `doc`, to pass that
/// check, and are returned, for Accessors to read as zeros again.
std::set<size_t> lendIndexViews(nlohmann::json& doc);

/// What gltf_loader's pre-check took from the JSON, and changed in it, that accessors must know.
struct JsonFacts {
    MeshoptViews meshopt;
    std::set<size_t> fallbackBuffers; // replaceFallbackBuffers
    std::set<size_t> lentViews;       // lendIndexViews
    // Buffer 0's bytes in the mapped GLB, where tinygltf holds only a placeholder (gltf_loader's
    // lendBinChunk): they must outlive the Accessors.
    std::optional<std::span<const unsigned char>> lentBin;
};

// ---------------------------------------------------------------------------------------------
// Accessors

inline constexpr unsigned char kZeroElement[128] = {}; // the largest element: MAT4 of doubles

/// A validated window on an accessor's elements: element(i) is valid for i < count.
struct AccessorView {
    const unsigned char* data = nullptr; // base values; nullptr: all zeros (no bufferView)
    size_t count = 0;
    size_t stride = 0;
    size_t elementSize = 0;
    int componentType = 0;
    int type = 0;
    bool normalized = false;
    // Sparse substitutions: sparseCount indices, strictly increasing and < count, and their
    // values, both tightly packed.
    const unsigned char* sparseIndices = nullptr;
    const unsigned char* sparseValues = nullptr;
    size_t sparseCount = 0;
    size_t sparseIndexSize = 0;

    [[nodiscard]] const unsigned char* element(size_t i) const {
        if (sparseCount)
            if (const unsigned char* value = substitute(i)) return value;
        return data ? data + i * stride : kZeroElement;
    }
    [[nodiscard]] const unsigned char* substitute(size_t i) const;
};

/// The model's accessors, each checked once against the bytes that really exist (overflow-safely,
/// so neither a read nor an allocation follows an absurd count or offset) and cached.
class Accessors {
public:
    Accessors(const tinygltf::Model& model, JsonFacts facts);

    /// Throws GltfError naming the accessor.
    const AccessorView& view(int index);
    /// Drops the lent BIN chunk's pages from this process's memory (the file's pages stay cached):
    /// once a primitive is decoded, cleaning it must not carry the file on top of its peak. Read
    /// again, they come back from the page cache.
    void releaseLentPages() const noexcept;
    /// Bytes decoded from EXT_meshopt_compression so far.
    [[nodiscard]] size_t decodedBytes() const { return decodedBytes_; }

private:
    struct Span {
        const unsigned char* data;
        size_t length;
        size_t stride; // the bufferView's byteStride; 0: tightly packed
    };
    Span viewBytes(int viewIndex);
    /// Buffer b's bytes: tinygltf's, or the lent BIN chunk's.
    std::span<const unsigned char> bufferData(size_t b) const;
    const std::vector<unsigned char>& decode(size_t viewIndex, const MeshoptView& compressed);
    void addSparse(AccessorView& v, const tinygltf::Accessor& acc, const std::string& name);

    const tinygltf::Model& model_;
    JsonFacts facts_;
    std::vector<std::optional<AccessorView>> cache_;
    std::map<size_t, std::vector<unsigned char>> decoded_; // by bufferView; nodes never move
    size_t decodedBytes_ = 0;
    uint64_t memory_; // what decoding may use in all
};

/// Positions (KHR_mesh_quantization): FLOAT, or BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT
/// normalized or not. Normals: FLOAT, or BYTE / SHORT normalized.
bool isPositionType(const AccessorView& v);
bool isNormalType(const AccessorView& v);

/// The VEC3 elements listed in `which` (each < v.count), in that order, as floats: normalized
/// integers as the glTF spec maps them (max(c / 127, -1) and the like), others converted.
std::vector<glm::vec3> readVec3(const AccessorView& v, const std::vector<uint32_t>& which);

/// Index values as stored (before triangle assembly), each checked against the vertex count.
std::vector<uint32_t> readIndices(const AccessorView& v, size_t vertexCount, const std::string& where);

} // namespace geometry::io::gltf
