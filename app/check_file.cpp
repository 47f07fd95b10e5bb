// Index
//   [SECTION] Typed values with JSON paths ... describe, Reader
//   [SECTION] Cases .......................... readBound, readExpect, readGolden, readCase
//   [SECTION] The file ....................... parseCheckFile, cross-case rules
//   [SECTION] Viewpoints ..................... caseViewpoint
//   [SECTION] Settings and figures ........... applySet, requireKeys, evaluateCase

#include "check_file.h"

#include "render_options.h"

#include "geometry/analysis/ground_truth.h"
#include "geometry/io/preset.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <map>

namespace app {

CheckFileError::CheckFileError(std::string path, const std::string& problem)
    : std::invalid_argument(path.empty() ? problem : path + ": " + problem), path_(std::move(path)) {}

const CheckCase* CheckFile::find(const std::string& name) const {
    const auto it = std::find_if(cases.begin(), cases.end(), [&](const CheckCase& c) { return c.name == name; });
    return it == cases.end() ? nullptr : &*it;
}

namespace {

using json = nlohmann::json;

// [SECTION] Typed values with JSON paths

/// A value for an error message: its type, and scalars themselves (shortened).
std::string describe(const json& v) {
    if (v.is_object() || v.is_array() || v.is_null()) return v.type_name();
    std::string text = v.dump(-1, ' ', false, json::error_handler_t::replace);
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return std::string(v.type_name()) + " " + text;
}

std::string member(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

struct Reader {
    [[noreturn]] static void fail(const std::string& path, const std::string& problem) {
        throw CheckFileError(path, problem);
    }
    static void checkObject(const json& v, const std::string& path, std::initializer_list<const char*> known) {
        if (!v.is_object()) fail(path, "expected an object, got " + describe(v));
        for (const auto& item : v.items()) {
            const std::string& key = item.key(); // (not a structured binding: clang 14 cannot capture one)
            if (std::none_of(known.begin(), known.end(), [&](const char* k) { return key == k; })) {
                std::string list;
                for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
                fail(member(path, key), "unknown key (known: " + list + ")");
            }
        }
    }
    static std::string string(const json& v, const std::string& path) {
        if (!v.is_string()) fail(path, "expected a string, got " + describe(v));
        std::string s = v.get<std::string>();
        if (s.empty()) fail(path, "expected a non-empty string");
        return s;
    }
    static double number(const json& v, const std::string& path) {
        if (!v.is_number()) fail(path, "expected a number, got " + describe(v));
        const double d = v.get<double>();
        if (!std::isfinite(d)) fail(path, "expected a finite number, got " + describe(v));
        return d;
    }
    static bool boolean(const json& v, const std::string& path) {
        if (!v.is_boolean()) fail(path, "expected true or false, got " + describe(v));
        return v.get<bool>();
    }
};

// [SECTION] Cases

/// Case names become folder names (DIR/NAME/) and appear in XML and HTML: keep them plain.
void checkName(const std::string& name, const std::string& path) {
    const bool plain = name.size() <= 100 && std::all_of(name.begin(), name.end(), [](char ch) {
                           return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
                                  ch == '.' || ch == '_' || ch == '-';
                       });
    if (!plain || name.front() == '.')
        Reader::fail(path, "'" + name +
                               "' is not a usable case name (letters, digits, '.', '_', '-', not starting with '.', "
                               "at most 100 characters)");
}

Bound readBound(const json& v, const std::string& path) {
    Reader::checkObject(v, path, {"min", "max", "min_ratio_to", "max_ratio_to"});
    Bound b;
    if (v.contains("min")) b.min = Reader::number(v["min"], member(path, "min"));
    if (v.contains("max")) b.max = Reader::number(v["max"], member(path, "max"));
    if (v.contains("min_ratio_to")) b.minRatioTo = Reader::string(v["min_ratio_to"], member(path, "min_ratio_to"));
    if (v.contains("max_ratio_to")) b.maxRatioTo = Reader::string(v["max_ratio_to"], member(path, "max_ratio_to"));
    if (!b.min && !b.max) Reader::fail(path, "expected \"min\" and/or \"max\"");
    if (!b.minRatioTo.empty() && !b.min)
        Reader::fail(member(path, "min_ratio_to"), "needs \"min\" (the bound on the ratio)");
    if (!b.maxRatioTo.empty() && !b.max)
        Reader::fail(member(path, "max_ratio_to"), "needs \"max\" (the bound on the ratio)");
    // Two bounds on the same quantity that nothing can meet are a typo, not a test.
    if (b.min && b.max && b.minRatioTo == b.maxRatioTo && !(*b.min <= *b.max))
        Reader::fail(path, "min " + formatFigure(*b.min) + " is greater than max " + formatFigure(*b.max));
    return b;
}

std::vector<Expectation> readExpect(const json& v, const std::string& path) {
    if (!v.is_object()) Reader::fail(path, "expected an object (key path → bounds), got " + describe(v));
    std::vector<Expectation> out;
    for (const auto& [key, bound] : v.items()) {
        const std::string where = member(path, key);
        Expectation e;
        e.key = key;
        try {
            e.path = parseKeyPath(key);
        } catch (const std::invalid_argument& err) {
            Reader::fail(where, err.what());
        }
        e.bound = readBound(bound, where);
        out.push_back(std::move(e));
    }
    return out;
}

GoldenSpec readGolden(const json& c, const std::string& path) {
    GoldenSpec g;
    g.path = Reader::string(c["golden"], member(path, "golden"));
    if (!c.contains("tolerance")) return g;
    const std::string where = member(path, "tolerance");
    const json& t = c["tolerance"];
    Reader::checkObject(t, where, {"channel", "fraction"});
    if (t.contains("channel")) {
        const json& ch = t["channel"];
        if (!ch.is_number_integer() || ch.get<long long>() < 0 || ch.get<long long>() > 255)
            Reader::fail(member(where, "channel"), "expected an integer in 0..255, got " + describe(ch));
        g.channel = ch.get<int>();
    }
    if (t.contains("fraction")) {
        g.fraction = Reader::number(t["fraction"], member(where, "fraction"));
        if (!(g.fraction >= 0 && g.fraction <= 1))
            Reader::fail(member(where, "fraction"), "expected a number in 0..1, got " + describe(t["fraction"]));
    }
    return g;
}

CheckCase readCase(const json& c, const std::string& path) {
    Reader::checkObject(c, path,
                        {"name", "description", "scene", "view", "size", "preset", "set", "truth", "truth_samples",
                         "expect", "golden", "tolerance", "camera", "light", "lights", "views", "up"});
    CheckCase out;
    out.where = path;
    if (!c.contains("name")) Reader::fail(path, "a case needs a \"name\"");
    out.name = Reader::string(c["name"], member(path, "name"));
    checkName(out.name, member(path, "name"));
    if (c.contains("description")) (void)Reader::string(c["description"], member(path, "description"));
    if (c.contains("scene")) out.scene = Reader::string(c["scene"], member(path, "scene"));
    if (c.contains("view")) out.view = Reader::string(c["view"], member(path, "view"));
    if (c.contains("size")) {
        const std::string where = member(path, "size");
        const std::string text = Reader::string(c["size"], where);
        try {
            out.size = parseSize(text);
        } catch (const std::invalid_argument& e) {
            std::string why = e.what(); // render's message names its option; here the JSON path does
            if (why.starts_with("--size: ")) why.erase(0, 8);
            Reader::fail(where, why);
        }
    }
    if (c.contains("preset")) {
        const std::string where = member(path, "preset");
        const json& p = c["preset"];
        if (p.is_array()) {
            if (p.empty()) Reader::fail(where, "expected a preset file or a non-empty list of them");
            for (size_t i = 0; i < p.size(); ++i)
                out.presets.push_back(Reader::string(p[i], where + "[" + std::to_string(i) + "]"));
        } else {
            out.presets.push_back(Reader::string(p, where));
        }
    }
    if (c.contains("set")) {
        if (!c["set"].is_object()) Reader::fail(member(path, "set"), "expected an object (setting key → value)");
        out.set = c["set"];
        (void)applySet(out, {}); // every key and value valid on its own, before any file is read
    }
    if (c.contains("truth")) out.truth = Reader::boolean(c["truth"], member(path, "truth"));
    if (c.contains("truth_samples")) {
        const std::string where = member(path, "truth_samples");
        const json& n = c["truth_samples"];
        constexpr int kMax = geometry::analysis::GroundTruth::kMaxSamplesPerAxis;
        if (!n.is_number_integer() || n.get<int64_t>() < 1 || n.get<int64_t>() > kMax)
            Reader::fail(where, "expected an integer in 1.." + std::to_string(kMax) +
                                    " (rays per pixel per axis), got " + describe(n));
        if (!out.truth) Reader::fail(where, "needs \"truth\": true");
        out.truthSamples = int(n.get<int64_t>());
    }
    // Camera, light(s) and views are read against the case's scene once it is loaded (check_command.cpp).
    for (const char* key : {"camera", "light", "lights", "views"})
        if (c.contains(key)) out.viewKeys[key] = c[key];
    if (c.contains("up")) {
        const std::string text = Reader::string(c["up"], member(path, "up"));
        out.up = geometry::io::parseUpAxis(text);
        if (!out.up) Reader::fail(member(path, "up"), "expected one of y, z, -y, -z, x, -x, got '" + text + "'");
    }
    if (c.contains("expect")) out.expect = readExpect(c["expect"], member(path, "expect"));
    if (c.contains("golden")) out.golden = readGolden(c, path);
    else if (c.contains("tolerance")) Reader::fail(member(path, "tolerance"), "needs a \"golden\" image to apply to");
    return out;
}

// [SECTION] The file

void checkReference(const CheckFile& file, const CheckCase& c, const Expectation& e, const std::string& name,
                    const char* key) {
    if (name.empty()) return;
    const std::string where = member(member(c.where + ".expect", e.key), key);
    const CheckCase* other = file.find(name);
    if (!other) {
        std::string names;
        for (const auto& k : file.cases) names += (names.empty() ? "" : ", ") + k.name;
        Reader::fail(where, "no case named '" + name + "' (cases: " + names + ")");
    }
    if (other == &c) Reader::fail(where, "names its own case");
    if (needsTruth(e.path) && !other->truth)
        Reader::fail(where, "case '" + name + "' has no " + e.key + " without \"truth\": true");
}

} // namespace

CheckFile parseCheckFile(const json& j) {
    Reader::checkObject(j, "", {"description", "cases"});
    if (j.contains("description")) (void)Reader::string(j["description"], "description");
    if (!j.contains("cases")) Reader::fail("cases", "missing: the file lists its cases in \"cases\": [ ... ]");
    const json& cases = j["cases"];
    if (!cases.is_array()) Reader::fail("cases", "expected an array of cases, got " + describe(cases));
    if (cases.empty()) Reader::fail("cases", "the array is empty: nothing to check");
    CheckFile file;
    std::map<std::string, size_t> seen;
    for (size_t i = 0; i < cases.size(); ++i) {
        const std::string path = "cases[" + std::to_string(i) + "]";
        CheckCase c = readCase(cases[i], path);
        if (const auto [it, added] = seen.emplace(c.name, i); !added)
            Reader::fail(path + ".name",
                         "duplicate case name '" + c.name + "' (also cases[" + std::to_string(it->second) + "])");
        file.cases.push_back(std::move(c));
    }
    // Rules across cases, once all names are known.
    for (const CheckCase& c : file.cases)
        for (const Expectation& e : c.expect) {
            if (needsTruth(e.path) && !c.truth)
                Reader::fail(member(c.where + ".expect", e.key),
                             "metrics.json has this figure only with \"truth\": true in the case");
            checkReference(file, c, e, e.bound.minRatioTo, "min_ratio_to");
            checkReference(file, c, e, e.bound.maxRatioTo, "max_ratio_to");
        }
    return file;
}

// [SECTION] Viewpoints

geometry::io::SceneFile caseViewpoint(const CheckCase& c, const geometry::io::SceneFile& scene) {
    geometry::io::SceneFile own;
    own.scene.camera = scene.scene.camera;
    own.scene.lights = scene.scene.lights;
    own.views = scene.views;
    try {
        geometry::io::applyViewKeys(own, c.viewKeys, c.where);
        // A scene's view named by the case: its camera and light are where the case's own keys start.
        const json* caseViews = c.viewKeys.contains("views") ? &c.viewKeys["views"] : nullptr;
        const bool ownView = caseViews && caseViews->is_object() && caseViews->contains(c.view);
        const auto view = scene.views.find(c.view);
        json keys = json::object();
        for (const char* key : {"camera", "light", "lights"})
            if (c.viewKeys.contains(key)) keys[key] = c.viewKeys[key];
        if (!ownView && view != scene.views.end() && !keys.empty()) {
            geometry::io::SceneFile base;
            base.scene.camera = view->second.camera;
            base.scene.lights = scene.scene.lights;
            if (base.scene.lights.empty()) base.scene.lights.push_back(view->second.light);
            else base.scene.lights[0] = view->second.light;
            geometry::io::applyViewKeys(base, keys, c.where);
            own.scene.camera = base.scene.camera;
            own.scene.lights = base.scene.lights;
            own.views[c.view] = {base.scene.camera, base.scene.lights[0]};
        }
    } catch (const geometry::io::SceneFileError& e) { // "cases[i]: camera.eye: problem"
        throw CheckFileError("", e.what());
    }
    return own;
}

// [SECTION] Settings and figures

geometry::shadow::ShadowSettings applySet(const CheckCase& c, geometry::shadow::ShadowSettings base) {
    for (const auto& [key, value] : c.set.items()) {
        const std::string where = member(c.where + ".set", key);
        if (value.is_object() || value.is_array() || value.is_null())
            Reader::fail(where, "expected a number, string or boolean, got " + describe(value));
        try {
            // One key at a time through the preset reader, so a value is typed exactly as in a preset.
            base = geometry::io::settingsFromJson(json{{key, value}}, base);
        } catch (const std::invalid_argument& e) {
            std::string why = e.what(); // "preset: KEY: problem" or "preset: unknown setting 'KEY' (...)"
            for (const std::string& prefix : {std::string("preset: "), key + ": "})
                if (why.starts_with(prefix)) why.erase(0, prefix.size());
            Reader::fail(where, why);
        }
    }
    return base;
}

void requireKeys(const CheckCase& c, const json& metrics) {
    for (const Expectation& e : c.expect) {
        const std::string where = member(c.where + ".expect", e.key);
        std::string missing;
        const json* v = findKey(metrics, e.path, &missing);
        if (!v) Reader::fail(where, "metrics.json has no such figure: " + missing);
        if (!numericValue(*v)) Reader::fail(where, "metrics.json holds " + describe(*v) + " there, not a number");
    }
}

std::vector<Verdict> evaluateCase(const CheckFile& file, size_t index, const std::vector<const json*>& metrics) {
    const CheckCase& c = file.cases.at(index);
    std::vector<Verdict> out;
    const auto figure = [&](size_t i, const Expectation& e) -> double {
        if (i >= metrics.size() || !metrics[i]) return std::numeric_limits<double>::quiet_NaN();
        std::string missing;
        const json* v = findKey(*metrics[i], e.path, &missing);
        const std::optional<double> n = v ? numericValue(*v) : std::nullopt;
        if (!n) {
            const CheckCase& other = file.cases[i];
            Reader::fail(member(c.where + ".expect", e.key),
                         i == index ? "metrics.json has no such number" + (v ? std::string() : ": " + missing)
                                    : "case '" + other.name + "' to compare with has no such number" +
                                          (v ? std::string() : ": " + missing));
        }
        return *n;
    };
    for (const Expectation& e : c.expect) {
        const double value = figure(index, e);
        const auto reference = [&](const std::string& name) {
            const CheckCase* other = file.find(name);
            return other ? figure(size_t(other - file.cases.data()), e) : std::numeric_limits<double>::quiet_NaN();
        };
        for (Verdict& v : evaluate(e, value, reference)) out.push_back(std::move(v));
    }
    return out;
}

} // namespace app
