#pragma once
// Widgets for the shadow settings, generated from geometry::settingsDeclaration(): one per key,
// with the key's help and range as the tooltip.
#include "geometry/shadow/settings.h"

#include <string>
#include <string_view>

namespace ui {

/// Draws the widgets of every key for which `inGroup(key)` holds. Returns true when a value
/// changed. A typed value outside the key's range (or NaN) is refused: the setting keeps its
/// value and `error` says why, in one line.
bool drawSettingsWidgets(geometry::shadow::ShadowSettings& settings,
                         bool (*inGroup)(std::string_view key, const void* ctx), const void* ctx, std::string* error);

/// Every key.
bool drawSettingsWidgets(geometry::shadow::ShadowSettings& settings);

} // namespace ui
