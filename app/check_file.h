#pragma once
// The check file of `shadowscope check` (README "check"): the cases to render and what each must
// meet. Parsing and validation are pure (no GL, no files), so every rule is unit-tested; the
// command resolves the paths, loads presets, scenes and goldens, and renders.
//
// Layout (unknown keys are errors, so typos cannot pass):
//   { "description": "...",
//     "cases": [ { "name": "deck-paper",                          (required; letters, digits, . _ -)
//                  "description": "...",
//                  "scene": "platform" | "scenes/x.json" | "model.stl",   (default platform)
//                  "view": "deck",                                (default: the scene's camera)
//                  "size": "480x270",                             (default 1280x720, as render)
//                  "preset": "paper.json" | ["a.json", "b.json"], (applied in order, then "set")
//                  "set": { "filter.kernel": 3 },                 (typed as in a preset)
//                  "truth": true,                                 (ray-traced ground truth)
//                  "expect": { "KEY.PATH": { "min": 0, "max": 6,
//                                            "min_ratio_to": "CASE", "max_ratio_to": "CASE" } },
//                  "golden": "golden/deck-paper.png",
//                  "tolerance": { "channel": 8, "fraction": 0.001 } } ] }
// Errors are CheckFileError, whose message starts with the JSON path of the offending value.
#include "check_expect.h"

#include "geometry/io/scene_file.h"
#include "geometry/io/up_axis.h"
#include "geometry/shadow/settings.h"
#include "geometry/shadow/shadow_plan.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace app {

/// A bad check file: what() is "PATH: problem", e.g. "cases[0].expect.aliasing.p95.max: expected a number",
/// or just the problem when it concerns the whole file (path empty).
class CheckFileError : public std::invalid_argument {
public:
    CheckFileError(std::string path, const std::string& problem);
    [[nodiscard]] const std::string& path() const noexcept { return path_; }

private:
    std::string path_;
};

struct GoldenSpec {
    std::string path;    // as written: relative to the check file's folder
    int channel = 0;     // a pixel differs when a channel differs by more than this
    double fraction = 0; // the case fails when more than this fraction of pixels differ
};

struct CheckCase {
    std::string where; // its JSON path, "cases[3]"
    std::string name;
    std::string scene = "platform"; // a built-in name, or a path relative to the check file's folder
    std::string view;
    geometry::shadow::Viewport size;
    std::vector<std::string> presets;              // paths as written
    nlohmann::json set = nlohmann::json::object(); // setting key → JSON value
    bool truth = false;
    int truthSamples = 1; // per axis: N × N rays per pixel
    // The case's own "camera", "light" or "lights" and "views", as written: read against its scene by
    // geometry::io::applyViewKeys (the scene file's rules), before anything renders.
    nlohmann::json viewKeys = nlohmann::json::object();
    std::optional<geometry::io::UpAxis> up; // a model file's up axis; empty: its format's
    std::vector<Expectation> expect;
    std::optional<GoldenSpec> golden;
};

struct CheckFile {
    std::vector<CheckCase> cases;
    /// The case called `name`, or nullptr.
    [[nodiscard]] const CheckCase* find(const std::string& name) const;
};

/// The check file's content, validated as far as it can be without files: types, unknown keys,
/// case names (unique, usable as folder names), sizes, setting keys and values, key path syntax,
/// ratio cases that exist (and are not the case itself), min <= max, truth figures in cases without
/// truth. Throws CheckFileError.
[[nodiscard]] CheckFile parseCheckFile(const nlohmann::json& j);

/// The scene's camera, lights and views with the case's own "camera", "light"/"lights" and "views" read
/// on top by the scene file's rules (no meshes: they stay shared). When the case's `view` names one of
/// the scene's views (not one of its own "views", which already start from its camera and light), the
/// case's camera and light(s) are read over that view's instead of the scene's, member by member, and
/// the view is replaced by the result: the case's own keys are the more specific, so rendering with
/// `view` (applyView) keeps them. Throws CheckFileError.
[[nodiscard]] geometry::io::SceneFile caseViewpoint(const CheckCase& c, const geometry::io::SceneFile& scene);

/// `base` with the case's "set" applied (after its presets). Throws CheckFileError naming the key.
[[nodiscard]] geometry::shadow::ShadowSettings applySet(const CheckCase& c, geometry::shadow::ShadowSettings base);

/// Throws CheckFileError (path: the expectation's key) when `metrics` lacks a key the case
/// expects, or holds something other than a number there: the check file asks for a figure that
/// render does not produce.
void requireKeys(const CheckCase& c, const nlohmann::json& metrics);

/// Every verdict of case `index`'s expectations, in file order. `metrics[i]` is case i's
/// metrics.json (nullptr when it did not render: ratios to it fail). Throws CheckFileError when a
/// case compared with lacks the key.
[[nodiscard]] std::vector<Verdict> evaluateCase(const CheckFile& file, size_t index,
                                                const std::vector<const nlohmann::json*>& metrics);

} // namespace app
