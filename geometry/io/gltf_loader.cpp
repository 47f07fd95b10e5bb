// glTF 2.0 loading (see gltf_loader.h). tinygltf parses the JSON / GLB container and resolves
// buffers; everything it leaves unchecked (accessor ranges, component types, index values, the
// shape of the node graph) is validated here, or by gltf_accessor.cpp (accessors, sparse and
// quantized data, EXT_meshopt_compression), before any element is read.
//
// Index
//   [SECTION] Errors .................... oneLine, firstLine
//   [SECTION] Files ..................... regularFileSize, readRegularFile, fsReadWholeFile, looksLikeJson,
//                                         nestingWithinLimit, readU32, checkDracoPrimitive, lendBinChunk,
//                                         precheck, withJson, parse
//   [SECTION] Node hierarchy ............ localMatrix, NodeWalker, rootNodes, collectInstances
//   [SECTION] Primitives ................ toTriangleList, baseColor, checkNormals, decodePrimitive
//   [SECTION] Cleaning and instancing ... decodeCost, checkDecodeBudget, cleanUsedMeshes, emitInstances
//   [SECTION] Loading ................... loadChecked, loadGltf
#include "geometry/io/gltf_loader.h"

#include "geometry/io/gltf_accessor.h"
#include "geometry/io/mapped_file.h"
#include "geometry/scene/chunking.h"
#include "geometry/scene/parallel_ranges.h"
#include "geometry/scene/unwritten_vector.h"

#include <tiny_gltf.h>

#include <draco/compression/decode.h>
#include <draco/core/decoder_buffer.h>
#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <map>
#include <new>
#include <numeric>
#include <optional>
#include <set>
#include <span>
#include <stdexcept>

namespace geometry::io {
namespace {

namespace fs = std::filesystem;
using Bytes = std::span<const unsigned char>;
using gltf::Accessors;
using gltf::AccessorView;
using gltf::componentName;
using gltf::GltfError;
using gltf::indexInto;
using gltf::member;
using gltf::str;
using gltf::typeName;

// Real CAD assemblies nest a few levels; 64 leaves headroom and bounds the recursion.
constexpr int kMaxNodeDepth = 64;
// A node may have several parents (instancing), so a tiny acyclic file can still describe
// 2^depth instances: cap the instances visited and the triangles the meshes hold (repeated
// meshes are instanced, not copied: emitInstances).
constexpr size_t kMaxNodeInstances = size_t{1} << 18;
constexpr size_t kMaxInstancedTriangles = size_t{1} << 27;
// tinygltf's LoadBinaryFromMemory / LoadASCIIFromString take 32-bit sizes.
constexpr uintmax_t kMaxFileBytes = std::numeric_limits<uint32_t>::max();
// tinygltf quotes whole data URIs in some messages; keep ours readable.
constexpr size_t kMaxMessageChars = 400;
constexpr size_t kMaxReasonChars = 200;
constexpr glm::vec3 kDefaultColor{0.8f};

// ---------------------------------------------------------------------------------------------
// [SECTION] Errors

/// tinygltf's messages span lines; the loader's contract is one line.
std::string oneLine(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '\n' || c == '\r') {
            if (!out.empty() && !out.ends_with("; ")) out += "; ";
        } else {
            out += c;
        }
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
    if (out.size() > kMaxMessageChars) out = out.substr(0, kMaxMessageChars) + "...";
    return out;
}

/// The first non-blank line of `text`, trimmed and bounded: why tinygltf gave up, in a message
/// that must stay one line.
std::string firstLine(std::string_view text) {
    constexpr std::string_view kBlank = " \t\r\n";
    while (!text.empty()) {
        const size_t end = text.find_first_of("\r\n");
        std::string_view line = text.substr(0, end);
        const size_t first = line.find_first_not_of(kBlank);
        if (first != std::string_view::npos) {
            line = line.substr(first, line.find_last_not_of(kBlank) - first + 1);
            if (line.size() <= kMaxReasonChars) return std::string(line);
            return std::string(line.substr(0, kMaxReasonChars)) + "...";
        }
        if (end == std::string_view::npos) break;
        text.remove_prefix(end + 1);
    }
    return {};
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Files

/// The size of a regular file of at most 4 GiB, or nullopt with `problem` set. Devices, FIFOs and
/// directories are refused, so a buffer URI naming /dev/zero or a pipe cannot hang the loader or
/// grow without bound.
std::optional<uint64_t> regularFileSize(const std::string& path, std::string& problem) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        problem = fs::exists(path, ec) ? "not a regular file" : "file not found";
        return std::nullopt;
    }
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) {
        problem = "cannot determine the file size";
        return std::nullopt;
    }
    if (size > kMaxFileBytes) {
        problem = "file larger than 4 GiB";
        return std::nullopt;
    }
    return uint64_t(size);
}

/// Reads a regular file whole (regularFileSize's limits).
bool readRegularFile(const std::string& path, std::vector<unsigned char>& out, std::string& problem) {
    const std::optional<uint64_t> size = regularFileSize(path, problem);
    if (!size) return false;
    std::ifstream in(path, std::ios::binary);
    out.resize(static_cast<size_t>(*size));
    if (!in || !in.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(*size))) {
        problem = "cannot read the file";
        return false;
    }
    return true;
}

bool fsFileExists(const std::string& path, void*) {
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}

// URIs come from the file: never expand them (no ~, no environment variables, no shell).
std::string fsExpandPath(const std::string& path, void*) { return path; }

bool fsReadWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    std::string problem;
    if (readRegularFile(path, *out, problem)) return true;
    if (err) *err += "'" + path + "': " + problem + "\n";
    return false;
}

bool fsWriteWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is disabled\n";
    return false;
}

// Textures are irrelevant to shadows; accepting them undecoded keeps stb_image (and its attack
// surface, and its memory) out of the loader.
bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

/// JSON glTF starts with '{' after an optional BOM and whitespace; anything else is not glTF,
/// and saying so beats relaying a JSON parser's column number.
bool looksLikeJson(Bytes bytes) {
    size_t i = 0;
    if (bytes.size() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF) i = 3;
    while (i < bytes.size() && std::isspace(bytes[i])) ++i;
    return i < bytes.size() && bytes[i] == '{';
}

/// nlohmann's tree and tinygltf's Value conversion recurse once per nesting level, so a file of
/// nested brackets would overflow the stack; real glTF nests about ten levels deep.
constexpr int kMaxJsonNesting = 256;

bool nestingWithinLimit(std::string_view json) {
    int depth = 0;
    bool inString = false, escaped = false;
    for (char c : json) {
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonNesting) return false;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return true;
}

/// The little-endian 32-bit number at `at` (0 past the end): GLB header fields.
uint32_t readU32(Bytes bytes, uint64_t at) {
    uint32_t v = 0;
    if (at + 4 <= bytes.size())
        for (int i = 3; i >= 0; --i) v = v << 8 | bytes[size_t(at) + size_t(i)];
    return v;
}

/// The JSON text: the whole file, or a GLB's first chunk (clamped to the file; tinygltf rejects
/// inconsistent GLB headers itself).
std::string_view jsonText(Bytes bytes, bool binary) {
    const auto* chars = reinterpret_cast<const char*>(bytes.data());
    if (!binary) return {chars, bytes.size()};
    if (bytes.size() < 20) return {};
    uint32_t length = 0;
    for (int i = 3; i >= 0; --i) length = length << 8 | bytes[size_t(12 + i)];
    return {chars + 20, std::min<size_t>(length, bytes.size() - 20)};
}

constexpr const char* kGltf1 = "glTF 1.0 is not supported (convert to glTF 2.0)";

// Extensions a file may require that loading geometry honours: Draco and meshopt are decoded,
// quantized positions read; the rest change shading or textures only, which shadows never read.
bool supportedRequiredExtension(const std::string& name) {
    static const char* const kSupported[] = {
        "KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_mesh_quantization", "KHR_texture_transform",
        "KHR_texture_basisu",         "EXT_texture_webp",        "KHR_lights_punctual",   "KHR_materials_variants"};
    if (name.starts_with("KHR_materials_")) return true;
    return std::find(std::begin(kSupported), std::end(kSupported), name) != std::end(kSupported);
}

/// The file as the pre-check sees it, with the buffers it has read so far.
struct Source {
    Bytes bytes;
    bool binary;
    std::string baseDir;
    std::map<size_t, std::vector<unsigned char>> buffers;
    std::set<size_t> decodedViews;
};

std::vector<unsigned char> base64Decode(std::string_view text) {
    std::vector<unsigned char> out;
    uint32_t bits = 0;
    int count = 0;
    for (char c : text) {
        int v = -1;
        if (c >= 'A' && c <= 'Z') v = c - 'A';
        else if (c >= 'a' && c <= 'z') v = c - 'a' + 26;
        else if (c >= '0' && c <= '9') v = c - '0' + 52;
        else if (c == '+') v = 62;
        else if (c == '/') v = 63;
        else break; // '=' padding or junk ends the data, as in tinygltf
        bits = bits << 6 | uint32_t(v);
        if ((count += 6) >= 8) out.push_back(static_cast<unsigned char>(bits >> (count -= 8)));
    }
    return out;
}

/// tinygltf's URI decoding of external buffer names ('+' is a space, %XX a byte).
std::string urlDecode(const std::string& uri) {
    auto hex = [](char c) {
        return c >= '0' && c <= '9'   ? c - '0'
               : c >= 'a' && c <= 'f' ? c - 'a' + 10
               : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                      : 0;
    };
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') out += ' ';
        else if (uri[i] == '%' && i + 2 < uri.size()) out += char(hex(uri[i + 1]) << 4 | hex(uri[i + 2])), i += 2;
        else out += uri[i];
    }
    return out;
}

/// A buffer's bytes found the way tinygltf finds them (GLB BIN chunk, data URI, or a file in
/// the glTF's folder, then the working folder, paths joined as tinygltf joins them), so the
/// stream checked is the stream tinygltf will decode.
const std::vector<unsigned char>& bufferBytes(Source& source, const nlohmann::json& buffer, size_t index,
                                              const std::string& name) {
    if (const auto it = source.buffers.find(index); it != source.buffers.end()) return it->second;
    std::vector<unsigned char> data;
    const nlohmann::json& uri = member(buffer, "uri");
    if (!uri.is_string()) {
        const size_t size = source.bytes.size();
        uint32_t jsonLength = 0, binLength = 0;
        if (source.binary && size >= 20) {
            std::memcpy(&jsonLength, source.bytes.data() + 12, 4); // GLB is little-endian, as are we
            const size_t header = 20 + size_t(jsonLength);
            if (header + 8 <= size) {
                std::memcpy(&binLength, source.bytes.data() + header, 4);
                const auto first = source.bytes.begin() + std::ptrdiff_t(header + 8);
                data.assign(first, first + std::ptrdiff_t(std::min<size_t>(binLength, size - header - 8)));
            }
        }
    } else if (const std::string text = uri.get<std::string>(); text.starts_with("data:")) {
        if (const size_t comma = text.find(";base64,"); comma != std::string::npos)
            data = base64Decode(std::string_view(text).substr(comma + 8));
    } else {
        const std::string file = urlDecode(text);
        std::string problem = "file not found";
        bool read = false;
        for (const std::string& dir : {source.baseDir, std::string(".")})
            if (!read)
                read =
                    readRegularFile(dir.empty() ? file : dir + (dir.ends_with('/') ? "" : "/") + file, data, problem);
        if (!read) throw GltfError(name + ": buffer " + str(index) + " '" + file + "': " + problem);
    }
    return source.buffers[index] = std::move(data);
}

/// The Draco stream is decoded once here, before tinygltf decodes it again: tinygltf 2.7
/// dereferences the attribute a unique id names without checking it exists and copies each
/// value through a 4-component array, so both are checked first, with Draco itself.
void checkDracoStream(const std::vector<unsigned char>& stream, const nlohmann::json& attributes,
                      std::optional<int64_t> indexType, const std::string& name) {
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(stream.data()), stream.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok())
        throw GltfError(name + ": cannot decode the Draco data (" + decoded.status().error_msg_string() + ")");
    const draco::Mesh& mesh = *decoded.value();
    for (const auto& [key, id] : attributes.items()) {
        const int64_t uid = id.get<int64_t>();
        const draco::PointAttribute* attribute =
            uid < 0 || uid > std::numeric_limits<int32_t>::max() ? nullptr : mesh.GetAttributeByUniqueId(uint32_t(uid));
        if (!attribute) throw GltfError(name + ": attribute " + key + " names no Draco attribute");
        if (attribute->num_components() < 1 || attribute->num_components() > 4)
            throw GltfError(name + ": attribute " + key + " has " + str(attribute->num_components()) + " components");
    }
    if (!indexType) return;
    // tinygltf writes the indices in the accessor's type: too narrow a type would wrap.
    const size_t limit = *indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? size_t{1} << 8
                         : *indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? size_t{1} << 16
                                                                                : size_t{1} << 32;
    if (mesh.num_points() > limit)
        throw GltfError(name + ": " + str(mesh.num_points()) + " vertices do not fit the indices' componentType");
    if (mesh.num_faces() == 0) throw GltfError(name + ": the Draco data has no faces");
}

/// tinygltf 2.7 decodes KHR_draco_mesh_compression while parsing and indexes bufferViews,
/// buffers and accessors from the extension without any range check, so the references are
/// validated here, before it runs. (Buffers: tinygltf itself makes each buffer's data exactly
/// its byteLength, so the declared lengths bound the views.)
void checkDracoPrimitive(Source& source, const nlohmann::json& doc, const nlohmann::json& prim,
                         const nlohmann::json& ext, const std::string& where) {
    const std::string name = where + ": KHR_draco_mesh_compression";
    const nlohmann::json& views = member(doc, "bufferViews");
    const nlohmann::json& buffers = member(doc, "buffers");
    const nlohmann::json& accessors = member(doc, "accessors");
    const auto viewIndex = indexInto(member(ext, "bufferView"), views);
    if (!viewIndex) throw GltfError(name + " names no existing bufferView");
    const nlohmann::json& view = views[*viewIndex];
    const auto bufferIndex = indexInto(member(view, "buffer"), buffers);
    if (!bufferIndex) throw GltfError(name + ": its bufferView names no existing buffer");
    const nlohmann::json& offset = member(view, "byteOffset");
    const nlohmann::json& length = member(view, "byteLength");
    const nlohmann::json& bufferLength = member(buffers[*bufferIndex], "byteLength");
    const bool numbers = (offset.is_null() || offset.is_number_unsigned()) && length.is_number_unsigned() &&
                         bufferLength.is_number_unsigned();
    const uint64_t o = offset.is_number_unsigned() ? offset.get<uint64_t>() : 0;
    if (!numbers || o > bufferLength.get<uint64_t>() || length.get<uint64_t>() > bufferLength.get<uint64_t>() - o)
        throw GltfError(name + ": its bufferView exceeds its buffer");

    // tinygltf sizes decoded data by the accessors' componentType: it must be a real one.
    auto accessorOf = [&](const nlohmann::json& index, std::initializer_list<int> types, const std::string& what) {
        const auto a = indexInto(index, accessors);
        if (!a) throw GltfError(name + ": " + what + " names no existing accessor");
        const nlohmann::json& type = member(accessors[*a], "componentType");
        if (!type.is_number_integer() || std::find(types.begin(), types.end(), type.get<int64_t>()) == types.end())
            throw GltfError(name + ": " + what + " accessor has an invalid componentType");
    };
    std::optional<int64_t> indexType;
    if (prim.contains("indices")) {
        accessorOf(prim["indices"],
                   {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                   "indices");
        indexType = member(accessors[size_t(prim["indices"].get<int64_t>())], "componentType").get<int64_t>();
    }
    const nlohmann::json& attributes = member(ext, "attributes");
    if (!attributes.is_object()) throw GltfError(name + " has no attributes object");
    for (const auto& [key, id] : attributes.items()) {
        if (!id.is_number_integer()) throw GltfError(name + ": attribute " + key + " id is not an integer");
        const nlohmann::json& accessor = member(member(prim, "attributes"), key.c_str());
        if (accessor.is_null()) throw GltfError(name + ": attribute " + key + " is not an attribute of the primitive");
        accessorOf(accessor,
                   {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_COMPONENT_TYPE_INT,
                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_COMPONENT_TYPE_FLOAT},
                   "attribute " + key);
    }

    // tinygltf decodes a view for the first primitive naming it and skips it for the others, so
    // must we: a file of many primitives sharing one stream must not decode it many times.
    if (!source.decodedViews.insert(*viewIndex).second) return;
    const std::vector<unsigned char>& data = bufferBytes(source, buffers[*bufferIndex], *bufferIndex, name);
    if (o > data.size() || length.get<uint64_t>() > data.size() - o)
        throw GltfError(name + ": its bufferView exceeds the " + str(data.size()) + " bytes of its buffer");
    const auto first = data.begin() + std::ptrdiff_t(o);
    checkDracoStream({first, first + std::ptrdiff_t(length.get<uint64_t>())}, attributes, indexType, name);
}

/// What the pre-check learnt that reading the model needs, and the JSON tinygltf must parse
/// instead of the file's own (empty: the file's).
struct Prechecked {
    nlohmann::json doc;                 // as tinygltf must see it, where `rewrite`
    bool rewrite = false;               // tinygltf must parse `doc`, not the file's own JSON
    std::optional<uint64_t> lentLength; // buffer 0 (the BIN chunk) is lent: its declared byteLength
    gltf::JsonFacts facts;
};

/// Buffers no larger than this are left to tinygltf to copy.
constexpr uint64_t kLentBinPlaceholder = 4;

/// A GLB's BIN chunk is read in place, from the mapped file (Accessors), instead of copied whole by
/// tinygltf (82 MB for the 4 M piperack): tinygltf is told buffer 0 holds its first 4 bytes. Not
/// with Draco, which tinygltf decodes from its copy, nor for a buffer 0 that is not the BIN chunk or
/// whose byteLength tinygltf would refuse. Returns the byteLength declared.
std::optional<uint64_t> lendBinChunk(nlohmann::json& doc, const std::set<size_t>& fallbackBuffers) {
    if (!member(doc, "buffers").is_array() || doc["buffers"].empty() || fallbackBuffers.contains(0)) return {};
    nlohmann::json& buffer = doc["buffers"][0];
    if (!buffer.is_object() || buffer.contains("uri")) return {};
    const nlohmann::json& length = member(buffer, "byteLength");
    if (!length.is_number_unsigned() || length.get<uint64_t>() <= kLentBinPlaceholder) return {};
    const uint64_t declared = length.get<uint64_t>();
    buffer["byteLength"] = kLentBinPlaceholder;
    return declared;
}

/// What tinygltf would report badly or not at all: glTF 1.0 (a different schema: tinygltf
/// complains about some missing field), required extensions we cannot honour (tinygltf ignores
/// extensionsRequired), Draco references (see checkDracoPrimitive) and EXT_meshopt_compression
/// (tinygltf ignores it, and refuses its fallback buffers: rewritten). Malformed JSON is left to
/// tinygltf, whose message names the position.
Prechecked precheck(Bytes bytes, bool binary, const std::string& baseDir) {
    nlohmann::json doc = nlohmann::json::parse(jsonText(bytes, binary), nullptr, false);
    if (!doc.is_object()) return {};
    const nlohmann::json& version = member(member(doc, "asset"), "version");
    if ((version.is_string() && version.get<std::string>().starts_with("1.")) || member(doc, "meshes").is_object())
        throw GltfError(kGltf1);
    if (const nlohmann::json& required = member(doc, "extensionsRequired"); required.is_array())
        for (const nlohmann::json& name : required)
            if (name.is_string() && !supportedRequiredExtension(name.get<std::string>()))
                throw GltfError("requires the unsupported glTF extension " + name.get<std::string>());
    Prechecked out;
    gltf::JsonFacts& facts = out.facts;
    facts.meshopt = gltf::readMeshoptViews(doc);
    facts.fallbackBuffers = gltf::replaceFallbackBuffers(doc, binary, facts.meshopt);
    facts.lentViews = gltf::lendIndexViews(doc);
    // Draco is checked against the document tinygltf will see.
    const nlohmann::json& meshes = member(doc, "meshes");
    Source source{bytes, binary, baseDir, {}, {}};
    bool draco = false;
    for (size_t m = 0; meshes.is_array() && m < meshes.size(); ++m) {
        const nlohmann::json& prims = member(meshes[m], "primitives");
        if (!prims.is_array()) continue;
        for (size_t p = 0; p < prims.size(); ++p) {
            const nlohmann::json& ext = member(member(prims[p], "extensions"), "KHR_draco_mesh_compression");
            if (!ext.is_object()) continue;
            checkDracoPrimitive(source, doc, prims[p], ext, "mesh " + str(m) + " primitive " + str(p));
            draco = true;
        }
    }
    if (binary && !draco) out.lentLength = lendBinChunk(doc, facts.fallbackBuffers);
    out.rewrite = !facts.fallbackBuffers.empty() || !facts.lentViews.empty() || out.lentLength;
    out.doc = std::move(doc);
    return out;
}

void putU32(std::vector<unsigned char>& out, size_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
}

/// The file with its JSON replaced: the whole text, or a GLB's JSON chunk, the rest of the
/// container kept byte for byte and its lengths updated. Empty where the GLB header disagrees
/// with the file: tinygltf refuses such a file whatever its JSON.
std::vector<unsigned char> withJson(Bytes bytes, bool binary, std::string json) {
    if (!binary) return {json.begin(), json.end()};
    uint32_t length = 0, jsonLength = 0;
    if (bytes.size() < 20) return {};
    std::memcpy(&length, bytes.data() + 8, 4); // GLB is little-endian, as are we
    std::memcpy(&jsonLength, bytes.data() + 12, 4);
    const uint64_t header = 20 + uint64_t(jsonLength);
    if (header > bytes.size() || length > bytes.size() || length < header) return {};
    while (json.size() % 4) json += ' ';
    const uint64_t total = uint64_t(length) - jsonLength + json.size();
    if (total > kMaxFileBytes) throw GltfError("file larger than 4 GiB once its fallback buffers are replaced");
    std::vector<unsigned char> out(bytes.begin(), bytes.begin() + 8);
    out.reserve(bytes.size() - jsonLength + json.size());
    putU32(out, size_t(total));
    putU32(out, json.size());
    out.insert(out.end(), bytes.begin() + 16, bytes.begin() + 20);
    out.insert(out.end(), json.begin(), json.end());
    out.insert(out.end(), bytes.begin() + std::ptrdiff_t(header), bytes.end());
    return out;
}

struct Parsed {
    tinygltf::Model model;
    bool binary = false;
    std::vector<std::string> notes; // tinygltf's warnings on a successful load
    gltf::JsonFacts facts;
};

Parsed parse(const std::string& path, MappedFile& file) {
    const Bytes bytes = file.bytes();
    Parsed parsed;
    // The GLB magic decides, not the extension: misnamed files are common.
    parsed.binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    if (!parsed.binary && !looksLikeJson(bytes))
        throw GltfError("neither glTF JSON nor GLB (expected '{' or the 'glTF' magic)");
    // GLB container version 1 is glTF 1.0's KHR_binary_glTF.
    if (parsed.binary && bytes.size() >= 8 && bytes[4] == 1 && bytes[5] == 0 && bytes[6] == 0 && bytes[7] == 0)
        throw GltfError(kGltf1);
    if (!nestingWithinLimit(jsonText(bytes, parsed.binary)))
        throw GltfError("JSON nested deeper than " + std::to_string(kMaxJsonNesting) + " levels");
    const std::string baseDir = fs::path(path).parent_path().string();
    Prechecked prechecked = precheck(bytes, parsed.binary, baseDir);
    const auto dump = [&] { return prechecked.doc.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); };
    std::string json = prechecked.rewrite ? dump() : std::string();
    // A GLB's new JSON goes in place of its own where it fits, padded with spaces (the file is mapped
    // privately: only this process's copy changes), so that the BIN chunk stays where it is.
    const std::string_view own = jsonText(bytes, parsed.binary);
    const bool inPlace = parsed.binary && !json.empty() && own.size() >= json.size() &&
                         own.data() == reinterpret_cast<const char*>(bytes.data()) + 20 &&
                         uint64_t(own.size()) == readU32(bytes, 12);
    if (!inPlace && prechecked.lentLength) { // the BIN chunk is copied after all: tinygltf reads it
        prechecked.doc["buffers"][0]["byteLength"] = *prechecked.lentLength;
        prechecked.lentLength.reset();
        prechecked.rewrite = !prechecked.facts.fallbackBuffers.empty() || !prechecked.facts.lentViews.empty();
        json = prechecked.rewrite ? dump() : std::string();
    }
    std::vector<unsigned char> rewritten;
    if (inPlace) {
        json.resize(own.size(), ' ');
        std::memcpy(file.writableData() + 20, json.data(), json.size());
    } else if (!json.empty()) {
        rewritten = withJson(bytes, parsed.binary, std::move(json));
    }
    // What tinygltf sees must be what the facts describe: nothing replaced or lent without a rewrite.
    if (!inPlace && rewritten.empty()) {
        prechecked.facts.fallbackBuffers.clear();
        prechecked.facts.lentViews.clear();
    }
    parsed.facts = std::move(prechecked.facts);
    const Bytes input = rewritten.empty() ? bytes : Bytes(rewritten);

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(ignoreImage, nullptr);
    loader.SetFsCallbacks({fsFileExists, fsExpandPath, fsReadWholeFile, fsWriteWholeFile, nullptr});
    const auto size = static_cast<unsigned int>(input.size());
    std::string err, warn;
    bool ok = false;
    try {
        ok = parsed.binary ? loader.LoadBinaryFromMemory(&parsed.model, &err, &warn, input.data(), size, baseDir)
                           : loader.LoadASCIIFromString(&parsed.model, &err, &warn,
                                                        reinterpret_cast<const char*>(input.data()), size, baseDir);
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        throw GltfError(std::string("glTF parser: ") + e.what());
    }
    if (!ok) {
        // The first line, bounded: tinygltf appends to `err` as it goes, quoting data URIs whole.
        const std::string reason = firstLine(err.find_first_not_of(" \t\r\n") != std::string::npos ? err : warn);
        throw GltfError("tinygltf could not load the file" + (reason.empty() ? "" : ": " + reason));
    }
    for (const std::string* text : {&err, &warn})
        if (const std::string line = oneLine(*text); !line.empty()) parsed.notes.push_back(line);
    if (prechecked.lentLength) {
        // tinygltf found the BIN chunk sound (its header, length and place in the file) and copied 4
        // bytes: the rest of its check of buffer 0, then the bytes it would have copied.
        const uint64_t binStart = 20 + uint64_t(readU32(bytes, 12)) + 8, binSize = readU32(bytes, binStart - 8);
        if (*prechecked.lentLength > binSize)
            throw GltfError("tinygltf could not load the file: Invalid `byteLength'. Must be equal or less than "
                            "binary size: `byteLength' = " +
                            str(*prechecked.lentLength) + ", binary size = " + str(binSize));
        parsed.facts.lentBin = Bytes(bytes.data() + binStart, size_t(*prechecked.lentLength));
    }
    return parsed;
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Node hierarchy

void requireFinite(const std::vector<double>& values, const std::string& what) {
    for (double v : values)
        if (!std::isfinite(v)) throw GltfError(what + " has a non-finite value");
}

/// The node's local matrix: `matrix` if present, else T * R * S (glTF's order).
glm::mat4 localMatrix(const tinygltf::Node& node, int index) {
    const std::string name = "node " + std::to_string(index);
    auto requireSize = [&](const std::vector<double>& v, size_t n, const char* field) {
        if (!v.empty() && v.size() != n)
            throw GltfError(name + ": " + field + " needs " + str(n) + " numbers, has " + str(v.size()));
        requireFinite(v, name + " " + field);
    };
    requireSize(node.matrix, 16, "matrix");
    requireSize(node.translation, 3, "translation");
    requireSize(node.rotation, 4, "rotation");
    requireSize(node.scale, 3, "scale");

    glm::dmat4 m(1.0);
    if (!node.matrix.empty()) {
        // glTF stores matrices column-major, as glm indexes them.
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[size_t(c * 4 + r)];
        return glm::mat4(m);
    }
    if (!node.translation.empty())
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (!node.rotation.empty()) {
        // glTF orders quaternions (x, y, z, w); glm's constructor takes w first.
        const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        m *= glm::mat4_cast(glm::normalize(q));
    }
    if (!node.scale.empty()) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return glm::mat4(m);
}

bool isFinite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

struct Instance {
    int mesh = -1;
    glm::mat4 world{1.f};
};

/// Depth-first walk composing world matrices. `onPath` marks the current ancestors, so a node
/// that is its own ancestor is reported instead of recursing forever. Local matrices are
/// validated once per node and cached: instancing may visit a node many times.
class NodeWalker {
public:
    explicit NodeWalker(const tinygltf::Model& model)
        : model_(model), onPath_(model.nodes.size(), 0), local_(model.nodes.size()) {}

    void walk(int node, const glm::mat4& parent, int depth) {
        if (node < 0 || size_t(node) >= model_.nodes.size()) throw GltfError(nodeName(node) + " does not exist");
        if (onPath_[size_t(node)])
            throw GltfError(nodeName(node) + " is its own ancestor (cycle in the node hierarchy)");
        if (depth >= kMaxNodeDepth)
            throw GltfError("node hierarchy deeper than " + std::to_string(kMaxNodeDepth) + " levels");
        if (++visits_ > kMaxNodeInstances)
            throw GltfError("node hierarchy expands to more than " + str(kMaxNodeInstances) + " node instances");

        const tinygltf::Node& n = model_.nodes[size_t(node)];
        const glm::mat4 world = parent * local(node);
        if (!isFinite(world)) throw GltfError(nodeName(node) + ": world transform is not finite");
        if (n.mesh != -1) {
            if (n.mesh < 0 || size_t(n.mesh) >= model_.meshes.size())
                throw GltfError(nodeName(node) + " references missing mesh " + std::to_string(n.mesh));
            instances_.push_back({n.mesh, world});
        }
        onPath_[size_t(node)] = 1;
        for (int child : n.children) walk(child, world, depth + 1);
        onPath_[size_t(node)] = 0;
    }

    [[nodiscard]] std::vector<Instance> take() { return std::move(instances_); }

private:
    static std::string nodeName(int node) { return "node " + std::to_string(node); }

    const glm::mat4& local(int node) {
        std::optional<glm::mat4>& m = local_[size_t(node)];
        if (!m) m = localMatrix(model_.nodes[size_t(node)], node);
        return *m;
    }

    const tinygltf::Model& model_;
    std::vector<char> onPath_;
    std::vector<std::optional<glm::mat4>> local_;
    size_t visits_ = 0;
    std::vector<Instance> instances_;
};

/// Root nodes: the default scene's; without one, scene 0's (the spec leaves the choice to the
/// viewer, and merging scenes would overlay alternatives, such as variants of one part); without
/// scenes, every node no other node lists as a child.
std::vector<int> rootNodes(const tinygltf::Model& model, std::vector<std::string>& notes) {
    // tinygltf's -1: no "scene" property.
    if (model.defaultScene != -1) {
        if (model.defaultScene < 0 || size_t(model.defaultScene) >= model.scenes.size())
            throw GltfError("default scene " + std::to_string(model.defaultScene) + " does not exist");
        return model.scenes[size_t(model.defaultScene)].nodes;
    }
    if (!model.scenes.empty()) {
        if (model.scenes.size() > 1)
            notes.push_back("no default scene: scene 0 of " + str(model.scenes.size()) + " shown");
        return model.scenes[0].nodes;
    }
    std::vector<char> isChild(model.nodes.size(), 0);
    for (const auto& node : model.nodes)
        for (int child : node.children)
            if (child >= 0 && size_t(child) < model.nodes.size()) isChild[size_t(child)] = 1;
    std::vector<int> roots;
    for (size_t i = 0; i < model.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    if (roots.empty() && !model.nodes.empty()) throw GltfError("every node has a parent (cycle in the node hierarchy)");
    return roots;
}

std::vector<Instance> collectInstances(const tinygltf::Model& model, std::vector<std::string>& notes) {
    if (model.nodes.empty()) {
        // Some exporters write bare meshes without nodes; place each once at the origin.
        std::vector<Instance> all;
        for (size_t i = 0; i < model.meshes.size(); ++i) all.push_back({int(i), glm::mat4(1.f)});
        if (!all.empty()) notes.push_back("no nodes: meshes placed untransformed");
        return all;
    }
    NodeWalker walker(model);
    for (int root : rootNodes(model, notes)) walker.walk(root, glm::mat4(1.f), 0);
    return walker.take();
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Primitives

std::string modeName(int mode) {
    switch (mode) {
    case TINYGLTF_MODE_POINTS: return "POINTS";
    case TINYGLTF_MODE_LINE: return "LINES";
    case TINYGLTF_MODE_LINE_LOOP: return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP: return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLES: return "TRIANGLES";
    case TINYGLTF_MODE_TRIANGLE_STRIP: return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN: return "TRIANGLE_FAN";
    default: return std::to_string(mode);
    }
}

bool isTriangleMode(int mode) {
    return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
           mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

/// A triangle list from the primitive's vertex sequence; strips and fans are unrolled with
/// glTF's winding rules so orientation survives.
std::vector<uint32_t> toTriangleList(std::vector<uint32_t> seq, int mode) {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        seq.resize(seq.size() / 3 * 3);
        return seq;
    }
    std::vector<uint32_t> out;
    if (seq.size() < 3) return out;
    out.reserve((seq.size() - 2) * 3);
    for (size_t i = 0; i + 2 < seq.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN) out.insert(out.end(), {seq[0], seq[i + 1], seq[i + 2]});
        else if (i % 2 == 0) out.insert(out.end(), {seq[i], seq[i + 1], seq[i + 2]});
        else out.insert(out.end(), {seq[i], seq[i + 2], seq[i + 1]});
    }
    return out;
}

glm::vec3 baseColor(const tinygltf::Model& model, int material, const std::string& where,
                    std::vector<std::string>& notes) {
    if (material < 0) return kDefaultColor;
    if (size_t(material) >= model.materials.size()) {
        notes.push_back(where + ": missing material " + std::to_string(material) + ", default colour used");
        return kDefaultColor;
    }
    const std::vector<double>& f = model.materials[size_t(material)].pbrMetallicRoughness.baseColorFactor;
    if (f.size() < 3 || !std::isfinite(f[0]) || !std::isfinite(f[1]) || !std::isfinite(f[2])) return kDefaultColor;
    return glm::clamp(glm::vec3(float(f[0]), float(f[1]), float(f[2])), glm::vec3(0.f), glm::vec3(1.f));
}

/// NORMAL is optional and recomputable, so a malformed one is dropped with a note rather than
/// rejecting the file; an out-of-range one is still an error (the file is corrupt).
/// The primitive's NORMAL accessor checked (and decoded, where compressed), not read: cleanup makes
/// every normal anew from the crease angle, so the file's would only be read to be dropped (the 4 M
/// piperack as GLB: 34 MB). A note says where they could not have served anyway.
void checkNormals(Accessors& accessors, const tinygltf::Primitive& prim, size_t accessorCount, const std::string& where,
                  std::vector<std::string>& notes) {
    const auto it = prim.attributes.find("NORMAL");
    if (it == prim.attributes.end()) return;
    const AccessorView& v = accessors.view(it->second);
    if (!gltf::isNormalType(v)) {
        notes.push_back(where + ": NORMAL is " + componentName(v.componentType) + " " + typeName(v.type) +
                        ", not FLOAT or normalized BYTE or SHORT VEC3; normals recomputed");
    } else if (v.count != accessorCount) {
        notes.push_back(where + ": NORMAL count differs from POSITION; normals recomputed");
    }
}

/// Indices or accessor elements a thread of decodePrimitive's passes takes at least.
constexpr size_t kDecodePerThreadMin = size_t(1) << 16;

/// One primitive as an object-space Mesh, or nothing (with a note) when it holds no triangles.
std::optional<scene::Mesh> decodePrimitive(const tinygltf::Model& model, Accessors& accessors, size_t meshIndex,
                                           size_t primIndex, std::vector<std::string>& notes) {
    const tinygltf::Mesh& gltfMesh = model.meshes[meshIndex];
    const tinygltf::Primitive& prim = gltfMesh.primitives[primIndex];
    const std::string where = "mesh " + str(meshIndex) + " primitive " + str(primIndex);
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (!isTriangleMode(mode)) {
        notes.push_back(where + ": mode " + modeName(mode) + " skipped");
        return std::nullopt;
    }
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) {
        // The spec lets clients skip primitives without positions.
        notes.push_back(where + ": no POSITION attribute, skipped");
        return std::nullopt;
    }
    const AccessorView& positions = accessors.view(position->second);
    if (!gltf::isPositionType(positions))
        throw GltfError(where + ": POSITION must be VEC3 of FLOAT, or of (UNSIGNED_)BYTE or (UNSIGNED_)SHORT (" +
                        "KHR_mesh_quantization), not " + componentName(positions.componentType) + " " +
                        typeName(positions.type));

    std::vector<uint32_t> sequence; // vertex sequence, as indices into `vertices` once remapped
    std::vector<uint32_t> vertices; // accessor elements this primitive uses, ascending
    if (prim.indices >= 0) {
        sequence = gltf::readIndices(accessors.view(prim.indices), positions.count, where);
        // Read only the vertices referenced: primitives often share one large vertex accessor,
        // and copying it whole per primitive would multiply memory by the primitive count.
        if (sequence.size() >= positions.count / 8) {
            // Most of the accessor is used (one mesh, one primitive: the common large file): a
            // table over the accessor numbers them in linear passes, in the same ascending order,
            // each on every core. Used elements are marked by relaxed atomic stores (any thread
            // writes the same 1); each range of the table then numbers its marks after the ranges
            // before it.
            scene::UnwrittenVector<uint32_t> renumbered(positions.count);
            const unsigned tableThreads = scene::rangeThreads(renumbered.size(), kDecodePerThreadMin),
                           sequenceThreads = scene::rangeThreads(sequence.size(), kDecodePerThreadMin);
            scene::forEachRange(renumbered.size(), tableThreads, [&](unsigned, size_t b, size_t e) {
                std::fill(renumbered.begin() + std::ptrdiff_t(b), renumbered.begin() + std::ptrdiff_t(e), 0u);
            });
            scene::forEachRange(sequence.size(), sequenceThreads, [&](unsigned, size_t b, size_t e) {
                for (size_t k = b; k < e; ++k)
                    std::atomic_ref(renumbered[sequence[k]]).store(1, std::memory_order_relaxed);
            });
            std::vector<size_t> first(tableThreads + 1, 0);
            scene::forEachRange(renumbered.size(), tableThreads, [&](unsigned r, size_t b, size_t e) {
                first[r + 1] = size_t(
                    std::count(renumbered.begin() + std::ptrdiff_t(b), renumbered.begin() + std::ptrdiff_t(e), 1u));
            });
            std::partial_sum(first.begin(), first.end(), first.begin());
            vertices.resize(first.back());
            scene::forEachRange(renumbered.size(), tableThreads, [&](unsigned r, size_t b, size_t e) {
                size_t id = first[r];
                for (size_t i = b; i < e; ++i)
                    if (renumbered[i]) {
                        renumbered[i] = uint32_t(id);
                        vertices[id++] = uint32_t(i);
                    }
            });
            scene::forEachRange(sequence.size(), sequenceThreads, [&](unsigned, size_t b, size_t e) {
                for (size_t k = b; k < e; ++k) sequence[k] = renumbered[sequence[k]];
            });
        } else {
            vertices = sequence;
            std::sort(vertices.begin(), vertices.end());
            vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
            for (uint32_t& i : sequence)
                i = uint32_t(std::lower_bound(vertices.begin(), vertices.end(), i) - vertices.begin());
        }
    } else {
        // positions.count fits uint32: bounded by the buffer (>= 3 bytes a vertex) or, without
        // one, by Accessors::view.
        vertices.resize(positions.count);
        for (size_t i = 0; i < vertices.size(); ++i) vertices[i] = uint32_t(i);
        sequence = vertices;
    }

    scene::Mesh mesh;
    mesh.name = (gltfMesh.name.empty() ? "mesh " + str(meshIndex) : gltfMesh.name) +
                (gltfMesh.primitives.size() > 1 ? " #" + str(primIndex) : "");
    mesh.positions = gltf::readVec3(positions, vertices);
    checkNormals(accessors, prim, positions.count, where, notes);
    if (mode == TINYGLTF_MODE_TRIANGLES && sequence.size() % 3 != 0)
        notes.push_back(where + ": " + str(sequence.size() % 3) + " trailing indices ignored");
    mesh.indices = toTriangleList(std::move(sequence), mode);

    mesh.color = baseColor(model, prim.material, where, notes);
    // Always two-sided: glTF's doubleSided=false is a shading hint, not a promise that the
    // surface is a closed solid, and one-sided casting would drop shadows of open CAD sheets.
    mesh.twoSided = true;
    return mesh;
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Cleaning and instancing

/// A primitive decoded and cleaned once, however many nodes instance it.
struct CleanPrimitive {
    scene::Mesh mesh;
    CleanupReport report;
};

/// glTF mesh index → its cleaned triangle primitives, for the meshes some node uses.
using CleanedMeshes = std::map<int, std::vector<CleanPrimitive>>;

/// Upper bound of what decodePrimitive() allocates, from (validated) accessor counts alone.
size_t decodeCost(Accessors& accessors, const tinygltf::Primitive& prim) {
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    const auto position = prim.attributes.find("POSITION");
    if (!isTriangleMode(mode) || position == prim.attributes.end()) return 0;
    const size_t vertices = accessors.view(position->second).count;
    const size_t sequence = prim.indices >= 0 ? accessors.view(prim.indices).count : vertices;
    // Index sequence, its sorted copy and the unrolled triangle list (strips triple); positions
    // and normals of at most min(vertices, sequence) vertices.
    return sequence * 5 * sizeof(uint32_t) + std::min(vertices, sequence) * 2 * sizeof(glm::vec3);
}

/// Every accessor fits its buffer, but any number of primitives may reference the same large
/// accessor, so a small JSON could demand terabytes. Honest files decode to a few times their
/// buffers' size (meshopt-compressed views counted decoded, as they are while checked); the
/// margin is generous, the bound is what matters. Checked before decoding, so a hostile file
/// fails fast.
void checkDecodeBudget(const tinygltf::Model& model, Accessors& accessors, const CleanedMeshes& used,
                       size_t fileBytes) {
    size_t available = fileBytes;
    for (const tinygltf::Buffer& buffer : model.buffers) available += buffer.data.size();
    size_t cost = 0;
    for (const auto& entry : used)
        for (const tinygltf::Primitive& prim : model.meshes[size_t(entry.first)].primitives) {
            // Each term < 2^44 (counts within 64 times a 4 GiB buffer): no overflow before the check.
            cost += decodeCost(accessors, prim);
            const size_t budget = 16 * (available + accessors.decodedBytes()) + (size_t{64} << 20);
            if (cost > budget)
                throw GltfError("primitives would decode to more than " + str(budget >> 20) +
                                " MiB (accessors shared by too many primitives)");
        }
}

void notify(const Progress& progress, float fraction, std::string_view stage) {
    if (progress) progress(fraction, stage);
}

/// Decodes and cleans each used mesh once; primitives that cleanup empties are noted and their
/// reports go to `emptied`. `hadTriangles` tells whether any primitive had triangles before
/// cleanup, so an empty result can say which of the two it is.
CleanedMeshes cleanUsedMeshes(const tinygltf::Model& model, Accessors& accessors,
                              const std::vector<Instance>& instances, size_t fileBytes, const CleanupOptions& options,
                              const Progress& progress, CleanupReport& emptied, bool& hadTriangles,
                              std::vector<std::string>& notes) {
    CleanedMeshes cleaned;
    size_t total = 0, done = 0;
    for (const Instance& inst : instances)
        if (cleaned.try_emplace(inst.mesh).second) total += model.meshes[size_t(inst.mesh)].primitives.size();
    checkDecodeBudget(model, accessors, cleaned, fileBytes);
    for (auto& [meshIndex, primitives] : cleaned) {
        for (size_t p = 0; p < model.meshes[size_t(meshIndex)].primitives.size(); ++p) {
            notify(progress, float(done++) / float(total), "cleaning");
            std::optional<scene::Mesh> mesh = decodePrimitive(model, accessors, size_t(meshIndex), p, notes);
            accessors.releaseLentPages(); // the file's pages are not part of cleanup's peak
            if (!mesh) continue;
            hadTriangles = hadTriangles || !mesh->indices.empty();
            CleanupReport report = cleanMesh(*mesh, options);
            if (mesh->indices.empty()) {
                notes.push_back("mesh " + std::to_string(meshIndex) + " primitive " + str(p) +
                                ": no triangles left after cleanup");
                emptied += report;
                continue;
            }
            primitives.push_back({std::move(*mesh), std::move(report)});
        }
    }
    return cleaned;
}

/// One chunked Mesh per cleaned primitive of each used glTF mesh, reports summed once per
/// primitive: placed at its node's world matrix, or, where several nodes use the glTF mesh, one
/// instanced Mesh placed at each (Mesh::instances): its arrays are held once however often a part
/// repeats. Meshes come in the order nodes first use them.
void emitInstances(const std::vector<Instance>& instances, CleanedMeshes& cleaned, const Progress& progress,
                   LoadedModel& result) {
    std::vector<int> order;
    std::map<int, std::vector<glm::mat4>> placements;
    for (const Instance& inst : instances) {
        auto [it, fresh] = placements.try_emplace(inst.mesh);
        if (fresh) order.push_back(inst.mesh);
        it->second.push_back(inst.world);
    }
    size_t triangles = 0;
    for (int m : order)
        for (const CleanPrimitive& prim : cleaned[m]) triangles += prim.mesh.triangleCount();
    if (triangles > kMaxInstancedTriangles)
        throw GltfError("the meshes hold " + str(triangles) + " triangles (limit " + str(kMaxInstancedTriangles) + ")");

    for (size_t k = 0; k < order.size(); ++k) {
        notify(progress, float(k) / float(order.size()), "chunking");
        const std::vector<glm::mat4>& worlds = placements[order[k]];
        for (CleanPrimitive& prim : cleaned[order[k]]) {
            scene::Mesh mesh = std::move(prim.mesh); // each glTF mesh is emitted once
            if (worlds.size() == 1) mesh.transform = worlds[0];
            else mesh.instances = worlds;
            scene::chunkMesh(mesh);
            result.report += prim.report;
            result.meshes.push_back(std::move(mesh));
        }
    }
    notify(progress, 1.f, "chunking");
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Loading

LoadedModel loadChecked(const std::string& path, const CleanupOptions& options, const Progress& progress) {
    notify(progress, 0.f, "reading");
    std::string problem;
    const std::optional<uint64_t> fileSize = regularFileSize(path, problem);
    if (!fileSize) throw GltfError(problem);
    const size_t fileBytes = size_t(*fileSize);
    // Mapped, not read: accessors read the BIN chunk in place (lendBinChunk). Writable, privately, for
    // a JSON rewritten in place (parse).
    MappedFile file(path, *fileSize, true);
    Parsed parsed = parse(path, file);
    const tinygltf::Model& model = parsed.model;
    std::vector<std::string> notes = std::move(parsed.notes);
    const std::vector<Instance> instances = collectInstances(model, notes);
    notify(progress, 1.f, "reading");

    LoadedModel result;
    result.format = parsed.binary ? "glb" : "gltf";
    bool hadTriangles = false;
    Accessors accessors(model, std::move(parsed.facts));
    CleanedMeshes cleaned =
        cleanUsedMeshes(model, accessors, instances, fileBytes, options, progress, result.report, hadTriangles, notes);
    emitInstances(instances, cleaned, progress, result);
    // The same words as the other formats; which primitives were skipped is no help to someone
    // who opened a point cloud or a file of lines.
    if (result.meshes.empty())
        throw GltfError(hadTriangles ? nothingLeftMessage(result.report) : "the file has no triangles");
    result.report.notes.insert(result.report.notes.end(), notes.begin(), notes.end());
    return result;
}

} // namespace

LoadedModel loadGltf(const std::string& path, const CleanupOptions& options, const Progress& progress) {
    try {
        return loadChecked(path, options, progress);
    } catch (const GltfError& e) {
        throw std::runtime_error(path + ": " + oneLine(e.what()));
    } catch (const std::bad_alloc&) {
        throw std::runtime_error(path + ": out of memory");
    }
}

} // namespace geometry::io
