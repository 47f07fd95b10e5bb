#include "renderer/settings_block.h"

#include <bit>

namespace renderer {

using Kind = geometry::shadow::SettingInfo::Kind;

std::string_view settingGlslType(const geometry::shadow::SettingInfo& info) noexcept {
    switch (info.kind) {
    case Kind::Float: return "float";
    case Kind::Bool: return "bool";
    case Kind::Int:
    case Kind::Choice: return "int";
    }
    return "float";
}

std::vector<std::uint32_t> settingsBlockWords(const geometry::shadow::ShadowSettings& s) {
    std::vector<std::uint32_t> words;
    settingsBlockWords(s, words);
    return words;
}

void settingsBlockWords(const geometry::shadow::ShadowSettings& s, std::vector<std::uint32_t>& words) {
    const auto& rows = geometry::shadow::settingsDeclaration();
    words.clear();
    words.reserve(rows.size() + 3);
    for (const auto& info : rows) {
        const double v = info.get(s);
        switch (info.kind) {
        case Kind::Float: words.push_back(std::bit_cast<std::uint32_t>(float(v))); break;
        case Kind::Bool: words.push_back(v != 0.0 ? 1u : 0u); break;
        case Kind::Int:
        case Kind::Choice: words.push_back(std::bit_cast<std::uint32_t>(std::int32_t(v))); break;
        }
    }
    words.resize((words.size() + 3) / 4 * 4, 0u); // std140 rounds the block up to 16 bytes
}

} // namespace renderer
