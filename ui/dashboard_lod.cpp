// The dashboard's side of the caster levels of detail (the build itself: caster_lod_job.h): asking
// for them when a side sets casters.lod = auto, handing them to the renderers, and their status.
#include "dashboard.h"

#include <cstdio>

namespace ui {

void Dashboard::stepCasterLod() {
    bool wanted = false;
    for (int i = 0; i < (comparing() ? 2 : 1); ++i)
        wanted = wanted || state_.settings[i].casters.lod == geometry::shadow::CasterLod::Auto;
    if (auto status = casterLod_.step(scene_.file.scene, wanted)) status_ = std::move(*status);
}

void Dashboard::giveCasterLod(renderer::Renderer& r) const {
    if (casterLod_.levels() && !r.hasCasterLod()) r.setCasterLod(*casterLod_.levels());
}

std::string Dashboard::casterLodStatus(int side) const {
    if (state_.settings[side].casters.lod != geometry::shadow::CasterLod::Auto) return "off";
    if (!casterLod_.levels()) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "building %.0f %% (full detail meanwhile)", 100.0 * casterLod_.progress());
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
