#include "caster_lod_job.h"

#include <chrono>

namespace ui {

std::optional<std::string> CasterLodJob::step(const geometry::scene::Scene& scene, bool wanted) {
    if (build_.valid()) {
        if (build_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
        std::string status;
        try {
            levels_ = std::make_shared<const geometry::lod::SceneLod>(build_.get());
            status = "caster LOD built: " + std::to_string(levels_->lodTriangles) + " triangles in simplified levels";
        } catch (const std::exception& e) {
            status = std::string("caster LOD failed: ") + e.what();
        }
        build_ = {};
        return status;
    }
    if (levels_ || !wanted) return std::nullopt;
    progress_ = 0.f;
    cancel_ = false;
    build_ = std::async(std::launch::async, [this, &scene] {
        return geometry::lod::buildCasterLod(scene, {}, [this](float done) {
            progress_ = done;
            return !cancel_.load();
        });
    });
    return std::nullopt;
}

void CasterLodJob::cancel() noexcept {
    cancel_ = true;
    if (build_.valid()) build_.wait();
    build_ = {};
    levels_.reset();
}

} // namespace ui
