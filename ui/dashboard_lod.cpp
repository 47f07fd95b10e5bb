// The dashboard's caster levels of detail: built once per scene on a worker thread the first time
// a side sets casters.lod = auto, with progress in the stats; until they are in, the shadow passes
// draw every triangle. A scene change cancels a build in flight.
#include "dashboard.h"

#include <chrono>
#include <cstdio>

namespace ui {

void Dashboard::stepCasterLod() {
    if (lodBuild_.valid()) {
        if (lodBuild_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
        try {
            lod_ = std::make_shared<const geometry::lod::SceneLod>(lodBuild_.get());
            status_ = "caster LOD built: " + std::to_string(lod_->lodTriangles) + " triangles in simplified levels";
        } catch (const std::exception& e) {
            status_ = std::string("caster LOD failed: ") + e.what();
        }
        lodBuild_ = {};
        return;
    }
    if (lod_) return;
    bool wanted = false;
    for (int i = 0; i < (comparing() ? 2 : 1); ++i)
        wanted = wanted || state_.settings[i].casters.lod == geometry::shadow::CasterLod::Auto;
    if (!wanted) return;
    lodProgress_ = 0.f;
    lodCancel_ = false;
    lodBuild_ = std::async(std::launch::async, [this, &scene = scene_.file.scene] {
        return geometry::lod::buildCasterLod(scene, {}, [this](float done) {
            lodProgress_ = done;
            return !lodCancel_.load();
        });
    });
}

void Dashboard::cancelCasterLod() noexcept {
    lodCancel_ = true;
    if (lodBuild_.valid()) lodBuild_.wait();
    lodBuild_ = {};
    lod_.reset();
}

void Dashboard::giveCasterLod(renderer::Renderer& r) const {
    if (lod_ && !r.hasCasterLod()) r.setCasterLod(*lod_);
}

std::string Dashboard::casterLodStatus(int side) const {
    if (state_.settings[side].casters.lod != geometry::shadow::CasterLod::Auto) return "off";
    if (!lod_) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "building %.0f %% (full detail meanwhile)", 100.0 * lodProgress_.load());
        return buf;
    }
    const renderer::Renderer* r = sides_[side].renderer.get();
    if (!r) return "built";
    uint64_t drawn = 0, full = 0;
    for (const uint64_t n : r->stats().splitTriangles) drawn += n;
    for (const uint64_t n : r->stats().splitTrianglesFull) full += n;
    char buf[96];
    std::snprintf(buf, sizeof buf, "%llu of %llu shadow triangles", static_cast<unsigned long long>(drawn),
                  static_cast<unsigned long long>(full));
    return buf;
}

} // namespace ui
