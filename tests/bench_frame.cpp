// Frame time of one configuration against another, measured in the same run (A and B alternate
// each iteration, so drift of the machine cancels in the ratio). Headless: EGL on a GPU when there
// is one, else OSMesa (llvmpipe). Scene `platform`, Barroso's setup: 800×600, 2048² maps.
//   Goals (issue 4): paper/ssm ≤ 1.3 on llvmpipe, ≤ 1.15 on a GPU; 5×5 PCF eye pass ≤ 1.1× hard test.
#include "geometry/io/preset.h"
#include "geometry/scene/builtin_scenes.h"
#include "renderer/context.h"
#include "renderer/renderer.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace geometry::scene;
using namespace geometry::shadow;
using namespace geometry::io;
using namespace geometry::analysis;

struct Setup {
    std::unique_ptr<renderer::GlContext> context;
    Scene scene = makePlatformScene();
    std::unique_ptr<renderer::Renderer> r;
    Setup() {
        const char* backend = std::getenv("SHADOWSCOPE_BENCH_BACKEND");
        context = renderer::createHeadlessContext(renderer::parseBackend(backend ? backend : "auto"));
        r = std::make_unique<renderer::Renderer>(scene);
    }
};

Setup& setup() {
    static Setup s;
    return s;
}

ShadowSettings preset(const std::string& name) {
    return geometry::io::loadPreset(std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/presets/" + name + ".json");
}

/// Renders one frame and waits for it; returns GPU times per pass.
renderer::PassTimes frame(const ShadowSettings& s, const Viewport& vp) {
    Setup& st = setup();
    const ShadowPlan plan = planShadows(s, st.scene.bounds(), st.scene.camera, st.scene.light, vp);
    renderer::ViewOptions views;
    views.lightViewSize = 64;
    views.overlays = views.unwarped = false; // time the shadowing, not the inspection views
    st.r->render(plan, vp, views);
    return st.r->waitForTimings();
}

void compare(benchmark::State& state, const ShadowSettings& a, const ShadowSettings& b, renderer::Pass pass,
             bool wholeFrame) {
    const Viewport vp{800, 600};
    frame(a, vp); // warm-up: shader compilation, allocation
    frame(b, vp);
    // Per-iteration ratios, reported as their median: one slow frame (the machine is shared) moves
    // a mean of sums but not the median.
    std::vector<double> ratios, as, bs;
    for (auto _ : state) {
        const auto pa = frame(a, vp);
        const auto pb = frame(b, vp);
        as.push_back(wholeFrame ? pa.frame() : pa.of(pass));
        bs.push_back(wholeFrame ? pb.frame() : pb.of(pass));
        ratios.push_back(bs.back() / as.back());
    }
    const auto median = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
        return v[v.size() / 2];
    };
    state.counters["A_ms"] = median(as);
    state.counters["B_ms"] = median(bs);
    state.counters["B_over_A"] = median(ratios);
    state.SetLabel(setup().context->rendererString());
}

void BM_PaperOverSsm(benchmark::State& state) {
    compare(state, preset("ssm"), preset("paper"), renderer::Pass::Shadow, true);
}

void BM_Pcf5EyeOverHard(benchmark::State& state) {
    ShadowSettings hard = preset("paper");
    hard.filter.type = FilterType::None;
    ShadowSettings pcf = preset("paper");
    pcf.filter.type = FilterType::Pcf;
    pcf.filter.kernel = 5;
    compare(state, hard, pcf, renderer::Pass::Eye, false);
}

void BM_PcfKernelEyeOverHard(benchmark::State& state) {
    ShadowSettings hard = preset("ssm");
    hard.filter.type = FilterType::None;
    ShadowSettings pcf = hard;
    pcf.filter.type = FilterType::Pcf;
    pcf.filter.kernel = int(state.range(0));
    compare(state, hard, pcf, renderer::Pass::Eye, false);
}

} // namespace

BENCHMARK(BM_PaperOverSsm)->Unit(benchmark::kMillisecond)->Iterations(9)->UseRealTime();
BENCHMARK(BM_Pcf5EyeOverHard)->Unit(benchmark::kMillisecond)->Iterations(9)->UseRealTime();
BENCHMARK(BM_PcfKernelEyeOverHard)->Arg(3)->Arg(7)->Unit(benchmark::kMillisecond)->Iterations(3)->UseRealTime();

BENCHMARK_MAIN();
