// Ground truth on the 250k-triangle platform: goal ≤ 150 ms per 1280×720 image on the 2-core
// dev machine (Release). Receivers are what the default camera sees, found once by primary rays
// outside the timed loops; only the shadow rays are timed.
#include "geometry/analysis/ground_truth.h"
#include "geometry/scene/builtin_scenes.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

using namespace geometry::scene;
using namespace geometry::analysis;

namespace {

constexpr int kWidth = 1280, kHeight = 720;

struct Fixture {
    Scene scene = makePlatformScene();
    GroundTruth truth{scene};
    PrimaryHits hits = truth.primaryHits(scene.camera, kWidth, kHeight);
};

const Fixture& fixture() {
    static const Fixture f;
    return f;
}

/// The fastest repetition: the dev machine is shared, and others' builds only ever add time.
/// Run with --benchmark_repetitions=N to get it next to the mean and median.
double fastest(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end()); }

/// Rays actually traced per call: pixels that see the sky are skipped.
void reportRays(benchmark::State& state, size_t rays) {
    state.counters["Mrays/s"] = benchmark::Counter(
        static_cast<double>(rays) * 1e-6 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
    state.counters["rays"] = static_cast<double>(rays);
}

/// Every benchmark here: wall-clock milliseconds, and the fastest repetition as "min".
void timed(benchmark::internal::Benchmark* b) {
    b->Unit(benchmark::kMillisecond)->UseRealTime()->ComputeStatistics("min", fastest);
}

/// The same with 1 and 2 threads.
void timedOnThreads(benchmark::internal::Benchmark* b) { timed(b->Arg(1)->Arg(2)->ArgName("threads")); }

} // namespace

/// occluded() over the image in row-major order: packets are 1×16 strips of pixels.
static void BM_Occluded(benchmark::State& state) {
    const Fixture& f = fixture();
    const int threads = static_cast<int>(state.range(0));
    for (auto _ : state) {
        auto shadow = f.truth.occluded(f.hits.points, f.hits.normals, f.scene.lights[0].l(), threads);
        benchmark::DoNotOptimize(shadow.data());
    }
    reportRays(state, f.hits.hitCount());
}
BENCHMARK(BM_Occluded)->Apply(timedOnThreads);

/// The untimed setup above, for reference: primary rays for 1280×720.
static void BM_PrimaryHits(benchmark::State& state) {
    const Fixture& f = fixture();
    for (auto _ : state) {
        PrimaryHits hits = f.truth.primaryHits(f.scene.camera, kWidth, kHeight);
        benchmark::DoNotOptimize(hits.points.data());
    }
    reportRays(state, static_cast<size_t>(kWidth) * kHeight);
}
BENCHMARK(BM_PrimaryHits)->Apply(timed);

/// sunVisibility() with the soft truth's 8 × 8 rays per receiver and a 0.53° sun, over the receivers
/// (facing the light) of a 320 × 180 view: 64 rays each, in packets of 16 per receiver.
static void BM_SunVisibility(benchmark::State& state) {
    const Fixture& f = fixture();
    static const PrimaryHits small = f.truth.primaryHits(f.scene.camera, 320, 180);
    const glm::vec3 l = f.scene.lights[0].l();
    std::vector<glm::vec3> normals = small.normals;
    size_t receivers = 0;
    for (glm::vec3& n : normals) {
        if (glm::dot(n, -l) > 0.f) ++receivers;
        else n = glm::vec3(0.f); // not a receiver: not traced, as addTruth does
    }
    const int threads = static_cast<int>(state.range(0));
    constexpr int kSamples = GroundTruth::kSunSamplesPerAxis;
    for (auto _ : state) {
        auto v = f.truth.sunVisibility(small.points, normals, l, glm::radians(0.53f), kSamples, threads);
        benchmark::DoNotOptimize(v.data());
    }
    reportRays(state, receivers * kSamples * kSamples);
}
BENCHMARK(BM_SunVisibility)->Apply(timedOnThreads);

/// BVH build over the 250k triangles (once per scene).
static void BM_Build(benchmark::State& state) {
    const Fixture& f = fixture();
    for (auto _ : state) {
        GroundTruth truth(f.scene);
        benchmark::DoNotOptimize(truth.triangleCount());
    }
}
BENCHMARK(BM_Build)->Apply(timed);

BENCHMARK_MAIN();
