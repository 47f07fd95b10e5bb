#pragma once
// The rendered shadow against ray-traced truth, decomposed (docs/design.md §4 "Truth classes"):
// errors inside lit or shadowed regions (acne, leaks, lost casters) apart from shadow edges drawn
// in slightly the wrong place, and pixels whose truth itself is ambiguous apart from both.
// Pure, no GL; per-pixel inputs are row-major, top row first.
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace geometry::analysis {

/// Why a pixel's truth is ambiguous (left out of the other classes).
enum class Ambiguity : uint8_t {
    None = 0,
    Terminator = 1, // |N·L| < 0.1 by the geometric normal: the surface grazes the light
    NormalFlip = 2, // the shading normal faces the light, the geometric one does not (or the reverse)
    Contact = 3,    // the occluder touches the receiver closer than the bias distance: no map can resolve it
};

/// Per pixel, the class it falls in (the truth heatmap's colours).
enum class TruthClass : uint8_t {
    NotCounted = 0, // not a receiver, or s or c not finite
    Agrees,         // rendered state = truth state
    InteriorFalseShadow,
    InteriorFalseLit,
    EdgeError, // misclassified within 1 px of a truth edge
    Ambiguous,
};

struct TruthClassInput {
    int width = 0;
    std::span<const float> s;        // rendered lit fraction
    std::span<const float> coverage; // truth lit fraction c ∈ [0, 1] over the pixel's samples
    std::span<const uint8_t> receiver;
    std::span<const uint8_t> ambiguity;    // Ambiguity per pixel (empty: none)
    std::span<const float> texelsPerPixel; // 1/m per pixel, for displacements in texels (empty: no texels)
};

struct TruthClasses {
    // Fractions of the counted pixels (receivers with a finite s and c).
    double interiorFalseShadow = 0; // truth lit (every sample), rendered shadowed, ≥ 1 px from a truth edge
    double interiorFalseLit = 0;    // truth shadowed (every sample), rendered lit, ≥ 1 px from a truth edge
    double edgeError = 0;           // rendered ≠ truth within 1 px of a truth edge
    double ambiguous = 0;           // left out of the three above
    double penumbraMeanAbs = 0;     // mean |s − c| over the counted, non-ambiguous pixels
    // Light in the umbra: mean s over the non-ambiguous pixels the truth shadows at every sample,
    // ≥ 1 px from a truth edge (light bleeding and leaks, partial light included); 0 when none.
    double umbraLight = 0;
    size_t umbraPixels = 0;
    // How far rendered edges lie from true ones, over the edge-error pixels: the width of the wrong
    // band each lies in, across the edge (from the nearest pixel whose truth is what was rendered
    // here to the nearest pixel rendered the other way, each less half a pixel: edges lie between
    // pixel centres); in texels of the pixel's map via texelsPerPixel.
    double edgeDisplacementPxMedian = 0, edgeDisplacementPxP95 = 0;
    double edgeDisplacementTexelsMedian = 0, edgeDisplacementTexelsP95 = 0;
    size_t count = 0;
};

/// Classifies every pixel. Rendered state: lit when s ≥ 0.5; truth state: lit when c ≥ 0.5. A truth
/// edge pixel has a fractional c or a counted 8-neighbour in the other truth state. `classes`
/// receives one TruthClass per pixel when not null. Throws std::invalid_argument when the spans'
/// sizes disagree or width does not divide them.
[[nodiscard]] TruthClasses truthClasses(const TruthClassInput& in, std::vector<TruthClass>* classes = nullptr);

/// The same per group, in one pass: result[g] over the pixels whose `group[i]` is g (a split index,
/// a mesh index), for g in [0, groups); pixels with a group outside that range are left out.
/// Throws std::invalid_argument as truthClasses, or when `group` does not hold one value per pixel.
[[nodiscard]] std::vector<TruthClasses> truthClassesByGroup(const TruthClassInput& in, std::span<const int> group,
                                                            int groups);

} // namespace geometry::analysis
