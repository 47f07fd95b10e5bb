// Input-to-updated-frame latency of the dashboard (issue 18): from the frame that takes an input
// event to the end of the frame that shows its effect (glFinish included), for a hover step, a
// slider step and an orbit step, and the cost of the full-resolution frame; each measured for the
// dashboard that draws only what changed ("after") and for one that draws every frame at full
// resolution as before (DashboardOptions::redrawEveryFrame, "before"), alternating in one run.
// Headless: OSMesa (llvmpipe) unless SHADOWSCOPE_BENCH_BACKEND says otherwise; `platform`
// (250k triangles), default settings, a 1600×900 dashboard. The window's idle CPU is measured on
// the real window by scripts/measure-idle-cpu.
//   Goals (issue 18, llvmpipe): hover ≤ 50 ms; first (coarse) frame after an orbit step ≤ 150 ms;
//   full-resolution frame unchanged in cost (after/before ≈ 1).
#include "app/dashboard_setup.h"
#include "renderer/context.h"
#include "ui/dashboard_headless.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kW = 1600, kH = 900;

struct Setup {
    std::unique_ptr<renderer::GlContext> context;
    std::unique_ptr<ui::HeadlessDashboard> after, before;
    Setup() {
        const char* backend = std::getenv("SHADOWSCOPE_BENCH_BACKEND");
        context = renderer::createHeadlessContext(renderer::parseBackend(backend ? backend : "auto"));
        after = make(false);
        before = make(true);
    }
    static std::unique_ptr<ui::HeadlessDashboard> make(bool redrawEveryFrame) {
        app::RenderOptions o;
        o.scene = "platform";
        o.size = {kW, kH};
        ui::LoadedScene scene = app::loadDashboardScene(o);
        ui::DashboardState state = app::initialDashboardState(scene, o);
        ui::DashboardOptions options = app::dashboardOptions(o);
        options.redrawEveryFrame = redrawEveryFrame;
        return std::make_unique<ui::HeadlessDashboard>(std::move(scene), state, options, kW, kH);
    }
};

Setup& setup() {
    static Setup s;
    return s;
}

double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

/// Full resolution, statistics in, nothing pending.
void settle(ui::HeadlessDashboard& d) {
    (void)d.render(1);
    if (d.dashboard().coarse()) {
        std::this_thread::sleep_for(std::chrono::duration<double>(ui::kRefinePause + 0.02));
        (void)d.render(1);
    }
}

glm::vec2 eyePoint(ui::HeadlessDashboard& d, float fx) {
    const ui::Rect& r = d.dashboard().rects().eye;
    return {r.x + r.w * fx, r.y + r.h * 0.6f};
}

struct Latencies {
    double hover = 0, slider = 0, orbit = 0, full = 0;
};

Latencies measure(ui::HeadlessDashboard& d, int iteration) {
    Latencies l;
    settle(d);
    // Hover: the frame that takes the pointer move shows the probe.
    const glm::vec2 h = eyePoint(d, 0.3f + 0.01f * float(iteration));
    auto t0 = Clock::now();
    d.step({h});
    l.hover = ms(t0, Clock::now());

    // Slider step (a typed or arrow-key change: not a drag): the event frame changes the value,
    // the next one draws it.
    settle(d);
    t0 = Clock::now();
    d.step({});
    d.dashboard().state().sun.azimuthDeg += (iteration % 2 ? -1.f : 1.f);
    d.step({});
    l.slider = ms(t0, Clock::now());

    // Orbit step from rest: the button is down; the frame that takes the move turns the camera
    // before it draws (coarse when drawing only what changed).
    settle(d);
    glm::vec2 p = eyePoint(d, 0.5f);
    d.step({p, {true, false, false}});
    p.x += 6.f;
    t0 = Clock::now();
    d.step({p, {true, false, false}});
    l.orbit = ms(t0, Clock::now());
    d.step({p, {false, false, false}});

    // The full-resolution frame: the refinement after the pause (before: any frame).
    std::this_thread::sleep_for(std::chrono::duration<double>(ui::kRefinePause + 0.02));
    t0 = Clock::now();
    d.step({});
    l.full = ms(t0, Clock::now());
    return l;
}

double median(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
}

void BM_DashboardLatency(benchmark::State& state) {
    Setup& s = setup();
    settle(*s.after);
    settle(*s.before);
    std::vector<Latencies> after, before;
    int i = 0;
    for (auto _ : state) {
        // Alternating, so drift of the machine shows in both columns alike.
        after.push_back(measure(*s.after, i));
        before.push_back(measure(*s.before, i));
        ++i;
    }
    const auto col = [](const std::vector<Latencies>& v, double Latencies::*f) {
        std::vector<double> x;
        for (const auto& l : v) x.push_back(l.*f);
        return median(x);
    };
    for (const auto& [name, field] : {std::pair{"hover", &Latencies::hover}, std::pair{"slider", &Latencies::slider},
                                      std::pair{"orbit", &Latencies::orbit}, std::pair{"full", &Latencies::full}}) {
        const double a = col(after, field), b = col(before, field);
        state.counters[std::string(name) + "_ms_after"] = a;
        state.counters[std::string(name) + "_ms_before"] = b;
        state.counters[std::string(name) + "_after_over_before"] = a / b;
    }
    const ui::PassCounts& c = s.after->dashboard().passCounts();
    state.counters["after_coarse_frames"] = double(c.eyeCoarse);
    state.counters["after_full_frames"] = double(c.eyeFull);
    state.SetLabel(s.context->rendererString());
}

} // namespace

BENCHMARK(BM_DashboardLatency)->Unit(benchmark::kMillisecond)->Iterations(7)->UseRealTime();

BENCHMARK_MAIN();
