#pragma once
// Which settings change anything under the others (each row's `when` in settings.h: bias.slope only
// for the slope biases, splits.alpha only for adaptive splits with more than one split, …), and the
// warnings for those set in vain (docs/design.md §3 "Settings without effect"). Pure.
#include "geometry/shadow/settings.h"

#include <string>
#include <string_view>
#include <vector>

namespace geometry::shadow {

/// Whether `key` changes anything under the other settings of `s` (its row's appliesTo; true for an
/// unknown key).
[[nodiscard]] bool settingMatters(const ShadowSettings& s, std::string_view key) noexcept;

/// One line per declared setting that differs from its default but has no effect under the others
/// ("bias.constant = 0.1 has no effect (bias.type = slope)").
[[nodiscard]] std::vector<std::string> inertSettingWarnings(const ShadowSettings& s);

} // namespace geometry::shadow
