#pragma once
// Shadow settings, declared once (docs/design.md §2.6): each setting's member and default below,
// and its row in settingsDeclaration() (key, help, range, when it applies, whether the shadow maps
// depend on it). Widgets, JSON presets, `--set key=value`, validation, the shaders' settings block,
// the shadow-map key and the "has no effect" warnings are all derived from these two places.
//
// Index
//   [SECTION] Enums and members ..... BiasType, FilterType, …, ShadowSettings (named_enum.h lists)
//   [SECTION] Rows .................. SettingInfo
//   [SECTION] The declaration ....... declare:: helpers, settingsDeclaration()
//   [SECTION] Parsing and checks .... findSetting, applySetting, validate, validateFrustum
#include "geometry/shadow/splits.h"
#include "geometry/shadow/warp.h"

#include <functional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace geometry::shadow {

// ---- [SECTION] Enums and members -----------------------------------------------------------------

// bias.type (named_enum.h: value, setting name, help; Barroso Table 1; Scherzer §4.2; docs/design.md
// §3.5). receiver_plane: every filter tap compares against the receiver's plane at that tap's texel
// centre, less the half-texel sampling error (Isidoro 2006; MJP's Shadows sample).
#define SHADOWSCOPE_BIAS_TYPES(X)                                                                                      \
    X(None, "none", "")                                                                                                \
    X(Constant, "constant", "z_offset along the light")                                                                \
    X(Slope, "slope", "polygon offset")                                                                                \
    X(SecondDepth, "second_depth", "back faces into the map")                                                          \
    X(Midpoint, "midpoint", "two-layer depth peeling")                                                                 \
    X(DualDepth, "dual_depth", "two-layer depth peeling, capped by bias.z_max")                                        \
    X(NormalOffset, "normal_offset", "receiver along its normal")                                                      \
    X(SlopeNormalOffset, "slope_normal_offset", "slope and normal offset together, as engines ship them")              \
    X(ReceiverPlane, "receiver_plane", "each filter tap compares against the receiver's plane; PCF family")
SHADOWSCOPE_NAMED_ENUM(BiasType, "BIAS_", SHADOWSCOPE_BIAS_TYPES);

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

// filter.type (Barroso §2.2; Scherzer §4.3; docs/design.md §3.6, docs/filters.md). The PCF family
// (none..disk, pcss) compares depths; the moment family (vsm, esm, evsm2, evsm4, msm) filters a
// blurred map of moments of linear light depth.
#define SHADOWSCOPE_FILTER_TYPES(X)                                                                                    \
    X(None, "none", "one tap")                                                                                         \
    X(Hw2x2, "hw2x2", "hardware bilinear compare")                                                                     \
    X(Pcf, "pcf", "k x k texels")                                                                                      \
    X(Disk, "disk", "Vogel disk taps")                                                                                 \
    X(Vsm, "vsm", "variance shadow maps")                                                                              \
    X(Pcss, "pcss", "percentage-closer soft shadows: blocker search, penumbra from light.angular_diameter_deg")        \
    X(Esm, "esm", "exponential")                                                                                       \
    X(Evsm2, "evsm2", "exponential variance, 2 moments")                                                               \
    X(Evsm4, "evsm4", "exponential variance, 4 moments")                                                               \
    X(Msm, "msm", "Hamburger four-moment shadow maps")
SHADOWSCOPE_NAMED_ENUM(FilterType, "FILTER_", SHADOWSCOPE_FILTER_TYPES);

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
    bool rotateTaps = true;       // filter.rotate_taps: disk and PCSS patterns turned per pixel
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

// stabilize.mode: what keeps shadow edges still while the camera moves.
#define SHADOWSCOPE_STABILIZE_MODES(X)                                                                                 \
    X(Off, "off", "")                                                                                                  \
    X(Snap, "snap",                                                                                                    \
      "unwarped maps fitted to their split's bounding sphere, moved in whole texels: edges hold still while the "      \
      "camera moves, at the cost of a larger map footprint")                                                           \
    X(Quantize, "quantize",                                                                                            \
      "snap, and warped maps' V_P in 1 deg steps, n' in 1/16 octaves, projection centre and extent on a texel grid")
SHADOWSCOPE_NAMED_ENUM(StabilizeMode, "STABILIZE_", SHADOWSCOPE_STABILIZE_MODES);

// focus.mode: what each split's map is fitted to.
#define SHADOWSCOPE_FOCUS_MODES(X)                                                                                     \
    X(Geometry, "geometry", "each split's view sub-frustum clipped by the scene bounds")                               \
    X(Samples, "samples",                                                                                              \
      "the depth range and light-space bounds of the pixels the eye sees, from a GPU reduction of the depth "          \
      "pre-pass; splits without samples are skipped (SDSM)")
SHADOWSCOPE_NAMED_ENUM(FocusMode, "FOCUS_", SHADOWSCOPE_FOCUS_MODES);

// casters.lod: every triangle, or simplified caster levels where a split's texels hide the detail.
#define SHADOWSCOPE_CASTER_LODS(X)                                                                                     \
    X(Off, "off", "every triangle")                                                                                    \
    X(Auto, "auto",                                                                                                    \
      "each shadow pass draws, per chunk, the coarsest simplified level whose error stays below "                      \
      "casters.lod_texels texels of that split's map; thin parts are never simplified")
SHADOWSCOPE_NAMED_ENUM(CasterLod, "CASTER_LOD_", SHADOWSCOPE_CASTER_LODS);

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

// technique: what holds the light's depths. Virtual shadow maps (issue 34; docs/design.md §3.11) take a
// directional light; the other settings of the maps (warp, splits, focus, stabilization, resolution,
// caster LOD) do not apply to them.
#define SHADOWSCOPE_TECHNIQUES(X)                                                                                      \
    X(Maps, "maps", "shadow maps fitted to the view: the warp, splits and focus as set")                               \
    X(Virtual, "virtual",                                                                                              \
      "a paged virtual shadow map: clipmap levels around the eye, of which only the pages that visible pixels "        \
      "need are drawn, each at the level its pixels' footprint asks; directional lights")
SHADOWSCOPE_NAMED_ENUM(Technique, "TECHNIQUE_", SHADOWSCOPE_TECHNIQUES);

/// Pages along a level's side at most (virtual.size / virtual.page_size): the page table's size.
inline constexpr int kMaxVirtualPagesPerSide = 512;

/// virtual.*: the virtual map's shape and its physical page pool (geometry/shadow/virtual_pages.h).
struct VirtualSettings {
    int size = 16384;     // virtual.size: texels along a level's side (a power of two)
    int pageSize = 128;   // virtual.page_size: texels along a page's side (a power of two)
    int levels = 8;       // virtual.levels: clipmap levels, each twice as wide as the one before
    int poolPages = 1024; // virtual.pool_pages: physical pages (1024 of 128² = one 4096² depth texture)
    [[nodiscard]] bool operator==(const VirtualSettings&) const = default;
};

struct ShadowSettings {
    Technique technique = Technique::Maps;
    VirtualSettings virtualMap;
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

// ---- [SECTION] Rows ------------------------------------------------------------------------------

/// Whether a setting applies, or draws the maps, under the others.
using SettingPredicate = bool (*)(const ShadowSettings&);

/// One row of the declaration. The row says everything the rest of the program derives: widgets
/// (ui/settings_panel.cpp), JSON presets and `--set` (settings.cpp, geometry/io), validation, the
/// GLSL settings block and enum constants (renderer/shadow_glsl_gen.cpp), what the shadow-map key
/// covers (renderer/shadow_map_key.cpp), and the warnings and tuner skips for values without effect.
struct SettingInfo {
    enum class Kind { Int, Float, Bool, Choice };
    std::string_view key;
    std::string help;
    Kind kind = Kind::Float;
    double min = 0, max = 0;                          // Int, Float: valid range (inclusive)
    bool odd = false;                                 // Int: only odd values
    std::vector<std::string_view> choices;            // Choice: names in enum order (named_enum.h)
    std::string_view glslPrefix;                      // Choice: the enum's GLSL constants' prefix
    bool logScale = false;                            // a hint for widgets
    std::function<double(const ShadowSettings&)> get; // Choice: index; Bool: 0/1
    std::function<void(ShadowSettings&, double)> set;
    /// A setting of the fitted maps alone: it has no effect under technique = virtual.
    bool mapsOnly = false;
    /// When the value changes anything; null: always. `governedBy` names the setting that decides.
    SettingPredicate appliesWhen = nullptr;
    std::string_view governedBy;
    /// When the shadow maps depend on the value (and it applies); null: never (an eye-side setting).
    SettingPredicate drawsMapsWhen = nullptr;

    [[nodiscard]] bool appliesTo(const ShadowSettings& s) const {
        return !(mapsOnly && s.technique == Technique::Virtual) && (!appliesWhen || appliesWhen(s));
    }
    [[nodiscard]] bool drawsMaps(const ShadowSettings& s) const {
        return drawsMapsWhen && drawsMapsWhen(s) && appliesTo(s);
    }
    /// The name of the value in the settings block the shaders read: the key with '.' → '_'.
    [[nodiscard]] std::string glslName() const;
    [[nodiscard]] std::string format(const ShadowSettings& s) const;
    [[nodiscard]] std::string rangeText() const;

    // Declaration helpers, chained onto a row.
    SettingInfo&& when(std::string_view by, SettingPredicate applies) && {
        governedBy = by;
        appliesWhen = applies;
        return std::move(*this);
    }
    SettingInfo&& drawsMapsIf(SettingPredicate p) && {
        drawsMapsWhen = p;
        return std::move(*this);
    }
    SettingInfo&& fittedMapsOnly() && {
        mapsOnly = true;
        return std::move(*this);
    }
    SettingInfo&& mapSide() && {
        return std::move(*this).drawsMapsIf([](const ShadowSettings&) { return true; });
    }
};

// ---- [SECTION] The declaration ------------------------------------------------------------------

namespace declare {

using Kind = SettingInfo::Kind;

/// A row for a number or a flag. `field` is a generic lambda naming the member: `[](auto& s) -> auto& {
/// return s.bias.slope; }` (const and non-const alike).
template <class Field>
SettingInfo number(std::string_view key, std::string_view help, Kind kind, double min, double max, Field field,
                   bool logScale = false) {
    SettingInfo info;
    info.key = key;
    info.help = help;
    info.kind = kind;
    info.min = min;
    info.max = max;
    info.logScale = logScale;
    info.get = [field](const ShadowSettings& s) { return double(field(s)); };
    info.set = [field](ShadowSettings& s, double v) {
        auto& ref = field(s);
        ref = static_cast<std::remove_reference_t<decltype(ref)>>(v);
    };
    return info;
}

template <class Field>
SettingInfo oddNumber(std::string_view key, std::string_view help, double min, double max, Field field) {
    SettingInfo info = number(key, help, Kind::Int, min, max, field);
    info.odd = true;
    return info;
}

/// A row for an enum declared with SHADOWSCOPE_NAMED_ENUM: its names, and the help "intro: name
/// (help), …" from the enum's list.
template <class Field> SettingInfo choice(std::string_view key, std::string_view intro, Field field) {
    using E = std::remove_cvref_t<decltype(field(std::declval<ShadowSettings&>()))>;
    SettingInfo info;
    info.key = key;
    info.kind = Kind::Choice;
    info.help = std::string(intro) + ": ";
    for (const auto& e : kEnumEntries<E>) {
        if (!info.choices.empty()) info.help += ", ";
        info.help += std::string(e.name) + (e.help.empty() ? "" : " (" + std::string(e.help) + ")");
        info.choices.push_back(e.name);
    }
    info.glslPrefix = EnumDeclaration<E>::glslPrefix;
    info.min = 0;
    info.max = double(info.choices.size() - 1);
    info.get = [field](const ShadowSettings& s) { return double(static_cast<int>(field(s))); };
    info.set = [field](ShadowSettings& s, double v) { field(s) = static_cast<E>(static_cast<int>(v)); };
    return info;
}

template <BiasType... B> bool biasIs(const ShadowSettings& s) { return ((s.bias.type == B) || ...); }
template <FilterType... F> bool filterIs(const ShadowSettings& s) { return ((s.filter.type == F) || ...); }
template <WarpMethod... W> bool warpIs(const ShadowSettings& s) { return ((s.warp.method == W) || ...); }
inline bool isVirtual(const ShadowSettings& s) { return s.technique == Technique::Virtual; }
inline bool momentFilter(const ShadowSettings& s) { return isMomentFilter(s.filter.type); }
inline bool warped(const ShadowSettings& s) { return s.warp.method != WarpMethod::Uniform; }
inline bool split(const ShadowSettings& s) { return s.splits.count > 1; }
template <SplitScheme K> bool splitSchemeIs(const ShadowSettings& s) { return split(s) && s.splits.scheme == K; }

} // namespace declare

/// Every setting, in the order widgets, presets and the GLSL settings block list them. A row: key,
/// help, kind and range, the member; then `.when(governing key, predicate)` if it only matters under
/// other values, and `.mapSide()` / `.drawsMapsIf(predicate)` if the shadow maps depend on it
/// (docs/design.md §5 "Adding a setting"). Defaults are the member initialisers above.
inline const std::vector<SettingInfo>& settingsDeclaration() {
    using namespace declare;
    using B = BiasType;
    using F = FilterType;
    static const std::vector<SettingInfo> table = {
        choice(
            "technique", "Technique", [](auto& s) -> auto& { return s.technique; })
            .mapSide(),
        number(
            "virtual.size", "virtual: texels along a clipmap level's side (a power of two; 16384 as Unreal Engine 5)",
            Kind::Int, 256, 65536, [](auto& s) -> auto& { return s.virtualMap.size; }, true)
            .when("technique", isVirtual)
            .mapSide(),
        number(
            "virtual.page_size",
            "virtual: texels along a page's side (a power of two, from virtual.size / 512 to virtual.size / 4)",
            Kind::Int, 16, 1024, [](auto& s) -> auto& { return s.virtualMap.pageSize; }, true)
            .when("technique", isVirtual)
            .mapSide(),
        number(
            "virtual.levels",
            "virtual: clipmap levels around the eye, each twice as wide as the one before; the coarsest covers the "
            "scene",
            Kind::Int, 1, 16, [](auto& s) -> auto& { return s.virtualMap.levels; })
            .when("technique", isVirtual)
            .mapSide(),
        number(
            "virtual.pool_pages",
            "virtual: physical pages; when the visible pixels ask for more, the finest levels give way to coarser ones",
            Kind::Int, 4, 16384, [](auto& s) -> auto& { return s.virtualMap.poolPages; }, true)
            .when("technique", isVirtual)
            .mapSide(),
        number(
            "shadow_map.resolution", "Shadow-map side in texels (first split)", Kind::Int, 16, 16384,
            [](auto& s) -> auto& { return s.resolution; }, true)
            .mapSide()
            .fittedMapsOnly(),
        choice(
            "bias.type", "Bias", [](auto& s) -> auto& { return s.bias.type; })
            // second depth draws back faces, midpoint and dual depth peel, the slope biases offset polygons
            .drawsMapsIf(biasIs<B::Slope, B::SlopeNormalOffset, B::SecondDepth, B::Midpoint, B::DualDepth>),
        number(
            "bias.constant", "Constant depth offset z_offset, in scene units along the light (Barroso Table 1)",
            Kind::Float, -10, 10, [](auto& s) -> auto& { return s.bias.constant; })
            .when("bias.type", biasIs<B::Constant>),
        number(
            "bias.slope", "slope, slope_normal_offset: polygon-offset factor (scales with the depth slope)",
            Kind::Float, 0, 32, [](auto& s) -> auto& { return s.bias.slope; })
            .when("bias.type", biasIs<B::Slope, B::SlopeNormalOffset>)
            .mapSide(),
        number(
            "bias.units", "slope, slope_normal_offset: polygon-offset units (smallest depth steps)", Kind::Float, 0,
            1024, [](auto& s) -> auto& { return s.bias.units; })
            .when("bias.type", biasIs<B::Slope, B::SlopeNormalOffset>)
            .mapSide(),
        number(
            "bias.z_max", "dual_depth: cap on the offset z1 + min((z2-z1)/2, z_max), scene units", Kind::Float, 0, 100,
            [](auto& s) -> auto& { return s.bias.zMax; })
            .when("bias.type", biasIs<B::DualDepth>)
            .mapSide()
            .fittedMapsOnly(),
        number(
            "bias.normal_offset",
            "normal_offset, slope_normal_offset: receiver moved along its normal by this many world-space "
            "texels",
            Kind::Float, 0, 16, [](auto& s) -> auto& { return s.bias.normalOffset; })
            .when("bias.type", biasIs<B::NormalOffset, B::SlopeNormalOffset>),
        number(
            "bias.linear_z",
            "Store linear light depth in the maps instead of post-perspective depth (Scherzer "
            "4.2)",
            Kind::Bool, 0, 1, [](auto& s) -> auto& { return s.bias.linearZ; })
            // moment filters and PCSS store linear depth anyway; dual_depth's cap is measured in it
            .when("filter.type",
                  [](const ShadowSettings& s) {
                      return !(momentFilter(s) || s.filter.type == F::Pcss) || s.bias.type == B::DualDepth;
                  })
            .mapSide()
            .fittedMapsOnly(),
        number(
            "bias.tangent_plane",
            "pcf, disk: filter taps compare against the receiver's tangent plane (Barroso 2.2; bias.type = "
            "receiver_plane does so anyway)",
            Kind::Bool, 0, 1, [](auto& s) -> auto& { return s.bias.tangentPlane; })
            .when("filter.type",
                  [](const ShadowSettings& s) { return filterIs<F::Pcf, F::Disk>(s) && !biasIs<B::ReceiverPlane>(s); }),
        choice(
            "filter.type", "Filter", [](auto& s) -> auto& { return s.filter.type; })
            // the moments pass writes what a moment filter reads; PCSS's maps hold linear depth
            .drawsMapsIf([](const ShadowSettings& s) { return momentFilter(s) || s.filter.type == F::Pcss; }),
        oddNumber(
            "filter.kernel", "pcf: k x k taps one texel apart; vsm, esm, evsm2, evsm4, msm: blur width (odd)", 1, 9,
            [](auto& s) -> auto& { return s.filter.kernel; })
            .when("filter.type", [](const ShadowSettings& s) { return s.filter.type == F::Pcf || momentFilter(s); })
            .drawsMapsIf(momentFilter),
        number(
            "filter.taps", "disk: number of taps; pcss: taps of the blocker search and of the filter", Kind::Int, 1, 64,
            [](auto& s) -> auto& { return s.filter.taps; })
            .when("filter.type", filterIs<F::Disk, F::Pcss>),
        number(
            "filter.radius", "disk: radius in texels", Kind::Float, 0.5, 16,
            [](auto& s) -> auto& { return s.filter.radius; })
            .when("filter.type", filterIs<F::Disk>),
        number(
            "filter.rotate_taps",
            "disk, pcss: turn the tap pattern per pixel (interleaved gradient noise), trading banding for "
            "noise; off: one pattern everywhere, smooth but banded",
            Kind::Bool, 0, 1, [](auto& s) -> auto& { return s.filter.rotateTaps; })
            .when("filter.type", filterIs<F::Disk, F::Pcss>),
        number(
            "filter.bleed_reduction",
            "vsm, evsm2, evsm4, msm: light-bleeding reduction (lit fractions below it become 0, the rest is "
            "rescaled)",
            Kind::Float, 0, 0.95, [](auto& s) -> auto& { return s.filter.bleedReduction; })
            .when("filter.type", filterIs<F::Vsm, F::Evsm2, F::Evsm4, F::Msm>),
        number(
            "filter.pcss.max_radius", "pcss: cap on the blocker search and filter radius, texels", Kind::Float, 1, 256,
            [](auto& s) -> auto& { return s.filter.pcssMaxRadius; })
            .when("filter.type", filterIs<F::Pcss>),
        number(
            "filter.esm.exponent",
            "esm: c in exp(c z) over linear depth z in [0,1]; higher bleeds less but rings at contacts", Kind::Float, 1,
            88, [](auto& s) -> auto& { return s.filter.esmExponent; })
            .when("filter.type", filterIs<F::Esm>)
            .mapSide(),
        number(
            "filter.evsm.positive_exponent", "evsm2, evsm4: c+ in exp(c+ z), z in [-1,1]", Kind::Float, 1, 42,
            [](auto& s) -> auto& { return s.filter.evsmPositive; })
            .when("filter.type", filterIs<F::Evsm2, F::Evsm4>)
            .mapSide(),
        number(
            "filter.evsm.negative_exponent", "evsm4: c- in -exp(-c- z), z in [-1,1]", Kind::Float, 1, 42,
            [](auto& s) -> auto& { return s.filter.evsmNegative; })
            .when("filter.type", filterIs<F::Evsm4>)
            .mapSide(),
        number(
            "filter.msm.moment_bias",
            "msm: alpha pulling the four moments towards (0.5, 0.5, 0.5, 0.5) against numeric failure; higher "
            "bleeds more",
            Kind::Float, 1e-8, 0.01, [](auto& s) -> auto& { return s.filter.momentBias; }, true)
            .when("filter.type", filterIs<F::Msm>),
        number(
            "filter.eye_blur.iterations",
            "Eye-space blur of the shadow mask, stronger near the viewer "
            "(Scherzer 4.3); 0 = off",
            Kind::Int, 0, 8, [](auto& s) -> auto& { return s.filter.eyeBlurIterations; }),
        number(
            "filter.eye_blur.falloff",
            "Eye-space blur: taps 1/(1 + falloff * view depth) pixels apart, 3 each side, per "
            "iteration",
            Kind::Float, 0, 10, [](auto& s) -> auto& { return s.filter.eyeBlurFalloff; }, true)
            .when("filter.eye_blur.iterations", [](const ShadowSettings& s) { return s.filter.eyeBlurIterations > 0; }),
        number(
            "light.angular_diameter_deg",
            "Angular diameter of the sun, degrees (0: a point; the real sun is 0.53): PCSS's penumbra, and truth "
            "traces rays over this disk",
            Kind::Float, 0, 20, [](auto& s) -> auto& { return s.light.angularDiameterDeg; }),
        choice(
            "stabilize.mode", "Stabilization", [](auto& s) -> auto& { return s.stabilize; })
            .mapSide()
            .fittedMapsOnly(),
        choice(
            "focus.mode", "Fit the maps to", [](auto& s) -> auto& { return s.focus; })
            .mapSide()
            .fittedMapsOnly(),
        choice(
            "warp.method", "Warp", [](auto& s) -> auto& { return s.warp.method; })
            .mapSide()
            .fittedMapsOnly(),
        choice(
            "warp.direction", "Warp direction V_P", [](auto& s) -> auto& { return s.direction; })
            .when("warp.method", warped)
            .mapSide()
            .fittedMapsOnly(),
        choice(
            "warp.falloff", "glispsm below gamma_lim", [](auto& s) -> auto& { return s.warp.falloff; })
            .when("warp.method", warpIs<WarpMethod::Glispsm>)
            .mapSide()
            .fittedMapsOnly(),
        number(
            "warp.n_prime", "manual: n' at gamma = 90 deg (scaled by 1/sin(gamma) like LiSPSM)", Kind::Float, 1e-4, 1e6,
            [](auto& s) -> auto& { return s.warp.manualNPrime; }, true)
            .when("warp.method", warpIs<WarpMethod::Manual>)
            .mapSide()
            .fittedMapsOnly(),
        number(
            "warp.multiplier", "Multiplies the chosen method's n' (weaker warp above 1, stronger below)", Kind::Float,
            1e-3, 1e3, [](auto& s) -> auto& { return s.warp.multiplier; }, true)
            .when("warp.method", warped)
            .mapSide()
            .fittedMapsOnly(),
        number(
            "warp.visible_far", "lispsm: visible far depth capping n + dz (Scherzer); 0 = off", Kind::Float, 0, 1e7,
            [](auto& s) -> auto& { return s.warp.visibleFar; })
            .when("warp.method", warpIs<WarpMethod::Lispsm>)
            .mapSide()
            .fittedMapsOnly(),
        number(
            "splits.count", "Number of z-partitions (split shadow maps)", Kind::Int, 1, kMaxSplits,
            [](auto& s) -> auto& { return s.splits.count; })
            .mapSide()
            .fittedMapsOnly(),
        choice(
            "splits.scheme", "Split scheme", [](auto& s) -> auto& { return s.splits.scheme; })
            .when("splits.count", split)
            .mapSide()
            .fittedMapsOnly(),
        number(
            "splits.lambda", "practical: weight of the log scheme", Kind::Float, 0, 1,
            [](auto& s) -> auto& { return s.splits.lambda; })
            .when("splits.scheme", splitSchemeIs<SplitScheme::Practical>)
            .mapSide()
            .fittedMapsOnly(),
        number(
            "splits.ratio", "pssm: length ratio of consecutive splits", Kind::Float, 1, 16,
            [](auto& s) -> auto& { return s.splits.ratio; })
            .when("splits.scheme", splitSchemeIs<SplitScheme::Pssm>)
            .mapSide()
            .fittedMapsOnly(),
        number(
            "splits.alpha", "adaptive: f_i/n_i at gamma = 0 (Barroso: <= 4 without PCF, <= 2 with PCF)", Kind::Float, 1,
            1000, [](auto& s) -> auto& { return s.splits.alpha; }, true)
            .when("splits.scheme", splitSchemeIs<SplitScheme::Adaptive>)
            .mapSide()
            .fittedMapsOnly(),
        number(
            "splits.blend",
            "Blend band: this fraction of each split's depth range before its far end fades into the next "
            "split's shadow (0 = a hard seam)",
            Kind::Float, 0, 0.3, [](auto& s) -> auto& { return s.splits.blend; })
            .when("splits.count", split)
            .mapSide()
            .fittedMapsOnly(), // the next split's map is focused over the band too
        number(
            "splits.resolution_falloff", "Halve the shadow-map resolution for each further split", Kind::Bool, 0, 1,
            [](auto& s) -> auto& { return s.splits.resolutionFalloff; })
            .when("splits.count", split)
            .mapSide()
            .fittedMapsOnly(),
        choice(
            "casters.lod", "Caster level of detail", [](auto& s) -> auto& { return s.casters.lod; })
            .mapSide()
            .fittedMapsOnly(),
        number(
            "casters.lod_texels",
            "auto: the geometric error a caster level may have, in texels of the map at the chunk", Kind::Float, 0.1,
            16, [](auto& s) -> auto& { return s.casters.lodTexels; }, true)
            .when("casters.lod", [](const ShadowSettings& s) { return s.casters.lod == CasterLod::Auto; })
            .mapSide()
            .fittedMapsOnly(),
    };
    return table;
}

// ---- [SECTION] Parsing and checks -----------------------------------------------------------------

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
