#pragma once
// The rendered shadow against ray-traced truth, decomposed (docs/design.md §4 "Truth classes"):
// errors inside lit or shadowed regions (acne, leaks, lost casters) apart from shadow edges drawn
// in slightly the wrong place, and pixels no shadow map can decide apart from both. Which pixels are
// undecidable comes from the scene and the view alone, never from the settings being judged.
// Pure, no GL; per-pixel inputs are row-major, top row first.
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace geometry::analysis {

/// Why a pixel is undecidable (left out of the other classes): properties of the scene and the view.
enum class Ambiguity : uint8_t {
    None = 0,
    Terminator = 1, // |N·L| < 0.1 by the geometric normal: the surface grazes the light
    NormalFlip = 2, // the shading normal faces the light, the geometric one does not (or the reverse)
    Contact = 3,    // an occluder lies within one eye-pixel footprint of the receiver along the light
};

/// Per pixel, the class it falls in (the truth heatmap's colours).
enum class TruthClass : uint8_t {
    NotCounted = 0, // not a receiver, or s or c not finite
    Agrees,         // rendered state = truth state
    InteriorFalseShadow,
    InteriorFalseLit,
    EdgeError, // misclassified within 1 px of a truth edge
    Ambiguous,
    Singular, // the eye pass's J is singular (m capped): its own class, as in the aliasing figures
};

struct TruthClassInput {
    int width = 0;
    std::span<const float> s{};        // rendered lit fraction
    std::span<const float> coverage{}; // truth lit fraction c ∈ [0, 1] over the pixel's samples
    std::span<const uint8_t> receiver{};
    std::span<const uint8_t> ambiguity{};    // Ambiguity per pixel (empty: none)
    std::span<const float> texelsPerPixel{}; // 1/m per pixel, for displacements in texels (empty: no texels)
    // Like for like (docs/design.md §4): the rendered s and the truth at the same samplesPerAxis²
    // positions per pixel, images (width·N) wide. sampleS: NaN where the sample sees no receiver;
    // sampleTruth: 1 lit, 0 shadowed, NaN no hit. Empty: each pixel's s against its c.
    int samplesPerAxis = 1;
    std::span<const float> sampleS{};
    std::span<const float> sampleTruth{};
    std::span<const uint8_t> singular{}; // 1 where J is singular (empty: none)
    std::span<const float> visibility{}; // soft truth v (empty: a point sun); the umbra is then where v = 0
    // The truth's lit fraction over a fixed grid finer than few samples see (empty: coverage): where
    // the edges lie, so that a thin sliver of light or shadow the N × N samples miss still makes its
    // pixels edge pixels, and N decides only how finely the error is counted.
    std::span<const float> edgeCoverage{};
    std::span<const float> contactGap{}; // distance to the occluder along the light within the peter-panning
                                         // reach (docs/design.md §4), +∞ beyond it (empty: none)
};

struct TruthClasses {
    // Fractions of the counted pixels (receivers with a finite s and c). A pixel adds the fraction of
    // its samples misclassified (docs/design.md §4 "Like for like"): a sample is wrong when its
    // rendered s lies on the other side of 0.5 from its truth; s exactly 0.5 is half wrong either way.
    double interiorFalseShadow = 0; // truth lit (every sample), rendered shadowed, ≥ 1 px from a truth edge
    double interiorFalseLit = 0;    // truth shadowed (every sample), rendered lit, ≥ 1 px from a truth edge
    double edgeError = 0;           // rendered ≠ truth within 1 px of a truth edge
    double ambiguous = 0;           // undecidable (Ambiguity): left out of the figures here
    double singular = 0;            // TruthClass::Singular: left out as well
    // Peter-panning: samples rendered lit whose truth is shadowed by an occluder within the
    // peter-panning reach (contactGap finite), decidable pixels only (a part of interior + edge).
    double contactFalseLit = 0;
    double contactGapMedian = 0, contactGapP95 = 0; // the occluder distance at those pixels, scene units
    double penumbraMeanAbs = 0;                     // mean |s − c| over the counted, decidable pixels
    double interiorMeanAbs = 0; // mean |s − c| over the decidable interiors (c = 0 or 1, ≥ 1 px from an
                                // edge): a filter's darkening of lit ground, light in shadows
    // Light in the umbra: mean s over the decidable pixels the truth shadows at every sample (with a
    // sun of size: where its disk is hidden, v = 0), ≥ 1 px from a truth edge; 0 when none.
    double umbraLight = 0;
    size_t umbraPixels = 0;
    // Edge error per unit of truth edge length: the misclassified area within 1 px of edges over the
    // edges' length (pixels with a fractional c, and 4-neighbour pairs whose truths differ), i.e.
    // the mean width of the wrong band, in pixels and in texels of each pixel's map (size-independent).
    double edgeLengthPx = 0, edgeWidthPx = 0, edgeWidthTexels = 0;
    // How far rendered edges lie from true ones, over the edge-error pixels: the width of the wrong
    // band each lies in, across the edge (from the nearest pixel whose truth is what was rendered
    // here to the nearest pixel rendered the other way, each less half a pixel: edges lie between
    // pixel centres); in texels of the pixel's map via texelsPerPixel.
    double edgeDisplacementPxMedian = 0, edgeDisplacementPxP95 = 0;
    double edgeDisplacementTexelsMedian = 0, edgeDisplacementTexelsP95 = 0;
    size_t count = 0;
};

/// Classifies every pixel. A truth edge pixel has a fractional c or a counted 8-neighbour whose c
/// differs, by the samples or by edgeCoverage (no tie decides anything: c = 0.5 is fractional). A pixel's class is an
/// error class when any of its samples is wrong; the fractions add the wrong share. `classes` receives one TruthClass
/// per pixel when not null. Throws std::invalid_argument when the spans' sizes disagree or width
/// does not divide them.
[[nodiscard]] TruthClasses truthClasses(const TruthClassInput& in, std::vector<TruthClass>* classes = nullptr);

/// The same per group, in one pass: result[g] over the pixels whose `group[i]` is g (a split index,
/// a mesh index), for g in [0, groups); pixels with a group outside that range are left out.
/// Throws std::invalid_argument as truthClasses, or when `group` does not hold one value per pixel.
[[nodiscard]] std::vector<TruthClasses> truthClassesByGroup(const TruthClassInput& in, std::span<const int> group,
                                                            int groups);

} // namespace geometry::analysis
