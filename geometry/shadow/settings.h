#pragma once
// Shadow settings, declared once: each key's name, help and range live in settingsDeclaration(),
// its default in the member initialiser below. Widgets, JSON presets, `--set key=value` and
// validation are all derived from that one table.
#include "geometry/shadow/splits.h"
#include "geometry/shadow/warp.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace geometry::shadow {

/// Bias types (Barroso Table 1; Scherzer §4.2; docs/design.md §3.5).
/// SlopeNormalOffset: slope-scaled polygon offset and normal offset together, as engines ship them.
/// ReceiverPlane: every filter tap compares against the receiver's plane at that tap's texel centre,
/// less the half-texel sampling error (Isidoro 2006; MJP's Shadows sample), for the PCF family.
enum class BiasType {
    None,
    Constant,
    Slope,
    SecondDepth,
    Midpoint,
    DualDepth,
    NormalOffset,
    SlopeNormalOffset,
    ReceiverPlane
};

struct BiasSettings {
    BiasType type = BiasType::Constant;
    float constant = 0.05f;    // bias.constant: z_offset, scene units along l
    float slope = 1.5f;        // bias.slope: polygon-offset factor
    float units = 4.f;         // bias.units: polygon-offset units
    float zMax = 0.5f;         // bias.z_max: dual-depth cap, scene units
    float normalOffset = 1.f;  // bias.normal_offset: × world-space texel size
    bool linearZ = false;      // bias.linear_z: store linear light depth (Scherzer §4.2)
    bool tangentPlane = false; // bias.tangent_plane: PCF reference depth on the receiver's plane
    [[nodiscard]] bool operator==(const BiasSettings&) const = default;
};

/// Filters (Barroso §2.2; Scherzer §4.3; docs/design.md §3.6, docs/filters.md). The PCF family
/// (none..disk, pcss) compares depths; the moment family (vsm, esm, evsm2, evsm4, msm) filters a
/// blurred map of moments of linear light depth.
enum class FilterType { None, Hw2x2, Pcf, Disk, Vsm, Pcss, Esm, Evsm2, Evsm4, Msm };

/// The filters that read a blurred moments map instead of comparing depths.
[[nodiscard]] constexpr bool isMomentFilter(FilterType f) noexcept {
    return f == FilterType::Vsm || f == FilterType::Esm || f == FilterType::Evsm2 || f == FilterType::Evsm4 ||
           f == FilterType::Msm;
}
/// Moments stored per texel: 1 (esm), 2 (vsm, evsm2), 4 (evsm4, msm); 0 for the PCF family.
[[nodiscard]] constexpr int momentCount(FilterType f) noexcept {
    switch (f) {
    case FilterType::Esm: return 1;
    case FilterType::Vsm:
    case FilterType::Evsm2: return 2;
    case FilterType::Evsm4:
    case FilterType::Msm: return 4;
    default: return 0;
    }
}

struct FilterSettings {
    FilterType type = FilterType::Hw2x2;
    int kernel = 3;               // filter.kernel: k×k PCF taps / moments blur width, odd
    int taps = 16;                // filter.taps: disk and PCSS taps
    float radius = 2.f;           // filter.radius: disk radius, texels
    float bleedReduction = 0.2f;  // filter.bleed_reduction: VSM/EVSM/MSM light-bleeding cut
    float pcssMaxRadius = 64.f;   // filter.pcss.max_radius: cap on the blocker search and filter radius, texels
    float esmExponent = 80.f;     // filter.esm.exponent: c in exp(c·z)
    float evsmPositive = 40.f;    // filter.evsm.positive_exponent: c+ in exp(c+·z)
    float evsmNegative = 5.f;     // filter.evsm.negative_exponent: c− in −exp(−c−·z) (evsm4)
    float momentBias = 3e-5f;     // filter.msm.moment_bias: α pulling the moments towards a safe vector
    int eyeBlurIterations = 0;    // filter.eye_blur.iterations: Scherzer's eye-space blur, 0 = off
    float eyeBlurFalloff = 0.05f; // filter.eye_blur.falloff: how fast the blur shrinks with view depth
    [[nodiscard]] bool operator==(const FilterSettings&) const = default;
};

/// stabilize.mode: off; snap (unwarped maps fitted to their split's bounding sphere and moved in
/// whole texels, so a moving camera does not make shadow edges shimmer); quantize (snap, and for
/// warped maps V_P, n', the projection centre and the map's extent held to steps).
enum class StabilizeMode { Off, Snap, Quantize };

/// focus.mode: what each split's map is fitted to. geometry: the view sub-frustum clipped by the
/// scene bounds; samples: the visible samples' depth range and light-space bounds (SDSM).
enum class FocusMode { Geometry, Samples };

/// casters.lod: off, or auto (simplified caster levels where a split's texels hide the detail).
enum class CasterLod { Off, Auto };

struct CasterSettings {
    CasterLod lod = CasterLod::Off;
    float lodTexels = 1.f; // casters.lod_texels: the error a level may have, in texels of the map
    [[nodiscard]] bool operator==(const CasterSettings&) const = default;
};

/// The sun as the shadows see it: light.angular_diameter_deg (0: a point; the real sun is 0.53°).
/// PCSS sizes its penumbra from it, and truth traces rays over its disk.
struct LightSettings {
    float angularDiameterDeg = 0.f;
    [[nodiscard]] bool operator==(const LightSettings&) const = default;
};

struct ShadowSettings {
    int resolution = 2048; // shadow_map.resolution
    StabilizeMode stabilize = StabilizeMode::Off;
    FocusMode focus = FocusMode::Geometry;
    BiasSettings bias;
    FilterSettings filter;
    WarpParams warp{WarpMethod::Uniform};
    WarpDirection direction = WarpDirection::Standard;
    SplitParams splits;
    CasterSettings casters;
    LightSettings light;
    [[nodiscard]] bool operator==(const ShadowSettings&) const = default;
};

struct SettingInfo {
    enum class Kind { Int, Float, Bool, Choice };
    std::string_view key;
    std::string_view help;
    Kind kind = Kind::Float;
    double min = 0, max = 0;                          // Int, Float: valid range (inclusive)
    bool odd = false;                                 // Int: only odd values
    std::vector<std::string_view> choices;            // Choice: names in enum order
    bool logScale = false;                            // a hint for widgets
    std::function<double(const ShadowSettings&)> get; // Choice: index; Bool: 0/1
    std::function<void(ShadowSettings&, double)> set;

    [[nodiscard]] std::string format(const ShadowSettings& s) const;
    [[nodiscard]] std::string rangeText() const;
};

[[nodiscard]] const std::vector<SettingInfo>& settingsDeclaration();
/// nullptr for an unknown key.
[[nodiscard]] const SettingInfo* findSetting(std::string_view key) noexcept;

/// Parses and applies one `key=value` / (key, value); throws std::invalid_argument naming the key
/// and its valid range or choices.
void applySetting(ShadowSettings& s, std::string_view key, std::string_view value);
void applyAssignment(ShadowSettings& s, std::string_view keyEqualsValue);

/// Every key whose value is outside its range (or NaN), as "key: value is outside range" lines.
[[nodiscard]] std::vector<std::string> validate(const ShadowSettings& s);
/// Throws std::invalid_argument with the first problem validate() finds.
void validateOrThrow(const ShadowSettings& s);

/// Camera frustum checks for the planner's formulas: n > 0, f > n, 0 < fov_y < 180, all finite.
/// Throws std::invalid_argument naming the key.
void validateFrustum(double near, double far, double fovYDeg);

} // namespace geometry::shadow
