#pragma once
// What a configuration costs, from the work it does rather than from the clock (docs/design.md §4
// "Cost model"): the triangles, texels and filter taps a frame counts, weighted by per-unit times
// calibrated once per backend. The same frame always costs the same, whatever the machine's load,
// so `tune` ranks reproducibly; the measured time is shown beside it. Pure.
#include "geometry/shadow/shadow_plan.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace geometry::analysis {

/// The work one frame of a plan does, by kind (kWorkKinds of them, in this order).
struct WorkCounts {
    static constexpr int kKinds = 6;
    double eyePixels = 0;       // the eye pass's pixels (pre-pass, shading, read-back)
    double eyeTriangles = 0;    // triangles the eye pass draws
    double eyeTaps = 0;         // shadow-map lookups: pixels × the filter's taps (and eye-blur passes)
    double shadowTriangles = 0; // triangles the shadow passes draw (every split, every peeling pass)
    double shadowTexels = 0;    // texels the shadow passes clear and rasterise (Σ splits res², × passes)
    double blurTexels = 0;      // moment maps: texels written and blurred (Σ res² × (1 + 2·kernel))
    [[nodiscard]] std::array<double, kKinds> values() const noexcept {
        return {eyePixels, eyeTriangles, eyeTaps, shadowTriangles, shadowTexels, blurTexels};
    }
};

/// The names of the kinds, as the calibration file spells them (ns per unit).
[[nodiscard]] const std::array<std::string_view, WorkCounts::kKinds>& workKindNames() noexcept;

/// Counts a frame of `plan` (drawn from `s`) at `size` whose passes drew the given triangles.
[[nodiscard]] WorkCounts countWork(const shadow::ShadowSettings& s, const shadow::ShadowPlan& plan,
                                   uint64_t shadowTriangles, uint64_t eyeTriangles, shadow::Viewport size) noexcept;

/// Nanoseconds per unit of each kind of work, for one backend.
struct CostModel {
    std::string backend;
    std::array<double, WorkCounts::kKinds> nsPerUnit{};
    [[nodiscard]] double costMs(const WorkCounts& w) const noexcept;
};

/// The stored calibration for a renderer string (GL_RENDERER): llvmpipe's for llvmpipe; for a
/// backend without one, llvmpipe's too, with `calibrated` false (tune says so).
[[nodiscard]] CostModel storedCostModel(std::string_view rendererString, bool* calibrated = nullptr);

/// One calibration sample: a frame's work and its measured time.
struct CostSample {
    WorkCounts work;
    double ms = 0;
};

/// Least squares of ms against the work, no coefficient negative (a kind that fits negative is
/// dropped and the rest refitted). Throws std::invalid_argument with fewer samples than kinds.
[[nodiscard]] CostModel fitCostModel(const std::vector<CostSample>& samples, std::string backend);

/// The model as a JSON object {"backend": …, "ns_per_unit": {kind: value, …}}.
[[nodiscard]] std::string costModelJson(const CostModel& model);

} // namespace geometry::analysis
