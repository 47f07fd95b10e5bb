#pragma once
// A test hook: with SHADOWSCOPE_WIDGET_MAP=FILE set, every frame writes where the dashboard's
// widgets are (screen rectangles by id, e.g. "warp.method", "warp.method=lispsm" for an open
// combo's item) plus the frame number and status line to FILE as JSON, so the end-to-end test can
// click them with xdotool. Without the variable every call is a no-op.
#include "dashboard_layout.h"

#include <string_view>

namespace ui {

void widgetMapBeginFrame(float width, float height);
/// The last ImGui item's rectangle under `id`.
void widgetMapRecord(std::string_view id);
void widgetMapRecordRect(std::string_view id, const Rect& r);
void widgetMapStatus(std::string_view status);
/// A number the tests read (e.g. how many passes the dashboard has drawn).
void widgetMapCounter(std::string_view name, double value);
void widgetMapEndFrame();

} // namespace ui
