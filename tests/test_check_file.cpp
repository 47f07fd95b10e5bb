// The check file of `shadowscope check` and its expectations, without rendering (app/check_file.h,
// app/check_expect.h): key paths, bounds and their verdict texts (NaN fails every bound), and a
// one-line error naming the JSON path for each kind of bad file.
#include "app/check_file.h"
#include "app/render_options.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

using app::CheckFileError;
using app::Expectation;
using app::KeyPath;
using json = nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The brief's example: a case bounded absolutely and by its ratio to another case.
json example() {
    return json::parse(R"({ "cases": [
      { "name": "deck-paper", "scene": "resources/scenes/platform.json", "view": "deck", "size": "480x270",
        "preset": "resources/presets/paper.json", "set": { "filter.kernel": 3 }, "truth": true,
        "expect": { "aliasing.p95": { "max": 6 }, "truth.interior_false_shadow": { "max": 0.002 },
                    "timing_ms.frame": { "max_ratio_to": "deck-ssm", "max": 1.3 } },
        "golden": "golden/deck-paper.png", "tolerance": { "channel": 8, "fraction": 0.001 } },
      { "name": "deck-ssm", "scene": "platform", "preset": ["a.json", "b.json"] } ] })");
}

/// The message parseCheckFile throws for `text`, or "" when it parses.
std::string parseError(const std::string& text) {
    try {
        (void)app::parseCheckFile(json::parse(text));
    } catch (const CheckFileError& e) {
        return e.what();
    }
    return "";
}

/// A one-case file with `caseBody` inside the case object (after its name).
std::string oneCase(const std::string& caseBody) {
    return R"({"cases": [{"name": "a", "truth": true)" + (caseBody.empty() ? "" : ", " + caseBody) + "}]}";
}

app::Bound bound(std::optional<double> min, std::optional<double> max, std::string minRatioTo = "",
                 std::string maxRatioTo = "") {
    app::Bound b;
    b.min = min;
    b.max = max;
    b.minRatioTo = std::move(minRatioTo);
    b.maxRatioTo = std::move(maxRatioTo);
    return b;
}

Expectation expectation(const std::string& key, app::Bound b) { return {key, app::parseKeyPath(key), std::move(b)}; }

std::vector<app::Verdict> evaluate(const Expectation& e, double value, double reference = kNaN) {
    return app::evaluate(e, value, [&](const std::string&) { return reference; });
}

} // namespace

TEST(CheckKeyPath, ParsesNamesIndicesAndQuotedNames) {
    EXPECT_EQ(app::parseKeyPath("aliasing.p95"), (KeyPath{{"aliasing", {}}, {"p95", {}}}));
    EXPECT_EQ(app::parseKeyPath("splits[0].truth.false_lit"),
              (KeyPath{{"splits", {}}, {"", 0}, {"truth", {}}, {"false_lit", {}}}));
    EXPECT_EQ(app::parseKeyPath("size[1]"), (KeyPath{{"size", {}}, {"", 1}}));
    EXPECT_EQ(app::parseKeyPath(R"(meshes["deck.stl"].truth)"),
              (KeyPath{{"meshes", {}}, {"deck.stl", {}}, {"truth", {}}}));
    for (const char* bad : {"", ".a", "a.", "a..b", "a[", "a[x]", "a[]", "[0]", "a[0]b", "a]", "a[\"\"]", "a[-1]"})
        EXPECT_THROW((void)app::parseKeyPath(bad), std::invalid_argument) << bad;
}

TEST(CheckKeyPath, FindsValuesAndSaysWhatIsMissing) {
    const json m = json::parse(R"({"aliasing": {"p95": 2.5, "max": 9}, "splits": [{"near": 0.5}],
                                   "n": null, "meshes": {"deck.stl": {"truth": {"edge_error": 0.1}}}})");
    ASSERT_NE(app::findKey(m, app::parseKeyPath("aliasing.p95")), nullptr);
    EXPECT_EQ(*app::findKey(m, app::parseKeyPath("aliasing.p95")), 2.5);
    EXPECT_EQ(*app::findKey(m, app::parseKeyPath("splits[0].near")), 0.5);
    EXPECT_EQ(*app::findKey(m, app::parseKeyPath(R"(meshes["deck.stl"].truth.edge_error)")), 0.1);
    std::string missing;
    EXPECT_EQ(app::findKey(m, app::parseKeyPath("aliasing.p96"), &missing), nullptr);
    EXPECT_EQ(missing, "no 'p96' in aliasing (it has: max, p95)");
    EXPECT_EQ(app::findKey(m, app::parseKeyPath("splits[1].near"), &missing), nullptr);
    EXPECT_EQ(missing, "no element [1] in splits (it has 1)");
    EXPECT_EQ(app::findKey(m, app::parseKeyPath("aliasing[0]"), &missing), nullptr);
    EXPECT_EQ(missing, "aliasing is object, not an array");
    EXPECT_EQ(app::findKey(m, app::parseKeyPath("truth.false_lit"), &missing), nullptr);
    EXPECT_NE(missing.find("no 'truth' in the top level"), std::string::npos) << missing;
}

TEST(CheckKeyPath, NumbersIncludeNaNAndInfinityAsMetricsJsonWritesThem) {
    EXPECT_EQ(app::numericValue(json(3)), 3.0);
    EXPECT_EQ(app::numericValue(json(-0.25)), -0.25);
    EXPECT_TRUE(std::isnan(*app::numericValue(json(nullptr)))); // nlohmann writes NaN as null
    EXPECT_TRUE(std::isnan(*app::numericValue(json(kNaN))));
    EXPECT_EQ(app::numericValue(json("inf")), std::numeric_limits<double>::infinity());
    EXPECT_FALSE(app::numericValue(json(true)));
    EXPECT_FALSE(app::numericValue(json("glispsm")));
    EXPECT_FALSE(app::numericValue(json::object()));
    EXPECT_TRUE(app::needsTruth(app::parseKeyPath("truth.false_shadow")));
    EXPECT_TRUE(app::needsTruth(app::parseKeyPath("splits[1].truth.edge_error")));
    EXPECT_TRUE(app::needsTruth(app::parseKeyPath("meshes.ground.truth.false_lit")));
    EXPECT_FALSE(app::needsTruth(app::parseKeyPath("splits[1].near")));
    EXPECT_FALSE(app::needsTruth(app::parseKeyPath("aliasing.p95")));
}

TEST(CheckBounds, VerdictsNameTheValueAndTheBound) {
    const Expectation p95 = expectation("aliasing.p95", bound({}, 6));
    auto v = evaluate(p95, 7.31);
    ASSERT_EQ(v.size(), 1u);
    EXPECT_FALSE(v[0].passed);
    EXPECT_EQ(v[0].text, "aliasing.p95 = 7.31 > max 6");
    EXPECT_EQ(v[0].what, "aliasing.p95");
    v = evaluate(p95, 6);
    EXPECT_TRUE(v[0].passed);
    EXPECT_EQ(v[0].text, "aliasing.p95 = 6 <= max 6");

    const Expectation both = expectation("truth.false_lit", bound(0.001, 0.002));
    v = evaluate(both, 0.0005);
    ASSERT_EQ(v.size(), 2u);
    EXPECT_FALSE(v[0].passed);
    EXPECT_EQ(v[0].text, "truth.false_lit = 0.0005 < min 0.001");
    EXPECT_TRUE(v[1].passed);
    // A value that differs from the bound never prints as the bound.
    EXPECT_EQ(evaluate(p95, 6.0000001)[0].text, "aliasing.p95 = 6.0000001 > max 6");
}

TEST(CheckBounds, NaNFailsEveryBound) {
    const Expectation both = expectation("aliasing.p95", bound(-1e300, 1e300));
    for (const auto& v : evaluate(both, kNaN)) {
        EXPECT_FALSE(v.passed) << v.text;
        EXPECT_NE(v.text.find("nan is not"), std::string::npos) << v.text;
    }
    // A ratio to a NaN or zero reference fails too (0/0 is NaN, x/0 is inf).
    const Expectation ratio = expectation("timing_ms.frame", bound({}, 1.3, "", "deck-ssm"));
    EXPECT_FALSE(evaluate(ratio, 1.0, kNaN)[0].passed);
    EXPECT_FALSE(evaluate(ratio, 0.0, 0.0)[0].passed);
    EXPECT_FALSE(evaluate(ratio, 1.0, 0.0)[0].passed);
}

TEST(CheckBounds, RatiosDivideByTheOtherCase) {
    const Expectation ratio = expectation("timing_ms.frame", bound({}, 1.3, "", "deck-ssm"));
    std::string asked;
    const auto v = app::evaluate(ratio, 12, [&](const std::string& name) {
        asked = name;
        return 8.0;
    });
    EXPECT_EQ(asked, "deck-ssm");
    ASSERT_EQ(v.size(), 1u);
    EXPECT_FALSE(v[0].passed);
    EXPECT_EQ(v[0].text, "timing_ms.frame / deck-ssm = 1.5 > max 1.3 (12 / 8)");
    EXPECT_TRUE(evaluate(ratio, 10, 8)[0].passed);
    // min bounds the ratio to its own case while max bounds the value.
    const Expectation mixed = expectation("aliasing.p95", bound(0.5, 6, "ssm"));
    const auto w = evaluate(mixed, 4, 10);
    ASSERT_EQ(w.size(), 2u);
    EXPECT_EQ(w[0].text, "aliasing.p95 / ssm = 0.4 < min 0.5 (4 / 10)");
    EXPECT_EQ(w[1].text, "aliasing.p95 = 4 <= max 6");
}

TEST(CheckFile, TheExampleParses) {
    const app::CheckFile f = app::parseCheckFile(example());
    ASSERT_EQ(f.cases.size(), 2u);
    const app::CheckCase& c = f.cases[0];
    EXPECT_EQ(c.where, "cases[0]");
    EXPECT_EQ(c.name, "deck-paper");
    EXPECT_EQ(c.scene, "resources/scenes/platform.json");
    EXPECT_EQ(c.view, "deck");
    EXPECT_EQ(c.size.width, 480);
    EXPECT_EQ(c.size.height, 270);
    EXPECT_EQ(c.presets, std::vector<std::string>{"resources/presets/paper.json"});
    EXPECT_TRUE(c.truth);
    ASSERT_EQ(c.expect.size(), 3u);
    ASSERT_TRUE(c.golden);
    EXPECT_EQ(c.golden->path, "golden/deck-paper.png");
    EXPECT_EQ(c.golden->channel, 8);
    EXPECT_DOUBLE_EQ(c.golden->fraction, 0.001);
    EXPECT_EQ(app::applySet(c, {}).filter.kernel, 3);
    const app::CheckCase& d = f.cases[1];
    EXPECT_EQ(d.presets, (std::vector<std::string>{"a.json", "b.json"}));
    EXPECT_EQ(d.size.width, 1280); // render's default
    EXPECT_FALSE(d.truth);
    EXPECT_FALSE(d.golden);
    EXPECT_EQ(f.find("deck-ssm"), &d);
    EXPECT_EQ(f.find("nope"), nullptr);
}

TEST(CheckFile, EachMistakeIsOneLineNamingItsPath) {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {oneCase(R"("expect": {"aliasing.p95": {"max": "6"}})"),
         "cases[0].expect.aliasing.p95.max: expected a number, got string \"6\""},
        {oneCase(R"("expect": {"aliasing.p95": {"maximum": 6}})"), "cases[0].expect.aliasing.p95.maximum: unknown key"},
        {oneCase(R"("expect": {"aliasing.p95": {}})"), "cases[0].expect.aliasing.p95: expected \"min\" and/or \"max\""},
        {oneCase(R"("expect": {"aliasing.p95": {"min": 3, "max": 2}})"),
         "cases[0].expect.aliasing.p95: min 3 is greater than max 2"},
        {oneCase(R"("expect": {"aliasing..p95": {"max": 1}})"), "cases[0].expect.aliasing..p95: bad key path"},
        {oneCase(R"("expect": {"timing_ms.frame": {"max_ratio_to": "ssm", "max": 1}})"),
         "cases[0].expect.timing_ms.frame.max_ratio_to: no case named 'ssm' (cases: a)"},
        {oneCase(R"("expect": {"timing_ms.frame": {"max_ratio_to": "a", "max": 1}})"),
         "cases[0].expect.timing_ms.frame.max_ratio_to: names its own case"},
        {oneCase(R"("expect": {"timing_ms.frame": {"min_ratio_to": "a"}})"), "cases[0].expect.timing_ms.frame"},
        {oneCase(R"("colour": "red")"), "cases[0].colour: unknown key (known: name, "},
        {oneCase(R"("truth": 1)"), "cases[0].truth: expected true or false, got number 1"},
        {oneCase(R"("size": "160")"), "cases[0].size: expected WxH (e.g. 1280x720), got '160'"},
        {oneCase(R"("size": "0x90")"), "cases[0].size: each side must be within 1..16384"},
        {oneCase(R"("preset": [])"), "cases[0].preset: expected a preset file or a non-empty list"},
        {oneCase(R"("preset": ["a.json", 3])"), "cases[0].preset[1]: expected a string, got number 3"},
        {oneCase(R"("set": {"filter.kernel": "3"})"), "cases[0].set.filter.kernel: expected an integer"},
        {oneCase(R"("set": {"filter.kernel": 4})"), "cases[0].set.filter.kernel: '4' is not valid"},
        {oneCase(R"("set": {"filter.colour": 4})"), "cases[0].set.filter.colour: unknown setting 'filter.colour'"},
        {oneCase(R"("set": {"filter": {"kernel": 3}})"), "cases[0].set.filter: expected a number, string or boolean"},
        {oneCase(R"("tolerance": {"channel": 8})"), "cases[0].tolerance: needs a \"golden\""},
        {oneCase(R"("golden": "g.png", "tolerance": {"channel": 256})"),
         "cases[0].tolerance.channel: expected an integer in 0..255"},
        {oneCase(R"("golden": "g.png", "tolerance": {"fraction": 1.5})"),
         "cases[0].tolerance.fraction: expected a number in 0..1"},
        {oneCase(R"("golden": "")"), "cases[0].golden: expected a non-empty string"},
        {R"({"cases": [{"name": "a", "expect": {"truth.false_shadow": {"max": 0}}}]})",
         "cases[0].expect.truth.false_shadow: metrics.json has this figure only with \"truth\": true"},
        {R"({"cases": [{"name": "a", "truth": true,
                        "expect": {"truth.false_shadow": {"max_ratio_to": "b", "max": 1}}}, {"name": "b"}]})",
         "cases[0].expect.truth.false_shadow.max_ratio_to: case 'b' has no truth.false_shadow without"},
        {R"({"cases": [{"name": "a"}, {"name": "a"}]})", "cases[1].name: duplicate case name 'a' (also cases[0])"},
        {R"({"cases": [{"name": "x/../y"}]})", "cases[0].name: 'x/../y' is not a usable case name"},
        {R"({"cases": [{"name": ".."}]})", "cases[0].name: '..' is not a usable case name"},
        {R"({"cases": [{"scene": "plane"}]})", "cases[0]: a case needs a \"name\""},
        {R"({"cases": []})", "cases: the array is empty"},
        {R"({"cases": {}})", "cases: expected an array of cases, got object"},
        {R"({"case": []})", "case: unknown key (known: description, cases)"},
        {R"([1])", "expected an object, got array"},
    };
    for (const auto& [text, expected] : cases) {
        const std::string message = parseError(text);
        EXPECT_EQ(message.rfind(expected, 0), 0u) << "got: " << message << "\nexpected it to start with: " << expected;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

TEST(CheckFile, MissingFiguresAreReportedWithTheirPath) {
    const app::CheckFile f = app::parseCheckFile(json::parse(R"({"cases": [
        {"name": "a", "expect": {"aliasing.p95": {"max": 6}, "splits[1].near": {"max": 1}}},
        {"name": "b", "expect": {"splits[0].near": {"max_ratio_to": "a", "max": 2}}}]})"));
    const json metrics = json::parse(R"({"aliasing": {"p95": 2}, "splits": [{"near": 0.5}]})");
    try {
        app::requireKeys(f.cases[0], metrics);
        FAIL() << "splits[1] is missing";
    } catch (const CheckFileError& e) {
        EXPECT_EQ(e.path(), "cases[0].expect.splits[1].near");
        EXPECT_EQ(
            std::string(e.what()),
            "cases[0].expect.splits[1].near: metrics.json has no such figure: no element [1] in splits (it has 1)");
    }
    const json notNumber = json::parse(R"({"aliasing": {"p95": "many"}, "splits": [{}, {"near": 1}]})");
    EXPECT_THROW(app::requireKeys(f.cases[0], notNumber), CheckFileError);
    // Case b compares with a's splits[0].near: present, 0.5 × 2 = 1 is the bound.
    const json bMetrics = json::parse(R"({"splits": [{"near": 1.2}]})");
    auto v = app::evaluateCase(f, 1, {&metrics, &bMetrics});
    ASSERT_EQ(v.size(), 1u);
    EXPECT_FALSE(v[0].passed);
    EXPECT_EQ(v[0].text, "splits[0].near / a = 2.4 > max 2 (1.2 / 0.5)");
    // When a did not render, the ratio cannot be met.
    v = app::evaluateCase(f, 1, {nullptr, &bMetrics});
    EXPECT_FALSE(v.at(0).passed);
    // When a lacks the figure, the check file is wrong.
    const json empty = json::object();
    EXPECT_THROW((void)app::evaluateCase(f, 1, {&empty, &bMetrics}), CheckFileError);
}

namespace {

/// A scene without meshes: its camera and sun, and a view "side" with its own camera and light.
geometry::io::SceneFile viewpointScene() {
    geometry::io::SceneFile f;
    f.scene.camera.eye = {0.f, 10.f, 10.f};
    f.scene.camera.fovYDeg = 60.f;
    f.scene.lights = {geometry::scene::Light{{0.f, -1.f, 0.f}}};
    geometry::scene::Camera side;
    side.eye = {10.f, 1.f, 0.f};
    side.target = {0.f, 1.f, 0.f};
    side.fovYDeg = 30.f;
    side.near = 1.f;
    side.far = 50.f;
    f.views["side"] = {side, geometry::scene::Light{{1.f, -1.f, 0.f}}};
    return f;
}

/// What case `caseJson` renders from: its viewpoint over the scene, then its `view` applied, as `check` does.
geometry::scene::Scene renderedViewpoint(const std::string& caseJson) {
    const app::CheckFile file = app::parseCheckFile(json::parse(R"({"cases": [)" + caseJson + "]}"));
    const app::CheckCase& c = file.cases.at(0);
    geometry::io::SceneFile scene = viewpointScene();
    const geometry::io::SceneFile own = app::caseViewpoint(c, scene);
    scene.scene.camera = own.scene.camera;
    scene.scene.lights = own.scene.lights;
    scene.views = own.views;
    app::RenderOptions options;
    options.view = c.view;
    app::applyView(scene, options);
    return scene.scene;
}

} // namespace

// A case's own camera and light are more specific than the view it names: they are read over the
// view's, member by member (the view keeps what the case does not give), never silently dropped.
TEST(CheckFile, TheCaseOwnCameraAndLightOverrideItsNamedView) {
    const geometry::scene::Scene s = renderedViewpoint(
        R"({"name": "a", "view": "side", "camera": {"eye": [5, 5, 5]}, "light": {"direction": [0, -1, 1]}})");
    EXPECT_EQ(s.camera.eye, glm::vec3(5.f, 5.f, 5.f)) << "the case's eye";
    EXPECT_EQ(s.camera.target, glm::vec3(0.f, 1.f, 0.f)) << "the view's target";
    EXPECT_EQ(s.camera.fovYDeg, 30.f) << "the view's fov_y";
    EXPECT_EQ(s.camera.far, 50.f) << "the view's far";
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_NEAR(glm::dot(s.lights[0].l(), glm::normalize(glm::vec3(0.f, -1.f, 1.f))), 1.f, 1e-6f) << "the case's light";

    // A camera alone keeps the view's light; "lights" start from the view's light.
    const geometry::scene::Scene cameraOnly =
        renderedViewpoint(R"({"name": "a", "view": "side", "camera": {"fov_y": 45}})");
    EXPECT_EQ(cameraOnly.camera.eye, glm::vec3(10.f, 1.f, 0.f));
    EXPECT_EQ(cameraOnly.camera.fovYDeg, 45.f);
    EXPECT_NEAR(glm::dot(cameraOnly.lights.at(0).l(), glm::normalize(glm::vec3(1.f, -1.f, 0.f))), 1.f, 1e-6f);
    const geometry::scene::Scene lights =
        renderedViewpoint(R"({"name": "a", "view": "side", "lights": [{"radius": 0.5}, {"direction": [0, 0, -1]}]})");
    ASSERT_EQ(lights.lights.size(), 2u);
    EXPECT_NEAR(glm::dot(lights.lights[0].l(), glm::normalize(glm::vec3(1.f, -1.f, 0.f))), 1.f, 1e-6f);
    EXPECT_EQ(lights.lights[0].radius, 0.5f);
    EXPECT_EQ(lights.camera.eye, glm::vec3(10.f, 1.f, 0.f)) << "no camera of its own: the view's";

    // A view of the case's own "views" starts from the case's camera, as a scene file's views do: it wins.
    const geometry::scene::Scene ownView = renderedViewpoint(
        R"({"name": "a", "view": "mine", "camera": {"eye": [5, 5, 5], "fov_y": 40},
            "views": {"mine": {"camera": {"eye": [1, 2, 3]}}}})");
    EXPECT_EQ(ownView.camera.eye, glm::vec3(1.f, 2.f, 3.f));
    EXPECT_EQ(ownView.camera.fovYDeg, 40.f);
    // Without a view, the case's keys are read over the scene's camera.
    const geometry::scene::Scene noView = renderedViewpoint(R"({"name": "a", "camera": {"fov_y": 20}})");
    EXPECT_EQ(noView.camera.eye, glm::vec3(0.f, 10.f, 10.f));
    EXPECT_EQ(noView.camera.fovYDeg, 20.f);
}
