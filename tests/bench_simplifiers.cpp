// OpenMesh's Decimater (what geometry/lod builds caster levels with) against meshoptimizer's
// simplifier (meshopt_simplify, Debian's libmeshoptimizer-dev) on the same chunks of a CAD-like
// model (the piperack, curved surfaces) at the same world-space errors: time, triangles left, and
// the error each result really has, measured the same way for both (the largest distance from an
// original vertex or edge midpoint to the simplified surface, the bound the caster levels promise).
// Both keep the chunk's open border where it is (it meets the neighbouring chunks). Reported in
// docs/performance.md "Caster levels at scale".
#include "geometry/lod/caster_lod.h"
#include "geometry/lod/chunk_levels.h"
#include "geometry/scene/builtin_scenes.h"

#include <benchmark/benchmark.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <tuple>
#include <vector>

using namespace geometry;

namespace {

/// A chunk's triangles over welded vertices, its open border locked (edges with one triangle).
lod::detail::ChunkTriangles gather(const scene::Mesh& mesh, const scene::Chunk& chunk) {
    lod::detail::ChunkTriangles out;
    std::map<std::tuple<float, float, float>, uint32_t> weld;
    for (uint32_t i = 3 * chunk.firstTriangle; i < 3 * (chunk.firstTriangle + chunk.triangleCount); ++i) {
        const glm::vec3& p = mesh.positions[mesh.indices[i]];
        const auto [it, fresh] = weld.try_emplace({p.x, p.y, p.z}, uint32_t(out.positions.size()));
        if (fresh) out.positions.push_back(p);
        out.triangles.push_back(it->second);
    }
    std::vector<uint32_t> kept;
    for (size_t t = 0; t + 2 < out.triangles.size(); t += 3) {
        const uint32_t a = out.triangles[t], b = out.triangles[t + 1], c = out.triangles[t + 2];
        if (a != b && b != c && a != c) kept.insert(kept.end(), {a, b, c});
    }
    out.triangles = std::move(kept);
    std::map<std::pair<uint32_t, uint32_t>, int> edges;
    for (size_t t = 0; t < out.triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = out.triangles[t + k], b = out.triangles[t + (k + 1) % 3];
            ++edges[{std::min(a, b), std::max(a, b)}];
        }
    out.locked.assign(out.positions.size(), 0);
    for (const auto& [e, n] : edges)
        if (n == 1) out.locked[e.first] = out.locked[e.second] = 1;
    return out;
}

double pointTriangleDistance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    // Ericson, Real-Time Collision Detection §5.1.5: the closest point by Voronoi regions.
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return glm::length(p - a);
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return glm::length(p - b);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(p - (a + ab * (d1 / (d1 - d3))));
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return glm::length(p - c);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(p - (a + ac * (d2 / (d2 - d6))));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return glm::length(p - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)))));
    const double denom = 1.0 / (va + vb + vc);
    return glm::length(p - (a + ab * (vb * denom) + ac * (vc * denom)));
}

/// The largest distance from the chunk's vertices and edge midpoints to the triangles `simplified`
/// (over `positions`); 0 when nothing was removed is not assumed: it is measured.
double measuredError(const lod::detail::ChunkTriangles& chunk, const std::vector<glm::vec3>& positions,
                     const std::vector<uint32_t>& simplified) {
    std::vector<glm::dvec3> probes;
    for (const glm::vec3& p : chunk.positions) probes.emplace_back(p);
    for (size_t t = 0; t < chunk.triangles.size(); t += 3)
        for (int k = 0; k < 3; ++k)
            probes.push_back(0.5 * (glm::dvec3(chunk.positions[chunk.triangles[t + k]]) +
                                    glm::dvec3(chunk.positions[chunk.triangles[t + (k + 1) % 3]])));
    double worst = 0;
    for (const glm::dvec3& p : probes) {
        double best = INFINITY;
        for (size_t t = 0; t + 2 < simplified.size() && best > 0; t += 3)
            best = std::min(best, pointTriangleDistance(p, glm::dvec3(positions[simplified[t]]),
                                                        glm::dvec3(positions[simplified[t + 1]]),
                                                        glm::dvec3(positions[simplified[t + 2]])));
        worst = std::max(worst, best);
    }
    return worst;
}

struct Tally {
    double seconds = 0;
    uint64_t triangles = 0;
    double worstRatio = 0; // measured error / allowed error, the worst chunk
};

const std::vector<lod::detail::ChunkTriangles>& sampleChunks() {
    static const std::vector<lod::detail::ChunkTriangles> chunks = [] {
        const scene::Scene s = scene::makePiperackScene({1'000'000, 1});
        std::vector<lod::detail::ChunkTriangles> out;
        size_t index = 0;
        for (const scene::Mesh& m : s.meshes) {
            if (m.name == "ground") continue;
            for (const scene::Chunk& c : m.chunks)
                if (index++ % 8 == 0) out.push_back(gather(m, c)); // every 8th: the error check is brute force
        }
        return out;
    }();
    return chunks;
}

uint64_t sourceTriangles() {
    uint64_t n = 0;
    for (const auto& c : sampleChunks()) n += c.triangles.size() / 3;
    return n;
}

float diagonal(const lod::detail::ChunkTriangles& c) {
    scene::Aabb b;
    for (const glm::vec3& p : c.positions) b.add(p);
    return glm::length(b.extent());
}

/// One relative error r (of each chunk's diagonal), both simplifiers.
void BM_Simplifiers(benchmark::State& state) {
    const float r = 1.f / float(state.range(0));
    Tally openMesh, meshopt, meshoptBounded;
    for (auto _ : state) {
        openMesh = meshopt = meshoptBounded = {};
        const std::atomic<bool> cancel{false};
        for (const lod::detail::ChunkTriangles& chunk : sampleChunks()) {
            const float allowed = r * diagonal(chunk);
            // OpenMesh: the caster levels' own decimation, one level, nothing kept exact as thin.
            lod::detail::LevelSettings s;
            s.errors = {allowed};
            s.thinFactor = 0.f;
            s.minReduction = 0.f;
            s.sourceTriangles = uint32_t(chunk.triangles.size() / 3);
            auto t0 = std::chrono::steady_clock::now();
            const lod::detail::ChunkLevels levels = lod::detail::buildChunkLevels(chunk, s, cancel);
            openMesh.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::vector<uint32_t> kept = chunk.triangles;
            std::vector<glm::vec3> keptPositions = chunk.positions;
            if (!levels.levels.empty()) {
                const lod::LodRange& l = levels.levels[0];
                kept.assign(levels.indices.begin() + 3 * l.firstTriangle,
                            levels.indices.begin() + 3 * (l.firstTriangle + l.triangleCount));
                keptPositions = levels.positions;
            }
            openMesh.triangles += kept.size() / 3;
            openMesh.worstRatio =
                std::max(openMesh.worstRatio, measuredError(chunk, keptPositions, kept) / double(allowed));

            // meshoptimizer: as small as the error allows, the border locked.
            t0 = std::chrono::steady_clock::now();
            std::vector<uint32_t> out(chunk.triangles.size());
            const float scale = meshopt_simplifyScale(&chunk.positions[0].x, chunk.positions.size(), sizeof(glm::vec3));
            const size_t n = meshopt_simplify(out.data(), chunk.triangles.data(), chunk.triangles.size(),
                                              &chunk.positions[0].x, chunk.positions.size(), sizeof(glm::vec3), 0,
                                              allowed / scale, meshopt_SimplifyLockBorder, nullptr);
            out.resize(n);
            meshopt.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            meshopt.triangles += n / 3;
            meshopt.worstRatio =
                std::max(meshopt.worstRatio, measuredError(chunk, chunk.positions, out) / double(allowed));

            // meshoptimizer held to the bound: its target error cut by 4 until the measured error
            // is within the allowed one (its quadric error is not a distance to the original).
            std::vector<uint32_t> bounded = chunk.triangles;
            for (float cut = 1.f; cut >= 1.f / 1024; cut /= 4) {
                std::vector<uint32_t> tryOut(chunk.triangles.size());
                t0 = std::chrono::steady_clock::now();
                const size_t m = meshopt_simplify(tryOut.data(), chunk.triangles.data(), chunk.triangles.size(),
                                                  &chunk.positions[0].x, chunk.positions.size(), sizeof(glm::vec3), 0,
                                                  cut * allowed / scale, meshopt_SimplifyLockBorder, nullptr);
                meshoptBounded.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                tryOut.resize(m);
                if (measuredError(chunk, chunk.positions, tryOut) <= double(allowed)) {
                    bounded = std::move(tryOut);
                    break;
                }
            }
            meshoptBounded.triangles += bounded.size() / 3;
        }
    }
    const double source = double(sourceTriangles());
    state.counters["openmesh_left"] = double(openMesh.triangles) / source;
    state.counters["meshopt_left"] = double(meshopt.triangles) / source;
    state.counters["openmesh_ms"] = 1e3 * openMesh.seconds;
    state.counters["meshopt_ms"] = 1e3 * meshopt.seconds;
    state.counters["openmesh_worst_error"] = openMesh.worstRatio; // × the allowed error
    state.counters["meshopt_worst_error"] = meshopt.worstRatio;
    state.counters["meshopt_bounded_left"] = double(meshoptBounded.triangles) / source;
    state.counters["meshopt_bounded_ms"] = 1e3 * meshoptBounded.seconds; // simplification alone, every try
    state.counters["source_tri"] = source;
}
BENCHMARK(BM_Simplifiers)->Arg(512)->Arg(128)->Arg(32)->Iterations(1)->Unit(benchmark::kSecond);

} // namespace

BENCHMARK_MAIN();
