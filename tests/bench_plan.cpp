// planShadows on the 250k-triangle platform: goal ≤ 20 µs for 4 splits on the 2-core dev machine.
#include "geometry/scene/builtin_scenes.h"
#include "geometry/shadow/shadow_plan.h"

#include <benchmark/benchmark.h>

using namespace geometry::scene;
using namespace geometry::shadow;

static void BM_PlanShadows(benchmark::State& state) {
    static const Scene scene = makePlatformScene();
    static const Aabb S = scene.bounds();
    ShadowSettings settings;
    settings.warp.method = state.range(1) ? WarpMethod::Lispsm : WarpMethod::Uniform;
    settings.splits.count = int(state.range(0));
    settings.splits.scheme = SplitScheme::Practical;
    for (auto _ : state) {
        ShadowPlan plan = planShadows(settings, S, scene.camera, scene.lights[0], {1920, 1080});
        benchmark::DoNotOptimize(plan);
    }
}
BENCHMARK(BM_PlanShadows)
    ->ArgsProduct({{1, 2, 4, 8}, {0, 1}})
    ->ArgNames({"splits", "lispsm"})
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
