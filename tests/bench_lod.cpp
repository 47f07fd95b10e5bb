// Caster levels (geometry/lod) on (a) 4 million triangles of tessellated tubes (32 sides,
// radius 0.3 m, 5 m long, 64 rows along; 4 meshes), chunked by chunkMesh and again with one chunk
// per tube, and (b) the built-in platform (box-shaped bars: should simplify little). One build
// each (seconds). Counters, for each relative error r of the default options: drawn@ the
// triangles a shadow pass draws if it allows r × each chunk's diagonal, over the source's; kept@
// the share of chunks that kept the level of error r.
#include "geometry/lod/caster_lod.h"
#include "geometry/scene/builtin_scenes.h"
#include "geometry/scene/chunking.h"
#include "lod_test_meshes.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

using namespace geometry;

namespace {

/// perTubeChunks: one chunk per tube (each is 4096 triangles) instead of chunkMesh's median
/// splits, which cut tubes across and along; every cut is locked, so this shows what they cost.
scene::Scene tubeScene(bool perTubeChunks) {
    scene::Scene s;
    constexpr int kMeshes = 4, kTubesPerMesh = 245; // × 4096 triangles ≈ 4.01 million
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int m = 0; m < kMeshes; ++m) {
        scene::Mesh mesh;
        mesh.name = "tubes" + std::to_string(m);
        mesh.twoSided = false;
        for (int i = 0; i < kTubesPerMesh; ++i) {
            const glm::vec3 cell(float(i % 7) * 6.f, float((i / 7) % 7) * 6.f + 50.f * float(m), float(i / 49) * 6.f);
            testutil::addTube(mesh, cell, axes[(i + m) % 3], 0.3f, 5.f, 32, 64, true);
        }
        if (perTubeChunks) {
            for (uint32_t first = 0; first < mesh.triangleCount(); first += 4096) {
                scene::Chunk c{{first, 4096, {}}};
                for (uint32_t i = 3 * first; i < 3 * (first + 4096); ++i) c.bounds.add(mesh.positions[mesh.indices[i]]);
                mesh.chunks.push_back(c);
            }
        } else {
            scene::chunkMesh(mesh);
        }
        s.meshes.push_back(std::move(mesh));
    }
    return s;
}

void report(benchmark::State& state, const scene::Scene& s, const lod::SceneLod& lod) {
    const std::vector<float> relative = lod::LodOptions{}.relativeErrors;
    for (size_t i = 0; i < relative.size(); ++i) {
        uint64_t drawn = 0, chunks = 0, withLevel = 0;
        for (size_t m = 0; m < s.meshes.size(); ++m)
            for (size_t c = 0; c < s.meshes[m].chunks.size(); ++c) {
                const scene::Chunk& chunk = s.meshes[m].chunks[c];
                const auto& levels = lod.meshes[m].chunkLevels[c];
                const float diagonal = glm::length(chunk.bounds.extent());
                const int k = lod::coarsestLevelWithin(levels, relative[i] * diagonal * 1.0001f);
                drawn += k < 0 ? chunk.triangleCount : levels[size_t(k)].triangleCount;
                ++chunks;
                for (const lod::LodRange& r : levels)
                    withLevel += std::abs(r.error - relative[i] * diagonal) <= 1e-4f * diagonal;
            }
        const std::string tier = "@1/" + std::to_string(int(1.f / relative[i] + 0.5f));
        state.counters["drawn" + tier] = double(drawn) / double(lod.sourceTriangles);
        state.counters["kept" + tier] = double(withLevel) / double(chunks); // chunks with this level
    }
    state.counters["source_Mtri"] = double(lod.sourceTriangles) * 1e-6;
    state.counters["levels_Mtri"] = double(lod.lodTriangles) * 1e-6;
}

void run(benchmark::State& state, const scene::Scene& s) {
    lod::LodOptions options;
    options.threads = unsigned(state.range(0));
    lod::SceneLod lod;
    for (auto _ : state) {
        lod = lod::buildCasterLod(s, options);
        benchmark::DoNotOptimize(lod.meshes.data());
    }
    report(state, s, lod);
}

} // namespace

static void BM_Tubes(benchmark::State& state) {
    static const scene::Scene s = tubeScene(false);
    run(state, s);
}
BENCHMARK(BM_Tubes)->Arg(2)->Arg(1)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

static void BM_TubesChunkPerTube(benchmark::State& state) {
    static const scene::Scene s = tubeScene(true);
    run(state, s);
}
BENCHMARK(BM_TubesChunkPerTube)->Arg(2)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

static void BM_Platform(benchmark::State& state) {
    static const scene::Scene s = scene::makePlatformScene();
    run(state, s);
}
BENCHMARK(BM_Platform)->Arg(2)->Unit(benchmark::kSecond)->UseRealTime()->Iterations(1);

BENCHMARK_MAIN();
