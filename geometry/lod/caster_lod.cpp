// buildCasterLod: welds each mesh, finds the vertices its chunks share, then builds every
// chunk's levels on worker threads (chunk_levels.cpp) and gathers them in chunk order.
//
// What the error bounds. Levels come from halfedge collapses, so every vertex of a level is a
// vertex of the original. ModDeviationT refuses any collapse that would leave a vertex or an
// edge midpoint of the original farther than error / stretch (object units) from the level's
// surface, stretch being the transform's largest singular value; so in world units they all lie
// within `error` of the level. That is a one-sided Hausdorff bound sampled at the original's
// vertices and edge midpoints, ModHausdorffT's idea with midpoints added. The other side, how far
// a level's triangles stray from the original, is not bounded; ModNormalFlippingT forbids
// fold-overs, and a stray needs an original sample under it to be seen. Measured by brute force
// (tests/test_caster_lod.cpp on tubes and capped cylinders, and on the platform): at most 0.93 ×
// error, against 1.39 × with vertices alone, whose bound missed corners cut across long creases.
//
// Index
//   [SECTION] Welding ........... weldPositions, sharedVertices
//   [SECTION] Chunk input ....... gatherChunk, levelErrors
//   [SECTION] Workers ........... forEachParallel
//   [SECTION] Building .......... buildCasterLod, coarsestLevelWithin
#include "geometry/lod/caster_lod.h"

#include "geometry/lod/chunk_levels.h"
#include "geometry/lod/lod_geometry.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <exception>
#include <mutex>
#include <numeric>
#include <optional>
#include <thread>

namespace geometry::lod {

using detail::ChunkTriangles;

namespace {

// ---- [SECTION] Welding ----------------------------------------------------------------------

/// A position's bits, with -0 read as +0, so equal positions get equal keys.
std::array<uint32_t, 3> positionKey(const glm::vec3& p) noexcept {
    std::array<uint32_t, 3> key{};
    for (int i = 0; i < 3; ++i) {
        const float f = p[i] == 0.f ? 0.f : p[i];
        std::memcpy(&key[i], &f, sizeof f);
    }
    return key;
}

/// Per vertex: the index of the first vertex at exactly its position. CAD exports split vertices
/// at creases; the decimation needs the connectivity back.
std::vector<uint32_t> weldPositions(const std::vector<glm::vec3>& positions) {
    std::vector<std::pair<std::array<uint32_t, 3>, uint32_t>> keyed(positions.size());
    for (uint32_t v = 0; v < positions.size(); ++v) keyed[v] = {positionKey(positions[v]), v};
    std::sort(keyed.begin(), keyed.end());
    std::vector<uint32_t> weld(positions.size());
    for (size_t i = 0; i < keyed.size(); ++i)
        weld[keyed[i].second] =
            i > 0 && keyed[i].first == keyed[i - 1].first ? weld[keyed[i - 1].second] : keyed[i].second;
    return weld;
}

bool chunkInRange(const scene::Mesh& mesh, const scene::Chunk& c) noexcept {
    return uint64_t(c.firstTriangle) + c.triangleCount <= mesh.triangleCount();
}

/// Per welded vertex: whether triangles of two or more chunks use it. Locking these keeps the
/// seams between neighbouring chunks' levels closed.
std::vector<uint8_t> sharedVertices(const scene::Mesh& mesh, const std::vector<uint32_t>& weld) {
    std::vector<uint32_t> owner(mesh.positions.size(), UINT32_MAX);
    std::vector<uint8_t> shared(mesh.positions.size(), 0);
    for (uint32_t c = 0; c < mesh.chunks.size(); ++c) {
        const scene::Chunk& chunk = mesh.chunks[c];
        if (!chunkInRange(mesh, chunk)) continue;
        for (size_t i = 3 * size_t(chunk.firstTriangle); i < 3 * (size_t(chunk.firstTriangle) + chunk.triangleCount);
             ++i) {
            const uint32_t v = mesh.indices[i];
            if (v >= mesh.positions.size()) continue;
            uint32_t& o = owner[weld[v]];
            if (o == UINT32_MAX) o = c;
            else if (o != c) shared[weld[v]] = 1;
        }
    }
    return shared;
}

// ---- [SECTION] Chunk input ------------------------------------------------------------------

/// The chunk's triangles over welded vertices, or nothing when it cannot be simplified safely
/// (an index out of range, a non-finite position).
std::optional<ChunkTriangles> gatherChunk(const scene::Mesh& mesh, const scene::Chunk& chunk,
                                          const std::vector<uint32_t>& weld, const std::vector<uint8_t>& shared) {
    if (!chunkInRange(mesh, chunk)) return std::nullopt;
    const size_t begin = 3 * size_t(chunk.firstTriangle), end = begin + 3 * size_t(chunk.triangleCount);
    std::vector<uint32_t> welded(mesh.indices.begin() + std::ptrdiff_t(begin),
                                 mesh.indices.begin() + std::ptrdiff_t(end));
    for (uint32_t& v : welded) {
        if (v >= mesh.positions.size()) return std::nullopt;
        const glm::vec3& p = mesh.positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return std::nullopt;
        v = weld[v];
    }
    std::vector<uint32_t> used = welded;
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    auto local = [&](uint32_t v) { return uint32_t(std::lower_bound(used.begin(), used.end(), v) - used.begin()); };

    ChunkTriangles out;
    out.positions.reserve(used.size());
    out.locked.reserve(used.size());
    for (uint32_t v : used) {
        out.positions.push_back(mesh.positions[v]);
        out.locked.push_back(shared[v]);
    }
    out.triangles.reserve(welded.size());
    for (size_t t = 0; t < welded.size(); t += 3) {
        const uint32_t a = welded[t], b = welded[t + 1], c = welded[t + 2];
        const glm::dvec3 pa(mesh.positions[a]), pb(mesh.positions[b]), pc(mesh.positions[c]);
        const glm::dvec3 n = glm::cross(pb - pa, pc - pa);
        if (n == glm::dvec3(0.)) continue; // no area (a repeated or collinear corner): casts nothing
        out.triangles.insert(out.triangles.end(), {local(a), local(b), local(c)});
    }
    return out;
}

/// The levels' errors for a chunk, world units: the relative errors × its world diagonal.
std::vector<float> levelErrors(const std::vector<float>& relative, const ChunkTriangles& chunk,
                               const glm::mat4& transform) {
    scene::Aabb world;
    for (const glm::vec3& p : chunk.positions) world.add(glm::vec3(transform * glm::vec4(p, 1.f)));
    const float diagonal = glm::length(world.extent());
    if (!(diagonal > 0.f) || !std::isfinite(diagonal)) return {};
    std::vector<float> errors;
    for (float r : relative) errors.push_back(r * diagonal);
    return errors;
}

std::vector<float> sanitizedRelativeErrors(std::vector<float> relative) {
    std::erase_if(relative, [](float r) { return !(r > 0.f) || !std::isfinite(r); });
    std::sort(relative.begin(), relative.end());
    relative.erase(std::unique(relative.begin(), relative.end()), relative.end());
    return relative;
}

// ---- [SECTION] Workers ----------------------------------------------------------------------

/// Runs task(i) for every i < count on `threads` workers, while the calling thread calls
/// poll() every 50 ms; poll() returning false stops the workers after their current task.
/// Returns false when stopped so; rethrows the first exception of a task.
bool forEachParallel(size_t count, unsigned threads, const std::function<void(size_t)>& task,
                     const std::function<bool()>& poll, std::atomic<bool>& stop) {
    std::atomic<size_t> next{0};
    std::mutex mutex;
    std::condition_variable finished;
    size_t running = std::clamp<size_t>(threads, 1, std::max<size_t>(count, 1));
    std::exception_ptr error;
    auto worker = [&] {
        try {
            for (size_t i; !stop.load() && (i = next.fetch_add(1)) < count;) task(i);
        } catch (...) {
            const std::lock_guard lock(mutex);
            if (!error) error = std::current_exception();
            stop = true;
        }
        const std::lock_guard lock(mutex);
        --running;
        finished.notify_all();
    };
    bool cancelled = false;
    {
        std::vector<std::jthread> workers;
        for (size_t t = running; t > 0; --t) workers.emplace_back(worker);
        std::unique_lock lock(mutex);
        while (running > 0) {
            finished.wait_for(lock, std::chrono::milliseconds(50));
            if (running == 0 || cancelled) continue;
            lock.unlock();
            bool go = false;
            try {
                go = poll();
            } catch (...) {
                stop = true;
                throw; // the workers stop and are joined on the way out
            }
            lock.lock();
            if (!go) cancelled = true, stop = true;
        }
    }
    if (error) std::rethrow_exception(error);
    return !cancelled;
}

} // namespace

// ---- [SECTION] Building ---------------------------------------------------------------------

SceneLod buildCasterLod(const scene::Scene& scene, const LodOptions& options,
                        const std::function<bool(float)>& progress) {
    auto report = [&](float done) { return !progress || progress(done); };
    if (!report(0.f)) return {};

    const std::vector<float> relative = sanitizedRelativeErrors(options.relativeErrors);
    const float thinFactor = std::isfinite(options.thinFactor) ? std::max(options.thinFactor, 0.f) : 0.f;
    const float minReduction =
        std::isfinite(options.minReduction) ? std::clamp(options.minReduction, 0.f, 0.99f) : 0.1f;
    const unsigned threads = options.threads > 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());

    SceneLod out;
    out.meshes.resize(scene.meshes.size());
    struct Job {
        uint32_t mesh, chunk;
    };
    std::vector<Job> jobs;
    uint64_t totalWork = 0;
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const scene::Mesh& mesh = scene.meshes[m];
        if (mesh.instanced()) continue; // drawn with its original triangles (docs/design.md §2 "Instances")
        out.meshes[m].chunkLevels.resize(mesh.chunks.size());
        for (uint32_t c = 0; c < mesh.chunks.size(); ++c) {
            jobs.push_back({m, c});
            if (chunkInRange(mesh, mesh.chunks[c])) {
                out.sourceTriangles += mesh.chunks[c].triangleCount;
                totalWork += mesh.chunks[c].triangleCount;
            }
        }
    }

    std::atomic<bool> stop{false};
    std::atomic<uint64_t> doneWork{0};
    auto poll = [&] { return report(totalWork > 0 ? float(double(doneWork.load()) / double(totalWork)) : 0.f); };

    // Welding is per mesh, before any of its chunks.
    std::vector<std::vector<uint32_t>> weld(scene.meshes.size());
    std::vector<std::vector<uint8_t>> shared(scene.meshes.size());
    auto prepare = [&](size_t m) {
        if (scene.meshes[m].instanced()) return;
        weld[m] = weldPositions(scene.meshes[m].positions);
        shared[m] = sharedVertices(scene.meshes[m], weld[m]);
    };
    if (!forEachParallel(scene.meshes.size(), threads, prepare, poll, stop)) return {};

    std::vector<detail::ChunkLevels> built(jobs.size());
    auto buildJob = [&](size_t j) {
        const scene::Mesh& mesh = scene.meshes[jobs[j].mesh];
        const scene::Chunk& chunk = mesh.chunks[jobs[j].chunk];
        if (const std::optional<ChunkTriangles> triangles =
                gatherChunk(mesh, chunk, weld[jobs[j].mesh], shared[jobs[j].mesh])) {
            detail::LevelSettings settings;
            settings.transform = mesh.transform;
            settings.stretch = detail::largestStretch(mesh.transform);
            settings.errors = levelErrors(relative, *triangles, mesh.transform);
            settings.thinFactor = thinFactor;
            settings.minReduction = minReduction;
            settings.sourceTriangles = chunk.triangleCount;
            built[j] = detail::buildChunkLevels(*triangles, settings, stop);
        }
        if (chunkInRange(mesh, chunk)) doneWork += chunk.triangleCount;
    };
    if (!forEachParallel(jobs.size(), threads, buildJob, poll, stop)) return {};

    for (size_t j = 0; j < jobs.size(); ++j) {
        MeshLod& lod = out.meshes[jobs[j].mesh];
        detail::ChunkLevels& b = built[j];
        const uint32_t firstVertex = uint32_t(lod.positions.size()), firstTriangle = uint32_t(lod.indices.size() / 3);
        lod.positions.insert(lod.positions.end(), b.positions.begin(), b.positions.end());
        lod.normals.insert(lod.normals.end(), b.normals.begin(), b.normals.end());
        for (uint32_t v : b.indices) lod.indices.push_back(firstVertex + v);
        for (LodRange& r : b.levels) {
            r.firstTriangle += firstTriangle;
            out.lodTriangles += r.triangleCount;
        }
        lod.chunkLevels[jobs[j].chunk] = std::move(b.levels);
        b = {};
    }
    if (!report(1.f)) return {};
    return out;
}

int coarsestLevelWithin(const std::vector<LodRange>& levels, float allowed) noexcept {
    int best = -1;
    for (size_t k = 0; k < levels.size(); ++k)
        if (levels[k].error <= allowed) best = int(k); // NaN allowed or error: never
    return best;
}

} // namespace geometry::lod
