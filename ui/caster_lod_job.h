#pragma once
// The dashboard's caster levels of detail (geometry/lod): built once per scene on a worker thread the
// first time a side asks for casters.lod = auto, with progress; until they are in, the shadow passes
// draw every triangle. cancel() (a scene change) stops a build in flight and drops the levels.
#include "geometry/lod/caster_lod.h"
#include "geometry/scene/scene.h"

#include <atomic>
#include <future>
#include <memory>
#include <optional>
#include <string>

namespace ui {

class CasterLodJob {
public:
    CasterLodJob() = default;
    CasterLodJob(const CasterLodJob&) = delete; // the worker reports progress into this object
    CasterLodJob& operator=(const CasterLodJob&) = delete;
    ~CasterLodJob() { cancel(); }

    /// Takes a finished build (returning its status line), or starts one over `scene` when `wanted`
    /// and there are no levels yet; `scene` must outlive the build or a cancel().
    std::optional<std::string> step(const geometry::scene::Scene& scene, bool wanted);
    /// Stops a build in flight (waiting for it) and forgets the levels.
    void cancel() noexcept;
    [[nodiscard]] bool building() const noexcept { return build_.valid(); }
    /// The levels once built; null before.
    [[nodiscard]] const geometry::lod::SceneLod* levels() const noexcept { return levels_.get(); }
    /// The build's progress in [0, 1].
    [[nodiscard]] float progress() const noexcept { return progress_.load(); }

private:
    std::future<geometry::lod::SceneLod> build_;
    std::shared_ptr<const geometry::lod::SceneLod> levels_;
    std::atomic<float> progress_{0.f};
    std::atomic<bool> cancel_{false};
};

} // namespace ui
