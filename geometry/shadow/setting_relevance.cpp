#include "geometry/shadow/setting_relevance.h"

namespace geometry::shadow {

bool settingMatters(const ShadowSettings& s, std::string_view key) noexcept {
    const SettingInfo* info = findSetting(key);
    return !info || info->appliesTo(s);
}

std::vector<std::string> inertSettingWarnings(const ShadowSettings& s) {
    std::vector<std::string> out;
    const ShadowSettings defaults;
    for (const SettingInfo& info : settingsDeclaration()) {
        if (info.appliesTo(s) || info.format(s) == info.format(defaults)) continue;
        std::string line = std::string(info.key) + " = " + info.format(s) + " has no effect";
        const std::string_view by =
            info.mapsOnly && s.technique == Technique::Virtual ? std::string_view("technique") : info.governedBy;
        if (const SettingInfo* governing = findSetting(by))
            line += " (" + std::string(by) + " = " + governing->format(s) + ")";
        out.push_back(std::move(line));
    }
    return out;
}

} // namespace geometry::shadow
