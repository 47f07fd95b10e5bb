#pragma once
// What the eye actually sees, reduced to a few numbers (sample-distribution shadow maps, Lauritzen
// et al. 2010; docs/design.md §3.7): the view-depth range of the visible samples and, per
// log-spaced view-depth bin, their extent along a few fixed directions (an 8-sided prism around the
// light direction l, closed along l). The renderer fills it on the GPU (renderer/sample_reduction);
// the planner takes it as a plain input value and fits splits and focus bodies to it.
#include "geometry/shadow/convex_body.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace geometry::shadow {

/// View-depth bins between the camera's n and f, log spaced (the shaders use the same count).
inline constexpr int kSampleBins = 128;
/// Directions each bin's samples are bounded along: four in the light's plane, 45° apart, and l.
inline constexpr int kSampleDirections = 5;

struct SampleBin {
    uint32_t count = 0;
    std::array<float, kSampleDirections> lo{}, hi{}; // min and max of d_k·x over the bin's samples
};

struct SampleBounds {
    float n = 0.f, f = 0.f;       // the bins' range: the camera's n and f
    glm::vec3 l{0.f, -1.f, 0.f};  // the light direction the directions were built for
    float zMin = 0.f, zMax = 0.f; // view depth of the nearest and farthest visible sample
    uint64_t count = 0;           // visible samples (pixels that hit geometry)
    std::vector<SampleBin> bins;  // kSampleBins, nearest first
    [[nodiscard]] bool empty() const noexcept { return count == 0 || bins.size() != size_t(kSampleBins); }
};

/// d_0..d_4: the four lateral directions (0°, 45°, 90°, 135° about l from a basis that depends on l
/// alone) and l itself. The renderer uploads these to the reduction shader.
[[nodiscard]] std::array<glm::vec3, kSampleDirections> sampleDirections(const glm::vec3& l) noexcept;

/// The bin of view depth z (clamped to the first or last); the reduction shader mirrors it.
[[nodiscard]] int sampleBin(double z, double n, double f) noexcept;
/// View depth where bin i starts (i = kSampleBins: f).
[[nodiscard]] double sampleBinStart(int i, double n, double f) noexcept;

/// The samples with view depth in [a, b], as far as the bins tell (every bin that overlaps the
/// range counts whole, so the bounds are conservative): how many, and the planes of their prism.
struct SampleSlab {
    uint64_t count = 0;
    std::vector<Plane> planes; // inside: n·x + d ≤ 0; empty when count = 0
};
/// `margin` widens every plane by that fraction of the prism's extent along its direction.
[[nodiscard]] SampleSlab samplesWithin(const SampleBounds& bounds, double a, double b, double margin);

/// The view depths where the samples' cumulative count reaches i/k of those in [a, b], i = 1..k−1
/// (k − 1 values, ascending, within [a, b]), from the log-spaced bins (log-linear within a bin):
/// each split of these holds the same share of the visible pixels. Empty without samples.
[[nodiscard]] std::vector<double> sampleQuantiles(const SampleBounds& bounds, double a, double b, int k);

/// The reference reduction on the CPU, for tests: samples are world points with their view depths.
[[nodiscard]] SampleBounds reduceSamples(std::span<const glm::vec3> world, std::span<const float> viewDepth, float n,
                                         float f, const glm::vec3& l);

} // namespace geometry::shadow
