#include "dashboard_config.h"

#include "file_list.h"
#include "geometry/io/json_file.h"
#include "geometry/io/preset.h"
#include "light_list.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
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

json lightToJson(const geometry::scene::Light& l) {
    const auto v3 = [](const glm::vec3& v) { return json::array({v.x, v.y, v.z}); };
    json j{{"type", geometry::scene::lightTypeName(l.type)},
           {"direction", v3(l.direction)},
           {"position", v3(l.position)},
           {"cone_deg", l.coneDeg},
           {"range", l.range},
           {"radius", l.radius}};
    if (!l.settings.empty()) j["settings"] = l.settings; // its overrides, "key=value" as --set takes them
    return j;
}

glm::vec3 configVec3(const json& obj, const char* key, const std::string& path, glm::vec3 current) {
    const json* v = member(obj, key);
    if (!v) return current;
    if (!v->is_array() || v->size() != 3 || !(*v)[0].is_number() || !(*v)[1].is_number() || !(*v)[2].is_number())
        bad(path + key, "expected 3 numbers");
    return {(*v)[0].get<float>(), (*v)[1].get<float>(), (*v)[2].get<float>()};
}

/// A light object as a scene file writes one (members it leaves out keep Light{}'s), checked whole.
geometry::scene::Light lightFromJson(const json& v, const std::string& path) {
    if (!v.is_object()) bad(path, "expected a light object");
    for (const auto& [key, _] : v.items())
        if (key != "type" && key != "direction" && key != "position" && key != "cone_deg" && key != "range" &&
            key != "radius" && key != "settings")
            bad(path + "." + key, "unknown key");
    geometry::scene::Light l;
    if (const json* t = member(v, "type")) {
        const std::string name = t->is_string() ? t->get<std::string>() : std::string();
        if (name == "directional") l.type = geometry::scene::LightType::Directional;
        else if (name == "spot") l.type = geometry::scene::LightType::Spot;
        else if (name == "point") l.type = geometry::scene::LightType::Point;
        else bad(path + ".type", "expected directional, spot or point");
    }
    const std::string p = path + ".";
    l.direction = configVec3(v, "direction", p, l.direction);
    l.position = configVec3(v, "position", p, l.position);
    // Bounds wider than a light's: lightProblem() below names what is wrong with the light.
    const double big = std::numeric_limits<float>::max();
    l.coneDeg = float(number(v, "cone_deg", p, -big, big, l.coneDeg));
    l.range = float(number(v, "range", p, -big, big, l.range));
    l.radius = float(number(v, "radius", p, -big, big, l.radius));
    if (const json* overrides = member(v, "settings")) {
        if (!overrides->is_array()) bad(path + ".settings", "expected an array of key=value overrides");
        geometry::shadow::ShadowSettings checked;
        for (const json& a : *overrides) {
            if (!a.is_string()) bad(path + ".settings", "expected key=value strings");
            try {
                geometry::shadow::applyAssignment(checked, a.get<std::string>());
            } catch (const std::invalid_argument& e) {
                bad(path + ".settings", e.what());
            }
            l.settings.push_back(a.get<std::string>());
        }
    }
    if (auto problem = lightProblem(l)) bad(path, *problem);
    return l;
}

} // namespace

json dashboardToJson(const DashboardState& s, const WindowGeometry& window) {
    const ViewSettings& v = s.views;
    json j{
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
          {"split_position", v.splitPosition},
          {"light_gizmo", v.lightGizmo}}},
        {"camera", {{"fly_speed", s.flySpeed}}},
        {"layout",
         {{"controls_width", s.layout.controlsWidth},
          {"eye_end", s.layout.eyeEnd},
          {"light_end", s.layout.lightEnd},
          {"stats_height", s.layout.statsHeight},
          {"window", {window.width, window.height}}}},
    };
    if (!s.recentFiles.empty()) j["recent_files"] = s.recentFiles;
    if (!s.lights.empty()) {
        json list = json::array();
        for (const auto& l : s.lights) list.push_back(lightToJson(l));
        j["lights"] = {{"scene", s.lightsScene}, {"inspected", s.inspectedLight}, {"list", std::move(list)}};
    }
    return j;
}

void dashboardFromJson(const json& j, DashboardState& state, WindowGeometry& window) {
    if (!j.is_object()) bad("(top level)", "expected an object");
    for (const auto& [key, _] : j.items())
        if (key != "settings" && key != "settings_b" && key != "views" && key != "camera" && key != "layout" &&
            key != "lights" && key != "recent_files")
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
    vs.lightGizmo = boolean(v, "light_gizmo", "views.", vs.lightGizmo);
    if (const json* lights = member(j, "lights")) {
        // The light list of the scene named; the dashboard takes it only for that scene.
        if (!lights->is_object()) bad("lights", "expected an object");
        for (const auto& [key, _] : lights->items())
            if (key != "scene" && key != "inspected" && key != "list") bad("lights." + key, "unknown key");
        const json* scene = member(*lights, "scene");
        if (scene && !scene->is_string()) bad("lights.scene", "expected a scene name or path");
        const json* list = member(*lights, "list");
        if (!list || !list->is_array() || list->empty() || list->size() > geometry::scene::kMaxLights)
            bad("lights.list", "expected 1 to " + std::to_string(geometry::scene::kMaxLights) + " lights");
        std::vector<geometry::scene::Light> parsed;
        for (size_t i = 0; i < list->size(); ++i)
            parsed.push_back(lightFromJson((*list)[i], "lights.list[" + std::to_string(i) + "]"));
        s.lights = std::move(parsed);
        s.lightsScene = scene ? scene->get<std::string>() : std::string();
        s.inspectedLight = int(number(*lights, "inspected", "lights.", 0, double(s.lights.size() - 1), 0));
    }
    if (const json* recent = member(j, "recent_files")) {
        if (!recent->is_array() || recent->size() > kMaxRecentFiles)
            bad("recent_files", "expected up to " + std::to_string(kMaxRecentFiles) + " paths");
        s.recentFiles.clear();
        for (const json& path : *recent) {
            if (!path.is_string() || path.get<std::string>().empty()) bad("recent_files", "expected paths");
            s.recentFiles.push_back(path.get<std::string>());
        }
    }
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
