#include "geometry/io/preset.h"
#include "geometry/io/json_file.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace geometry::io {

namespace {

using Kind = shadow::SettingInfo::Kind;
using json = nlohmann::json;

std::string shortestText(double v) {
    char buf[64];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc{} ? std::string(buf, end) : std::to_string(v);
}

/// Float settings hold floats: write 0.05 rather than 0.05000000074505806 when the shorter
/// number stores back to the same value. Double fields keep their full precision (probing
/// through the accessors tells which storage a key has).
double shortestStored(const shadow::SettingInfo& info, const shadow::ShadowSettings& s) {
    const double v = info.get(s);
    const float f = static_cast<float>(v);
    if (static_cast<double>(f) != v) return v;
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, f);
    double shorter = 0;
    if (ec != std::errc{} || std::from_chars(buf, end, shorter).ec != std::errc{}) return v;
    shadow::ShadowSettings probe = s;
    info.set(probe, shorter);
    return info.get(probe) == v ? shorter : v;
}

template <class Json> Json leafValue(const shadow::SettingInfo& info, const shadow::ShadowSettings& s) {
    switch (info.kind) {
    case Kind::Int: return Json(static_cast<long long>(info.get(s)));
    case Kind::Float: return Json(shortestStored(info, s));
    case Kind::Bool: return Json(info.get(s) != 0.0);
    case Kind::Choice: return Json(info.format(s));
    }
    return Json();
}

/// Adds every declared key to `out`, nesting at each '.'. Templated so savePreset can keep the
/// declaration order (ordered_json) while the public API returns plain json.
template <class Json> Json toJson(const shadow::ShadowSettings& s, Json out) {
    for (const auto& info : geometry::shadow::settingsDeclaration()) {
        Json* node = &out;
        std::string_view rest = info.key;
        for (auto dot = rest.find('.'); dot != std::string_view::npos; dot = rest.find('.')) {
            node = &(*node)[std::string(rest.substr(0, dot))];
            rest.remove_prefix(dot + 1);
        }
        (*node)[std::string(rest)] = leafValue<Json>(info, s);
    }
    return out;
}

std::string expectedType(const shadow::SettingInfo& info) {
    switch (info.kind) {
    case Kind::Int: return "an integer (" + info.rangeText() + ")";
    case Kind::Float: return "a number (" + info.rangeText() + ")";
    case Kind::Bool: return "true or false";
    case Kind::Choice: return "a string, " + info.rangeText();
    }
    return "?";
}

/// The text applySetting parses for a JSON leaf. The JSON type must match the setting's kind,
/// so "3" (a string) is refused for an int even though `--set` would take it.
std::string leafText(const shadow::SettingInfo& info, const json& v) {
    const auto wrongType = [&] {
        return std::invalid_argument(std::string(info.key) + ": expected " + expectedType(info) + ", got " +
                                     describeJsonValue(v));
    };
    switch (info.kind) {
    case Kind::Int:
    case Kind::Float:
        if (v.is_number_unsigned()) return std::to_string(v.get<unsigned long long>());
        if (v.is_number_integer()) return std::to_string(v.get<long long>());
        if (v.is_number_float()) return shortestText(v.get<double>()); // inf from 1e999 → applySetting refuses it
        break;
    case Kind::Bool:
        if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
        break;
    case Kind::Choice:
        if (v.is_string()) return v.get<std::string>();
        break;
    }
    throw wrongType();
}

/// True when `path` names a group of settings ("filter", "filter.eye_blur").
bool isGroup(std::string_view path) {
    for (const auto& info : geometry::shadow::settingsDeclaration())
        if (info.key.size() > path.size() && info.key.starts_with(path) && info.key[path.size()] == '.') return true;
    return false;
}

std::string knownKeys() {
    std::string out;
    for (const auto& info : geometry::shadow::settingsDeclaration())
        out += (out.empty() ? "" : ", ") + std::string(info.key);
    return out;
}

/// Applies the members of `object`, found at `prefix` (empty for the top level) and nesting
/// level `depth` (1 for the top level). Messages are not yet prefixed with "preset ...: ".
void applyObject(shadow::ShadowSettings& s, const json& object, const std::string& prefix, int depth,
                 std::vector<std::string>* assignments = nullptr) {
    // Recursion only enters declared groups (3 levels today), so hostile trees stop at their first
    // unknown member; this guard keeps the bound explicit should keys ever nest deeper.
    if (depth > kMaxPresetDepth)
        throw std::invalid_argument("'" + prefix + "' is nested deeper than " + std::to_string(kMaxPresetDepth) +
                                    " levels");
    for (const auto& [name, value] : object.items()) {
        if (depth == 1 && (name == "name" || name == "description")) {
            if (!value.is_string())
                throw std::invalid_argument(name + ": expected a string, got " + describeJsonValue(value));
            continue;
        }
        const std::string key = prefix.empty() ? name : prefix + "." + name;
        if (const shadow::SettingInfo* info = geometry::shadow::findSetting(key)) {
            const std::string text = leafText(*info, value);
            geometry::shadow::applySetting(s, key, text);
            if (assignments) assignments->push_back(key + "=" + text);
        } else if (!isGroup(key))
            throw std::invalid_argument("unknown setting '" + key + "' (known: " + knownKeys() + ")");
        else if (value.is_object()) applyObject(s, value, key, depth + 1, assignments);
        else
            throw std::invalid_argument(key + ": expected an object (a group of settings), got " +
                                        describeJsonValue(value));
    }
}

shadow::ShadowSettings applyTopLevel(const json& j, shadow::ShadowSettings base) {
    if (!j.is_object()) throw std::invalid_argument(std::string("expected a JSON object, got ") + j.type_name());
    applyObject(base, j, "", 1);
    return base;
}

std::runtime_error fileError(const std::string& path, const std::string& problem) {
    return std::runtime_error("preset " + path + ": " + problem);
}

} // namespace

json settingsToJson(const shadow::ShadowSettings& s) { return toJson(s, json::object()); }

std::vector<std::string> settingAssignments(const json& j) {
    if (!j.is_object()) throw std::invalid_argument(std::string("expected a JSON object, got ") + j.type_name());
    shadow::ShadowSettings checked;
    std::vector<std::string> out;
    applyObject(checked, j, "", 1, &out);
    return out;
}

shadow::ShadowSettings settingsFromJson(const json& j, shadow::ShadowSettings base) {
    try {
        return applyTopLevel(j, std::move(base));
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("preset: ") + e.what());
    }
}

shadow::ShadowSettings loadPreset(const std::string& path, shadow::ShadowSettings base) {
    const json j = geometry::io::readJsonFile(path, "preset " + path, kMaxPresetBytes, kMaxPresetDepth);
    if (!j.is_object())
        throw fileError(path, std::string("expected a JSON object at the top level, got ") + j.type_name());
    try {
        return applyTopLevel(j, std::move(base));
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("preset " + path + ": " + e.what());
    }
}

void savePreset(const std::string& path, const shadow::ShadowSettings& s, std::string_view name,
                std::string_view description) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    if (!name.empty()) j["name"] = std::string(name);
    if (!description.empty()) j["description"] = std::string(description);
    j = toJson(s, std::move(j));
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw fileError(path, std::string("cannot write (") + std::strerror(errno) + ")");
    out << j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << '\n';
    out.close();
    if (!out) throw fileError(path, "cannot write");
}

} // namespace geometry::io
