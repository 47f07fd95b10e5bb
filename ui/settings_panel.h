#pragma once
// Widgets for every shadow setting, generated from geometry::settingsDeclaration().
#include "geometry/settings.h"

namespace ui {
/// Draws one widget per declared setting (help text on hover); true when a value changed.
/// Values outside a key's range are never stored: the previous value stays.
bool drawSettingsWidgets(geometry::ShadowSettings& settings);
} // namespace ui
