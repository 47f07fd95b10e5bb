#include "dashboard_config.h"

#include "geometry/io/json_file.h"
#include "geometry/io/preset.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace ui {

using json = nlohmann::json;

std::string_view heatmapName(HeatmapKind k) noexcept {
    switch (k) {
    case HeatmapKind::Aliasing: return "aliasing";
    case HeatmapKind::Truth: return "truth";
    case HeatmapKind::Splits: return "splits";
    case HeatmapKind::Texels: return "texels";
    case HeatmapKind::Difference: return "difference";
    case HeatmapKind::Soft: return "soft";
    case HeatmapKind::Count: break;
    }
    return "?";
}

std::string_view compareName(CompareMode m) noexcept {
    switch (m) {
    case CompareMode::Off: return "off";
    case CompareMode::SideBySide: return "side_by_side";
    case CompareMode::Split: return "split";
    case CompareMode::Count: break;
    }
    return "?";
}

std::filesystem::path configDirectory() {
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x) return std::filesystem::path(x) / "shadowscope";
    if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".config" / "shadowscope";
    return {};
}

namespace {

[[noreturn]] void bad(const std::string& key, const std::string& problem) {
    throw std::invalid_argument("config: " + key + ": " + problem);
}

const json* member(const json& obj, const char* key) {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
}

double number(const json& obj, const char* key, const std::string& path, double lo, double hi, double current) {
    const json* v = member(obj, key);
    if (!v) return current;
    if (!v->is_number()) bad(path + key, "expected a number");
    const double d = v->get<double>();
    if (!std::isfinite(d) || d < lo || d > hi)
        bad(path + key, "outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return d;
}

bool boolean(const json& obj, const char* key, const std::string& path, bool current) {
    const json* v = member(obj, key);
    if (!v) return current;
    if (!v->is_boolean()) bad(path + key, "expected true or false");
    return v->get<bool>();
}

template <typename Enum, typename NameFn>
Enum choice(const json& obj, const char* key, const std::string& path, Enum current, NameFn name) {
    const json* v = member(obj, key);
    if (!v) return current;
    if (!v->is_string()) bad(path + key, "expected a name");
    for (int i = 0; i < int(Enum::Count); ++i)
        if (name(Enum(i)) == v->get<std::string>()) return Enum(i);
    bad(path + key, "unknown value '" + v->get<std::string>() + "'");
}

const json& object(const json& j, const char* key, const std::string& path) {
    static const json empty = json::object();
    const json* v = member(j, key);
    if (!v) return empty;
    if (!v->is_object()) bad(path + key, "expected an object");
    return *v;
}

} // namespace

json dashboardToJson(const DashboardState& s, const WindowGeometry& window) {
    const ViewSettings& v = s.views;
    return json{
        {"settings", geometry::io::settingsToJson(s.settings[0])},
        {"settings_b", geometry::io::settingsToJson(s.settings[1])},
        {"views",
         {{"light_split", v.lightSplit},
          {"overlays", v.overlays},
          {"unwarped", v.unwarped},
          {"heatmap", heatmapName(v.heatmap)},
          {"heatmap_blend", v.heatmapBlend},
          {"texel_grid", v.texelGrid},
          {"truth", v.truth},
          {"truth_samples", v.truthSamples},
          {"compare", compareName(v.compare)},
          {"split_position", v.splitPosition}}},
        {"camera", {{"fly_speed", s.flySpeed}}},
        {"layout",
         {{"controls_width", s.layout.controlsWidth},
          {"eye_end", s.layout.eyeEnd},
          {"light_end", s.layout.lightEnd},
          {"stats_height", s.layout.statsHeight},
          {"window", {window.width, window.height}}}},
    };
}

void dashboardFromJson(const json& j, DashboardState& state, WindowGeometry& window) {
    if (!j.is_object()) bad("(top level)", "expected an object");
    for (const auto& [key, _] : j.items())
        if (key != "settings" && key != "settings_b" && key != "views" && key != "camera" && key != "layout")
            bad(key, "unknown key");
    DashboardState s = state; // applied only when everything parses
    WindowGeometry w = window;
    try {
        if (const json* a = member(j, "settings")) s.settings[0] = geometry::io::settingsFromJson(*a, s.settings[0]);
        if (const json* b = member(j, "settings_b")) s.settings[1] = geometry::io::settingsFromJson(*b, s.settings[1]);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("config: ") + e.what());
    }
    const json& v = object(j, "views", "views.");
    ViewSettings& vs = s.views;
    vs.lightSplit = int(number(v, "light_split", "views.", 0, geometry::shadow::kMaxSplits - 1, vs.lightSplit));
    vs.overlays = boolean(v, "overlays", "views.", vs.overlays);
    vs.unwarped = boolean(v, "unwarped", "views.", vs.unwarped);
    vs.heatmap = choice(v, "heatmap", "views.", vs.heatmap, heatmapName);
    vs.heatmapBlend = float(number(v, "heatmap_blend", "views.", 0, 1, vs.heatmapBlend));
    vs.texelGrid = int(number(v, "texel_grid", "views.", 1, 64, vs.texelGrid));
    vs.truth = boolean(v, "truth", "views.", vs.truth);
    vs.truthSamples = int(number(v, "truth_samples", "views.", 1, 4, vs.truthSamples));
    vs.compare = choice(v, "compare", "views.", vs.compare, compareName);
    vs.splitPosition = float(number(v, "split_position", "views.", 0, 1, vs.splitPosition));
    const json& c = object(j, "camera", "camera.");
    s.flySpeed = float(number(c, "fly_speed", "camera.", 1e-3, 1e6, s.flySpeed));
    const json& l = object(j, "layout", "layout.");
    s.layout.controlsWidth = float(number(l, "controls_width", "layout.", 100, 4000, s.layout.controlsWidth));
    s.layout.eyeEnd = float(number(l, "eye_end", "layout.", 0, 1, s.layout.eyeEnd));
    s.layout.lightEnd = float(number(l, "light_end", "layout.", 0, 1, s.layout.lightEnd));
    s.layout.statsHeight = float(number(l, "stats_height", "layout.", 0, 1, s.layout.statsHeight));
    s.layout = clampFractions(s.layout);
    if (const json* win = member(l, "window")) {
        if (!win->is_array() || win->size() != 2 || !(*win)[0].is_number_integer() || !(*win)[1].is_number_integer())
            bad("layout.window", "expected [width, height]");
        const int ww = (*win)[0].get<int>(), wh = (*win)[1].get<int>();
        if (ww < 200 || wh < 150 || ww > 16384 || wh > 16384) bad("layout.window", "size outside 200×150 … 16384²");
        w = {ww, wh};
    }
    state = s;
    window = w;
}

std::optional<std::string> loadDashboardConfig(const std::filesystem::path& path, DashboardState& state,
                                               WindowGeometry& window) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return std::nullopt;
    try {
        const json j = geometry::io::readJsonFile(path.string(), path.string(), 1u << 20, 16);
        dashboardFromJson(j, state, window);
        return std::nullopt;
    } catch (const std::exception& e) {
        return std::string(e.what());
    }
}

std::optional<std::string> saveDashboardConfig(const std::filesystem::path& path, const DashboardState& state,
                                               const WindowGeometry& window) {
    try {
        std::error_code ec;
        std::filesystem::create_directories(path.parent_path(), ec);
        const std::filesystem::path tmp = path.string() + ".tmp";
        {
            std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
            if (!out) return "cannot write " + tmp.string();
            out << dashboardToJson(state, window).dump(2) << '\n';
            if (!out) return "cannot write " + tmp.string();
        }
        std::filesystem::rename(tmp, path, ec);
        if (ec) return "cannot replace " + path.string() + ": " + ec.message();
        return std::nullopt;
    } catch (const std::exception& e) {
        return std::string(e.what());
    }
}

} // namespace ui
