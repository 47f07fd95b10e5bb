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
        if (const SettingInfo* governing = findSetting(info.governedBy))
            line += " (" + std::string(info.governedBy) + " = " + governing->format(s) + ")";
        out.push_back(std::move(line));
    }
    return out;
}

} // namespace geometry::shadow
