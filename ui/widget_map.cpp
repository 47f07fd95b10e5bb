#include "widget_map.h"

#include <imgui.h>
#include <imgui_internal.h> // the last item's disabled flag (1.86 has no public query)
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace ui {

namespace {
struct MapState {
    const char* path = std::getenv("SHADOWSCOPE_WIDGET_MAP");
    nlohmann::json current;
    long frame = 0;
    bool capture = false; // in memory only (tests)
    bool paused = false;
    std::string last = "{}";
};
MapState& map() {
    static MapState s;
    return s;
}
bool toFile() { return map().path && *map().path; }
bool enabled() { return (toFile() || map().capture) && !map().paused; }
} // namespace

void widgetMapBeginFrame(float width, float height) {
    if (!enabled()) return;
    MapState& m = map();
    m.current = {{"window", {width, height}}, {"widgets", nlohmann::json::object()}, {"status", ""}};
}

void widgetMapRecordRect(std::string_view id, const Rect& r) {
    if (!enabled()) return;
    map().current["widgets"][std::string(id)] = {r.x, r.y, r.w, r.h};
}

void widgetMapRecord(std::string_view id) {
    if (!enabled()) return;
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    // Only items that are actually visible (not scrolled out of their window) can be clicked.
    if (!ImGui::IsItemVisible()) return;
    widgetMapRecordRect(id, {a.x, a.y, b.x - a.x, b.y - a.y});
    if (GImGui->LastItemData.InFlags & ImGuiItemFlags_Disabled)
        map().current["disabled"].push_back(std::string(id)); // greyed: the e2e tests read it
}

void widgetMapStatus(std::string_view status) {
    if (!enabled()) return;
    map().current["status"] = std::string(status);
}

void widgetMapCounter(std::string_view name, double value) {
    if (!enabled()) return;
    map().current["counters"][std::string(name)] = value;
}

void widgetMapEndFrame() {
    if (!enabled()) return;
    MapState& m = map();
    ++m.frame;
    // Every frame (tests wait on the frame counter); the file is small and only written under the hook.
    nlohmann::json out = m.current;
    out["frame"] = m.frame;
    m.last = out.dump();
    if (!toFile()) return;
    const std::string tmp = std::string(m.path) + ".tmp";
    {
        std::ofstream f(tmp, std::ios::trunc);
        f << out.dump(1) << '\n';
    }
    std::rename(tmp.c_str(), m.path);
}

void widgetMapPause(bool paused) { map().paused = paused; }

void widgetMapCapture(bool on) { map().capture = on; }

std::string widgetMapLast() { return map().last; }

} // namespace ui
