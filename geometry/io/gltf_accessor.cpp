// glTF accessor data (see gltf_accessor.h): what tinygltf 2.7 hands over raw or not at all.
//
// Index
//   [SECTION] Names and JSON ............ str, componentName, typeName, member, indexInto
//   [SECTION] EXT_meshopt_compression ... readMeshoptViews, replaceFallbackBuffers
//   [SECTION] Sparse indices ............ lendIndexViews, readUnsigned, AccessorView::substitute
//   [SECTION] Accessors ................. Accessors (view, viewBytes, releaseLentPages, bufferData, decode,
//                                         addSparse)
//   [SECTION] Reading ................... isPositionType, isNormalType, readVec3, readIndices
#include "geometry/io/gltf_accessor.h"

#include "geometry/io/mapped_file.h"
#include "geometry/io/mesh_limits.h"

#include "geometry/scene/parallel_ranges.h"
#include "geometry/scene/scratch_pages.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

namespace geometry::io::gltf {

// ---------------------------------------------------------------------------------------------
// [SECTION] Names and JSON

std::string str(size_t n) { return std::to_string(n); }

std::string componentName(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "DOUBLE";
    default: return "componentType " + std::to_string(componentType);
    }
}

std::string typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "type " + std::to_string(type);
    }
}

const nlohmann::json& member(const nlohmann::json& object, const char* key) {
    static const nlohmann::json kNull;
    if (!object.is_object()) return kNull;
    const auto it = object.find(key);
    return it == object.end() ? kNull : *it;
}

std::optional<size_t> indexInto(const nlohmann::json& value, const nlohmann::json& array) {
    if (!value.is_number_integer() || !array.is_array()) return std::nullopt;
    const auto i = value.get<int64_t>();
    if (i < 0 || uint64_t(i) >= array.size()) return std::nullopt;
    return size_t(i);
}

// ---------------------------------------------------------------------------------------------
// [SECTION] EXT_meshopt_compression

namespace {

constexpr const char* kMeshopt = "EXT_meshopt_compression";

/// meshoptimizer's codecs spend at least 2 header bits on each 16 decoded bytes (attributes), a
/// byte on each triangle or index: no valid stream decodes to more than 64 times its length, so
/// a larger claim is refused before anything is allocated for it.
constexpr uint64_t kMaxMeshoptRatio = 64;

/// A buffer standing in for one whose bytes are never read: tinygltf refuses empty data URIs.
constexpr const char* kPlaceholderUri = "data:application/octet-stream;base64,AA==";

MeshoptView readMeshoptView(const nlohmann::json& doc, const nlohmann::json& view, const nlohmann::json& ext,
                            const std::string& name) {
    if (!ext.is_object()) throw GltfError(name + " is not an object");
    auto number = [&](const char* key, std::optional<uint64_t> absent) -> size_t {
        const nlohmann::json& value = member(ext, key);
        if (value.is_null() && absent) return *absent;
        // Beyond 2^40 no check below can pass; bounding here keeps the products exact.
        if (!value.is_number_unsigned() || value.get<uint64_t>() > (uint64_t{1} << 40))
            throw GltfError(name + ": " + key + " must be an integer from 0 to 2^40");
        return size_t(value.get<uint64_t>());
    };
    MeshoptView m;
    const nlohmann::json& buffers = member(doc, "buffers");
    const auto buffer = indexInto(member(ext, "buffer"), buffers);
    if (!buffer) throw GltfError(name + " names no existing buffer");
    m.buffer = *buffer;
    m.byteOffset = number("byteOffset", 0);
    m.byteLength = number("byteLength", std::nullopt);
    m.byteStride = number("byteStride", std::nullopt);
    m.count = number("count", std::nullopt);

    const nlohmann::json& mode = member(ext, "mode");
    if (mode == "ATTRIBUTES") m.mode = MeshoptMode::Attributes;
    else if (mode == "TRIANGLES") m.mode = MeshoptMode::Triangles;
    else if (mode == "INDICES") m.mode = MeshoptMode::Indices;
    else throw GltfError(name + ": mode must be ATTRIBUTES, TRIANGLES or INDICES");
    const nlohmann::json& filter = member(ext, "filter");
    if (filter.is_null() || filter == "NONE") m.filter = MeshoptFilter::None;
    else if (filter == "OCTAHEDRAL") m.filter = MeshoptFilter::Octahedral;
    else if (filter == "QUATERNION") m.filter = MeshoptFilter::Quaternion;
    else if (filter == "EXPONENTIAL") m.filter = MeshoptFilter::Exponential;
    else throw GltfError(name + ": filter must be NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");

    // The spec's validity rules, which are also what meshoptimizer asserts (an abort, not an
    // error code, in Debian's build).
    const size_t stride = m.byteStride;
    if (m.mode == MeshoptMode::Attributes) {
        if (stride == 0 || stride > 256 || stride % 4 != 0)
            throw GltfError(name + ": ATTRIBUTES byteStride " + str(stride) + " is not a multiple of 4 up to 256");
    } else {
        if (stride != 2 && stride != 4) throw GltfError(name + ": index byteStride " + str(stride) + " is not 2 or 4");
        if (m.filter != MeshoptFilter::None) throw GltfError(name + ": index data cannot have a filter");
        if (m.mode == MeshoptMode::Triangles && m.count % 3 != 0)
            throw GltfError(name + ": TRIANGLES count " + str(m.count) + " is not a multiple of 3");
    }
    if (m.filter == MeshoptFilter::Octahedral && stride != 4 && stride != 8)
        throw GltfError(name + ": OCTAHEDRAL byteStride " + str(stride) + " is not 4 or 8");
    if (m.filter == MeshoptFilter::Quaternion && stride != 8)
        throw GltfError(name + ": QUATERNION byteStride " + str(stride) + " is not 8");
    if (m.count > detail::kMaxIndexed)
        throw GltfError(name + ": count " + str(m.count) + " is over the 2^32 - 1 that 32-bit indices reach");

    const uint64_t decoded = uint64_t(m.count) * stride; // < 2^40
    if (decoded / kMaxMeshoptRatio > m.byteLength)
        throw GltfError(name + ": " + str(m.count) + " elements of " + str(stride) + " bytes cannot come from " +
                        str(m.byteLength) + " compressed bytes");
    const nlohmann::json& length = member(view, "byteLength");
    if (!length.is_number_unsigned() || length.get<uint64_t>() != decoded)
        throw GltfError(name + ": the buffer view's byteLength is not count * byteStride (" + str(decoded) + ")");
    if (const nlohmann::json& parent = member(view, "byteStride"); !parent.is_null() && parent != stride)
        throw GltfError(name + ": byteStride differs from the buffer view's");
    const nlohmann::json& bufferLength = member(buffers[m.buffer], "byteLength");
    const uint64_t available = bufferLength.is_number_unsigned() ? bufferLength.get<uint64_t>() : 0;
    if (m.byteOffset > available || m.byteLength > available - m.byteOffset)
        throw GltfError(name + ": compressed data (offset " + str(m.byteOffset) + ", length " + str(m.byteLength) +
                        ") exceeds buffer " + str(m.buffer) + " (" + std::to_string(available) + " bytes)");
    return m;
}

} // namespace

MeshoptViews readMeshoptViews(const nlohmann::json& doc) {
    MeshoptViews views;
    const nlohmann::json& all = member(doc, "bufferViews");
    if (!all.is_array()) return views;
    for (size_t i = 0; i < all.size(); ++i) {
        const nlohmann::json& ext = member(member(all[i], "extensions"), kMeshopt);
        if (!ext.is_null())
            views[i] = readMeshoptView(doc, all[i], ext, "buffer view " + str(i) + ": " + std::string(kMeshopt));
    }
    return views;
}

std::set<size_t> replaceFallbackBuffers(nlohmann::json& doc, bool binary, const MeshoptViews& views) {
    if (views.empty() || !member(doc, "buffers").is_array()) return {};
    nlohmann::json& buffers = doc["buffers"];
    std::set<size_t> parents, sources;
    for (const auto& [index, compressed] : views) {
        if (const auto parent = indexInto(member(doc["bufferViews"][index], "buffer"), buffers))
            parents.insert(*parent);
        sources.insert(compressed.buffer);
    }
    std::set<size_t> replaced;
    for (size_t b = 0; b < buffers.size(); ++b) {
        const bool fallback = member(member(member(buffers[b], "extensions"), kMeshopt), "fallback") == true;
        // Without a URI a buffer has no bytes, except a GLB's first (its BIN chunk).
        const bool empty = !member(buffers[b], "uri").is_string() && !(binary && b == 0) && parents.contains(b);
        if ((fallback || empty) && !sources.contains(b) && buffers[b].is_object()) {
            buffers[b]["uri"] = kPlaceholderUri;
            buffers[b]["byteLength"] = 1;
            replaced.insert(b);
        }
    }
    return replaced;
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Sparse indices

std::set<size_t> lendIndexViews(nlohmann::json& doc) {
    const nlohmann::json& meshes = member(doc, "meshes");
    const nlohmann::json& accessors = member(doc, "accessors");
    const nlohmann::json& views = member(doc, "bufferViews");
    if (!meshes.is_array() || !accessors.is_array() || !views.is_array() || views.empty()) return {};
    // tinygltf gives the accessors of Draco primitives bufferViews of their own: leave them.
    std::set<size_t> draco, candidates;
    for (const nlohmann::json& mesh : meshes)
        for (const nlohmann::json& prim : member(mesh, "primitives")) {
            const auto indices = indexInto(member(prim, "indices"), accessors);
            if (member(member(prim, "extensions"), "KHR_draco_mesh_compression").is_object()) {
                if (indices) draco.insert(*indices);
                for (const nlohmann::json& attribute : member(prim, "attributes"))
                    if (const auto a = indexInto(attribute, accessors)) draco.insert(*a);
            } else if (indices && member(accessors[*indices], "bufferView").is_null() &&
                       member(accessors[*indices], "sparse").is_object()) {
                candidates.insert(*indices);
            }
        }
    std::set<size_t> lent;
    for (size_t a : candidates)
        if (!draco.contains(a)) {
            doc["accessors"][a]["bufferView"] = 0;
            lent.insert(a);
        }
    return lent;
}

namespace {

uint64_t readUnsigned(const unsigned char* p, size_t size) {
    switch (size) {
    case 1: return *p;
    case 2: {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    default: {
        uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

} // namespace

const unsigned char* AccessorView::substitute(size_t i) const {
    // Indices are strictly increasing (checked by Accessors::addSparse): binary search.
    size_t lo = 0, hi = sparseCount;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (readUnsigned(sparseIndices + mid * sparseIndexSize, sparseIndexSize) < i) lo = mid + 1;
        else hi = mid;
    }
    if (lo < sparseCount && readUnsigned(sparseIndices + lo * sparseIndexSize, sparseIndexSize) == i)
        return sparseValues + lo * elementSize;
    return nullptr;
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Accessors

Accessors::Accessors(const tinygltf::Model& model, JsonFacts facts)
    : model_(model), facts_(std::move(facts)), cache_(model.accessors.size()),
      memory_(facts_.meshopt.empty() ? 0 : detail::availableMemory()) {}

const AccessorView& Accessors::view(int index) {
    const std::string name = "accessor " + std::to_string(index);
    if (index < 0 || size_t(index) >= model_.accessors.size()) throw GltfError(name + " does not exist");
    std::optional<AccessorView>& cached = cache_[size_t(index)];
    if (cached) return *cached;
    const tinygltf::Accessor& acc = model_.accessors[size_t(index)];

    const int componentSize = tinygltf::GetComponentSizeInBytes(uint32_t(acc.componentType));
    const int components = tinygltf::GetNumComponentsInType(uint32_t(acc.type));
    if (componentSize <= 0 || components <= 0) throw GltfError(name + " has an invalid componentType or type");
    AccessorView v;
    v.count = acc.count;
    v.elementSize = size_t(componentSize) * size_t(components);
    v.stride = v.elementSize;
    v.componentType = acc.componentType;
    v.type = acc.type;
    v.normalized = acc.normalized;

    const int viewIndex = facts_.lentViews.contains(size_t(index)) ? -1 : acc.bufferView;
    if (viewIndex >= 0) {
        const Span bytes = viewBytes(viewIndex);
        if (bytes.stride) v.stride = bytes.stride;
        if (v.stride < v.elementSize)
            throw GltfError(name + ": byteStride " + str(v.stride) + " is smaller than an element (" +
                            str(v.elementSize) + " bytes)");
        if (acc.count > 0) {
            // byteOffset + (count - 1) * stride + elementSize <= length, without overflow.
            bool fits = acc.byteOffset <= bytes.length && v.elementSize <= bytes.length - acc.byteOffset;
            if (fits) fits = acc.count - 1 <= (bytes.length - acc.byteOffset - v.elementSize) / v.stride;
            if (!fits)
                throw GltfError(name + ": " + str(acc.count) + " elements (stride " + str(v.stride) + ", offset " +
                                str(acc.byteOffset) + ") exceed buffer view " + std::to_string(viewIndex) + " (" +
                                str(bytes.length) + " bytes)");
            v.data = bytes.data + acc.byteOffset;
        }
    } else if (acc.count > detail::kMaxIndexed) {
        // Zeros cost the file nothing: their count is bounded as every reader bounds vertices
        // (what decoding them costs is checked against the decode budget, in gltf_loader.cpp).
        throw GltfError(name + ": " + str(acc.count) + " elements without a bufferView, over the 2^32 - 1 limit");
    }
    if (acc.sparse.isSparse) addSparse(v, acc, name);
    cached = v;
    return *cached;
}

Accessors::Span Accessors::viewBytes(int viewIndex) {
    const std::string name = "buffer view " + std::to_string(viewIndex);
    if (viewIndex < 0 || size_t(viewIndex) >= model_.bufferViews.size()) throw GltfError(name + " does not exist");
    const tinygltf::BufferView& view = model_.bufferViews[size_t(viewIndex)];
    if (const auto it = facts_.meshopt.find(size_t(viewIndex)); it != facts_.meshopt.end()) {
        // The decoded layout is count elements of the extension's byteStride.
        const std::vector<unsigned char>& bytes = decode(size_t(viewIndex), it->second);
        return {bytes.data(), bytes.size(), view.byteStride ? view.byteStride : it->second.byteStride};
    }
    if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
        throw GltfError(name + " references missing buffer " + std::to_string(view.buffer));
    if (facts_.fallbackBuffers.contains(size_t(view.buffer)))
        throw GltfError(name + " reads buffer " + std::to_string(view.buffer) + ", an " + kMeshopt +
                        " fallback that only compressed views may use");
    const std::span<const unsigned char> data = bufferData(size_t(view.buffer));
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        throw GltfError(name + " (offset " + str(view.byteOffset) + ", length " + str(view.byteLength) +
                        ") exceeds buffer " + std::to_string(view.buffer) + " (" + str(data.size()) + " bytes)");
    return {data.data() + view.byteOffset, view.byteLength, view.byteStride};
}

void Accessors::releaseLentPages() const noexcept {
    if (facts_.lentBin) MappedFile::release(facts_.lentBin->data(), facts_.lentBin->data() + facts_.lentBin->size());
}

std::span<const unsigned char> Accessors::bufferData(size_t b) const {
    if (b == 0 && facts_.lentBin) return *facts_.lentBin;
    return model_.buffers[b].data;
}

const std::vector<unsigned char>& Accessors::decode(size_t viewIndex, const MeshoptView& compressed) {
    if (const auto it = decoded_.find(viewIndex); it != decoded_.end()) return it->second;
    const std::string name = "buffer view " + str(viewIndex) + ": " + kMeshopt;
    // Rechecked against the bytes tinygltf loaded: readMeshoptViews saw only declared lengths.
    if (compressed.buffer >= model_.buffers.size())
        throw GltfError(name + " references missing buffer " + str(compressed.buffer));
    const std::span<const unsigned char> source = bufferData(compressed.buffer);
    if (compressed.byteOffset > source.size() || compressed.byteLength > source.size() - compressed.byteOffset)
        throw GltfError(name + ": compressed data (offset " + str(compressed.byteOffset) + ", length " +
                        str(compressed.byteLength) + ") exceeds buffer " + str(compressed.buffer) + " (" +
                        str(source.size()) + " bytes)");
    const size_t size = compressed.count * compressed.byteStride; // at most 64 × byteLength: readMeshoptViews
    if (size > memory_ || decodedBytes_ > memory_ - size)
        throw GltfError(name + ": decoding " + str(decodedBytes_ + size) + " bytes in all exceeds the " +
                        std::to_string(memory_) + " bytes of memory available");
    std::vector<unsigned char> out(size);
    if (size > 0) {
        const unsigned char* in = source.data() + compressed.byteOffset;
        const size_t count = compressed.count, stride = compressed.byteStride, length = compressed.byteLength;
        int status = 0;
        switch (compressed.mode) {
        case MeshoptMode::Attributes: status = meshopt_decodeVertexBuffer(out.data(), count, stride, in, length); break;
        case MeshoptMode::Triangles: status = meshopt_decodeIndexBuffer(out.data(), count, stride, in, length); break;
        case MeshoptMode::Indices: status = meshopt_decodeIndexSequence(out.data(), count, stride, in, length); break;
        }
        if (status != 0)
            throw GltfError(name + ": the compressed data cannot be decoded (meshoptimizer error " +
                            std::to_string(status) + ")");
        switch (compressed.filter) {
        case MeshoptFilter::None: break;
        case MeshoptFilter::Octahedral: meshopt_decodeFilterOct(out.data(), count, stride); break;
        case MeshoptFilter::Quaternion: meshopt_decodeFilterQuat(out.data(), count, stride); break;
        case MeshoptFilter::Exponential: meshopt_decodeFilterExp(out.data(), count, stride); break;
        }
    }
    decodedBytes_ += size;
    return decoded_.emplace(viewIndex, std::move(out)).first->second;
}

void Accessors::addSparse(AccessorView& v, const tinygltf::Accessor& acc, const std::string& name) {
    const auto& sparse = acc.sparse;
    if (sparse.count < 1 || size_t(sparse.count) > acc.count)
        throw GltfError(name + ": sparse count " + std::to_string(sparse.count) + " is not within 1 to its " +
                        str(acc.count) + " elements");
    const size_t indexSize = sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                             : sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                             : sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                                      : 0;
    if (indexSize == 0)
        throw GltfError(name + ": sparse indices must be unsigned integers, not " +
                        componentName(sparse.indices.componentType));
    const auto n = size_t(sparse.count); // < 2^31, so the byte counts below cannot overflow
    auto window = [&](int viewIndex, int offset, size_t bytes, const char* what) {
        const Span span = viewBytes(viewIndex);
        if (offset < 0 || size_t(offset) > span.length || bytes > span.length - size_t(offset))
            throw GltfError(name + ": sparse " + what + " (" + str(bytes) + " bytes at offset " +
                            std::to_string(offset) + ") exceed buffer view " + std::to_string(viewIndex) + " (" +
                            str(span.length) + " bytes)");
        return span.data + offset;
    };
    v.sparseIndices = window(sparse.indices.bufferView, sparse.indices.byteOffset, n * indexSize, "indices");
    v.sparseValues = window(sparse.values.bufferView, sparse.values.byteOffset, n * v.elementSize, "values");
    v.sparseIndexSize = indexSize;
    // Checked once here, so that element() may binary-search them.
    uint64_t previous = 0;
    for (size_t k = 0; k < n; ++k) {
        const uint64_t i = readUnsigned(v.sparseIndices + k * indexSize, indexSize);
        if (i >= acc.count)
            throw GltfError(name + ": sparse index " + std::to_string(i) + " out of range (" + str(acc.count) +
                            " elements)");
        if (k > 0 && i <= previous)
            throw GltfError(name + ": sparse indices not strictly increasing (" + std::to_string(previous) + " then " +
                            std::to_string(i) + ")");
        previous = i;
    }
    v.sparseCount = n;
}

// ---------------------------------------------------------------------------------------------
// [SECTION] Reading

bool isPositionType(const AccessorView& v) {
    switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return v.type == TINYGLTF_TYPE_VEC3;
    default: return false;
    }
}

bool isNormalType(const AccessorView& v) {
    const bool quantized = v.normalized && (v.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                                            v.componentType == TINYGLTF_COMPONENT_TYPE_SHORT);
    return v.type == TINYGLTF_TYPE_VEC3 && (v.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || quantized);
}

namespace {

template <typename T> float component(const unsigned char* p, bool normalized) {
    T c;
    std::memcpy(&c, p, sizeof c);
    if constexpr (std::is_floating_point_v<T>) {
        return c;
    } else {
        constexpr auto max = float(std::numeric_limits<T>::max());
        if (!normalized) return float(c);
        // glTF: max(c / MAX, -1) for signed types, so that MIN and -MAX both give -1.
        return std::is_signed_v<T> ? std::max(float(c) / max, -1.f) : float(c) / max;
    }
}

/// Accessor elements a thread reads at least: below this one thread reads them all.
constexpr size_t kElementsPerThreadMin = size_t(1) << 16;

template <typename T>
void readVec3As(const AccessorView& v, const std::vector<uint32_t>& which, glm::vec3* out, size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
        const unsigned char* p = v.element(which[i]);
        out[i] = {component<T>(p, v.normalized), component<T>(p + sizeof(T), v.normalized),
                  component<T>(p + 2 * sizeof(T), v.normalized)};
    }
}

template <typename T> void readIndicesAs(const AccessorView& v, uint32_t* out, size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
        T value;
        std::memcpy(&value, v.element(i), sizeof(T));
        out[i] = uint32_t(value);
    }
}

} // namespace

std::vector<glm::vec3> readVec3(const AccessorView& v, const std::vector<uint32_t>& which) {
    if (v.type != TINYGLTF_TYPE_VEC3) throw GltfError("a " + typeName(v.type) + " accessor read as VEC3");
    void (*read)(const AccessorView&, const std::vector<uint32_t>&, glm::vec3*, size_t, size_t) = nullptr;
    switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: read = readVec3As<float>; break;
    case TINYGLTF_COMPONENT_TYPE_BYTE: read = readVec3As<int8_t>; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: read = readVec3As<uint8_t>; break;
    case TINYGLTF_COMPONENT_TYPE_SHORT: read = readVec3As<int16_t>; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: read = readVec3As<uint16_t>; break;
    default: throw GltfError("a " + componentName(v.componentType) + " accessor read as VEC3");
    }
    // Pages in memory first: a large accessor's copy faulted them in one by one on one thread (the
    // 4 M GLB's 12 M indices: a fifth of its load's page faults).
    std::vector<glm::vec3> out;
    scene::scratch::resizePrepared(out, which.size());
    scene::forEachRange(which.size(), scene::rangeThreads(which.size(), kElementsPerThreadMin),
                        [&](unsigned, size_t b, size_t e) { read(v, which, out.data(), b, e); });
    return out;
}

std::vector<uint32_t> readIndices(const AccessorView& v, size_t vertexCount, const std::string& where) {
    if (v.type != TINYGLTF_TYPE_SCALAR) throw GltfError(where + ": indices must be SCALAR, not " + typeName(v.type));
    const int type = v.componentType;
    if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        throw GltfError(where + ": indices must be unsigned integers, not " + componentName(type));
    std::vector<uint32_t> out;
    scene::scratch::resizePrepared(out, v.count);
    // Read and checked on every core; the error names the first index out of range, as one thread
    // reading front to back would.
    const unsigned threads = scene::rangeThreads(v.count, kElementsPerThreadMin);
    std::vector<size_t> firstBad(threads, v.count);
    scene::forEachRange(v.count, threads, [&](unsigned r, size_t b, size_t e) {
        if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) readIndicesAs<uint8_t>(v, out.data(), b, e);
        else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) readIndicesAs<uint16_t>(v, out.data(), b, e);
        else readIndicesAs<uint32_t>(v, out.data(), b, e);
        for (size_t i = b; i < e; ++i)
            if (out[i] >= vertexCount) {
                firstBad[r] = i;
                return;
            }
    });
    if (const size_t bad = *std::min_element(firstBad.begin(), firstBad.end()); bad < v.count)
        throw GltfError(where + ": index " + std::to_string(out[bad]) + " out of range (" + str(vertexCount) +
                        " vertices)");
    return out;
}

} // namespace geometry::io::gltf
