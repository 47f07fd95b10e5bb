#pragma once
// A test hook: with SHADOWSCOPE_WIDGET_MAP=FILE set, every frame writes where the dashboard's
// widgets are (screen rectangles by id, e.g. "warp.method", "warp.method=lispsm" for an open
// combo's item) plus the frame number and status line to FILE as JSON, so the end-to-end test can
// click them with xdotool. Without the variable every call is a no-op.
#include "dashboard_layout.h"

#include <string>
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

/// While paused nothing is recorded or written (a dashboard drawn offscreen for an export).
void widgetMapPause(bool paused);

/// Keeps the map in memory without the variable (headless tests); widgetMapLast() reads it.
void widgetMapCapture(bool on);
/// The last finished frame's map as JSON text ("{}" before one, or when the map is off). Besides
/// "widgets": "disabled", the ids recorded while greyed (ImGui::BeginDisabled), and "counters".
[[nodiscard]] std::string widgetMapLast();

} // namespace ui
