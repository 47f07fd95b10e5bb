#pragma once
// Shadow settings, declared once: each key's name, help and range live in settingsDeclaration(),
// its default in the member initialiser below. Widgets, JSON presets, `--set key=value` and
// validation are all derived from that one table.
#include "splits.h"
#include "warp.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace geometry {

struct ShadowSettings {
    int resolution = 2048;      // shadow_map.resolution
    float constantBias = 0.05f; // bias.constant: z_offset (Barroso Table 1), scene units along l
    WarpParams warp{WarpMethod::Uniform};
    WarpDirection direction = WarpDirection::Standard;
    SplitParams splits;
};

struct SettingInfo {
    enum class Kind { Int, Float, Bool, Choice };
    std::string_view key;
    std::string_view help;
    Kind kind = Kind::Float;
    double min = 0, max = 0;                // Int, Float: valid range (inclusive)
    std::vector<std::string_view> choices;  // Choice: names in enum order
    bool logScale = false;                  // a hint for widgets
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

} // namespace geometry
