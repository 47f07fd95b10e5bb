#pragma once
// The shaders' settings block (std140, binding kSettingsBlockBinding): every declared setting
// (geometry/shadow/settings.h) as one 4-byte scalar, in declaration order, named by
// SettingInfo::glslName() — `settings.filter_radius`, `settings.bias_type == BIAS_CONSTANT`. The GLSL
// block is generated from the same table (renderer/shadow_glsl_gen.cpp), so a new setting reaches the
// shaders with no code here (docs/design.md §5 "Adding a setting").
#include "geometry/shadow/settings.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace renderer {

inline constexpr unsigned kSettingsBlockBinding = 1;

/// The GLSL type a row is stored as: float (Float), int (Int, Choice: the enum's index) or bool.
[[nodiscard]] std::string_view settingGlslType(const geometry::shadow::SettingInfo& info) noexcept;

/// The block's contents for `s`: one word per row (floats as their IEEE bits, ints as two's
/// complement, flags 0 or 1), padded to a whole number of 16-byte rows.
[[nodiscard]] std::vector<std::uint32_t> settingsBlockWords(const geometry::shadow::ShadowSettings& s);
/// The same, written over `words` (which keeps its capacity: the renderer's per-frame upload allocates nothing).
void settingsBlockWords(const geometry::shadow::ShadowSettings& s, std::vector<std::uint32_t>& words);

} // namespace renderer
