#include "sweep_frame.h"

#include "caster_lod_setup.h"
#include "geometry/scene/chunking.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>

namespace app {

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

std::string duration(double s) {
    char buf[32];
    if (s < 90) std::snprintf(buf, sizeof buf, "%.0f s", s);
    else std::snprintf(buf, sizeof buf, "%.0f min", s / 60);
    return buf;
}

/// A copy whose arrays the truth can share (a copied vector has no spare capacity).
geometry::scene::Scene shareableCopy(const geometry::scene::Scene& scene) {
    geometry::scene::Scene copy = scene;
    for (geometry::scene::Mesh& m : copy.meshes) geometry::scene::reserveSpareVertex(m);
    return copy;
}

} // namespace

SweepRenderer::SweepRenderer(const geometry::scene::Scene& scene, const std::string& backend)
    : scene_(shareableCopy(scene)), context_(renderer::createHeadlessContext(renderer::parseBackend(backend))),
      renderer_(std::make_unique<renderer::Renderer>(scene_)),
      truth_(geometry::analysis::GroundTruth::borrowing(scene_)) {}

SweepFrame SweepRenderer::render(const geometry::shadow::ShadowSettings& settings,
                                 const geometry::scene::Camera& camera, const geometry::scene::Light& light,
                                 const geometry::shadow::Viewport& viewport,
                                 std::span<const geometry::scene::Light> others) {
    ensureCasterLod(*renderer_, scene_, settings);
    context_->makeCurrent();
    SweepFrame f;
    renderer::Measurement m = renderer::measure(*renderer_, settings, scene_.bounds(), camera, light, viewport,
                                                {.warmup = 0, .frames = 1, .timed = false}, nullptr, others);
    f.plan = std::move(m.plan);
    f.in = std::move(m.inspection);
    const geometry::analysis::TruthLight truthLight = geometry::analysis::truthLight(f.plan);
    const bool same = f.plan.eyeView == truthView_ && f.plan.eyeProj == truthProj_ && truthLight == truthLight_ &&
                      truthOccluded_.size() == f.in.positions.size();
    if (!same) {
        truthOccluded_ = geometry::analysis::truthOcclusion(f.in, f.plan.eye, truthLight, truth_);
        truthView_ = f.plan.eyeView;
        truthProj_ = f.plan.eyeProj;
        truthLight_ = truthLight;
    }
    f.in.occluded = truthOccluded_;
    f.in.truth = geometry::analysis::truthStats(f.in.shadow, *f.in.occluded, f.in.receiver);
    f.glErrors = renderer::takeGlErrors();
    return f;
}

SweepProgress::SweepProgress(std::string label, int total)
    : label_(std::move(label)), total_(total), terminal_(isatty(STDERR_FILENO) == 1), start_(now()) {}

SweepProgress::~SweepProgress() {
    if (!shown_) return;
    if (std::uncaught_exceptions() > 0) std::cerr << "\r\033[K" << std::flush;
    else
        std::cerr << "\r\033[K" << label_ << ": " << total_ << " frames in " << duration(now() - start_) << '\n'
                  << std::flush;
}

void SweepProgress::step(int done, const std::string& detail) {
    if (!terminal_) return;
    const double t = now();
    if (last_ >= 0 && t - last_ < 0.2 && done < total_) return;
    last_ = t;
    shown_ = true;
    const double elapsed = t - start_;
    std::string eta;
    if (done > 0 && done < total_) eta = ", ~" + duration(elapsed / done * (total_ - done)) + " left";
    const int percent = total_ > 0 ? int(std::lround(100.0 * done / total_)) : 100;
    std::cerr << "\r\033[K" << label_ << ": " << done << '/' << total_ << " (" << percent << " %), " << detail << ", "
              << duration(elapsed) << eta << std::flush;
}

} // namespace app
