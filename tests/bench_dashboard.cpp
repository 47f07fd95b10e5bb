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
// BM_DashboardResponse (issue 32): for a warp change, a split-count change and turning A/B side by
// side on, the first visible response (from the frame that takes the event to the end of the first frame that drew
// every shown side again) and the refinement (to the end of the frame that completed the full-
// resolution views). Goal: first response ≤ 250 ms on llvmpipe.
#include "app/dashboard_setup.h"
#include "renderer/context.h"
#include "ui/dashboard_headless.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
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
    std::unique_ptr<ui::HeadlessDashboard> fullFirst; // discrete changes drawn at full resolution at once
    Setup() {
        const char* backend = std::getenv("SHADOWSCOPE_BENCH_BACKEND");
        context = renderer::createHeadlessContext(renderer::parseBackend(backend ? backend : "auto"));
        after = make(false);
        before = make(true);
        fullFirst = make(false, INFINITY);
    }
    static std::unique_ptr<ui::HeadlessDashboard> make(bool redrawEveryFrame,
                                                       double responseBudgetMs = ui::kResponseBudgetMs) {
        app::RenderOptions o;
        o.scene = "platform";
        o.size = {kW, kH};
        ui::LoadedScene scene = app::loadDashboardScene(o);
        ui::DashboardState state = app::initialDashboardState(scene, o);
        ui::DashboardOptions options = app::dashboardOptions(o);
        options.redrawEveryFrame = redrawEveryFrame;
        if (!redrawEveryFrame) options.responseBudgetMs = responseBudgetMs; // the window's: kResponseBudgetMs
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

/// Eye passes drawn so far (coarse or full).
uint64_t eyePasses(ui::HeadlessDashboard& d) {
    const ui::PassCounts& c = d.dashboard().passCounts();
    return c.eyeCoarse + c.eyeFull;
}

struct Response {
    double first = 0, refine = 0;
};

/// Applies `change` to a settled dashboard in the frame that takes the event and steps frames
/// until it shows every side again (first) and until the views are at full resolution (refine);
/// the pause before refining is real time.
template <class Change> Response respond(ui::HeadlessDashboard& d, Change change) {
    settle(d);
    const uint64_t before = eyePasses(d);
    // As a combo or a typed value does: the frame that takes the event changes the state while
    // ImGui builds it, and the frames after draw the change.
    const auto t0 = Clock::now();
    d.step({});
    change(d.dashboard().state());
    const int sides = d.dashboard().state().views.compare == ui::CompareMode::Off ? 1 : 2;
    Response r;
    for (int frame = 0; frame < 200; ++frame) {
        d.step({});
        if (r.first == 0 && eyePasses(d) >= before + uint64_t(sides)) r.first = ms(t0, Clock::now());
        if (r.first > 0 && !d.dashboard().coarse()) {
            r.refine = ms(t0, Clock::now());
            break;
        }
    }
    if (r.refine == 0) r.refine = ms(t0, Clock::now());
    return r;
}

/// The three changes once each on `d`; appends the responses to `out` (warp, splits, A/B).
void respondToChanges(ui::HeadlessDashboard& d, std::array<std::vector<Response>, 3>& out) {
    using geometry::shadow::WarpMethod;
    out[0].push_back(respond(d, [](ui::DashboardState& st) {
        WarpMethod& m = st.settings[0].warp.method;
        m = m == WarpMethod::Uniform ? WarpMethod::Lispsm : WarpMethod::Uniform;
    }));
    out[1].push_back(respond(d, [](ui::DashboardState& st) {
        int& k = st.settings[0].splits.count;
        k = k == 1 ? 3 : 1;
    }));
    // A/B on after B's settings changed, so that both sides draw (as the first time it is turned on).
    out[2].push_back(respond(d, [](ui::DashboardState& st) {
        st.views.compare = ui::CompareMode::SideBySide;
        int& k = st.settings[1].splits.count;
        k = k == 1 ? 2 : 1;
    }));
    d.dashboard().state().views.compare = ui::CompareMode::Off;
    settle(d);
}

void BM_DashboardResponse(benchmark::State& state) {
    Setup& s = setup();
    std::array<std::vector<Response>, 3> coarseFirst, fullFirst;
    for (auto _ : state) {
        // Alternating, so drift of the machine shows in both alike.
        respondToChanges(*s.after, coarseFirst);
        respondToChanges(*s.fullFirst, fullFirst);
    }
    const auto col = [](const std::vector<Response>& v, double Response::*f) {
        std::vector<double> x;
        for (const Response& r : v) x.push_back(r.*f);
        return median(x);
    };
    const char* names[] = {"warp", "splits", "ab"};
    for (size_t c = 0; c < 3; ++c) {
        const std::string n = names[c];
        state.counters[n + "_first_ms"] = col(coarseFirst[c], &Response::first);
        state.counters[n + "_refine_ms"] = col(coarseFirst[c], &Response::refine);
        state.counters[n + "_full_first_ms"] = col(fullFirst[c], &Response::first);
        state.counters[n + "_first_over_full_first"] =
            col(coarseFirst[c], &Response::first) / col(fullFirst[c], &Response::first);
    }
    state.SetLabel(s.context->rendererString());
}

} // namespace

BENCHMARK(BM_DashboardResponse)->Unit(benchmark::kMillisecond)->Iterations(5)->UseRealTime();
BENCHMARK(BM_DashboardLatency)->Unit(benchmark::kMillisecond)->Iterations(7)->UseRealTime();

BENCHMARK_MAIN();
