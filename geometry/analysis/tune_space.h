#pragma once
// The settings `tune` searches (docs/design.md §4 "Tuning"): the default candidates per key,
// overrides from --space, and which settings matter under the others. Pure.
#include "geometry/shadow/setting_relevance.h"
#include "geometry/shadow/settings.h"

#include <string>
#include <string_view>
#include <vector>

namespace geometry::analysis {

/// One searched setting and its candidate values (as `--set` spells them).
struct TuneAxis {
    std::string key;
    std::vector<std::string> values;
};

/// bias.type and its amounts, filter.type and kernel, resolution, warp.method, splits count, scheme
/// and α, tangent plane (docs/design.md §4 "Tuning" lists the values).
[[nodiscard]] std::vector<TuneAxis> defaultTuneSpace();
/// Applies "key=v1,v2,...": replaces that key's candidates, or adds the key. Throws
/// std::invalid_argument (naming --space) for a malformed spec, an unknown key or an invalid value.
void overrideTuneAxis(std::vector<TuneAxis>& space, std::string_view spec);
/// The number of configurations the space spans (the product of its axes' sizes).
[[nodiscard]] double tuneSpaceSize(const std::vector<TuneAxis>& space) noexcept;

/// Whether a setting matters under the others (geometry/shadow/setting_relevance.h).
using shadow::settingMatters;

} // namespace geometry::analysis
