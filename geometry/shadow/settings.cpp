#include "geometry/shadow/settings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace geometry::shadow {

namespace {

using Kind = SettingInfo::Kind;

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
    info.get = [field](const ShadowSettings& s) { return double(field(const_cast<ShadowSettings&>(s))); };
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

template <class Field>
SettingInfo choice(std::string_view key, std::string_view help, std::vector<std::string_view> names, Field field) {
    SettingInfo info;
    info.key = key;
    info.help = help;
    info.kind = Kind::Choice;
    info.min = 0;
    info.max = double(names.size() - 1);
    info.choices = std::move(names);
    info.get = [field](const ShadowSettings& s) {
        return double(static_cast<int>(field(const_cast<ShadowSettings&>(s))));
    };
    info.set = [field](ShadowSettings& s, double v) {
        auto& ref = field(s);
        ref = static_cast<std::remove_reference_t<decltype(ref)>>(static_cast<int>(v));
    };
    return info;
}

std::string formatNumber(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

} // namespace

std::string SettingInfo::format(const ShadowSettings& s) const {
    const double v = get(s);
    switch (kind) {
    case Kind::Choice: {
        const int i = static_cast<int>(v);
        return i >= 0 && i < int(choices.size()) ? std::string(choices[i]) : "?";
    }
    case Kind::Bool: return v != 0.0 ? "true" : "false";
    case Kind::Int: return std::to_string(static_cast<long long>(v));
    case Kind::Float: return formatNumber(v);
    }
    return "?";
}

std::string SettingInfo::rangeText() const {
    switch (kind) {
    case Kind::Choice: {
        std::string out;
        for (auto c : choices) out += (out.empty() ? "" : ", ") + std::string(c);
        return "one of " + out;
    }
    case Kind::Bool: return "true or false";
    default: return (odd ? "odd " : "") + formatNumber(min) + ".." + formatNumber(max);
    }
}

const std::vector<SettingInfo>& settingsDeclaration() {
    static const std::vector<SettingInfo> table = {
        number(
            "shadow_map.resolution", "Shadow-map side in texels (first split)", Kind::Int, 16, 16384,
            [](ShadowSettings & s) -> auto& { return s.resolution; }, true),
        choice(
            "bias.type",
            "Bias: none, constant (z_offset along the light), slope (polygon offset), second_depth (back faces "
            "into the map), midpoint and dual_depth (two-layer depth peeling), normal_offset (receiver along "
            "its normal), slope_normal_offset (slope and normal offset together, as engines ship them), "
            "receiver_plane (each filter tap compares against the receiver's plane; PCF family)",
            {"none", "constant", "slope", "second_depth", "midpoint", "dual_depth", "normal_offset",
             "slope_normal_offset", "receiver_plane"},
            [](ShadowSettings & s) -> auto& { return s.bias.type; }),
        number(
            "bias.constant", "Constant depth offset z_offset, in scene units along the light (Barroso Table 1)",
            Kind::Float, -10, 10, [](ShadowSettings & s) -> auto& { return s.bias.constant; }),
        number(
            "bias.slope", "slope, slope_normal_offset: polygon-offset factor (scales with the depth slope)",
            Kind::Float, 0, 32, [](ShadowSettings & s) -> auto& { return s.bias.slope; }),
        number(
            "bias.units", "slope, slope_normal_offset: polygon-offset units (smallest depth steps)", Kind::Float, 0,
            1024, [](ShadowSettings & s) -> auto& { return s.bias.units; }),
        number(
            "bias.z_max", "dual_depth: cap on the offset z1 + min((z2-z1)/2, z_max), scene units", Kind::Float, 0, 100,
            [](ShadowSettings & s) -> auto& { return s.bias.zMax; }),
        number(
            "bias.normal_offset",
            "normal_offset, slope_normal_offset: receiver moved along its normal by this many world-space "
            "texels",
            Kind::Float, 0, 16, [](ShadowSettings & s) -> auto& { return s.bias.normalOffset; }),
        number(
            "bias.linear_z",
            "Store linear light depth in the maps instead of post-perspective depth (Scherzer "
            "4.2)",
            Kind::Bool, 0, 1, [](ShadowSettings & s) -> auto& { return s.bias.linearZ; }),
        number(
            "bias.tangent_plane", "Filter taps compare against the receiver's tangent plane (Barroso 2.2)", Kind::Bool,
            0, 1, [](ShadowSettings & s) -> auto& { return s.bias.tangentPlane; }),
        choice(
            "filter.type",
            "Filter: none (one tap), hw2x2 (hardware bilinear compare), pcf (k x k texels), disk "
            "(rotated disk taps), vsm (variance shadow maps), pcss (percentage-closer soft shadows: blocker "
            "search, penumbra from light.angular_diameter_deg), esm (exponential), evsm2 and evsm4 (exponential "
            "variance, 2 or 4 moments), msm (Hamburger four-moment shadow maps)",
            {"none", "hw2x2", "pcf", "disk", "vsm", "pcss", "esm", "evsm2", "evsm4", "msm"},
            [](ShadowSettings & s) -> auto& { return s.filter.type; }),
        oddNumber(
            "filter.kernel", "pcf: k x k taps one texel apart; vsm, esm, evsm2, evsm4, msm: blur width (odd)", 1, 9,
            [](ShadowSettings & s) -> auto& { return s.filter.kernel; }),
        number(
            "filter.taps", "disk: number of taps; pcss: taps of the blocker search and of the filter", Kind::Int, 1, 64,
            [](ShadowSettings & s) -> auto& { return s.filter.taps; }),
        number(
            "filter.radius", "disk: radius in texels", Kind::Float, 0.5, 16,
            [](ShadowSettings & s) -> auto& { return s.filter.radius; }),
        number(
            "filter.bleed_reduction",
            "vsm, evsm2, evsm4, msm: light-bleeding reduction (lit fractions below it become 0, the rest is "
            "rescaled)",
            Kind::Float, 0, 0.95, [](ShadowSettings & s) -> auto& { return s.filter.bleedReduction; }),
        number(
            "filter.pcss.max_radius", "pcss: cap on the blocker search and filter radius, texels", Kind::Float, 1, 256,
            [](ShadowSettings & s) -> auto& { return s.filter.pcssMaxRadius; }),
        number(
            "filter.esm.exponent",
            "esm: c in exp(c z) over linear depth z in [0,1]; higher bleeds less but rings at contacts", Kind::Float, 1,
            88, [](ShadowSettings & s) -> auto& { return s.filter.esmExponent; }),
        number(
            "filter.evsm.positive_exponent", "evsm2, evsm4: c+ in exp(c+ z), z in [-1,1]", Kind::Float, 1, 42,
            [](ShadowSettings & s) -> auto& { return s.filter.evsmPositive; }),
        number(
            "filter.evsm.negative_exponent", "evsm4: c- in -exp(-c- z), z in [-1,1]", Kind::Float, 1, 42,
            [](ShadowSettings & s) -> auto& { return s.filter.evsmNegative; }),
        number(
            "filter.msm.moment_bias",
            "msm: alpha pulling the four moments towards (0.5, 0.5, 0.5, 0.5) against numeric failure; higher "
            "bleeds more",
            Kind::Float, 1e-8, 0.01, [](ShadowSettings & s) -> auto& { return s.filter.momentBias; }, true),
        number(
            "filter.eye_blur.iterations",
            "Eye-space blur of the shadow mask, stronger near the viewer "
            "(Scherzer 4.3); 0 = off",
            Kind::Int, 0, 8, [](ShadowSettings & s) -> auto& { return s.filter.eyeBlurIterations; }),
        number(
            "filter.eye_blur.falloff",
            "Eye-space blur: taps 1/(1 + falloff * view depth) pixels apart, 3 each side, per "
            "iteration",
            Kind::Float, 0, 10, [](ShadowSettings & s) -> auto& { return s.filter.eyeBlurFalloff; }, true),
        number(
            "light.angular_diameter_deg",
            "Angular diameter of the sun, degrees (0: a point; the real sun is 0.53): PCSS's penumbra, and truth "
            "traces rays over this disk",
            Kind::Float, 0, 20, [](ShadowSettings & s) -> auto& { return s.light.angularDiameterDeg; }),
        choice(
            "stabilize.mode",
            "Stabilization: off; snap (unwarped maps fitted to their split's bounding sphere, moved in whole "
            "texels: edges hold still while the camera moves, at the cost of a larger map footprint); quantize "
            "(snap, and warped maps' V_P in 1 deg steps, n' in 1/16 octaves, projection centre and extent on a "
            "texel grid)",
            {"off", "snap", "quantize"}, [](ShadowSettings & s) -> auto& { return s.stabilize; }),
        choice(
            "focus.mode",
            "Fit the maps to: geometry (each split's view sub-frustum clipped by the scene bounds) or samples "
            "(the depth range and light-space bounds of the pixels the eye sees, from a GPU reduction of the "
            "depth pre-pass; splits without samples are skipped)",
            {"geometry", "samples"}, [](ShadowSettings & s) -> auto& { return s.focus; }),
        choice(
            "warp.method",
            "Warp: uniform (none), psm (n' = n / sin(gamma)), lispsm (Wimmer), glispsm (Barroso eqs 13-18), gmnpr "
            "(Zhang eq 8), "
            "manual (warp.n_prime)",
            {"uniform", "psm", "lispsm", "glispsm", "gmnpr", "manual"},
            [](ShadowSettings & s) -> auto& { return s.warp.method; }),
        choice(
            "warp.direction",
            "Warp direction V_P: standard (view projected onto the light plane) or middle "
            "(Scherzer's middle vector over the focus body)",
            {"standard", "middle"}, [](ShadowSettings & s) -> auto& { return s.direction; }),
        choice(
            "warp.falloff", "glispsm below gamma_lim: eq18 (default) or eq17", {"eq18", "eq17"},
            [](ShadowSettings & s) -> auto& { return s.warp.falloff; }),
        number(
            "warp.n_prime", "manual: n' at gamma = 90 deg (scaled by 1/sin(gamma) like LiSPSM)", Kind::Float, 1e-4, 1e6,
            [](ShadowSettings & s) -> auto& { return s.warp.manualNPrime; }, true),
        number(
            "warp.multiplier", "Multiplies the chosen method's n' (weaker warp above 1, stronger below)", Kind::Float,
            1e-3, 1e3, [](ShadowSettings & s) -> auto& { return s.warp.multiplier; }, true),
        number(
            "warp.visible_far", "lispsm: visible far depth capping n + dz (Scherzer); 0 = off", Kind::Float, 0, 1e7,
            [](ShadowSettings & s) -> auto& { return s.warp.visibleFar; }),
        number(
            "splits.count", "Number of z-partitions (split shadow maps)", Kind::Int, 1, kMaxSplits,
            [](ShadowSettings & s) -> auto& { return s.splits.count; }),
        choice(
            "splits.scheme",
            "Split scheme: uniform, log (Lloyd), practical (log/uniform blend), pssm "
            "(geometric lengths), adaptive (Barroso eq 19)",
            {"uniform", "log", "practical", "pssm", "adaptive"},
            [](ShadowSettings & s) -> auto& { return s.splits.scheme; }),
        number(
            "splits.lambda", "practical: weight of the log scheme", Kind::Float, 0, 1,
            [](ShadowSettings & s) -> auto& { return s.splits.lambda; }),
        number(
            "splits.ratio", "pssm: length ratio of consecutive splits", Kind::Float, 1, 16,
            [](ShadowSettings & s) -> auto& { return s.splits.ratio; }),
        number(
            "splits.alpha", "adaptive: f_i/n_i at gamma = 0 (Barroso: <= 4 without PCF, <= 2 with PCF)", Kind::Float, 1,
            1000, [](ShadowSettings & s) -> auto& { return s.splits.alpha; }, true),
        number(
            "splits.blend",
            "Blend band: this fraction of each split's depth range before its far end fades into the next "
            "split's shadow (0 = a hard seam)",
            Kind::Float, 0, 0.3, [](ShadowSettings & s) -> auto& { return s.splits.blend; }),
        number(
            "splits.resolution_falloff", "Halve the shadow-map resolution for each further split", Kind::Bool, 0, 1,
            [](ShadowSettings & s) -> auto& { return s.splits.resolutionFalloff; }),
        choice(
            "casters.lod",
            "Caster level of detail: off (every triangle), auto (each shadow pass draws, per chunk, the "
            "coarsest simplified level whose error stays below casters.lod_texels texels of that split's "
            "map; thin parts are never simplified)",
            {"off", "auto"}, [](ShadowSettings & s) -> auto& { return s.casters.lod; }),
        number(
            "casters.lod_texels",
            "auto: the geometric error a caster level may have, in texels of the map at the chunk", Kind::Float, 0.1,
            16, [](ShadowSettings & s) -> auto& { return s.casters.lodTexels; }, true),
    };
    return table;
}

const SettingInfo* findSetting(std::string_view key) noexcept {
    for (const auto& info : settingsDeclaration())
        if (info.key == key) return &info;
    return nullptr;
}

static std::string knownKeys() {
    std::string out;
    for (const auto& info : settingsDeclaration()) out += (out.empty() ? "" : ", ") + std::string(info.key);
    return out;
}

void applySetting(ShadowSettings& s, std::string_view key, std::string_view value) {
    const SettingInfo* info = findSetting(key);
    if (!info) throw std::invalid_argument("unknown setting '" + std::string(key) + "' (known: " + knownKeys() + ")");
    const std::string text(value);
    const auto bad = [&] {
        return std::invalid_argument(std::string(key) + ": '" + text + "' is not valid (" + info->rangeText() + ")");
    };
    double v = 0;
    switch (info->kind) {
    case Kind::Choice: {
        size_t i = 0;
        while (i < info->choices.size() && info->choices[i] != value) ++i;
        if (i == info->choices.size()) throw bad();
        v = double(i);
        break;
    }
    case Kind::Bool:
        if (value == "true" || value == "1" || value == "on") v = 1;
        else if (value == "false" || value == "0" || value == "off") v = 0;
        else throw bad();
        break;
    case Kind::Int:
    case Kind::Float: {
        size_t used = 0;
        try {
            v = std::stod(text, &used);
        } catch (const std::exception&) {
            throw bad();
        }
        if (used != text.size() || !std::isfinite(v)) throw bad();
        if (info->kind == Kind::Int && v != std::floor(v)) throw bad();
        if (!(v >= info->min && v <= info->max)) throw bad();
        if (info->odd && std::fmod(v, 2.0) == 0.0) throw bad();
        break;
    }
    }
    info->set(s, v);
}

void applyAssignment(ShadowSettings& s, std::string_view kv) {
    const auto eq = kv.find('=');
    if (eq == std::string_view::npos)
        throw std::invalid_argument("--set expects key=value, got '" + std::string(kv) + "'");
    applySetting(s, kv.substr(0, eq), kv.substr(eq + 1));
}

std::vector<std::string> validate(const ShadowSettings& s) {
    std::vector<std::string> problems;
    for (const auto& info : settingsDeclaration()) {
        const double v = info.get(s);
        if (!(std::isfinite(v) && v >= info.min && v <= info.max) || (info.odd && std::fmod(v, 2.0) == 0.0))
            problems.push_back(std::string(info.key) + ": " + formatNumber(v) + " is outside " + info.rangeText());
    }
    return problems;
}

void validateOrThrow(const ShadowSettings& s) {
    const auto problems = validate(s);
    if (!problems.empty()) throw std::invalid_argument(problems.front());
}

void validateFrustum(double n, double f, double fovYDeg) {
    if (!(std::isfinite(n) && n > 0)) throw std::invalid_argument("near: " + formatNumber(n) + " must be > 0");
    if (!(std::isfinite(f) && f > n))
        throw std::invalid_argument("far: " + formatNumber(f) + " must be finite and > near (" + formatNumber(n) + ")");
    if (!(std::isfinite(fovYDeg) && fovYDeg > 0 && fovYDeg < 180))
        throw std::invalid_argument("fov-y: " + formatNumber(fovYDeg) + " must be within 0..180 (exclusive)");
}

} // namespace geometry::shadow
