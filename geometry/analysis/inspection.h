#pragma once
// Everything the inspection views and metrics need from one rendered frame: per-pixel shadow
// factor, map coordinates, aliasing error, receivers, optional ray-traced truth, and the
// statistics over them. Built from the renderer's read-backs (renderer/inspection.h).
#include "geometry/analysis/cancelled.h"
#include "geometry/analysis/ground_truth.h"
#include "geometry/analysis/metrics.h"
#include "geometry/analysis/truth_classes.h"
#include "geometry/shadow/shadow_plan.h"

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <stop_token>
#include <string>
#include <vector>

namespace geometry::analysis {

class GroundTruth;

/// The soft truth's figures (docs/design.md §4 "Soft truth"): the rendered s against the fraction v
/// of the sun's disk each receiver sees.
struct SoftTruthStats {
    double meanAbs = 0;            // soft_mean_abs: mean |s − v| over the receivers (NaN: none)
    double angularDiameterDeg = 0; // the sun's, from the plan
    int raysPerPixel = 0;          // GroundTruth::kSunSamplesPerAxis²
    // With a scene's occluder edge (Scene::occluderEdge): penumbraWidth's error measured on s, and
    // on v (the measurement's own error); NaN when too few pixels cross the penumbra.
    std::optional<double> penumbraWidthError, penumbraWidthErrorTruth;
};

struct Inspection {
    int width = 0, height = 0;
    std::vector<float> shadow;                    // s per pixel
    std::vector<float> m;                         // aliasing error per pixel (docs/design.md §4)
    std::vector<glm::vec4> aux;                   // map texel u, v, split, map depth
    std::vector<glm::vec3> positions;             // world
    std::vector<glm::vec3> normals;               // facing normal
    std::vector<uint8_t> receiver;                // visible and facing the light (N·L > 0)
    std::vector<int> resolutions;                 // per split, the map resolution actually drawn
    std::optional<std::vector<uint8_t>> occluded; // ground truth, 1 = shadowed
    // With truth (addTruth): the geometric normal and the scene mesh (−1: none found) under each
    // pixel, the truth's lit fraction c over truthSamples² samples, why a pixel's truth is ambiguous
    // (Ambiguity), and each pixel's TruthClass.
    int truthSamples = 1; // per axis
    std::vector<glm::vec3> geometricNormals;
    std::vector<int> mesh;
    std::vector<float> coverage;
    std::vector<uint8_t> ambiguity;
    std::vector<TruthClass> classes;
    // With truth at N > 1 samples per axis and the samples drawn (FrameReadback::sampleShadow): the
    // rendered s at the truth's N × N positions per pixel, (width·N) wide; NaN off the receivers.
    std::vector<float> sampleShadow;
    // With truth and a sun of non-zero size (plan.settings.light.angularDiameterDeg > 0): the fraction v of
    // the sun's disk each receiver sees (GroundTruth::sunVisibility; NaN for non-receivers), and
    // the figures over it. Empty and nullopt for a point sun.
    std::vector<float> sunVisibility;
    std::optional<SoftTruthStats> softTruth;

    AliasingStats aliasing;
    std::optional<TruthStats> truth;
    std::optional<TruthClasses> truthClasses;    // over all receivers
    std::vector<TruthClasses> splitTruthClasses; // per split
    std::vector<std::string> meshNames;          // the scene's, by mesh index
    std::vector<TruthClasses> meshTruthClasses;  // per scene mesh (count 0: not seen)
    std::vector<double> utilization;             // per split
};

/// The eye pass's per-pixel outputs, read back once (all top row first, width·height values).
struct FrameReadback {
    int width = 0;
    std::vector<float> shadow;        // s
    std::vector<glm::vec4> aux;       // map texel u, v, split (−1 sky), map depth
    std::vector<glm::vec4> positions; // world position, m
    std::vector<glm::vec4> normals;   // facing normal, N·L
    std::vector<int> resolutions;     // per split, the map resolution actually drawn
    // Like for like (docs/design.md §4): the eye pass again at samplesPerAxis² samples per pixel
    // (Renderer::readShadowSamples), s at the truth's sample positions; empty: not drawn.
    int samplesPerAxis = 1;
    std::vector<float> sampleShadow;
};

/// Splits the read-back of a frame drawn with `plan` into per-pixel fields and computes the
/// statistics; `truth` adds the ground truth (addTruth) with truthSamples² samples per pixel.
/// Throws Cancelled once `stop` is requested.
[[nodiscard]] Inspection makeInspection(FrameReadback frame, const shadow::ShadowPlan& plan, const GroundTruth* truth,
                                        int truthSamples = 1, std::stop_token stop = {});

/// Adds ground truth to `in` (a frame drawn with `plan`; docs/design.md §4 "Truth classes"):
/// - occlusion at each pixel's centre, traced with geometric normals (truthOcclusion), for TruthStats;
/// - the lit fraction c: 1 − that verdict at one sample per axis, else the mean of GroundTruth::coverage
///   at samplesPerAxis² samples of the pixel's footprint, each compared with the rendered s at the
///   same position when `in.sampleShadow` holds them (like for like);
/// - the ambiguity of each receiver, from the scene and the view alone: the terminator (|N·L| < 0.1 by
///   the geometric normal), a normal flip (shading and geometric normal on different sides of the
///   light), or a contact (an occluder within one eye-pixel footprint, pixelFootprint(), along the light);
/// - the peter-panning reach: the occluder distance where it is under kPeterPanningReach footprints;
/// - the TruthClasses overall, per split and per scene mesh;
/// - with plan.settings.light.angularDiameterDeg > 0 (a positional light: its radius > 0), the soft
///   truth: sunVisibility over
///   GroundTruth::kSunSamplesPerAxis² rays per receiver (geometric normals), softTruth's
///   soft_mean_abs and, where the truth's scene has an occluder edge, the penumbra width errors.
/// Throws std::invalid_argument for samplesPerAxis outside 1..GroundTruth::kMaxSamplesPerAxis, and
/// Cancelled once `stop` is requested, leaving `in` partly updated (discard it).
void addTruth(Inspection& in, const shadow::ShadowPlan& plan, const GroundTruth& truth, int samplesPerAxis = 1,
              std::stop_token stop = {});

/// Within this many eye-pixel footprints of the receiver along the light, a shadow lost to the bias
/// counts as peter-panning (contact_false_lit); further, as a leak. Scene and view only.
inline constexpr float kPeterPanningReach = 32.f;

/// The truth samples per axis that place the edges (TruthClassInput::edgeCoverage) when
/// --truth-samples is lower: fine enough that N = 2 and N = 3 find the same thin slivers.
inline constexpr int kEdgeSamplesPerAxis = 4;

/// The world-space side of one eye pixel at `p` (at its view depth) for an image `height` pixels
/// high seen through `plan`'s camera: the contact band, from the view alone.
[[nodiscard]] float pixelFootprint(const shadow::ShadowPlan& plan, const glm::vec3& p, int height) noexcept;

/// Ground truth for the receiver pixels of `in` (1 = shadowed; 0 for non-receivers): each traced
/// with the geometric normal of the surface under it (GroundTruth::surfaceNormals), as
/// docs/design.md §4 "Ground truth" says, not with the renderer's interpolated shading normal,
/// which on smooth-shaded facets would make the verdict at the terminator stripe with the facets.
/// Throws Cancelled once `stop` is requested.
[[nodiscard]] std::vector<uint8_t> truthOcclusion(const Inspection& in, const glm::vec3& eye, const TruthLight& light,
                                                  const GroundTruth& truth, std::stop_token stop = {});
/// The same with the geometric normals already found (GroundTruth::surfaceNormals).
[[nodiscard]] std::vector<uint8_t> truthOcclusion(const Inspection& in, const std::vector<glm::vec3>& geometricNormals,
                                                  const TruthLight& light, const GroundTruth& truth,
                                                  std::stop_token stop = {});

/// The light `plan` shadows as the truth traces it: plan.l for a directional light, else plan.light
/// (its position, cone, range and radius; docs/design.md §3.10 "Truth per light").
[[nodiscard]] TruthLight truthLight(const shadow::ShadowPlan& plan) noexcept;

/// One per-pixel quantity for offline analysis (`render --views pixels`): written as
/// pixels_<name>.pfm, one float per pixel, top row first in memory (PFM stores bottom-up).
struct PixelLayer {
    std::string name;
    std::string meaning;
    std::vector<float> values;
};

/// The per-pixel quantities behind every figure of an inspection with truth (addTruth): view_depth,
/// split, normal_x/y/z (geometric), n_dot_l (geometric normal · direction to the light), m, s,
/// coverage (the truth's lit fraction c), class (TruthClass as a number) and visibility (the soft
/// truth's fraction of the sun's disk seen; NaN without one, or off the receivers). Pixels that see no
/// geometry hold NaN (split: −1); m at the singular cap is NaN. `eye` and unit `viewDir` place the
/// camera for the view depth. Throws std::invalid_argument without truth.
[[nodiscard]] std::vector<PixelLayer> pixelLayers(const Inspection& in, const glm::vec3& eye, const glm::vec3& viewDir,
                                                  const TruthLight& light);

/// metrics.json fields: aliasing{mean,p50,p95,max,undersampled,singular}; with truth, truth{false_shadow,
/// false_lit, mean_abs, samples_per_pixel, the classes}, splits[i].truth and meshes[name].truth; with
/// soft truth, truth{soft_mean_abs, sun_angular_diameter_deg, sun_rays_per_pixel} and, with an occluder
/// edge, truth{penumbra_width_error, penumbra_width_error_truth} (NaN written as null).
void addInspectionMetrics(nlohmann::json& j, const Inspection& in);

} // namespace geometry::analysis
