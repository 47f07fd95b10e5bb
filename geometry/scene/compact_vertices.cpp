#include "geometry/scene/compact_vertices.h"

#include "geometry/scene/parallel_ranges.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace geometry::scene {

namespace {

constexpr uint32_t kUnseen = std::numeric_limits<uint32_t>::max();
constexpr uint32_t kMaxChunkVertices = 1u << 16;                // 16-bit indices
constexpr double kMaxCount = double((1u << kPositionBits) - 1); // the largest 16-bit count
constexpr size_t kSnapPerThreadMin = size_t(1) << 16;           // vertices a thread snaps at least

/// The chunks must tile the index buffer in order, each naming vertices that exist.
bool chunksTile(const Mesh& mesh) noexcept {
    uint32_t next = 0;
    for (const Chunk& c : mesh.chunks) {
        if (c.firstTriangle != next) return false;
        next += c.triangleCount;
    }
    return next == mesh.triangleCount();
}

/// Every component a whole number.
bool whole(const glm::vec3& q) noexcept { return q == glm::floor(q); }

/// On the grid (snapToGrid's result): a float multiple of the step, which the step's power of two
/// divides exactly.
bool onGrid(const glm::vec3& p, float step) noexcept { return whole(p / step); }

int snorm10(float c) noexcept {
    if (!std::isfinite(c)) return 0;
    return int(std::lround(std::clamp(c, -1.f, 1.f) * 511.f));
}

/// Pass 1 of compactVertices: each chunk's vertices (counted once per chunk that uses them), its
/// object-space box, and the grid.
struct Layout {
    std::vector<uint32_t> seenIn; // scratch: the last chunk that used each vertex
    std::vector<Aabb> boxes;
    std::vector<uint32_t> chunkVertices;
    float step = 0.f;
};

std::optional<Layout> layout(const Mesh& mesh) {
    if (mesh.chunks.empty() || mesh.positions.empty() || !chunksTile(mesh)) return std::nullopt;
    const size_t vertexCount = mesh.positions.size();
    Layout out;
    std::vector<uint32_t>& seenIn = out.seenIn;
    std::vector<Aabb>& boxes = out.boxes;
    seenIn.assign(vertexCount, kUnseen);
    boxes.resize(mesh.chunks.size());
    out.chunkVertices.resize(mesh.chunks.size());
    out.step = gridStep(mesh);
    for (size_t k = 0; k < mesh.chunks.size(); ++k) {
        const Chunk& c = mesh.chunks[k];
        uint32_t count = 0;
        for (size_t i = size_t(c.firstTriangle) * 3; i < (size_t(c.firstTriangle) + c.triangleCount) * 3; ++i) {
            const uint32_t v = mesh.indices[i];
            if (v >= vertexCount) return std::nullopt;
            if (seenIn[v] == uint32_t(k)) continue;
            seenIn[v] = uint32_t(k);
            const glm::vec3& p = mesh.positions[v];
            if (!finite(p) || !onGrid(p, out.step)) return std::nullopt;
            boxes[k].add(p);
            ++count;
        }
        if (count > kMaxChunkVertices) return std::nullopt;
        out.chunkVertices[k] = count;
    }
    return out;
}

} // namespace

glm::vec3 CompactVertices::position(size_t chunk, size_t local) const noexcept {
    const CompactChunk& c = chunks[chunk];
    if (c.wide) return floatPositions[c.firstVertex + local];
    const auto& q = positions[c.firstVertex + local];
    return c.origin + step * glm::vec3(float(q[0]), float(q[1]), float(q[2]));
}

uint32_t packNormal(const glm::vec3& n) noexcept {
    const auto field = [](float c) { return uint32_t(snorm10(c)) & 0x3ffu; };
    return field(n.x) | field(n.y) << 10 | field(n.z) << 20;
}

glm::vec3 unpackNormal(uint32_t packed) noexcept {
    const auto field = [packed](int shift) {
        int v = int((packed >> shift) & 0x3ffu);
        if (v >= 512) v -= 1024;
        return std::max(float(v) / 511.f, -1.f);
    };
    return {field(0), field(10), field(20)};
}

float gridStep(const Mesh& mesh) noexcept {
    // The largest of each range's largest, on every core: the same for any split.
    const size_t n = mesh.positions.size();
    const unsigned threads = rangeThreads(n, kSnapPerThreadMin);
    std::vector<float> largest(threads, 0.f);
    forEachRange(n, threads, [&](unsigned r, size_t b, size_t e) {
        float l = 0.f;
        for (size_t i = b; i < e; ++i) {
            const glm::vec3& p = mesh.positions[i];
            if (finite(p)) l = std::max({l, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        }
        largest[r] = l;
    });
    const float l = *std::max_element(largest.begin(), largest.end());
    return std::ldexp(float(kGridUlps), std::ilogb(std::max(l, std::numeric_limits<float>::min())) - 23);
}

void snapToGrid(Mesh& mesh) {
    const double step = gridStep(mesh), inverse = 1.0 / step; // exact: a power of two
    constexpr double kLargest = std::numeric_limits<float>::max();
    std::vector<glm::vec3>& positions = mesh.positions;
    forEachRange(
        positions.size(), rangeThreads(positions.size(), kSnapPerThreadMin), [&](unsigned, size_t b, size_t e) {
            const auto snap = [step, inverse](float& c) noexcept {
                // Exact: a power of two divides, and |q| < 2^22 with at most 24 significant bits (the step is
                // 8 spacings at the largest coordinate), so q ± 0.5 is exact too and the conversion that
                // truncates it is std::round(q), sign of a zero included, without a library call.
                const double q = double(c) * inverse; // = c / step: scaling by a power of two is exact
                double x = std::copysign(double(int64_t(q + std::copysign(0.5, q))), q) * step; // exact in float
                // Within half a step of float's largest value, rounding up would leave its range: round
                // towards zero instead (less than a step away).
                if (std::abs(x) > kLargest) x = std::trunc(q) * step;
                c = float(x);
            };
            for (size_t i = b; i < e; ++i) {
                glm::vec3& p = positions[i];
                if (!finite(p)) continue;
                snap(p.x);
                snap(p.y);
                snap(p.z);
            }
        });
}

namespace {

/// layout()'s step where its success is certain without its pass over every corner (half of `mesh
/// info`'s time after loading): a chunk of at most kMaxChunkVertices / 3 triangles cannot name more
/// vertices than a chunk may hold, so with every index in range and every vertex, used or not, finite
/// and on the grid, layout() succeeds. None: ask layout().
std::optional<float> certainStep(const Mesh& mesh) {
    if (mesh.chunks.empty() || mesh.positions.empty() || !chunksTile(mesh)) return std::nullopt;
    for (const Chunk& c : mesh.chunks)
        if (c.triangleCount > kMaxChunkVertices / 3) return std::nullopt;
    const float step = gridStep(mesh), inverse = 1.f / step;
    const bool exactInverse = std::isfinite(inverse) && inverse * step == 1.f; // not for a subnormal step
    const size_t n = mesh.positions.size();
    std::atomic<bool> certain{true};
    forEachRange(n, rangeThreads(n, kSnapPerThreadMin), [&](unsigned, size_t b, size_t e) {
        for (size_t i = b; i < e; ++i)
            // With an exact inverse, a product in place of each division gives the same quotient (both
            // exact, or rounded alike); three divisions a vertex were most of the pass.
            if (!finite(mesh.positions[i]) ||
                !(exactInverse ? whole(mesh.positions[i] * inverse) : onGrid(mesh.positions[i], step))) {
                certain.store(false, std::memory_order_relaxed);
                return;
            }
    });
    const size_t corners = mesh.indices.size();
    forEachRange(corners, rangeThreads(corners, kSnapPerThreadMin), [&](unsigned, size_t b, size_t e) {
        for (size_t i = b; i < e; ++i)
            if (mesh.indices[i] >= n) {
                certain.store(false, std::memory_order_relaxed);
                return;
            }
    });
    return certain.load(std::memory_order_relaxed) ? std::optional(step) : std::nullopt;
}

} // namespace

std::optional<float> compactStep(const Mesh& mesh) {
    if (const std::optional<float> step = certainStep(mesh)) return step;
    const std::optional<Layout> l = layout(mesh);
    return l ? std::optional(l->step) : std::nullopt;
}

std::optional<CompactVertices> compactVertices(const Mesh& mesh) {
    std::optional<Layout> l = layout(mesh);
    if (!l) return std::nullopt;
    const std::vector<Aabb>& boxes = l->boxes;
    std::vector<uint32_t>& seenIn = l->seenIn;
    CompactVertices out;
    out.step = l->step;
    const double step = out.step;
    // Which chunks are too wide for 16-bit counts, and how many vertices each kind has.
    out.chunks.resize(mesh.chunks.size());
    size_t narrowVertices = 0, wideVertices = 0;
    for (size_t k = 0; k < mesh.chunks.size(); ++k) {
        CompactChunk& cc = out.chunks[k];
        cc.origin = glm::vec3(glm::floor(glm::dvec3(boxes[k].lo) / step) * step); // a multiple of the step: exact
        const glm::dvec3 span = (glm::dvec3(boxes[k].hi) - glm::dvec3(cc.origin)) / step;
        cc.wide = !(std::max({span.x, span.y, span.z}) < kMaxCount + 0.5); // rounds past the largest count
        (cc.wide ? wideVertices : narrowVertices) += l->chunkVertices[k];
    }
    out.positions.resize(narrowVertices);
    out.normals.resize(narrowVertices);
    out.floatPositions.resize(wideVertices);
    out.floatNormals.resize(wideVertices);
    out.indices.resize(mesh.indices.size());
    // Pass 2: number each chunk's vertices in first use and store them on the grid.
    std::fill(seenIn.begin(), seenIn.end(), kUnseen);
    std::vector<uint16_t> local(mesh.positions.size());
    uint32_t nextNarrow = 0, nextWide = 0;
    for (size_t k = 0; k < mesh.chunks.size(); ++k) {
        const Chunk& c = mesh.chunks[k];
        CompactChunk& cc = out.chunks[k];
        uint32_t& next = cc.wide ? nextWide : nextNarrow;
        cc.firstVertex = next;
        const glm::dvec3 origin(cc.origin);
        uint32_t count = 0;
        for (size_t i = size_t(c.firstTriangle) * 3; i < (size_t(c.firstTriangle) + c.triangleCount) * 3; ++i) {
            const uint32_t v = mesh.indices[i];
            if (seenIn[v] != uint32_t(k)) {
                seenIn[v] = uint32_t(k);
                local[v] = uint16_t(count);
                const glm::dvec3 q = glm::round((glm::dvec3(mesh.positions[v]) - origin) / step);
                const uint32_t normal =
                    packNormal(v < mesh.normals.size() ? mesh.normals[v] : glm::vec3(0.f, 1.f, 0.f));
                const size_t at = cc.wide ? size_t(nextWide) + count : size_t(nextNarrow) + count;
                if (cc.wide) {
                    out.floatPositions[at] = mesh.positions[v];
                    out.floatNormals[at] = normal;
                } else {
                    out.positions[at] = {uint16_t(q.x), uint16_t(q.y), uint16_t(q.z), 0};
                    out.normals[at] = normal;
                }
                ++count;
            }
            out.indices[i] = local[v];
        }
        next += count;
    }
    return out;
}

} // namespace geometry::scene
