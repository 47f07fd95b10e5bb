#include "geometry/scene/chunking.h"

#include "geometry/scene/block_select.h"
#include "geometry/scene/compact_vertices.h"
#include "geometry/scene/parallel_ranges.h"
#include "geometry/scene/scratch_pages.h"
#include "geometry/scene/unwritten_vector.h"

#include <algorithm>
#include <bit>
#include <exception>
#include <numeric>
#include <thread>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace geometry::scene {

namespace {

using Range = std::pair<uint32_t, uint32_t>; // [begin, end) into the triangle order

/// Ranges this large are split on two threads (the halves are independent; each thread keeps its own
/// lists, joined in order, so the result is the same for any thread count).
constexpr uint32_t kParallelTriangles = 1u << 16;

/// A triangle's centroid with its index: the split moves these, so its comparisons and boxes read
/// contiguous memory instead of chasing indices into a centroid array.
struct Item {
    glm::vec3 c;
    uint32_t id;
};
static_assert(sizeof(Item) == 16, "centroidBox loads an item as four floats");
/// Every triangle's item, written by one parallel pass.
using Items = UnwrittenVector<Item>;

/// The box of the centroids of items [begin, end), as Aabb::add makes it (up to the sign of a zero
/// bound, which no extent comparison sees). Four boxes over interleaved items, joined at the end: one
/// running min and max per axis is a chain of dependent instructions (4 M piperack STL, one thread:
/// chunking 0.445 -> 0.42 s).
Aabb centroidBox(const Items& items, uint32_t begin, uint32_t end) noexcept {
    Aabb box;
#if defined(__SSE2__)
    // _mm_min_ps(p, lo) is p < lo ? p : lo, lane by lane: Aabb::add's comparison, NaN included. The
    // fourth lane holds the item's index and is not read.
    __m128 lo[4], hi[4];
    for (int k = 0; k < 4; ++k) {
        lo[k] = _mm_set1_ps(box.lo.x);
        hi[k] = _mm_set1_ps(box.hi.x);
    }
    uint32_t i = begin;
    for (; i + 4 <= end; i += 4)
        for (int k = 0; k < 4; ++k) {
            const __m128 p = _mm_loadu_ps(&items[i + k].c.x);
            lo[k] = _mm_min_ps(p, lo[k]);
            hi[k] = _mm_max_ps(p, hi[k]);
        }
    for (; i < end; ++i) {
        const __m128 p = _mm_loadu_ps(&items[i].c.x);
        lo[0] = _mm_min_ps(p, lo[0]);
        hi[0] = _mm_max_ps(p, hi[0]);
    }
    // Joined lane by lane: the starting values are what min and max leave alone.
    alignas(16) float l[4], h[4];
    _mm_store_ps(l, _mm_min_ps(_mm_min_ps(lo[0], lo[1]), _mm_min_ps(lo[2], lo[3])));
    _mm_store_ps(h, _mm_max_ps(_mm_max_ps(hi[0], hi[1]), _mm_max_ps(hi[2], hi[3])));
    box.lo = glm::vec3(l[0], l[1], l[2]);
    box.hi = glm::vec3(h[0], h[1], h[2]);
#else
    for (uint32_t i = begin; i < end; ++i) box.add(items[i].c);
#endif
    return box;
}

struct Splitter {
    uint32_t maxTriangles, maxPartTriangles;
    std::vector<Range> chunks, parts; // each in order of begin

    /// `spawn`: levels below this one that may still hand their upper half to a new thread. `box`:
    /// centroidBox(items, begin, end) where the caller has it.
    void split(Items& items, uint32_t begin, uint32_t end, bool inChunk, int spawn, const Aabb* box = nullptr) {
        if (!inChunk && end - begin <= maxTriangles) {
            chunks.emplace_back(begin, end);
            inChunk = true;
        }
        if (inChunk && end - begin <= maxPartTriangles) {
            parts.emplace_back(begin, end);
            return;
        }
        const glm::vec3 e = (box != nullptr ? *box : centroidBox(items, begin, end)).extent();
        const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        const uint32_t mid = begin + (end - begin) / 2;
        Item *const first = items.data() + begin, *const nth = items.data() + mid, *const last = items.data() + end;
        // One key per axis: indexing a glm vector by a variable is a switch in every comparison.
        if (axis == 0) blockSelect(first, nth, last, [](const Item& i) { return i.c.x; });
        else if (axis == 1) blockSelect(first, nth, last, [](const Item& i) { return i.c.y; });
        else blockSelect(first, nth, last, [](const Item& i) { return i.c.z; });
        if (spawn <= 0 || end - begin < kParallelTriangles) {
            split(items, begin, mid, inChunk, 0);
            split(items, mid, end, inChunk, 0);
            return;
        }
        Splitter upper{maxTriangles, maxPartTriangles, {}, {}};
        std::exception_ptr failed;
        std::thread t([&] {
            try {
                upper.split(items, mid, end, inChunk, spawn - 1);
            } catch (...) {
                failed = std::current_exception();
            }
        });
        try {
            split(items, begin, mid, inChunk, spawn - 1);
        } catch (...) {
            t.join();
            throw;
        }
        t.join();
        if (failed) std::rethrow_exception(failed);
        chunks.insert(chunks.end(), upper.chunks.begin(), upper.chunks.end());
        parts.insert(parts.end(), upper.parts.begin(), upper.parts.end());
    }
};

/// Levels of the split that may start a thread: enough for one per loader thread (rangeThreadCap,
/// the cores unless a test sets fewer), ⌈log2 threads⌉.
int spawnLevels() noexcept {
    return int(std::bit_width(std::max(1u, rangeThreadCap().load(std::memory_order_relaxed)) - 1));
}

/// World bounds of a run's triangles: the box of the transformed vertices (a transformed local box
/// is loose under rotation).
Aabb runBounds(const Mesh& mesh, const TriangleRun& run) {
    Aabb world;
    const size_t end = std::min(3 * (size_t(run.firstTriangle) + run.triangleCount), mesh.indices.size());
    if (mesh.transform == glm::mat4(1.f)) { // a loaded model's: no product needed
        // In both branches + 0 makes −0 +0, as the product does: the same box bit for bit.
#if defined(__SSE2__)
        // Aabb::add's comparisons lane by lane (as centroidBox's), one box per corner of a triangle:
        // one running min and max is a chain of dependent instructions (16 M piperack STL, every
        // part's box: 0.053 -> 0.033 s). A position is loaded as its 12 bytes: the last may end the
        // array.
        const size_t n = mesh.positions.size();
        const glm::vec3* const pos = mesh.positions.data();
        const __m128 zero = _mm_setzero_ps();
        const auto load = [&](uint32_t v) {
            const __m128 xy = _mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(&pos[v].x)));
            return _mm_add_ps(_mm_movelh_ps(xy, _mm_load_ss(&pos[v].z)), zero);
        };
        __m128 lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            lo[k] = _mm_set1_ps(world.lo.x);
            hi[k] = _mm_set1_ps(world.hi.x);
        }
        size_t i = 3 * size_t(run.firstTriangle);
        for (; i + 3 <= end; i += 3)
            for (int k = 0; k < 3; ++k)
                if (const uint32_t v = mesh.indices[i + k]; v < n) {
                    const __m128 p = load(v);
                    lo[k] = _mm_min_ps(p, lo[k]);
                    hi[k] = _mm_max_ps(p, hi[k]);
                }
        for (; i < end; ++i)
            if (const uint32_t v = mesh.indices[i]; v < n) {
                const __m128 p = load(v);
                lo[0] = _mm_min_ps(p, lo[0]);
                hi[0] = _mm_max_ps(p, hi[0]);
            }
        alignas(16) float l[4], h[4];
        _mm_store_ps(l, _mm_min_ps(_mm_min_ps(lo[0], lo[1]), lo[2]));
        _mm_store_ps(h, _mm_max_ps(_mm_max_ps(hi[0], hi[1]), hi[2]));
        world.lo = glm::vec3(l[0], l[1], l[2]);
        world.hi = glm::vec3(h[0], h[1], h[2]);
#else
        for (size_t i = 3 * size_t(run.firstTriangle); i < end; ++i)
            if (mesh.indices[i] < mesh.positions.size()) world.add(mesh.positions[mesh.indices[i]] + glm::vec3(0.f));
#endif
        return world;
    }
    for (size_t i = 3 * size_t(run.firstTriangle); i < end; ++i)
        if (mesh.indices[i] < mesh.positions.size())
            world.add(glm::vec3(mesh.transform * glm::vec4(mesh.positions[mesh.indices[i]], 1.f)));
    return world;
}

} // namespace

void reserveSpareVertex(Mesh& mesh) {
    if (mesh.positions.capacity() == mesh.positions.size()) mesh.positions.reserve(mesh.positions.size() + 1);
}

void chunkMesh(Mesh& mesh, uint32_t maxTriangles, uint32_t maxPartTriangles) {
    maxTriangles = std::max<uint32_t>(maxTriangles, 1);
    maxPartTriangles = std::clamp<uint32_t>(maxPartTriangles, 1, maxTriangles);
    const uint32_t triCount = static_cast<uint32_t>(mesh.triangleCount());
    mesh.chunks.clear();
    mesh.parts.clear();
    reserveSpareVertex(mesh); // the last step of every loader and builder
    if (triCount == 0) return;

    const unsigned threads = rangeThreads(triCount, kParallelTriangles);
    Items items(triCount);
    // The first split's box is made here, on every core: on its own it was a pass over every item on
    // one thread (the first split is one thread's).
    std::vector<Aabb> boxes(threads);
    forEachRange(triCount, threads, [&](unsigned r, size_t b, size_t e) {
        Aabb box;
        for (size_t t = b; t < e; ++t) {
            const glm::vec3 c = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                                 mesh.positions[mesh.indices[3 * t + 2]]) /
                                3.f;
            items[t] = {c, uint32_t(t)};
            box.add(c);
        }
        boxes[r] = box;
    });
    Aabb box;
    for (const Aabb& b : boxes) box.add(b);
    Splitter splitter{maxTriangles, maxPartTriangles, {}, {}};
    splitter.split(items, 0, triCount, false, spawnLevels(), &box);

    // The new order alone (4 bytes a triangle) outlives the items (16), so that the indices' copy
    // below takes their pages: items and copy together were the load's peak (16 M piperack STL:
    // 872 MiB; now 820, the crease normals').
    UnwrittenVector<uint32_t> order(triCount);
    forEachRange(triCount, threads, [&](unsigned, size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) order[i] = items[i].id;
    });
    Items().swap(items);
    // Reordered in place from a scratch copy: a new std::vector would be zeroed on one thread first,
    // faulting in all its pages there, where the copy takes pages a load has freed.
    UnwrittenVector<uint32_t> before(mesh.indices.size());
    forEachRange(triCount, threads, [&](unsigned, size_t b, size_t e) {
        std::copy(mesh.indices.begin() + 3 * b, mesh.indices.begin() + 3 * e, before.begin() + 3 * b);
    });
    forEachRange(triCount, threads, [&](unsigned, size_t b, size_t e) {
        for (size_t i = b; i < e; ++i)
            for (int k = 0; k < 3; ++k) mesh.indices[3 * i + k] = before[3 * size_t(order[i]) + k];
    });
    decltype(order)().swap(order);
    decltype(before)().swap(before);
    // A load's last scratch temporaries are gone: the pages they kept would stay resident under the
    // lists and boxes made below, which come from the heap (50 M piperack STL: 13 MiB above the
    // load's peak until 2026-12-07).
    scratch::releaseKept();

    // Parts come in order of begin and tile the chunks, which come in the same order. A chunk of one
    // part keeps none (the part would be the chunk again).
    size_t part = 0;
    for (const auto& [b, e] : splitter.chunks) {
        Chunk c;
        c.firstTriangle = b;
        c.triangleCount = e - b;
        const size_t first = part;
        while (part < splitter.parts.size() && splitter.parts[part].second <= e) ++part;
        if (part - first > 1) {
            c.firstPart = uint32_t(mesh.parts.size());
            c.partCount = uint32_t(part - first);
            for (size_t k = first; k < part; ++k)
                mesh.parts.push_back({splitter.parts[k].first, splitter.parts[k].second - splitter.parts[k].first, {}});
        }
        mesh.chunks.push_back(c);
    }
    snapToGrid(mesh); // the GL buffers' compact positions are these exactly (compact_vertices.h)
    reboundRuns(mesh);
}

void reboundRuns(Mesh& mesh) {
    forEachRange(mesh.parts.size(), rangeThreads(mesh.parts.size(), 16), [&](unsigned, size_t b, size_t e) {
        for (size_t k = b; k < e; ++k) mesh.parts[k].bounds = runBounds(mesh, mesh.parts[k]);
    });
    for (Chunk& c : mesh.chunks) {
        if (c.partCount == 0 || size_t(c.firstPart) + c.partCount > mesh.parts.size()) {
            c.bounds = runBounds(mesh, c);
            continue;
        }
        c.bounds = {}; // the union of its parts' boxes is exact: they tile it
        for (uint32_t k = c.firstPart; k < c.firstPart + c.partCount; ++k) c.bounds.add(mesh.parts[k].bounds);
    }
}

} // namespace geometry::scene
