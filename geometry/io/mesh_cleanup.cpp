// Mesh cleanup on flat arrays (positions/indices). A halfedge structure cannot hold the
// non-manifold edges CAD exports are full of, and flat arrays keep every step O(n).
//
// Index
//   [SECTION] Cleanup report ............. CleanupReport::operator+=
//   [SECTION] Small helpers .............. Faces, mix, tableSize, keepUnmarked, renumber,
//                                          bucketFaces, fitCapacity
//   [SECTION] Bad faces and duplicates ... dropNonFinite, MergeGrid, TwoBitCounts, mergeCandidates,
//                                          mergeDuplicates, dropDegenerate, dropDuplicateFaces
//   [SECTION] Orientation ................ VertexFaces, cornerOf, fixOrientation
//   [SECTION] Normals .................... clusterCornerNormals, cornerNormals, splitCornersByNormal,
//                                          computeNormals
//   [SECTION] Cleaning a mesh ............ cleanMesh
#include "geometry/io/model_loader.h"
#include "geometry/scene/parallel_ranges.h"
#include "geometry/scene/scratch_pages.h"
#include "geometry/scene/unwritten_vector.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <span>
#include <tuple>
#include <utility>

namespace geometry::io {

// ---- [SECTION] Cleanup report ---------------------------------------------------------------

CleanupReport& CleanupReport::operator+=(const CleanupReport& o) {
    inputVertices += o.inputVertices;
    inputFaces += o.inputFaces;
    nonFiniteVertices += o.nonFiniteVertices;
    nonFiniteFaces += o.nonFiniteFaces;
    degenerateFaces += o.degenerateFaces;
    mergedVertices += o.mergedVertices;
    mergeTolerance = std::max(mergeTolerance, o.mergeTolerance);
    duplicateFaces += o.duplicateFaces;
    isolatedVertices += o.isolatedVertices;
    flippedFaces += o.flippedFaces;
    polygonsTriangulated += o.polygonsTriangulated;
    nonPlanarFaces += o.nonPlanarFaces;
    earClipFallbacks += o.earClipFallbacks;
    outputVertices += o.outputVertices;
    outputFaces += o.outputFaces;
    notes.insert(notes.end(), o.notes.begin(), o.notes.end());
    return *this;
}

namespace {

// ---- [SECTION] Small helpers ----------------------------------------------------------------

constexpr uint32_t kNone = ~0u;
using Tri = std::array<uint32_t, 3>;
/// The faces being cleaned: the mesh's own index array, three corners a face, taken over and handed
/// back as the mesh's indices. A copy of it (and a new array for the result) would be two more arrays
/// of the model's size to fault in and fill.
class Faces {
public:
    explicit Faces(std::vector<uint32_t>&& flat) noexcept : flat_(std::move(flat)) {
        flat_.resize(flat_.size() / 3 * 3); // a trailing part of a face is none (Mesh::triangleCount)
    }
    [[nodiscard]] size_t size() const noexcept { return flat_.size() / 3; }
    [[nodiscard]] std::span<uint32_t, 3> operator[](size_t f) noexcept {
        return std::span<uint32_t, 3>(flat_.data() + 3 * f, 3);
    }
    [[nodiscard]] Tri tri(size_t f) const noexcept { return {flat_[3 * f], flat_[3 * f + 1], flat_[3 * f + 2]}; }
    /// Every corner, face after face.
    [[nodiscard]] std::span<uint32_t> corners() noexcept { return flat_; }
    [[nodiscard]] std::span<const uint32_t> corners() const noexcept { return flat_; }
    /// Keeps the first `faces` faces.
    void truncate(size_t faces) { flat_.resize(3 * std::min(faces, size())); }
    [[nodiscard]] std::vector<uint32_t> release() && noexcept { return std::move(flat_); }

private:
    std::vector<uint32_t> flat_;
};

uint64_t mix(uint64_t x) { // splitmix64 finaliser: cheap, good enough spread for probing
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

size_t tableSize(size_t n) {
    size_t cap = 16;
    while (cap < 2 * n) cap <<= 1;
    return cap;
}

/// Faces per thread below which a pass over the faces stays on one thread.
constexpr size_t kFacesPerThreadMin = size_t(1) << 17;

/// Drops the faces marked in `drop`, keeping the others in order; returns how many went. The faces
/// before the first mark stay where they are: most files have nothing to drop.
size_t keepUnmarked(Faces& tris, const scene::ScratchVector<char>& drop) {
    const size_t first = size_t(std::find(drop.begin(), drop.end(), char(1)) - drop.begin());
    if (first == drop.size()) return 0;
    size_t out = first;
    for (size_t f = first + 1; f < tris.size(); ++f) {
        if (drop[f]) continue;
        std::ranges::copy(tris[f], tris[out].begin());
        ++out;
    }
    const size_t dropped = tris.size() - out;
    tris.truncate(out);
    return dropped;
}

/// Every corner v becomes to[v], on every core.
void renumber(Faces& tris, const scene::ScratchVector<uint32_t>& to) {
    const std::span<uint32_t> corners = tris.corners();
    scene::forEachRange(corners.size(), scene::rangeThreads(tris.size(), kFacesPerThreadMin),
                        [&](unsigned, size_t b, size_t e) {
                            for (size_t c = b; c < e; ++c) corners[c] = to[corners[c]];
                        });
}

/// Faces a bucketing pass looks at together: a block whose vertices all lie outside a thread's range
/// is skipped by that thread.
constexpr size_t kBucketBlockFaces = 4096;

/// Faces bucketed by vertex (a counting sort): `corners(f, emit)` calls emit(v) for each vertex face f
/// is listed under; `start` gets vertexCount + 1 offsets into `order`, which lists each vertex's faces
/// in face order. On every core: each thread owns a range of vertices and writes only their counts and
/// list entries, reading the blocks of faces that touch its range (a loaded mesh numbers its vertices
/// about in face order, so mostly its own share), so the result is the same for any thread count.
template <class Corners>
void bucketFaces(size_t vertexCount, size_t faceCount, const Corners& corners, scene::ScratchVector<uint32_t>& start,
                 scene::UnwrittenVector<uint32_t>& order) {
    const unsigned threads = scene::rangeThreads(faceCount, kFacesPerThreadMin);
    const size_t blocks = (faceCount + kBucketBlockFaces - 1) / kBucketBlockFaces;
    // body(v, f) for every vertex v that the faces of block k list under.
    const auto forBlockCorners = [&](size_t k, const auto& body) {
        for (size_t f = k * kBucketBlockFaces; f < std::min(faceCount, (k + 1) * kBucketBlockFaces); ++f)
            corners(f, [&](uint32_t v) { body(v, uint32_t(f)); });
    };
    std::vector<std::pair<uint32_t, uint32_t>> span(blocks, {~0u, 0u}); // the vertices a block lists under
    scene::forEachRange(blocks, threads, [&](unsigned, size_t b, size_t e) {
        for (size_t k = b; k < e; ++k)
            forBlockCorners(k, [&](uint32_t v, uint32_t) {
                span[k].first = std::min(span[k].first, v);
                span[k].second = std::max(span[k].second, v);
            });
    });
    // Each thread's faces listed under its vertices [lo, hi), block by block.
    const auto forOwnCorners = [&](size_t lo, size_t hi, const auto& body) {
        for (size_t k = 0; k < blocks; ++k)
            if (span[k].second >= lo && span[k].first < hi)
                forBlockCorners(k, [&](uint32_t v, uint32_t f) {
                    if (v >= lo && v < hi) body(v, f);
                });
    };
    start.assign(vertexCount + 1, 0);
    scene::forEachRange(vertexCount, threads, [&](unsigned, size_t lo, size_t hi) {
        forOwnCorners(lo, hi, [&](uint32_t v, uint32_t) { ++start[v + 1]; });
    });
    std::partial_sum(start.begin(), start.end(), start.begin());
    order.resize(start.back());
    scene::forEachRange(vertexCount, threads, [&](unsigned, size_t lo, size_t hi) {
        std::vector<uint32_t> fill(start.begin() + lo, start.begin() + hi);
        forOwnCorners(lo, hi, [&](uint32_t v, uint32_t f) { order[fill[v - lo]++] = f; });
    });
}

/// Reallocates `v` to its size plus `spare` when it holds more than 1/16 beyond that.
template <class T> void fitCapacity(std::vector<T>& v, size_t spare) {
    const size_t want = v.size() + spare;
    if (v.capacity() <= want + v.size() / 16) return;
    std::vector<T> tight;
    tight.reserve(want);
    scene::scratch::prepareCapacity(tight);
    tight.assign(v.begin(), v.end());
    v.swap(tight);
}

// ---- [SECTION] Bad faces and duplicates -----------------------------------------------------

/// Drops faces with an index out of range or touching a NaN/Inf vertex. Returns the
/// finite-vertex mask. Faces are judged on every core, each range counting its own.
scene::ScratchVector<char> dropNonFinite(const scene::Mesh& mesh, Faces& tris, CleanupReport& r) {
    const size_t n = mesh.positions.size();
    scene::ScratchVector<char> ok(n);
    scene::forEachRange(n, scene::rangeThreads(n, kFacesPerThreadMin), [&](unsigned, size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) ok[i] = scene::finite(mesh.positions[i]);
    });
    r.nonFiniteVertices = static_cast<size_t>(std::count(ok.begin(), ok.end(), 0));
    const unsigned threads = scene::rangeThreads(tris.size(), kFacesPerThreadMin);
    std::vector<std::pair<size_t, size_t>> counts(threads); // faces out of range, faces touching non-finite
    scene::ScratchVector<char> drop(tris.size());
    scene::forEachRange(tris.size(), threads, [&](unsigned t, size_t b, size_t e) {
        size_t outOfRange = 0, nonFinite = 0;
        for (size_t f = b; f < e; ++f) {
            const Tri tri = tris.tri(f);
            if (tri[0] >= n || tri[1] >= n || tri[2] >= n) { // not a face at all
                ++outOfRange;
                drop[f] = 1;
                continue;
            }
            const bool bad = !ok[tri[0]] || !ok[tri[1]] || !ok[tri[2]];
            nonFinite += bad;
            drop[f] = bad;
        }
        counts[t] = {outOfRange, nonFinite};
    });
    for (const auto& [outOfRange, nonFinite] : counts) {
        r.degenerateFaces += outOfRange;
        r.nonFiniteFaces += nonFinite;
    }
    keepUnmarked(tris, drop);
    return ok;
}

/// A grid of cubic cells `size` wide, or with `exact` the coordinates' bits (−0 as +0): a zero
/// tolerance merges bit-equal points only, so many distinct points close together never share a cell.
struct MergeGrid {
    bool exact;
    double size;
    [[nodiscard]] int64_t cell(const glm::vec3& p, int axis) const noexcept {
        if (exact) {
            const float x = p[axis] == 0.f ? 0.f : p[axis];
            uint32_t bits;
            std::memcpy(&bits, &x, sizeof bits);
            return bits;
        }
        return static_cast<int64_t>(std::clamp(std::floor(p[axis] / size), -1e15, 1e15));
    }
    [[nodiscard]] uint64_t hash(const glm::vec3& p) const noexcept { return hash(cell(p, 0), cell(p, 1), cell(p, 2)); }
    [[nodiscard]] static uint64_t hash(int64_t x, int64_t y, int64_t z) noexcept {
        return mix(static_cast<uint64_t>(x) * 0x9E3779B97F4A7C15ull ^ mix(static_cast<uint64_t>(y)) * 31 ^
                   mix(static_cast<uint64_t>(z) + 0x632BE59BD9B4E019ull));
    }
};

/// Vertices per thread below which the merge's linear passes stay on one thread.
constexpr size_t kMergePerThreadMin = size_t(1) << 16;

/// Occupancy counters that count to 2 (more is the same): two bits hold one, 32 to a word, a quarter
/// of a byte table's size, which at plant scale is far larger than the caches (the 50 M piperack STL:
/// 64 instead of 256 MiB). At least 8 counters an item: few collisions.
struct TwoBitCounts {
    uint32_t mask;
    scene::ScratchVector<uint64_t> words;
    explicit TwoBitCounts(size_t items)
        : mask(uint32_t(std::min<size_t>(tableSize(4 * items), size_t(1) << 30) - 1)),
          words((size_t(mask) + 32) / 32, 0) {}
    [[nodiscard]] unsigned operator[](uint32_t s) const noexcept {
        return unsigned(words[s >> 5] >> (2 * (s & 31)) & 3);
    }
    /// Counts item i at counter slotOf(i) (none for kNone), i < items. Each thread owns a slice of the
    /// counters (whole words) and reads every item's, so no increment needs to be atomic. Counters
    /// are prefetched a few items ahead: the table may be larger than the caches.
    template <class SlotOf> void count(size_t items, unsigned threads, const SlotOf& slotOf) {
        constexpr size_t kAhead = 16;
        const size_t slice = (words.size() + threads - 1) / threads * 32;
        scene::forEachRange(threads, threads, [&](unsigned t, size_t, size_t) {
            const size_t lo = slice * t, hi = lo + slice;
            for (size_t i = 0; i < items; ++i) {
                if (i + kAhead < items) __builtin_prefetch(&words[(slotOf(i + kAhead) & mask) >> 5], 1);
                const uint32_t s = slotOf(i);
                if (s >= lo && s < hi && (*this)[s] < 2) words[s >> 5] += uint64_t(1) << (2 * (s & 31));
            }
        });
    }
};

/// The finite vertices that may lie within `tol` of another, in index order. A vertex alone in its
/// cell of a coarse grid (64 tolerances wide) and farther than `tol` from the cell's faces has no
/// other within `tol`, and none has it: it can be left out of the merge without changing any
/// result, and the set kept holds every neighbour of its members. Occupancy is counted in a table
/// by hash (a collision only keeps a vertex in), in parallel: the final counts, and so the set, do
/// not depend on the order of the increments. Where collisions would be most of the vertices a count
/// does not clear, those are counted again by other bits of the same hash in a table of their own
/// (every vertex of a cell goes on to the second count, so none is lost). With `among`
/// (ascending vertex ids, all finite), only those are looked at and counted: the others must be
/// alone in their cells.
scene::ScratchVector<uint32_t> mergeCandidates(std::span<const glm::vec3> pos, const scene::ScratchVector<char>& ok,
                                               double tol, std::span<const uint32_t> among = {}) {
    const size_t n = among.empty() ? pos.size() : among.size();
    const auto vertex = [&](size_t i) { return among.empty() ? uint32_t(i) : among[i]; };
    const bool exact = !(tol > 0);
    const double inv = exact ? 1.0 : 1.0 / (64 * tol), reach = 1.0 / 64;
    // The coarse cell's hash; `near` tells whether p lies within `tol` of one of its faces.
    const auto coarse = [&](const glm::vec3& p, bool& near) noexcept {
        if (exact) return MergeGrid{true, 1.0}.hash(p);
        int64_t c[3];
        for (int a = 0; a < 3; ++a) {
            const double x = double(p[a]) * inv, cell = std::floor(x), f = x - cell;
            near = near || f < reach || f > 1 - reach;
            c[a] = static_cast<int64_t>(std::clamp(cell, -1e15, 1e15));
        }
        return MergeGrid::hash(c[0], c[1], c[2]);
    };
    const unsigned threads = scene::rangeThreads(n, kMergePerThreadMin);
    constexpr uint32_t kNear = 0x80000000u, kMet = 0x40000000u, kNotFinite = kNone;
    // Each vertex's first counter (bit 31: near a cell face), then the counts (near or not: a vertex
    // near a face may share its cell with one that is not).
    TwoBitCounts first(n);
    scene::UnwrittenVector<uint32_t> slot(n);
    scene::forEachRange(n, threads, [&](unsigned, size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) {
            bool near = false;
            const uint32_t v = vertex(i);
            slot[i] = ok[v] ? uint32_t(coarse(pos[v], near) & first.mask) | (near ? kNear : 0u) : kNotFinite;
        }
    });
    first.count(n, threads, [&](size_t i) { return slot[i] == kNotFinite ? kNone : slot[i] & ~kNear; });
    // Each range's vertices near a face or met in the first count, with a code: bit 31 near, bit 30
    // met, and then (for the second count) its counter in the second table.
    struct alignas(scene::kRangeStateAlign) Kept {
        scene::ScratchVector<uint32_t> v, code;
        size_t met = 0;
    };
    std::vector<Kept> kept(threads);
    scene::forEachRange(n, threads, [&](unsigned t, size_t b, size_t e) {
        constexpr size_t kAhead = 16;
        Kept& k = kept[t];
        for (size_t i = b; i < e; ++i) {
            if (i + kAhead < e) __builtin_prefetch(&first.words[(slot[i + kAhead] & first.mask) >> 5]);
            if (slot[i] == kNotFinite) continue;
            const bool near = (slot[i] & kNear) != 0, met = first[slot[i] & first.mask] >= 2;
            if (!near && !met) continue;
            k.v.push_back(vertex(i));
            k.code.push_back((near ? kNear : 0u) | (met ? kMet : 0u));
            k.met += met;
        }
    });
    decltype(slot)().swap(slot);
    decltype(first.words)().swap(first.words);
    std::vector<size_t> offset(threads + 1, 0);
    for (unsigned t = 0; t < threads; ++t) offset[t + 1] = offset[t] + kept[t].met;
    // The second count, over the met vertices alone, by the same hash's high bits, in a table sized for
    // them: where most met only another cell's vertex (the 50 M piperack STL: 2.1 M of 24 M, about as
    // many as n·(1 − e^(−n/counters)) collisions), not where most share a cell (a glTF's copies of a
    // position, one for each normal, before they are folded).
    const double counters = double(first.mask) + 1, collisions = double(n) * -std::expm1(-double(n) / counters);
    if (double(offset.back()) < 2 * collisions) {
        TwoBitCounts second(offset.back());
        scene::UnwrittenVector<uint32_t> metSlot(offset.back());
        scene::forEachRange(threads, threads, [&](unsigned t, size_t, size_t) {
            Kept& k = kept[t];
            size_t j = offset[t];
            for (size_t i = 0; i < k.v.size(); ++i) {
                if (!(k.code[i] & kMet)) continue;
                bool unused = false;
                k.code[i] |= uint32_t(coarse(pos[k.v[i]], unused) >> 32) & second.mask;
                metSlot[j++] = k.code[i] & second.mask;
            }
        });
        second.count(offset.back(), threads, [&](size_t i) { return metSlot[i]; });
        decltype(metSlot)().swap(metSlot);
        // Kept: near a face, or met in both counts.
        scene::forEachRange(threads, threads, [&](unsigned t, size_t, size_t) {
            Kept& k = kept[t];
            size_t j = 0;
            for (size_t i = 0; i < k.v.size(); ++i)
                if ((k.code[i] & kNear) || second[k.code[i] & second.mask] >= 2) k.v[j++] = k.v[i];
            k.v.resize(j);
        });
    }
    for (size_t t = 1; t < kept.size(); ++t) {
        kept[0].v.insert(kept[0].v.end(), kept[t].v.begin(), kept[t].v.end());
        scene::ScratchVector<uint32_t>().swap(kept[t].v);
    }
    return std::move(kept[0].v);
}

/// Candidates ahead whose slot a pass over them prefetches.
constexpr uint32_t kMergeAhead = 8;

/// Removes from `candidates` (vertex ids, ascending) each whose position is bit-equal to an earlier
/// one's (−0 as +0), pointing its `rep` at that first copy (no list: a mesh may hold as many copies
/// as vertices); returns how many went. A table of candidate indices, compared through their
/// positions.
size_t dropBitEqualCopies(std::span<const glm::vec3> pos, scene::ScratchVector<uint32_t>& candidates,
                          scene::ScratchVector<uint32_t>& rep) {
    const MergeGrid bits{true, 1.0}; // a zero tolerance's grid: cells are the coordinates' bits
    const auto same = [&](uint32_t a, uint32_t b) {
        return bits.cell(pos[a], 0) == bits.cell(pos[b], 0) && bits.cell(pos[a], 1) == bits.cell(pos[b], 1) &&
               bits.cell(pos[a], 2) == bits.cell(pos[b], 2);
    };
    const size_t cap = tableSize(candidates.size());
    scene::ScratchVector<uint32_t> slots(cap, kNone); // vertex ids
    size_t kept = 0;
    for (size_t k = 0; k < candidates.size(); ++k) {
        if (k + kMergeAhead < candidates.size())
            __builtin_prefetch(&slots[bits.hash(pos[candidates[k + kMergeAhead]]) & (cap - 1)]);
        const uint32_t v = candidates[k];
        size_t s = bits.hash(pos[v]) & (cap - 1);
        while (slots[s] != kNone && !same(slots[s], v)) s = (s + 1) & (cap - 1);
        if (slots[s] == kNone) {
            slots[s] = v;
            candidates[kept++] = v;
        } else {
            rep[v] = slots[s];
        }
    }
    const size_t copies = candidates.size() - kept;
    candidates.resize(kept);
    return copies;
}

/// Maps every vertex to the first vertex within `tol` of it (spatial hash over the candidates of
/// mergeCandidates, in index order); non-finite vertices map to themselves and are dropped later
/// as unused. With `read` Distinct no candidate is looked for among bit-equal copies.
scene::ScratchVector<uint32_t> mergeDuplicates(std::span<const glm::vec3> pos, const scene::ScratchVector<char>& ok,
                                               double tol, ReadPositions read, CleanupReport& r) {
    const size_t n = pos.size();
    scene::ScratchVector<uint32_t> rep(n);
    std::iota(rep.begin(), rep.end(), 0u);
    scene::ScratchVector<uint32_t> candidates = mergeCandidates(pos, ok, tol);
    // Bit-equal candidates are one vertex before the ordered merge, as a binary STL's corners are when
    // read: a glTF, OBJ or PLY file repeats a position for each normal it has there, most of such a
    // file's candidates (the 4 M piperack as GLB: 1.8 M of 2.8 M vertices), all on one thread below.
    // Each later copy takes its first copy's result. A binary STL's weld leaves none (its 50 M
    // piperack: 0.21 s on one thread over 4.1 M candidates, to find none).
    const size_t copies = read == ReadPositions::Distinct ? 0 : dropBitEqualCopies(pos, candidates, rep);
    // A position that was a candidate for its copies alone is now alone in its cell: counted again
    // among the distinct candidates (every other vertex is alone in its cell), most go.
    if (copies > 0) candidates = mergeCandidates(pos, ok, tol, candidates);
    // Cells four tolerances wide: most points are far enough from every cell face that only
    // their own cell needs looking at.
    const MergeGrid grid{!(tol > 0), tol > 0 ? 4 * tol : 1.0};
    const double reach = tol > 0 ? 0.25 : 0.0;
    const double tol2 = tol * tol;
    const size_t cap = tableSize(candidates.size());
    // Cell lists of candidates, by their index in `candidates`.
    scene::ScratchVector<uint32_t> heads(cap, kNone), next(candidates.size(), kNone);
    // One bit a cell hash, set where a cell holds a candidate: nearly every cell a search looks at is
    // empty (merges beyond the STL weld are rare), and a clear bit says so from a table a quarter of
    // the size of `heads`, which stays in the cache where `heads` does not. A set bit may be another
    // cell's: the table decides. With the slot prefetch below, the 16 M piperack STL's loop (1.5 M
    // candidates) took 0.35-0.49 s instead of 0.65-0.75 s.
    const uint64_t bitMask = 8 * cap - 1;
    scene::ScratchVector<uint64_t> occupied(cap / 8, 0);
    const auto bitOf = [&](uint64_t h) -> std::pair<uint64_t&, uint64_t> {
        return {occupied[(h & bitMask) >> 6], uint64_t(1) << (h & 63)};
    };
    const auto maybeOccupied = [&](uint64_t h) {
        const auto [word, bit] = bitOf(h);
        return (word & bit) != 0;
    };
    // Each candidate's cell, its hash and which neighbours it reaches, worked out on every core: the
    // loop below, which must run in order, only looks them up (the 4 M piperack STL's merge stage:
    // 0.108 -> 0.092 s). The same expressions as before, so the same cells.
    struct Cell {
        int64_t c[3];
        uint64_t h;
    };
    scene::UnwrittenVector<Cell> cells(candidates.size());
    scene::UnwrittenVector<uint8_t> reaches(candidates.size()); // bit a: cell −1 on axis a; bit 3 + a: +1
    scene::forEachRange(candidates.size(), scene::rangeThreads(candidates.size(), kMergePerThreadMin),
                        [&](unsigned, size_t b, size_t e) {
                            for (size_t k = b; k < e; ++k) {
                                const glm::vec3& p = pos[candidates[k]];
                                Cell& cell = cells[k];
                                uint8_t bits = 0;
                                for (int a = 0; a < 3; ++a) {
                                    cell.c[a] = grid.cell(p, a);
                                    const double f = grid.exact ? 0.5 : p[a] / grid.size - std::floor(p[a] / grid.size);
                                    bits |= uint8_t((f < reach ? 1 : 0) << a | (f > 1 - reach ? 1 : 0) << (3 + a));
                                }
                                cell.h = MergeGrid::hash(cell.c[0], cell.c[1], cell.c[2]);
                                reaches[k] = bits;
                            }
                        });
    // Slot holding the list head of cell (x, y, z) of hash h, or the empty slot where it would go.
    auto find = [&](uint64_t h, int64_t x, int64_t y, int64_t z) -> size_t {
        for (size_t s = h & (cap - 1);; s = (s + 1) & (cap - 1)) {
            const uint32_t head = heads[s];
            if (head == kNone) return s;
            const Cell& q = cells[head];
            if (q.c[0] == x && q.c[1] == y && q.c[2] == z) return s;
        }
    };
    // The cells a candidate looks at, its own and those within reach in the order the search takes
    // them, with their hashes: worked out kMergeAhead candidates ahead, so that their occupied bits
    // and the candidate's own slot are prefetched. The bits' loads, from a table larger than the
    // caches keep (8 MiB at 50 M triangles), were most of the loop's time.
    struct Look {
        int count;
        int64_t c[8][3];
        uint64_t h[8];
    };
    std::array<Look, 2 * kMergeAhead> ring;
    const auto lookAhead = [&](size_t k) {
        Look& look = ring[k % ring.size()];
        const Cell& own = cells[k];
        look.count = 0;
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = reaches[k] >> a & 1 ? -1 : 0;
            hi[a] = reaches[k] >> (3 + a) & 1 ? 1 : 0;
        }
        for (int dx = lo[0]; dx <= hi[0]; ++dx)
            for (int dy = lo[1]; dy <= hi[1]; ++dy)
                for (int dz = lo[2]; dz <= hi[2]; ++dz) {
                    const int64_t x = own.c[0] + dx, y = own.c[1] + dy, z = own.c[2] + dz;
                    const uint64_t h = (dx | dy | dz) == 0 ? own.h : MergeGrid::hash(x, y, z);
                    look.c[look.count][0] = x;
                    look.c[look.count][1] = y;
                    look.c[look.count][2] = z;
                    look.h[look.count++] = h;
                    __builtin_prefetch(&occupied[(h & bitMask) >> 6]);
                }
        __builtin_prefetch(&heads[own.h & (cap - 1)]);
    };
    for (size_t k = 0; k < std::min<size_t>(kMergeAhead, candidates.size()); ++k) lookAhead(k);
    for (uint32_t k = 0; k < candidates.size(); ++k) {
        if (k + kMergeAhead < candidates.size()) lookAhead(k + kMergeAhead);
        const Look& look = ring[k % ring.size()];
        const uint32_t i = candidates[k];
        const glm::vec3& p = pos[i];
        const Cell& own = cells[k];
        const int64_t* const c = own.c;
        uint32_t found = kNone;
        for (int j = 0; j < look.count && found == kNone; ++j) {
            if (!maybeOccupied(look.h[j])) continue;
            for (uint32_t q = heads[find(look.h[j], look.c[j][0], look.c[j][1], look.c[j][2])]; q != kNone;
                 q = next[q]) {
                const glm::dvec3 d = glm::dvec3(pos[candidates[q]]) - glm::dvec3(p);
                if (glm::dot(d, d) <= tol2) {
                    found = candidates[q];
                    break;
                }
            }
        }
        if (found != kNone) {
            rep[i] = found;
            ++r.mergedVertices;
            continue;
        }
        const auto [word, bit] = bitOf(own.h);
        word |= bit;
        const size_t s = find(own.h, c[0], c[1], c[2]);
        if (heads[s] == kNone) heads[s] = k;
        else {
            next[k] = next[heads[s]];
            next[heads[s]] = k;
        }
    }
    if (copies > 0) {
        // A copy's rep is its first copy, whose own rep is now final (a vertex that maps to itself):
        // one step on. Only copies are written, and no copy is read.
        scene::forEachRange(n, scene::rangeThreads(n, kMergePerThreadMin), [&](unsigned, size_t b, size_t e) {
            for (size_t v = b; v < e; ++v)
                if (const uint32_t to = rep[rep[v]]; to != rep[v]) rep[v] = to;
        });
        r.mergedVertices += copies;
    }
    return rep;
}

/// Removes faces with a repeated index or an area below the merge resolution.
void dropDegenerate(std::span<const glm::vec3> pos, Faces& tris, double tol, CleanupReport& r) {
    const double minCross2 = tol * tol * tol * tol; // |cross| = 2·area ≤ tol²
    scene::ScratchVector<char> bad(tris.size());
    scene::forEachRange(tris.size(), scene::rangeThreads(tris.size(), kFacesPerThreadMin),
                        [&](unsigned, size_t b, size_t e) {
                            for (size_t f = b; f < e; ++f) {
                                const Tri t = tris.tri(f);
                                bool out = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
                                if (!out) {
                                    const glm::dvec3 p0(pos[t[0]]), p1(pos[t[1]]), p2(pos[t[2]]);
                                    const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
                                    out = glm::dot(n, n) <= minCross2;
                                }
                                bad[f] = out;
                            }
                        });
    r.degenerateFaces += keepUnmarked(tris, bad);
}

/// A face's vertices in ascending order: faces on the same three vertices, whatever their winding,
/// have the same key. Three compare-exchanges: std::sort's set-up costs more than its work.
Tri sortedKey(Tri t) noexcept {
    if (t[1] < t[0]) std::swap(t[0], t[1]);
    if (t[2] < t[1]) std::swap(t[1], t[2]);
    if (t[1] < t[0]) std::swap(t[0], t[1]);
    return t;
}

/// Faces a bucket holds up to which each is compared with every earlier one instead of sorting them.
constexpr size_t kPairwiseBucket = 8;

/// Keeps the first of every set of faces on the same three vertices, whatever their winding.
/// Duplicates share their smallest vertex, so faces are bucketed by it (counting sort: cache
/// friendly, unlike a hash table over all faces) and compared within a bucket only; buckets are
/// looked at on their own threads by vertex range (each face is in one bucket). Keys are worked out
/// from the faces where they are compared: an array of them was the model's size again (12 bytes a
/// face) to write and read.
void dropDuplicateFaces(size_t vertexCount, Faces& tris, CleanupReport& r) {
    const unsigned threads = scene::rangeThreads(tris.size(), kFacesPerThreadMin);
    scene::ScratchVector<uint32_t> start;
    scene::UnwrittenVector<uint32_t> order;
    bucketFaces(
        vertexCount, tris.size(), [&](size_t f, const auto& emit) { emit(sortedKey(tris.tri(f))[0]); }, start, order);
    scene::ScratchVector<char> dup(tris.size(), 0);
    scene::forEachRange(
        vertexCount, threads,
        [&](unsigned, size_t first, size_t last) {
            std::vector<std::pair<Tri, uint32_t>> large; // a bucket above kPairwiseBucket: keys and faces, sorted
            for (size_t v = first; v < last; ++v) {
                const uint32_t* begin = order.data() + start[v];
                const size_t count = start[v + 1] - start[v];
                if (count < 2) continue;
                // Faces come in face order: a face equal to an earlier one is the duplicate.
                if (count <= kPairwiseBucket) {
                    std::array<Tri, kPairwiseBucket> key;
                    for (size_t i = 0; i < count; ++i) {
                        key[i] = sortedKey(tris.tri(begin[i]));
                        for (size_t j = 0; j < i; ++j)
                            if (key[j] == key[i]) {
                                dup[begin[i]] = 1;
                                break;
                            }
                    }
                    continue;
                }
                // Equal keys end up adjacent, the earliest face first (it is the one kept).
                large.clear();
                for (size_t i = 0; i < count; ++i) large.emplace_back(sortedKey(tris.tri(begin[i])), begin[i]);
                std::sort(large.begin(), large.end());
                for (size_t i = 1; i < large.size(); ++i)
                    if (large[i].first == large[i - 1].first) dup[large[i].second] = 1;
            }
        },
        start);
    r.duplicateFaces += keepUnmarked(tris, dup);
}

// ---- [SECTION] Orientation ------------------------------------------------------------------

/// Vertex → incident faces, compressed (counting sort).
struct VertexFaces {
    scene::ScratchVector<uint32_t> offset;
    scene::UnwrittenVector<uint32_t> faces;
    VertexFaces(size_t vertexCount, const Faces& tris) {
        bucketFaces(
            vertexCount, tris.size(),
            [&](size_t f, const auto& emit) {
                for (uint32_t v : tris.tri(f)) emit(v);
            },
            offset, faces);
    }
    [[nodiscard]] std::pair<const uint32_t*, const uint32_t*> of(uint32_t v) const {
        return {faces.data() + offset[v], faces.data() + offset[v + 1]};
    }
};

int cornerOf(const Tri& t, uint32_t v) { return t[0] == v ? 0 : (t[1] == v ? 1 : (t[2] == v ? 2 : -1)); }

/// Makes winding consistent across edge-adjacent faces, per connected component, keeping the
/// majority orientation of each component (so a few flipped faces are the ones turned).
void fixOrientation(size_t vertexCount, Faces& tris, CleanupReport& r) {
    const VertexFaces vf(vertexCount, tris);
    scene::ScratchVector<char> seen(tris.size(), 0), flip(tris.size(), 0);
    scene::ScratchVector<uint32_t> component, queue;
    for (uint32_t seed = 0; seed < tris.size(); ++seed) {
        if (seen[seed]) continue;
        component.clear();
        queue.assign(1, seed);
        seen[seed] = 1;
        while (!queue.empty()) {
            const uint32_t f = queue.back();
            queue.pop_back();
            component.push_back(f);
            const Tri t = tris.tri(f);
            for (int e = 0; e < 3; ++e) {
                // Directed edge a→b of f as it will be drawn (after its own flip).
                uint32_t a = t[e], b = t[(e + 1) % 3];
                if (flip[f]) std::swap(a, b);
                const auto [begin, end] = vf.of(a);
                for (const uint32_t* g = begin; g != end; ++g) {
                    if (*g == f || seen[*g]) continue;
                    const Tri u = tris.tri(*g);
                    const int ca = cornerOf(u, a);
                    if (u[(ca + 1) % 3] == b) {
                        flip[*g] = 1;
                    } // same direction: g is inverted
                    else if (u[(ca + 2) % 3] != b)
                        continue; // shares only the vertex
                    seen[*g] = 1;
                    queue.push_back(*g);
                }
            }
        }
        size_t flips = 0;
        for (uint32_t f : component) flips += flip[f];
        if (2 * flips > component.size()) {
            for (uint32_t f : component) flip[f] = !flip[f];
            flips = component.size() - flips;
        }
        r.flippedFaces += flips;
    }
    for (size_t f = 0; f < tris.size(); ++f)
        if (flip[f]) std::swap(tris[f][1], tris[f][2]);
}

// ---- [SECTION] Normals ----------------------------------------------------------------------

/// Area-weighted face normals, one a face, written by one parallel pass.
using FaceNormals = scene::UnwrittenVector<glm::vec3>;

/// Above this many faces around one vertex (fans of huge cones, hostile input) per-corner
/// averaging is quadratic; faces are grouped instead.
constexpr size_t kExactCornerDegree = 256;

/// Groups the faces around a vertex greedily by normal (a face joins the first group whose seed
/// is within the crease angle) and gives every corner its group's average. O(faces × groups);
/// groups stay few because their seeds are more than the crease angle apart.
void clusterCornerNormals(const uint32_t* begin, const uint32_t* end, const FaceNormals& faceN,
                          const std::vector<glm::vec3>& unit, float cosCrease, std::vector<glm::vec3>& cornerN) {
    // Below ~5° the seeds could be as many as the faces: keep the grouping coarse enough.
    const float cosGroup = std::min(cosCrease, 0.996f);
    std::vector<uint32_t> seed, group(static_cast<size_t>(end - begin));
    std::vector<glm::vec3> sum;
    for (size_t i = 0; i < group.size(); ++i) {
        const glm::vec3& n = unit[i];
        size_t g = 0;
        while (g < seed.size() && glm::dot(unit[seed[g]], n) < cosGroup) ++g;
        if (g == seed.size()) {
            seed.push_back(static_cast<uint32_t>(i));
            sum.emplace_back(0.f);
        }
        group[i] = static_cast<uint32_t>(g);
        sum[g] += faceN[begin[i]];
    }
    for (size_t i = 0; i < group.size(); ++i) {
        const float len = glm::length(sum[group[i]]);
        cornerN[i] = len > 0 ? sum[group[i]] / len : unit[i];
    }
}

/// A face's unit normal from its area-weighted one (0 for a face too small to have a direction).
glm::vec3 unitOf(const glm::vec3& n) {
    const float len = glm::length(n);
    return len > 0 ? n / len : glm::vec3(0.f);
}

/// One block of vertices' output, in the order of their vertices: each output vertex's normal, and
/// how many outputs each input vertex [first, last) has. An output's position is its input vertex's,
/// copied at the join: kept here as well, it would be 12 bytes an output vertex more at the load's
/// peak (50 M-triangle STL: ~400 MB).
struct alignas(scene::kRangeStateAlign) SplitVertices {
    uint32_t first = 0, last = 0;
    scene::ScratchVector<glm::vec3> normals;
    /// Outputs of vertex first + i (at least one: every vertex left has a face); 0 for a vertex of
    /// more than 255, whose count is the next one in `manyOutputs`.
    scene::UnwrittenVector<uint8_t> outputs;
    std::vector<uint32_t> manyOutputs;
};

/// Degrees up to which a corner's faces within the crease angle are kept as a bit mask.
constexpr size_t kMaskedCornerDegree = 64;

/// cornerNormals for a vertex of at most 64 faces, with the same result bit for bit: whether two faces
/// are within the crease angle is symmetric, so each pair is tested once, and corners whose faces
/// within the angle are the same set (every corner of a smooth vertex, the corners of one side of a
/// crease) share one sum, added in the same order and normalised once.
void maskedCornerNormals(const uint32_t* begin, size_t deg, const FaceNormals& faceN,
                         const std::vector<glm::vec3>& unit, float cosCrease, std::vector<glm::vec3>& cornerN) {
    std::array<uint64_t, kMaskedCornerDegree> within;              // bit k of within[i]: face k counts for corner i
    for (size_t i = 0; i < deg; ++i) within[i] = uint64_t(1) << i; // a corner's own face always counts
    // Without a branch: at a crease the test goes either way, and a branch would guess wrong often.
    for (size_t i = 0; i < deg; ++i)
        for (size_t k = i + 1; k < deg; ++k) {
            const uint64_t near = glm::dot(unit[i], unit[k]) >= cosCrease; // dot(a, b) == dot(b, a) exactly
            within[i] |= near << k;
            within[k] |= near << i;
        }
    uint64_t summed = 0; // corners whose sum had a length: their normal is the set's, not their own face's
    for (size_t i = 0; i < deg; ++i) {
        size_t same = 0;
        while (same < i && !(within[same] == within[i] && (summed >> same & 1))) ++same;
        if (same < i) {
            cornerN[i] = cornerN[same];
            summed |= uint64_t(1) << i;
            continue;
        }
        glm::vec3 sum(0.f);
        for (uint64_t bits = within[i]; bits != 0; bits &= bits - 1) sum += faceN[begin[std::countr_zero(bits)]];
        const float len = glm::length(sum);
        cornerN[i] = len > 0 ? sum / len : unit[i];
        if (len > 0) summed |= uint64_t(1) << i;
    }
}

/// The corner normals of vertex `v` into `cornerN` (one per face around it, in `vf.of(v)`'s order): each
/// averages the (area-weighted) normals of the faces around v within the crease angle of its own face.
void cornerNormals(uint32_t v, const VertexFaces& vf, const FaceNormals& faceN, float cosCrease,
                   std::vector<glm::vec3>& cornerN, std::vector<glm::vec3>& unit) {
    const auto [begin, end] = vf.of(v);
    const size_t deg = static_cast<size_t>(end - begin);
    cornerN.resize(deg);
    unit.resize(deg);
    for (size_t i = 0; i < deg; ++i) unit[i] = unitOf(faceN[begin[i]]);
    if (deg > kExactCornerDegree) {
        clusterCornerNormals(begin, end, faceN, unit, cosCrease, cornerN);
        return;
    }
    if (deg <= kMaskedCornerDegree) {
        maskedCornerNormals(begin, deg, faceN, unit, cosCrease, cornerN);
        return;
    }
    for (size_t i = 0; i < deg; ++i) {
        glm::vec3 sum(0.f);
        const glm::vec3& own = unit[i];
        for (size_t k = 0; k < deg; ++k) // a face meets a vertex once: k == i is the own face
            if (k == i || glm::dot(own, unit[k]) >= cosCrease) sum += faceN[begin[k]];
        const float len = glm::length(sum);
        cornerN[i] = len > 0 ? sum / len : own;
    }
}

/// Vertices ahead whose faces splitCornersByNormal prefetches (4 and 8 were alike, 16 slower).
constexpr uint32_t kAheadVertices = 4;

/// Crease-angle normals (computeNormals' first stage) for the vertices [first, last): one output vertex
/// per distinct corner normal, appended to `out`; each corner of `tris` at such a vertex gets
/// `provisional` + its output's index in `out`, marked (bit 31) so that a later vertex's search
/// does not take it for its own id. Blocks are independent: each writes its own corners only.
void splitCornersByNormal(uint32_t first, uint32_t last, const VertexFaces& vf, const FaceNormals& faceN,
                          float cosCrease, uint32_t provisional, Faces& tris, SplitVertices& out) {
    out.first = first;
    out.last = last;
    out.outputs.resize(last - first);
    // Crease splits add vertices: room for half as many again, so that growth by doubling rarely
    // comes on top of this stage's temporaries.
    out.normals.reserve((last - first) + (last - first) / 2);
    std::vector<glm::vec3> cornerN, unit;
    for (uint32_t v = first; v < last; ++v) {
        // A vertex's faces lie apart in the face arrays (around a vertex of a tube, a ring of faces
        // apart): the normals and corners of the faces of a vertex a few on are fetched ahead.
        if (v + kAheadVertices < last)
            for (auto [f, end] = vf.of(v + kAheadVertices); f != end; ++f) {
                __builtin_prefetch(&faceN[*f]);
                __builtin_prefetch(tris[*f].data());
            }
        cornerNormals(v, vf, faceN, cosCrease, cornerN, unit);
        const uint32_t* begin = vf.of(v).first;
        const uint32_t base = static_cast<uint32_t>(out.normals.size());
        for (size_t i = 0; i < cornerN.size(); ++i) {
            // A face too small for float cross products has no direction: any unit normal will do.
            if (!(glm::dot(cornerN[i], cornerN[i]) > 0.f)) cornerN[i] = glm::vec3(0.f, 0.f, 1.f);
            uint32_t local = kNone;
            for (uint32_t k = base; k < out.normals.size(); ++k)
                if (glm::dot(out.normals[k], cornerN[i]) > 0.99999f) {
                    local = k;
                    break;
                }
            if (local == kNone) {
                local = static_cast<uint32_t>(out.normals.size());
                out.normals.push_back(cornerN[i]);
            }
            // Another block may be writing another corner of this face: corners are read and
            // written as atomics (plain moves on common hardware). Which corner is v's is found
            // without a branch: it is any of the three alike, so a branch would guess wrong about
            // every other time. A face meets v once (degenerate faces are gone): the corner is the
            // first if neither of the others holds v.
            const std::span<uint32_t, 3> face = tris[begin[i]];
            const auto at = [&](int k) { return std::atomic_ref<uint32_t>(face[k]).load(std::memory_order_relaxed); };
            const int k = int(at(1) == v) | int(at(2) == v) << 1;
            std::atomic_ref<uint32_t>(face[k]).store((provisional + local) | 0x80000000u, std::memory_order_relaxed);
        }
        const uint32_t outputs = static_cast<uint32_t>(out.normals.size()) - base;
        out.outputs[v - first] = outputs <= 255 ? uint8_t(outputs) : uint8_t(0);
        if (outputs > 255) out.manyOutputs.push_back(outputs);
    }
}

/// Vertices per thread below which the crease normals stay on one thread.
constexpr size_t kNormalsPerThreadMin = size_t(1) << 16;
/// Blocks of vertices per thread that the crease normals share out (forEachRange's even ranges by
/// corners left one thread idle a third of the 4 M piperack's pass), and the fewest vertices a block.
constexpr size_t kNormalsBlocksPerThread = 16, kNormalsPerBlockMin = size_t(1) << 14;

/// Crease-angle normals: corners of one vertex whose averaged normals differ become separate
/// vertices, so sharp CAD edges stay sharp. The faces become mesh.indices. Blocks of vertices go to
/// whichever thread is free, each into its own arrays, joined in vertex order once the face normals
/// and the vertex → face table are gone (the load's memory peak at scale), so the result is the same
/// for any thread count.
void computeNormals(scene::Mesh& mesh, std::vector<glm::vec3>& pos, Faces& tris, double creaseDeg) {
    const float cosCrease = static_cast<float>(std::cos(glm::radians(std::clamp(creaseDeg, 0.0, 180.0))));
    // Provisional indices are corner counts (an upper bound on the outputs before a vertex), marked
    // by bit 31: past 2³¹ corners one block is all there can be.
    const unsigned threads =
        3 * tris.size() < 0x80000000ull ? scene::rangeThreads(pos.size(), kNormalsPerThreadMin) : 1u;
    const size_t blocks =
        threads == 1 ? 1
                     : std::clamp<size_t>(pos.size() / kNormalsPerBlockMin, threads, threads * kNormalsBlocksPerThread);
    std::vector<SplitVertices> out(blocks);
    std::vector<uint32_t> provisional(blocks + 1, 0); // the blocks' first provisional index
    {
        // Unit normals are made per vertex from these, not kept per face: 12 bytes a triangle less
        // at the load's peak.
        FaceNormals faceN(tris.size());
        scene::forEachRange(tris.size(), scene::rangeThreads(tris.size(), kNormalsPerThreadMin),
                            [&](unsigned, size_t b, size_t e) {
                                for (size_t f = b; f < e; ++f) {
                                    const Tri t = tris.tri(f);
                                    faceN[f] = glm::cross(pos[t[1]] - pos[t[0]], pos[t[2]] - pos[t[0]]);
                                }
                            });
        const VertexFaces vf(pos.size(), tris);
        provisional.back() = vf.offset.back();
        scene::forEachBlock(
            pos.size(), blocks, threads,
            [&](size_t k, size_t b, size_t e) {
                provisional[k] = vf.offset[b];
                splitCornersByNormal(uint32_t(b), uint32_t(e), vf, faceN, cosCrease, provisional[k], tris, out[k]);
            },
            vf.offset);
    }
    // Join: exact sizes, one spare vertex of capacity for positions (Embree's last load,
    // scene::reserveSpareVertex). The mesh's arrays come from the heap: they take the pages kept from
    // the face normals and the vertex → face table, which would otherwise stay resident beside them,
    // above the load's peak, while these faulted in fresh ones.
    std::vector<uint32_t> base(blocks + 1, 0); // the blocks' first real index
    for (size_t k = 0; k < blocks; ++k) base[k + 1] = base[k] + uint32_t(out[k].normals.size());
    mesh.positions.clear();
    mesh.normals.clear();
    mesh.positions.reserve(base.back() + 1);
    mesh.normals.reserve(base.back());
    scene::scratch::prepareCapacity(mesh.positions);
    scene::scratch::prepareCapacity(mesh.normals);
    for (SplitVertices& o : out) {
        const uint32_t* many = o.manyOutputs.data();
        for (uint32_t v = o.first; v < o.last; ++v) {
            const uint32_t outputs = o.outputs[v - o.first] != 0 ? o.outputs[v - o.first] : *many++;
            for (uint32_t k = 0; k < outputs; ++k) mesh.positions.push_back(pos[v]);
        }
        mesh.normals.insert(mesh.normals.end(), o.normals.begin(), o.normals.end());
        o = {};
    }
    std::vector<glm::vec3>().swap(pos);
    // Every corner now holds a provisional index: renumbered in place, the faces become the indices.
    const std::span<uint32_t> corners = tris.corners();
    scene::forEachRange(
        corners.size(), scene::rangeThreads(tris.size(), kNormalsPerThreadMin), [&](unsigned, size_t b, size_t e) {
            size_t k = 0; // the block of the last corner: a face's and its neighbours' corners mostly share it
            for (size_t c = b; c < e; ++c) {
                const uint32_t p = corners[c] & 0x7fffffffu;
                if (p < provisional[k] || p >= provisional[k + 1])
                    k = size_t(std::upper_bound(provisional.begin() + 1, provisional.end() - 1, p) -
                               (provisional.begin() + 1));
                corners[c] = p - provisional[k] + base[k];
            }
        });
    mesh.indices = std::move(tris).release();
}

} // namespace

// ---- [SECTION] Cleaning a mesh --------------------------------------------------------------

std::string nothingLeftMessage(const CleanupReport& r) {
    std::string message = "no triangles left after cleanup";
    if (r.degenerateFaces > 0 && r.mergeTolerance > 0) {
        char tol[32];
        std::snprintf(tol, sizeof tol, "%g", r.mergeTolerance);
        message += " (" + std::to_string(r.degenerateFaces) + " faces lie within the merge tolerance, " + tol +
                   " model units: a model this small needs a smaller one, e.g. mesh clean --merge-tolerance 0)";
    }
    return message;
}

CleanupReport cleanMesh(scene::Mesh& mesh, const CleanupOptions& options, const Progress& progress,
                        ReadPositions read) {
    // Shares of cleanup's time on a 4 M-triangle STL (2 cores): the merge ~20 %, faces ~20 %, normals ~60 %.
    const auto stage = [&](float done, std::string_view name) {
        if (progress) progress(done, name);
    };
    CleanupReport r;
    r.inputVertices = mesh.positions.size();
    r.inputFaces = mesh.triangleCount();
    Faces tris(std::move(mesh.indices)); // computeNormals hands them back
    {
        // Each temporary lives in this block only, so that none is held through computeNormals
        // (the peak: face normals, vertex → faces and the output arrays at once).
        stage(0.f, "cleaning: non-finite vertices");
        const scene::ScratchVector<char> ok = dropNonFinite(mesh, tris, r);
        scene::Aabb box;
        for (size_t i = 0; i < mesh.positions.size(); ++i)
            if (ok[i]) box.add(mesh.positions[i]);
        const double diag = box.empty() ? 0.0 : glm::length(glm::dvec3(box.extent()));
        // NaN and negative mean no tolerance (bit-equal points still merge); so does infinity, which
        // has no cell size.
        const double asked = std::isfinite(options.mergeTolerance) ? std::max(0.0, options.mergeTolerance) : 0.0;
        const double tol = options.mergeToleranceOfDiagonal ? asked * diag : asked;
        r.mergeTolerance = tol;

        stage(0.05f, "cleaning: merging vertices");
        const scene::ScratchVector<uint32_t> rep = mergeDuplicates(mesh.positions, ok, tol, read, r);
        renumber(tris, rep);
        stage(0.2f, "cleaning: degenerate and duplicate faces");
        dropDegenerate(mesh.positions, tris, tol, r);
        dropDuplicateFaces(mesh.positions.size(), tris, r);

        // Compact: keep referenced vertices, in their original order, in place. A copy would free the
        // positions' pages to the system just before the load's peak, where they would be faulted in
        // afresh (50 M-triangle STL: 290 MB).
        scene::ScratchVector<uint32_t> newIndex(mesh.positions.size(), kNone);
        for (const uint32_t v : std::as_const(tris).corners()) newIndex[v] = 0;
        size_t kept = 0;
        for (size_t i = 0; i < newIndex.size(); ++i) {
            if (newIndex[i] == kNone) continue;
            newIndex[i] = static_cast<uint32_t>(kept);
            if (kept != i) mesh.positions[kept] = mesh.positions[i];
            ++kept;
        }
        mesh.positions.resize(kept);
        // Every finite vertex is either merged away, kept, or isolated.
        r.isolatedVertices = r.inputVertices - r.nonFiniteVertices - r.mergedVertices - kept;
        renumber(tris, newIndex);
    }
    // computeNormals writes the positions anew from these; the pages of those dropped (a triangle
    // soup's merged corners) are given back now, not held through its peak.
    std::vector<glm::vec3> pos = std::move(mesh.positions);
    scene::scratch::dropPages(pos.data() + pos.size(), (pos.capacity() - pos.size()) * sizeof(glm::vec3));
    std::vector<glm::vec3>().swap(mesh.normals);

    if (options.fixOrientation) {
        stage(0.35f, "cleaning: orientation");
        fixOrientation(pos.size(), tris, r);
    }
    stage(0.4f, "cleaning: normals");
    computeNormals(mesh, pos, tris, options.creaseAngleDeg); // frees pos
    // The slack left for crease splits (and by dropped faces) would stay resident for the model's
    // life. Positions keep one spare vertex (Embree's last load, scene::reserveSpareVertex).
    fitCapacity(mesh.positions, 1);
    fitCapacity(mesh.normals, 0);
    fitCapacity(mesh.indices, 0);
    mesh.chunks.clear(); // indices changed: chunk again (loadModel does)
    mesh.parts.clear();
    r.outputVertices = mesh.positions.size();
    r.outputFaces = mesh.triangleCount();
    stage(1.f, "cleaning: done");
    return r;
}

} // namespace geometry::io
