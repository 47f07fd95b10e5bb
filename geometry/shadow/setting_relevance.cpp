#include "geometry/shadow/setting_relevance.h"

namespace geometry::shadow {

bool settingMatters(const ShadowSettings& s, std::string_view key) noexcept {
    const BiasType bias = s.bias.type;
    const FilterType filter = s.filter.type;
    const bool split = s.splits.count > 1;
    const bool warped = s.warp.method != WarpMethod::Uniform;
    if (key == "bias.constant") return bias == BiasType::Constant;
    if (key == "bias.slope" || key == "bias.units")
        return bias == BiasType::Slope || bias == BiasType::SlopeNormalOffset;
    if (key == "bias.z_max") return bias == BiasType::DualDepth;
    if (key == "bias.normal_offset") return bias == BiasType::NormalOffset || bias == BiasType::SlopeNormalOffset;
    if (key == "bias.tangent_plane") return filter == FilterType::Pcf || filter == FilterType::Disk;
    if (key == "filter.kernel") return filter == FilterType::Pcf || isMomentFilter(filter);
    if (key == "filter.taps") return filter == FilterType::Disk || filter == FilterType::Pcss;
    if (key == "filter.radius") return filter == FilterType::Disk;
    if (key == "filter.pcss.max_radius") return filter == FilterType::Pcss;
    if (key == "filter.bleed_reduction") return isMomentFilter(filter) && filter != FilterType::Esm;
    if (key == "filter.esm.exponent") return filter == FilterType::Esm;
    if (key == "filter.evsm.positive_exponent") return filter == FilterType::Evsm2 || filter == FilterType::Evsm4;
    if (key == "filter.evsm.negative_exponent") return filter == FilterType::Evsm4;
    if (key == "filter.msm.moment_bias") return filter == FilterType::Msm;
    if (key == "filter.eye_blur.falloff") return s.filter.eyeBlurIterations > 0;
    if (key == "warp.direction" || key == "warp.multiplier") return warped;
    if (key == "warp.falloff") return s.warp.method == WarpMethod::Glispsm;
    if (key == "warp.n_prime") return s.warp.method == WarpMethod::Manual;
    if (key == "warp.visible_far") return s.warp.method == WarpMethod::Lispsm;
    if (key == "splits.scheme" || key == "splits.resolution_falloff" || key == "splits.blend") return split;
    if (key == "splits.lambda") return split && s.splits.scheme == SplitScheme::Practical;
    if (key == "splits.ratio") return split && s.splits.scheme == SplitScheme::Pssm;
    if (key == "splits.alpha") return split && s.splits.scheme == SplitScheme::Adaptive;
    return true;
}

namespace {

/// The setting that decides whether `key` matters: named in the warning.
std::string_view governingKey(std::string_view key) noexcept {
    if (key.starts_with("bias.")) return key == "bias.tangent_plane" ? "filter.type" : "bias.type";
    if (key == "filter.eye_blur.falloff") return "filter.eye_blur.iterations";
    if (key.starts_with("filter.")) return "filter.type";
    if (key.starts_with("warp.")) return "warp.method";
    if (key == "splits.lambda" || key == "splits.ratio" || key == "splits.alpha") return "splits.scheme";
    if (key.starts_with("splits.")) return "splits.count";
    return {};
}

} // namespace

std::vector<std::string> inertSettingWarnings(const ShadowSettings& s) {
    std::vector<std::string> out;
    const ShadowSettings defaults;
    for (const SettingInfo& info : settingsDeclaration()) {
        if (settingMatters(s, info.key) || info.format(s) == info.format(defaults)) continue;
        std::string line = std::string(info.key) + " = " + info.format(s) + " has no effect";
        if (const std::string_view by = governingKey(info.key); !by.empty())
            if (const SettingInfo* governing = findSetting(by))
                line += " (" + std::string(by) + " = " + governing->format(s) + ")";
        out.push_back(std::move(line));
    }
    return out;
}

} // namespace geometry::shadow
