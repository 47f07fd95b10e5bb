#pragma once
// JSON presets of the shadow settings. The layout is derived from settingsDeclaration() by
// splitting each key at '.': "filter.eye_blur.iterations" lives at {"filter": {"eye_blur":
// {"iterations": N}}}. Values go through geometry::applySetting, so a preset is validated exactly
// like `--set key=value`. Optional top-level "name" and "description" strings document the file.
#include "geometry/shadow/settings.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace geometry::io {

/// Files above this size are refused before parsing.
inline constexpr std::size_t kMaxPresetBytes = 1u << 20;
/// Objects may nest at most this deep (the deepest declared key uses 3 levels).
inline constexpr int kMaxPresetDepth = 8;

/// Every declared key as a nested object: ints as integers, floats as numbers, bools as
/// booleans, choices as their names.
[[nodiscard]] nlohmann::json settingsToJson(const shadow::ShadowSettings& settings);

/// `base` with every setting present in `j` applied; missing keys keep base's value. Throws
/// std::invalid_argument starting with "preset: " and naming the key path for an unknown key, a
/// value of the wrong JSON type (numbers given as strings included), an out-of-range value, or
/// nesting deeper than kMaxPresetDepth.
[[nodiscard]] shadow::ShadowSettings settingsFromJson(const nlohmann::json& j, shadow::ShadowSettings base = {});

/// The `key=value` assignments (applyAssignment's form) of a preset-shaped object `j` (nested groups
/// or dotted keys), in the order applied, each checked as settingsFromJson checks it: a light's
/// overrides of the shared settings (docs/design.md §3.10). Throws std::invalid_argument naming the key.
[[nodiscard]] std::vector<std::string> settingAssignments(const nlohmann::json& j);

/// Reads a preset file over `base`. Throws std::runtime_error (file problems: missing,
/// unreadable, empty, larger than kMaxPresetBytes, not JSON, not an object) or
/// std::invalid_argument (bad settings), each with a one-line message starting "preset PATH: ".
[[nodiscard]] shadow::ShadowSettings loadPreset(const std::string& path, shadow::ShadowSettings base = {});

/// Writes every setting as pretty JSON (2-space indent, trailing newline), keys in declaration
/// order after the optional name and description. Throws std::runtime_error when it cannot write.
void savePreset(const std::string& path, const shadow::ShadowSettings& settings, std::string_view name = "",
                std::string_view description = "");

} // namespace geometry::io
