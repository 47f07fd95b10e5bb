// Drawing only what changed (docs/design.md §2.6): each frame compares a side's PassInputs with what
// its images were drawn from and draws again only on a difference, coarse while the user drags and
// at full resolution once input pauses; the statistics and ground truth of a full-resolution frame
// are computed on a worker thread and shown when ready; the heatmap is rebuilt only when what it
// shows changed.
//
// Index
//   [SECTION] Inputs ............... passInputs, inspectionInputs
//   [SECTION] Drawing .............. renderViews, drawSide
//   [SECTION] Inspection ........... updateInspection, startInspection, pollInspections, abandonInspection,
//                                    cancelInspections, finishBackgroundWork
//   [SECTION] Heatmap .............. updateHeatmap
//   [SECTION] Scheduling ........... backgroundBusy, now, nextFrameIn
#include "dashboard.h"

#include "geometry/analysis/view_images.h"
#include "renderer/inspection.h"
#include "renderer/plan_frame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace ui {

namespace {

using Clock = std::chrono::steady_clock;

/// A coarse frame should leave the UI responsive: the shadow maps, the light views and the eye
/// view at reduced size within this many GPU milliseconds, so that with the dashboard's own
/// drawing (≈ 20 ms on llvmpipe at 1600×900) a drag step shows within ~100 ms.
constexpr double kCoarseBudgetMs = 60.0;

geometry::analysis::Image placeholder(int w, int h) {
    geometry::analysis::Image img;
    img.width = std::max(w, 1);
    img.height = std::max(h, 1);
    img.rgba.assign(size_t(img.width) * img.height * 4, 38);
    for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
    return img;
}

/// Nice 10 for the calling thread (Linux: per thread, inherited by the threads it starts).
void lowerThreadPriority() noexcept {
#ifdef __linux__
    (void)setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
#endif
}

/// A side's predicted GPU milliseconds at full resolution, from its last frame's pass times: the
/// eye-side passes, which scale with the pixel count, and the fixed part (shadow maps, light view).
struct FrameCost {
    double perPixel = NAN, fixed = 0.0; // perPixel NaN: not timed yet
    [[nodiscard]] double full() const noexcept { return perPixel + fixed; }
};

FrameCost frameCost(const renderer::PassTimes& t, int shownDivisor, double shadowGpuMs) noexcept {
    FrameCost c;
    if (t.valid)
        c.perPixel = (t.of(renderer::Pass::Prepass) + t.of(renderer::Pass::Eye)) * double(shownDivisor * shownDivisor);
    c.fixed = (std::isfinite(shadowGpuMs) ? shadowGpuMs : 0.0) + (t.valid ? t.of(renderer::Pass::LightView) : 0.0);
    return c;
}

bool ready(const std::future<geometry::analysis::Inspection>& f) {
    return f.valid() && f.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

} // namespace

// ---- [SECTION] Inputs -----------------------------------------------------------------------

PassInputs Dashboard::passInputs(int side) const {
    PassInputs in;
    in.settings = state_.settings[side];
    in.camera = scene_.file.scene.camera; // its lens (fov, near, far); eye and target from the rig
    state_.camera.applyTo(in.camera);
    in.lights = lights();
    in.inspectedLight = inspectedLight();
    in.size = eyeSize_;
    in.lightViewSize = lightViewSize_;
    in.lightSplit = state_.views.lightSplit;
    in.overlays = state_.views.overlays;
    in.unwarped = state_.views.unwarped && side == shownSide();
    in.sceneGeneration = sceneGeneration_;
    in.casterLod = sides_[side].renderer && sides_[side].renderer->hasCasterLod();
    return in;
}

InspectionInputs Dashboard::inspectionInputs(int side) const {
    return {passInputs(side), state_.views.truth && scene_.truth ? state_.views.truthSamples : 0};
}

// ---- [SECTION] Drawing ----------------------------------------------------------------------

void Dashboard::renderViews() {
    drewThisFrame_ = false;
    geometry::scene::Scene& scene = scene_.file.scene;
    state_.camera.applyTo(scene.camera);
    commitSun();
    scene.lights = state_.lights; // what the background measurements and the gizmo read

    const bool sideBySide = state_.views.compare == CompareMode::SideBySide;
    eyeSize_ = {std::max(16, int(sideBySide ? std::floor((eyeArea_.w - 2.f) * 0.5f) : eyeArea_.w)),
                std::max(16, int(eyeArea_.h))};
    const double t = now();
    const int sides = comparing() ? 2 : 1;
    std::array<PassInputs, 2> inputs;
    std::array<bool, 2> changed{};
    bool anyChanged = false;
    for (int i = 0; i < sides; ++i) {
        Side& side = sides_[i];
        if (!side.renderer) side.renderer = std::make_unique<renderer::Renderer>(scene);
        giveCasterLod(*side.renderer);
        inputs[i] = passInputs(i);
        changed[i] = !side.drawn || *side.drawn != inputs[i] || options_.redrawEveryFrame;
        anyChanged = anyChanged || changed[i];
    }
    const bool continuous = (continuousInput_ || flying_) && !options_.redrawEveryFrame;
    if (anyChanged) {
        lastChange_ = t;
        refinePause_ = continuous ? kRefinePause : 0.0; // a discrete change: nothing more follows
    }
    const double since = t - lastChange_;
    // Predicted from each side's last frames; a new side B costs what A did.
    std::array<FrameCost, 2> cost{};
    for (int i = 0; i < sides; ++i)
        cost[i] = frameCost(sides_[i].renderer->stats().gpu, sides_[i].coarseDivisor, sides_[i].shadowGpuMs);
    if (sides == 2 && !(cost[1].perPixel > 0.0)) cost[1] = cost[0];
    const int changedSides = int(changed[0]) + int(sides == 2 && changed[1]);
    bool fits = true;
    for (int i = 0; i < sides; ++i)
        fits = fits && fullFrameFits(cost[i].full(), changedSides, options_.responseBudgetMs);
    for (int i = 0; i < sides; ++i) {
        const Draw draw = decideDraw(changed[i], continuous, fits, sides_[i].coarseDivisor > 1, since, refinePause_);
        if (draw == Draw::None) continue;
        const int divisor =
            draw == Draw::Coarse ? coarseDivisor(cost[i].perPixel * sides, cost[i].fixed * sides, kCoarseBudgetMs) : 1;
        // A discrete change drawn coarse has new maps to draw anyway: at the same reduction as the
        // view, which keeps texels per pixel (and so the aliasing shown) as in the full frame.
        const int mapDivisor = draw == Draw::Coarse && !continuous ? divisor : 1;
        if (changed[i]) abandonInspection(sides_[i]); // it would describe a view no longer shown
        drawSide(i, inputs[i], divisor, mapDivisor);
    }
}

void Dashboard::drawSide(int i, const PassInputs& in, int divisor, int mapDivisor) {
    Side& side = sides_[i];
    const geometry::scene::Scene& scene = scene_.file.scene;
    const geometry::shadow::Viewport full = in.size;
    const geometry::shadow::Viewport size{std::max(8, full.width / divisor), std::max(8, full.height / divisor)};
    try {
        double us = 0;
        // Planned for the full view, so the full frame that refines a coarse drag frame keeps its
        // maps; with focus.mode = samples the plan comes from the samples of the pre-pass at the
        // drawn size.
        // Every light is planned for the same camera (docs/design.md §3.10); the plan kept is the
        // inspected light's, which the light view, the statistics and the heatmaps describe.
        geometry::shadow::ShadowSettings settings = in.settings;
        settings.resolution = std::max(16, settings.resolution / mapDivisor);
        const bool samples = settings.focus == geometry::shadow::FocusMode::Samples;
        if (in.lights.empty()) throw std::runtime_error("no light to draw");
        std::vector<geometry::shadow::ShadowPlan> plans;
        plans.reserve(in.lights.size());
        for (const geometry::scene::Light& light : in.lights) {
            double lightUs = 0;
            plans.push_back(renderer::planFrame(*side.renderer, settings, scene.bounds(), in.camera, light,
                                                samples ? size : full, &lightUs));
            us += lightUs;
        }
        const size_t inspected = std::min(in.inspectedLight, plans.size() - 1);
        side.plan = plans[inspected];
        side.planMicroseconds.add(us);
        renderer::ViewOptions v;
        v.lightViewSize = in.lightViewSize;
        v.lightSplit = std::clamp(in.lightSplit, 0, std::max(0, int(side.plan.splits.size()) - 1));
        v.overlays = in.overlays;
        v.unwarped = in.unwarped;
        v.reuseShadowMaps = !options_.redrawEveryFrame;
        v.depthPrePass = divisor == 1;
        side.renderer->render(plans, size, v, inspected); // the inspected light last
        const renderer::FrameStats& st = side.renderer->stats();
        if (!st.shadowMapsReused) ++counts_.shadow;
        ++(divisor > 1 ? counts_.eyeCoarse : counts_.eyeFull);
        side.size = full;
        side.coarseDivisor = divisor;
        side.drawn = in;
        drewThisFrame_ = true;
    } catch (const std::exception& e) {
        status_ = std::string(i ? "B: " : "") + e.what();
        side.drawn = in; // not again until something changes
    }
}

// ---- [SECTION] Inspection -------------------------------------------------------------------

void Dashboard::updateInspection() {
    const int sides = comparing() ? 2 : 1;
    for (int i = 0; i < sides; ++i) {
        const Side& side = sides_[i];
        // Only a frame drawn at full resolution from the current inputs is inspected.
        if (!side.renderer || !side.drawn || side.coarseDivisor > 1) continue;
        const InspectionInputs in = inspectionInputs(i);
        if (in.passes != *side.drawn) continue;
        if ((side.inspected && *side.inspected == in) || (side.job && side.job->inputs == in)) continue;
        startInspection(i, in);
    }
}

void Dashboard::startInspection(int i, const InspectionInputs& in) {
    Side& side = sides_[i];
    abandonInspection(side); // one for other inputs (e.g. the truth samples changed)
    try {
        // The read-back needs the GL context, so it happens here; the analysis runs on a worker.
        geometry::analysis::FrameReadback frame = renderer::readBack(*side.renderer, side.plan);
        InspectionJob job;
        job.inputs = in;
        job.eye = side.renderer->readEye();
        job.plan = side.plan;
        const geometry::analysis::GroundTruth* truth = in.truthSamples > 0 ? scene_.truth.get() : nullptr;
        const int samples = std::max(1, in.truthSamples);
        job.result = std::async(std::launch::async, [frame = std::move(frame), plan = job.plan, truth, samples,
                                                     stop = job.stop.get_token()]() mutable {
            lowerThreadPriority(); // the UI thread (and its GL) first; the truth's threads inherit it
            return geometry::analysis::makeInspection(std::move(frame), plan, truth, samples, stop);
        });
        side.job = std::move(job);
    } catch (const std::exception& e) {
        status_ = std::string("inspection failed: ") + e.what();
        side.inspection.reset();
        side.inspected = in; // not again until something changes
    }
}

void Dashboard::pollInspections() {
    std::erase_if(retiring_, [](const std::future<geometry::analysis::Inspection>& f) { return ready(f); });
    for (Side& side : sides_) {
        if (!side.job || !ready(side.job->result)) continue;
        InspectionJob job = std::move(*side.job);
        side.job.reset();
        try {
            side.inspection = job.result.get();
            side.eye = std::move(job.eye);
            ++counts_.inspections;
        } catch (const geometry::analysis::Cancelled&) {
            continue; // only a stop request cancels, and that job was not this one
        } catch (const std::exception& e) {
            status_ = std::string("inspection failed: ") + e.what();
            side.inspection.reset();
        }
        side.inspected = job.inputs;
        side.inspectionSerial = nextInspectionSerial_++;
    }
}

void Dashboard::abandonInspection(Side& side) {
    if (!side.job) return;
    side.job->stop.request_stop();
    retiring_.push_back(std::move(side.job->result)); // polled until its worker has stopped
    side.job.reset();
    ++counts_.cancelled;
}

void Dashboard::cancelInspections() {
    for (Side& side : sides_) abandonInspection(side);
}

bool Dashboard::finishBackgroundWork() {
    bool any = !retiring_.empty();
    for (Side& side : sides_)
        if (side.job && side.job->result.valid()) {
            side.job->result.wait();
            any = true;
        }
    for (auto& f : retiring_) f.wait();
    retiring_.clear();
    pollInspections();
    return any;
}

// ---- [SECTION] Heatmap ----------------------------------------------------------------------

void Dashboard::updateHeatmap() {
    const ViewSettings& v = state_.views;
    const int s = shownSide();
    const HeatmapInputs in{sides_[0].inspectionSerial,
                           comparing() ? sides_[1].inspectionSerial : 0,
                           s,
                           comparing(),
                           v.heatmap,
                           v.heatmapBlend,
                           v.texelGrid};
    if (heatmapShown_ && *heatmapShown_ == in) return;
    heatmapShown_ = in;
    const Side& side = sides_[s];
    geometry::analysis::Image img;
    geometry::analysis::Legend legend; // the panel draws it in the UI font; files bake it in
    try {
        if (!side.inspection) {
            img = placeholder(side.size.width, side.size.height);
        } else {
            const geometry::analysis::Inspection& in = *side.inspection;
            switch (v.heatmap) {
            case HeatmapKind::Aliasing:
                img = geometry::analysis::aliasingView(in, side.eye, v.heatmapBlend, &legend);
                break;
            case HeatmapKind::Truth:
                img = in.occluded ? geometry::analysis::truthView(in, side.eye, v.heatmapBlend, &legend)
                                  : placeholder(in.width, in.height);
                break;
            case HeatmapKind::Splits: img = geometry::analysis::splitsView(side.eye, in, side.plan, &legend); break;
            case HeatmapKind::Texels:
                img = geometry::analysis::texelsView(side.eye, in, std::max(1, v.texelGrid));
                break;
            case HeatmapKind::Difference:
                img = comparing() && sides_[0].inspection && sides_[1].inspection &&
                              sides_[0].inspection->width == sides_[1].inspection->width &&
                              sides_[0].inspection->height == sides_[1].inspection->height
                          ? geometry::analysis::differenceView(*sides_[0].inspection, *sides_[1].inspection, &legend)
                          : placeholder(in.width, in.height);
                break;
            case HeatmapKind::Soft:
                img = in.softTruth ? geometry::analysis::softView(in, side.eye, v.heatmapBlend, &legend)
                                   : placeholder(in.width, in.height);
                break;
            case HeatmapKind::Count: img = placeholder(in.width, in.height); break;
            }
        }
    } catch (const std::exception& e) {
        status_ = std::string("heatmap: ") + e.what();
        img = placeholder(side.size.width, side.size.height);
    }
    heatmapImage_ = std::move(img);
    heatmapLegend_ = std::move(legend);
    heatmap_.upload(heatmapImage_);
}

// ---- [SECTION] Scheduling -------------------------------------------------------------------

bool Dashboard::backgroundBusy() const noexcept {
    return !retiring_.empty() || sides_[0].job || sides_[1].job || loader_.busy() || casterLod_.building() ||
           sweep_.running() || recommend_.running();
}

double Dashboard::now() const {
    if (options_.clock) return options_.clock();
    return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}

std::optional<double> Dashboard::nextFrameIn() const {
    if (drewThisFrame_) return 0.0; // once more, so the panels' text matches the new images
    const int sides = comparing() ? 2 : 1;
    for (int i = 0; i < sides; ++i)
        if (!sides_[i].drawn || *sides_[i].drawn != passInputs(i)) return 0.0;
    std::optional<double> wait;
    if (coarse()) {
        wait = std::max(0.0, refinePause_ - (now() - lastChange_));
    }
    if (backgroundBusy() || gpuTimesInFlight_) wait = std::min(wait.value_or(0.05), 0.05);
    return wait;
}

} // namespace ui
