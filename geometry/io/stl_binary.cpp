#include "geometry/io/stl_binary.h"

#include "geometry/io/mapped_file.h"

#include "geometry/scene/parallel_ranges.h"
#include "geometry/scene/scratch_pages.h"
#include "geometry/scene/unwritten_vector.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <vector>

namespace geometry::io::detail {

namespace {

constexpr uint32_t kEmpty = ~0u;
constexpr size_t kHeaderBytes = 84, kFacetBytes = 50;
constexpr size_t kFacetsPerThreadMin = 1 << 16;    // below this a thread costs more than it saves
constexpr std::ptrdiff_t kReleaseBytes = 16 << 20; // read pages dropped every 16 MiB
constexpr size_t kAheadFacets = 16;                // facets whose slots are prefetched ahead (8 to 32 alike)
constexpr size_t kAheadLookups = 16;               // keys whose slots a range's lookups prefetch

/// A corner's coordinates as bits, −0 as +0 (equal as numbers, so the same vertex).
struct Key {
    uint32_t x, y, z;
    [[nodiscard]] bool operator==(const Key&) const = default;
};

Key keyOf(const char* p) noexcept {
    Key k;
    std::memcpy(&k, p, sizeof k);
    for (uint32_t* c : {&k.x, &k.y, &k.z})
        if (*c == 0x80000000u) *c = 0;
    return k;
}

bool finite(const Key& k) noexcept { // exponent not all ones
    return (k.x & 0x7f800000u) != 0x7f800000u && (k.y & 0x7f800000u) != 0x7f800000u &&
           (k.z & 0x7f800000u) != 0x7f800000u;
}

uint32_t hashOf(const Key& k) noexcept {
    uint64_t h = (uint64_t(k.x) * 0x9E3779B97F4A7C15ull) ^ (uint64_t(k.y) * 0xC2B2AE3D27D4EB4Full) ^
                 (uint64_t(k.z) * 0x165667B19E3779F9ull);
    h ^= h >> 29;
    return uint32_t(h * 0xBF58476D1CE4E5B9ull >> 32);
}

/// Distinct corners in order of first use: an open-addressing table of vertex ids (4 bytes a
/// slot, compared through the keys they name), grown at half load.
class Welder {
public:
    explicit Welder(size_t expected) {
        size_t cap = 1024;
        while (cap < 2 * expected) cap <<= 1;
        slots_.assign(cap, kEmpty);
        keys_.reserve(expected);
    }
    /// The vertex of `k`: an existing one when welded (`welded` set), else a new one.
    uint32_t add(const Key& k, bool& welded) {
        if (!finite(k)) return push(k); // never welded: cleanup drops it with its faces
        const uint32_t h = hashOf(k);
        // A corner is mostly a repeat of one a few facets back: those are found in a small table
        // that stays in the cache before the large one is searched.
        uint32_t& recent = recent_[h >> (32 - kRecentBits)];
        if (recent != kEmpty && keys_[recent] == k) {
            welded = true;
            return recent;
        }
        const size_t mask = slots_.size() - 1;
        for (size_t s = h & mask;; s = (s + 1) & mask) {
            const uint32_t id = slots_[s];
            if (id == kEmpty) {
                slots_[s] = recent = push(k);
                if (2 * ++used_ > slots_.size()) grow();
                return recent;
            }
            if (keys_[id] == k) {
                welded = true;
                return recent = id;
            }
        }
    }
    /// The vertex of `k` if the table holds it, else kEmpty (never one for a non-finite key). Only
    /// reads: any number of threads may look up at once.
    [[nodiscard]] uint32_t find(const Key& k) const noexcept {
        if (!finite(k)) return kEmpty;
        const size_t mask = slots_.size() - 1;
        for (size_t s = hashOf(k) & mask;; s = (s + 1) & mask) {
            const uint32_t id = slots_[s];
            if (id == kEmpty || keys_[id] == k) return id;
        }
    }
    /// Starts loading the slot where `k`'s search begins: the table is far larger than the caches.
    /// Forced inline: GCC 12 takes a function whose only effect is a prefetch for one without effects
    /// and drops its calls (until 2026-12 the weld prefetched nothing).
    [[gnu::always_inline]] void prefetch(const Key& k) const noexcept {
        __builtin_prefetch(&slots_[hashOf(k) & (slots_.size() - 1)]);
    }
    [[nodiscard]] const scene::ScratchVector<Key>& keys() const noexcept { return keys_; }
    /// Gives back the table (no search after this); the keys stay.
    void releaseTable() noexcept { scene::ScratchVector<uint32_t>().swap(slots_); }

private:
    uint32_t push(const Key& k) {
        keys_.push_back(k);
        return uint32_t(keys_.size() - 1);
    }
    void grow() {
        scene::ScratchVector<uint32_t> old(slots_.size() * 2, kEmpty);
        old.swap(slots_);
        const size_t mask = slots_.size() - 1;
        for (const uint32_t id : old) {
            if (id == kEmpty) continue;
            size_t s = hashOf(keys_[id]) & mask;
            while (slots_[s] != kEmpty) s = (s + 1) & mask;
            slots_[s] = id;
        }
    }
    static constexpr int kRecentBits = 12;
    scene::ScratchVector<uint32_t> slots_; // scratch pages, as every large temporary of a load
    std::vector<uint32_t> recent_ = std::vector<uint32_t>(size_t(1) << kRecentBits, kEmpty);
    scene::ScratchVector<Key> keys_;
    size_t used_ = 0;
};

/// Facets [first, last) welded on their own: indices local to the range's welder. One thread's.
struct alignas(scene::kRangeStateAlign) RangeWeld {
    size_t first = 0, last = 0;
    Welder welder{0};
    size_t welded = 0;
};

void weldRange(const char* data, RangeWeld& r, std::vector<uint32_t>& indices, const Progress& progress = {}) {
    r.welder = Welder((r.last - r.first) * 3 / 5); // CAD surfaces: ~0.5 distinct corners per facet
    const char* released = data + kHeaderBytes + kFacetBytes * r.first;
    for (size_t t = r.first; t < r.last; ++t) {
        const char* facet = data + kHeaderBytes + kFacetBytes * t;
        const char* corner = facet + 12; // past the facet normal
        // Only the slot: reading it a few facets on to prefetch its key as well cost more than it
        // saved (three in four corners are found in the recent table and read neither).
        if (t + kAheadFacets < r.last)
            for (size_t k = 0; k < 3; ++k) r.welder.prefetch(keyOf(corner + kAheadFacets * kFacetBytes + 12 * k));
        for (size_t k = 0; k < 3; ++k) {
            bool welded = false;
            indices[3 * t + k] = r.welder.add(keyOf(corner + 12 * k), welded);
            r.welded += welded;
        }
        if (facet - released >= kReleaseBytes) {
            MappedFile::release(released, facet);
            released = facet;
            if (progress) progress(float(t - r.first) / float(r.last - r.first), "reading");
        }
    }
}

} // namespace

scene::Mesh readBinaryStl(const std::string& path, uint64_t size, CleanupReport& counts, unsigned threads,
                          const Progress& progress) {
    const size_t n = (size - kHeaderBytes) / kFacetBytes;
    const MappedFile file(path, size);
    const char* const bytes = reinterpret_cast<const char*>(file.data());
    if (threads == 0) threads = scene::rangeThreads(n, kFacetsPerThreadMin); // automatic: the loader's thread rule
    threads = unsigned(std::clamp<size_t>(threads, 1, std::max<size_t>(n, 1)));
    // Threads for a later pass over m items: the same rule, never more than the weld used.
    const auto threadsFor = [threads](size_t m) {
        return std::min(threads, scene::rangeThreads(m, kFacetsPerThreadMin));
    };

    scene::Mesh mesh;
    scene::scratch::resizePrepared(mesh.indices, 3 * n);
    std::vector<RangeWeld> ranges(threads);
    for (unsigned i = 0; i < threads; ++i) {
        ranges[i].first = n * i / threads;
        ranges[i].last = n * (i + 1) / threads;
    }
    {
        std::vector<std::jthread> workers;
        for (unsigned i = 1; i < threads; ++i)
            workers.emplace_back([&, i] { weldRange(bytes, ranges[i], mesh.indices); });
        weldRange(bytes, ranges[0], mesh.indices, progress); // this thread: progress may be reported
    }
    // The ranges in order, each range's corners welded against what came before: the result is
    // what one thread reading the file front to back would give. Every range but the last adds its
    // new keys to the first range's table, for the ranges after it to find.
    size_t welded = ranges[0].welded;
    Welder& all = ranges[0].welder;
    // Each key of `local` looked up in `all` on every core (the table is only read): its vertex, or
    // kEmpty for a new one (a range's keys are distinct). `fresh` gets each part's count of new keys.
    const auto lookUp = [&](const scene::ScratchVector<Key>& local, scene::UnwrittenVector<uint32_t>& global,
                            std::vector<size_t>& fresh) {
        const unsigned parts = threadsFor(local.size());
        fresh.assign(parts + 1, 0);
        scene::forEachRange(local.size(), parts, [&](unsigned part, size_t b, size_t e) {
            size_t count = 0;
            for (size_t v = b; v < e; ++v) {
                if (v + kAheadLookups < e) all.prefetch(local[v + kAheadLookups]);
                global[v] = all.find(local[v]);
                count += global[v] == kEmpty;
            }
            fresh[part + 1] = count;
        });
    };
    const auto renumber = [&](const RangeWeld& r, const scene::UnwrittenVector<uint32_t>& global) {
        scene::forEachRange(r.last - r.first, threadsFor(r.last - r.first), [&](unsigned, size_t b, size_t e) {
            for (size_t j = 3 * (r.first + b); j < 3 * (r.first + e); ++j) mesh.indices[j] = global[mesh.indices[j]];
        });
    };
    std::vector<size_t> fresh;
    for (unsigned i = 1; i + 1 < threads; ++i) {
        const scene::ScratchVector<Key>& local = ranges[i].welder.keys();
        scene::UnwrittenVector<uint32_t> global(local.size());
        lookUp(local, global, fresh);
        for (size_t v = 0; v < local.size(); ++v) {
            if (global[v] != kEmpty) {
                ++welded;
                continue;
            }
            bool seen = false; // cannot be: the key was not found
            global[v] = all.add(local[v], seen);
        }
        welded += ranges[i].welded;
        renumber(ranges[i], global);
        ranges[i].welder = Welder(0); // its memory back before the next range
    }
    // The last range's new keys are numbered after the table's, in the range's order, and go
    // straight to the mesh's positions from every core: appended to the table one by one, then
    // copied, they were two serial passes over the model's vertices (at 50 M triangles, 12 M new keys).
    const scene::ScratchVector<Key>& keys = all.keys();
    scene::ScratchVector<Key> noKeys;
    const scene::ScratchVector<Key>& last = threads > 1 ? ranges[threads - 1].welder.keys() : noKeys;
    scene::UnwrittenVector<uint32_t> global(last.size());
    fresh.assign(2, 0);
    if (threads > 1) lookUp(last, global, fresh);
    all.releaseTable(); // its pages, and the last range's, for the positions
    if (threads > 1) ranges[threads - 1].welder.releaseTable();
    std::partial_sum(fresh.begin(), fresh.end(), fresh.begin()); // each part's first new key
    const size_t vertices = keys.size() + fresh.back();
    // One spare vertex of capacity: Embree reads 4 bytes past the last (scene::reserveSpareVertex).
    scene::scratch::resizePrepared(mesh.positions, vertices, 1); // the welders' pages
    static_assert(sizeof(Key) == sizeof(glm::vec3));
    scene::forEachRange(keys.size(), threadsFor(keys.size()), [&](unsigned, size_t b, size_t e) {
        if (e > b) std::memcpy(mesh.positions.data() + b, keys.data() + b, (e - b) * sizeof(Key));
    });
    if (threads > 1) {
        scene::forEachRange(last.size(), unsigned(fresh.size() - 1), [&](unsigned part, size_t b, size_t e) {
            size_t id = keys.size() + fresh[part];
            for (size_t v = b; v < e; ++v) {
                if (global[v] != kEmpty) continue;
                std::memcpy(&mesh.positions[id], &last[v], sizeof(Key));
                global[v] = uint32_t(id++);
            }
        });
        welded += last.size() - fresh.back() + ranges[threads - 1].welded;
        renumber(ranges[threads - 1], global);
    }
    counts.inputVertices = 3 * n;
    counts.mergedVertices = welded;
    return mesh;
}

} // namespace geometry::io::detail
