// JSON presets: settingsToJson/settingsFromJson round-trip every declared key, the shipped presets
// hold what they promise, bad files give one-line errors, and --preset / --set precedence does not
// depend on the order on the command line.
#include "app/render_options.h"
#include "geometry/io/preset.h"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using geometry::shadow::SettingInfo;
using geometry::shadow::ShadowSettings;
using json = nlohmann::json;
using Kind = SettingInfo::Kind;

namespace {

fs::path testDir() {
    static const fs::path dir = [] {
        // One folder per process: ctest runs each test in its own process, in parallel.
        const fs::path d = fs::temp_directory_path() / ("shadowscope_test_presets_" + std::to_string(::getpid()));
        fs::remove_all(d);
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

std::string writeFile(const std::string& name, const std::string& text) {
    const fs::path path = testDir() / name;
    std::ofstream(path, std::ios::binary) << text;
    return path.string();
}

std::string presetPath(const std::string& name) {
    return std::string(SHADOWSCOPE_SOURCE_DIR) + "/resources/presets/" + name;
}

/// The message of what `f` throws; "" when it does not throw.
std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

std::string loadError(const std::string& path) {
    return errorOf([&] { (void)geometry::io::loadPreset(path); });
}

std::string fromJsonError(const json& j) {
    return errorOf([&] { (void)geometry::io::settingsFromJson(j); });
}

/// The JSON leaf of a dotted key, or nullptr.
const json* leaf(const json& j, std::string_view key) {
    const json* node = &j;
    size_t start = 0;
    while (true) {
        const size_t dot = key.find('.', start);
        const std::string part(key.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start));
        if (!node->is_object() || !node->contains(part)) return nullptr;
        node = &(*node)[part];
        if (dot == std::string_view::npos) return node;
        start = dot + 1;
    }
}

/// Every key at the end of its range away from its default: the maximum (the minimum where the default
/// is the maximum: a flag on by default is turned off), the last choice.
ShadowSettings extremeSettings() {
    const ShadowSettings defaults;
    ShadowSettings s;
    for (const auto& info : geometry::shadow::settingsDeclaration())
        info.set(s, info.get(defaults) == info.max ? info.min : info.max); // the end away from the default
    return s;
}

/// Floats that no short decimal represents, to check no precision is lost on the way.
ShadowSettings awkwardSettings() {
    ShadowSettings s = extremeSettings();
    for (const auto& info : geometry::shadow::settingsDeclaration())
        if (info.kind == Kind::Float) info.set(s, info.min + (info.max - info.min) / 3.0);
    return s;
}

void expectSameSettings(const ShadowSettings& a, const ShadowSettings& b) {
    for (const auto& info : geometry::shadow::settingsDeclaration()) EXPECT_EQ(info.get(a), info.get(b)) << info.key;
}

void parseArgs(CLI::App& cli, std::vector<std::string> args) {
    std::reverse(args.begin(), args.end()); // CLI11 takes the vector last argument first
    cli.parse(args);
}

} // namespace

TEST(Presets, EveryKeyIsPresentWithItsJsonType) {
    const ShadowSettings s = extremeSettings();
    const json j = geometry::io::settingsToJson(s);
    for (const auto& info : geometry::shadow::settingsDeclaration()) {
        const json* v = leaf(j, info.key);
        ASSERT_NE(v, nullptr) << info.key;
        switch (info.kind) {
        case Kind::Int: EXPECT_TRUE(v->is_number_integer()) << info.key; break;
        case Kind::Float: EXPECT_TRUE(v->is_number()) << info.key; break;
        case Kind::Bool: EXPECT_TRUE(v->is_boolean()) << info.key; break;
        case Kind::Choice: EXPECT_EQ(v->get<std::string>(), info.format(s)) << info.key; break;
        }
    }
    EXPECT_EQ(j.at("filter").at("eye_blur").at("iterations"), 8);
    EXPECT_EQ(geometry::io::settingsToJson(ShadowSettings{}).at("bias").at("constant").dump(), "0.05")
        << "floats print short";
}

TEST(Presets, EveryKeyRoundTrips) {
    const ShadowSettings defaults;
    for (const ShadowSettings& s : {extremeSettings(), awkwardSettings()}) {
        for (const auto& info : geometry::shadow::settingsDeclaration())
            EXPECT_NE(info.get(s), info.get(defaults)) << info.key << " should differ from its default";
        expectSameSettings(geometry::io::settingsFromJson(geometry::io::settingsToJson(s)), s);
        expectSameSettings(geometry::io::settingsFromJson(json::parse(geometry::io::settingsToJson(s).dump())), s);
        const std::string path = (testDir() / "roundtrip.json").string();
        geometry::io::savePreset(path, s, "round trip");
        expectSameSettings(geometry::io::loadPreset(path), s);
    }
}

TEST(Presets, SaveWritesPrettyJsonWithNameFirst) {
    const std::string path = (testDir() / "saved.json").string();
    geometry::io::savePreset(path, ShadowSettings{}, "mine", "what it is");
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.rfind("{\n  \"name\": \"mine\",\n  \"description\": \"what it is\",\n  \"technique\"", 0), 0u)
        << text;
    EXPECT_EQ(text.back(), '\n');
    EXPECT_EQ(json::parse(text).at("name"), "mine");
    EXPECT_NE(
        errorOf([] { geometry::io::savePreset("/nonexistent-dir/x.json", ShadowSettings{}); }).find("cannot write"),
        std::string::npos);
}

TEST(Presets, MissingKeysKeepTheBase) {
    ShadowSettings base;
    base.splits.count = 5;
    base.bias.constant = 0.3f;
    const ShadowSettings s = geometry::io::settingsFromJson(json::parse(R"({"warp": {"method": "psm"}})"), base);
    EXPECT_EQ(s.warp.method, geometry::shadow::WarpMethod::Psm);
    EXPECT_EQ(s.splits.count, 5);
    EXPECT_EQ(s.bias.constant, 0.3f);
    const ShadowSettings t =
        geometry::io::loadPreset(writeFile("partial.json", R"({"name": "x", "filter": {"eye_blur": {}}})"), base);
    expectSameSettings(t, base);
}

// Each preset shows its technique as engines ship it (slope-scaled + normal-offset bias, 3×3 PCF);
// paper stays Barroso's recommendation.
TEST(Presets, ShippedPresetsHoldTheirTechnique) {
    using namespace geometry::scene;
    using namespace geometry::shadow;
    using namespace geometry::io;
    const ShadowSettings ssm = geometry::io::loadPreset(presetPath("ssm.json"));
    EXPECT_EQ(ssm.warp.method, WarpMethod::Uniform);
    EXPECT_EQ(ssm.splits.count, 1);
    EXPECT_EQ(ssm.bias.type, BiasType::SlopeNormalOffset);
    EXPECT_EQ(ssm.bias.normalOffset, 1.f);
    EXPECT_EQ(ssm.filter.type, FilterType::Pcf);
    EXPECT_EQ(ssm.filter.kernel, 3);

    const ShadowSettings lispsm = geometry::io::loadPreset(presetPath("lispsm.json"));
    EXPECT_EQ(lispsm.warp.method, WarpMethod::Lispsm);
    EXPECT_EQ(lispsm.splits.count, 1);
    EXPECT_EQ(lispsm.bias.type, BiasType::SlopeNormalOffset);
    EXPECT_EQ(lispsm.bias.normalOffset, 1.f);
    EXPECT_EQ(lispsm.filter.type, FilterType::Pcf);
    EXPECT_EQ(lispsm.filter.kernel, 3);

    const ShadowSettings pssm = geometry::io::loadPreset(presetPath("pssm3.json"));
    EXPECT_EQ(pssm.splits.count, 3);
    EXPECT_EQ(pssm.splits.scheme, SplitScheme::Practical);
    EXPECT_EQ(pssm.splits.lambda, 0.5);
    EXPECT_EQ(pssm.warp.method, WarpMethod::Uniform);
    EXPECT_EQ(pssm.bias.type, BiasType::SlopeNormalOffset);
    EXPECT_EQ(pssm.bias.normalOffset, 1.f);
    EXPECT_EQ(pssm.filter.type, FilterType::Pcf);
    EXPECT_EQ(pssm.filter.kernel, 3);

    const ShadowSettings paper = geometry::io::loadPreset(presetPath("paper.json"));
    EXPECT_EQ(paper.bias.type, BiasType::Constant);
    EXPECT_EQ(paper.warp.method, WarpMethod::Glispsm);
    EXPECT_EQ(paper.splits.count, 2);
    EXPECT_EQ(paper.splits.scheme, SplitScheme::Adaptive);
    EXPECT_EQ(paper.splits.alpha, 2.0);
    EXPECT_EQ(paper.filter.type, FilterType::Pcf);
    EXPECT_EQ(paper.filter.kernel, 5);

    // virtual: the paged map as Unreal Engine 5 ships it, with pssm3's bias and filter (like for like).
    const ShadowSettings paged = geometry::io::loadPreset(presetPath("virtual.json"));
    EXPECT_EQ(paged.technique, Technique::Virtual);
    EXPECT_EQ(paged.virtualMap.size, 16384);
    EXPECT_EQ(paged.virtualMap.pageSize, 128);
    EXPECT_EQ(paged.bias, pssm.bias);
    EXPECT_EQ(paged.filter, pssm.filter);
    EXPECT_TRUE(validate(paged).empty());
}

TEST(Presets, ShippedPresetsAreWhatSavePresetWrites) {
    // Every value a shipped preset holds comes back from savePreset; keys it predates (settings
    // declared since) are written with their defaults, so a new setting needs no preset edits.
    const json defaults = geometry::io::settingsToJson({}).flatten();
    for (const char* name : {"ssm.json", "lispsm.json", "pssm3.json", "paper.json", "virtual.json"}) {
        const json j = json::parse(std::ifstream(presetPath(name), std::ios::binary));
        ASSERT_TRUE(j.at("name").is_string()) << name;
        ASSERT_TRUE(j.at("description").is_string()) << name;
        const std::string again = (testDir() / name).string();
        geometry::io::savePreset(again, geometry::io::loadPreset(presetPath(name)), j.at("name").get<std::string>(),
                                 j.at("description").get<std::string>());
        const json shipped = j.flatten(), written = json::parse(std::ifstream(again, std::ios::binary)).flatten();
        for (const auto& [path, value] : shipped.items()) EXPECT_EQ(written.value(path, json()), value) << name << path;
        for (const auto& [path, value] : written.items()) {
            if (!shipped.contains(path)) {
                EXPECT_EQ(defaults.value(path, json()), value) << name << path;
            }
        }
    }
    EXPECT_NE(json::parse(std::ifstream(presetPath("paper.json"))).at("description").get<std::string>().find("5x5"),
              std::string::npos);
}

TEST(Presets, BadFilesGiveOneLineErrorsNamingTheProblem) {
    const std::string deepArrays = std::string(100000, '[') + std::string(100000, ']');
    std::string deepObjects;
    for (int i = 0; i < 100000; ++i) deepObjects += "{\"a\":";
    deepObjects += "1" + std::string(100000, '}');
    std::string huge = "{\"name\": \"" + std::string(2u << 20, 'x') + "\"}";

    struct Case {
        std::string name, text;
        std::vector<std::string> expected;
    };
    const std::vector<Case> cases = {
        {"empty.json", "", {"file is empty"}},
        {"blank.json", " \n\t ", {"file is empty"}},
        {"brace.json", "{", {"not valid JSON (line 1, column 2)"}},
        {"secondline.json", "{\n  \"splits\": ?\n}", {"not valid JSON (line 2, column 13)"}},
        {"array.json", "[]", {"expected a JSON object at the top level, got array"}},
        {"number.json", "3", {"expected a JSON object at the top level, got number"}},
        {"range.json", R"({"splits": {"count": 99}})", {"splits.count", "'99' is not valid", "1..8"}},
        {"string.json", R"({"splits": {"count": "3"}})", {"splits.count: expected an integer", "got string \"3\""}},
        {"unknown.json", R"({"nope": 1})", {"unknown setting 'nope'", "splits.count"}},
        {"unknown2.json", R"({"splits": {"cuont": 1}})", {"unknown setting 'splits.cuont'"}},
        {"deeparrays.json", deepArrays, {"nested deeper than 8 levels"}},
        {"deepobjects.json", deepObjects, {"nested deeper than 8 levels"}},
        {"huge.json", huge, {"larger than 1 MiB"}},
        {"inf.json", R"({"bias": {"constant": 1e999}})", {"not valid JSON (number overflow", "1e999"}},
        {"kernel.json", R"({"filter": {"kernel": 4}})", {"filter.kernel", "odd 1..9"}},
        {"leafarray.json", R"({"splits": {"count": [3]}})", {"splits.count: expected an integer", "got array"}},
        {"leafobject.json", R"({"splits": {"count": {}}})", {"splits.count: expected an integer", "got object"}},
        {"leafnull.json", R"({"splits": {"count": null}})", {"splits.count: expected an integer", "got null"}},
        {"groupscalar.json", R"({"splits": 3})", {"splits: expected an object"}},
        {"fraction.json", R"({"splits": {"count": 2.5}})", {"splits.count", "'2.5' is not valid"}},
        {"bool.json", R"({"bias": {"linear_z": 1}})", {"bias.linear_z: expected true or false", "got number 1"}},
        {"choice.json", R"({"warp": {"method": "fast"}})", {"warp.method", "'fast' is not valid", "one of uniform"}},
        {"choicetype.json", R"({"warp": {"method": 2}})", {"warp.method: expected a string"}},
        {"floatstring.json", R"({"bias": {"constant": "0.1"}})", {"bias.constant: expected a number"}},
        {"name.json", R"({"name": 3})", {"name: expected a string"}},
        {"trailing.json", R"({"splits": {"count": 2}} x)", {"not valid JSON (line 1, column 26)"}},
        {"badutf8.json", "{\"name\": \"\xff\"}", {"not valid JSON"}},
    };
    for (const Case& c : cases) {
        const std::string path = writeFile(c.name, c.text);
        const std::string message = loadError(path);
        EXPECT_EQ(message.rfind("preset " + path + ": ", 0), 0u) << c.name << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << c.name << ": " << message;
        for (const auto& part : c.expected)
            EXPECT_NE(message.find(part), std::string::npos) << c.name << ": " << message;
    }
    const std::string missing = (testDir() / "missing.json").string();
    EXPECT_EQ(loadError(missing), "preset " + missing + ": no such file");
    EXPECT_EQ(loadError(testDir().string()), "preset " + testDir().string() + ": is a directory");
}

TEST(Presets, JsonErrorsArePrefixedAndMatchSet) {
    ShadowSettings s;
    const std::string setMessage = errorOf([&] { geometry::shadow::applySetting(s, "splits.count", "99"); });
    EXPECT_EQ(fromJsonError(json::parse(R"({"splits": {"count": 99}})")), "preset: " + setMessage);
    EXPECT_EQ(fromJsonError(json::array()), "preset: expected a JSON object, got array");
    EXPECT_EQ(fromJsonError(json::parse(R"({"nope": 1})")).rfind("preset: unknown setting 'nope' (known: ", 0), 0u);

    // Deep trees built in memory are refused at their first unknown level, never walked.
    json deepObject = 1, deepArray = json::array();
    for (int i = 0; i < 100000; ++i) { // moves, not initializer lists: those copy the whole tree
        json object = json::object(), array = json::array();
        object["a"] = std::move(deepObject);
        array.push_back(std::move(deepArray));
        deepObject = std::move(object);
        deepArray = std::move(array);
    }
    EXPECT_EQ(fromJsonError(deepObject).rfind("preset: unknown setting 'a'", 0), 0u);
    json splits = json::object();
    splits["splits"] = std::move(deepArray); // moved: nlohmann copies recursively
    EXPECT_EQ(fromJsonError(splits).rfind("preset: splits: expected an object", 0), 0u);
}

TEST(Presets, SetWinsOverPresetWhateverTheOrder) {
    const std::string paper = presetPath("paper.json");
    const std::vector<std::vector<std::string>> orders = {
        {"--preset", paper, "--set", "splits.count=4", "--shadow-res", "512"},
        {"--set", "splits.count=4", "--shadow-res", "512", "--preset", paper},
        {"--shadow-res", "512", "--set", "splits.count=4", "--preset", paper},
    };
    for (const auto& args : orders) {
        CLI::App cli;
        app::RenderOptions o;
        app::addRenderOptions(cli, o);
        parseArgs(cli, args);
        EXPECT_EQ(o.settings.splits.count, 4) << args[0];
        EXPECT_EQ(o.settings.resolution, 512) << args[0];
        EXPECT_EQ(o.settings.warp.method, geometry::shadow::WarpMethod::Glispsm) << args[0];
        EXPECT_EQ(o.settings.splits.scheme, geometry::shadow::SplitScheme::Adaptive) << args[0];
        EXPECT_EQ(o.settings.filter.type, geometry::shadow::FilterType::Pcf) << args[0];
        EXPECT_EQ(o.settings.filter.kernel, 5) << args[0];
    }
}

TEST(Presets, LaterPresetsAndSetsWin) {
    const std::string partial = writeFile("kernel7.json", R"({"filter": {"kernel": 7}, "splits": {"count": 6}})");
    CLI::App cli;
    app::RenderOptions o;
    app::addRenderOptions(cli, o);
    parseArgs(cli, {"--set", "splits.count=3", "--preset", presetPath("paper.json"), "--set", "splits.count=5",
                    "--preset", partial});
    EXPECT_EQ(o.settings.filter.kernel, 7);                               // the later preset
    EXPECT_EQ(o.settings.filter.type, geometry::shadow::FilterType::Pcf); // the earlier one, not overridden
    EXPECT_EQ(o.settings.splits.count, 5);                                // the last --set
}

TEST(Presets, OptionsOnlyTouchTheirCommand) {
    CLI::App cli;
    cli.require_subcommand(0, 1);
    app::RenderOptions top, render;
    top.settings.splits.count = 7; // a base set before the options are declared survives
    app::addRenderOptions(cli, top);
    app::addRenderOptions(*cli.add_subcommand("render"), render);
    parseArgs(cli, {"render", "--set", "splits.count=4", "--preset", presetPath("lispsm.json")});
    EXPECT_EQ(render.settings.splits.count, 4);
    EXPECT_EQ(render.settings.warp.method, geometry::shadow::WarpMethod::Lispsm);
    EXPECT_EQ(top.settings.splits.count, 7);
    EXPECT_EQ(top.settings.warp.method, ShadowSettings{}.warp.method);
}

TEST(Presets, BadPresetOnTheCommandLineThrows) {
    CLI::App cli;
    app::RenderOptions o;
    app::addRenderOptions(cli, o);
    const std::string bad = writeFile("cli_bad.json", R"({"splits": {"count": 0}})");
    const std::string message = errorOf([&] { parseArgs(cli, {"--set", "splits.count=2", "--preset", bad}); });
    EXPECT_EQ(message.rfind("preset " + bad + ": splits.count", 0), 0u) << message;
}
