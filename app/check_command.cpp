// Index
//   [SECTION] Preparing ...... resolvePath, PreparedCase, prepare (everything read before rendering)
//   [SECTION] Goldens ........ checkGolden, updateGolden
//   [SECTION] Cases .......... CaseResults, goldenVerdict, renderCase, judgeCase, writeReports (render all, then judge)
//   [SECTION] The command .... addCheckCommand, runCheck

#include "check_command.h"
#include "app/output_folder.h"

#include "check_file.h"
#include "check_report.h"
#include "golden_image.h"
#include "render_command.h"
#include "render_options.h"
#include "resources.h"
#include "shard.h"

#include "geometry/io/json_file.h"
#include "geometry/io/preset.h"
#include "geometry/io/scene_file.h"
#include "geometry/scene/builtin_scenes.h"

#include <CLI/CLI.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <system_error>

namespace app {

namespace {

namespace fs = std::filesystem;
using geometry::analysis::Image;
using json = nlohmann::json;

/// A check file is a few hundred lines; its deepest legal value is 5 levels down.
constexpr std::size_t kMaxCheckFileBytes = 1u << 20;
constexpr int kMaxCheckFileDepth = 16;

// [SECTION] Preparing

/// A path from the check file: relative to the file's folder; failing that, "resources/REST" is also
/// looked for in this installation's resources (app/resources.h), so a check file kept anywhere can
/// name the shipped scenes and presets. Unchanged when absolute; the folder-relative path when
/// nothing exists, for the error to name.
std::string resolvePath(const fs::path& folder, const std::string& raw) {
    const fs::path p(raw);
    if (p.is_absolute()) return raw;
    std::error_code ec;
    const fs::path local = (folder / p).lexically_normal();
    if (fs::exists(local, ec)) return local.string();
    if (*p.begin() == "resources") {
        const fs::path root = resourceDirectory();
        const fs::path shipped = root / p.lexically_relative("resources");
        if (!root.empty() && fs::exists(shipped, ec)) return shipped.string();
    }
    return local.string();
}

struct PreparedCase {
    const CheckCase* spec = nullptr;
    RenderOptions render;                           // scene resolved; settings: presets, then "set"
    const geometry::io::SceneFile* scene = nullptr; // loaded once per scene, shared by its cases
    // The case's own camera, lights and views (its "camera", "light(s)", "views"), without meshes.
    std::optional<geometry::io::SceneFile> viewpoint;
    std::string golden;               // resolved path; empty without a golden
    std::optional<Image> goldenImage; // the stored golden, when there is one
    bool ownsGolden = false;          // the first case naming it: --update writes it from this one
};

std::string sceneNames(const geometry::io::SceneFile& f) {
    std::string names;
    for (const auto& [name, view] : f.views) names += (names.empty() ? "" : ", ") + name;
    return names.empty() ? "it has none" : "available: " + names;
}

/// The case's scene as its file describes it; a scene that does not load is a bad check file.
geometry::io::SceneFile loadCaseScene(const CheckCase& c, const RenderOptions& r) {
    try {
        return resolveSceneFile(r);
    } catch (const std::exception& e) {
        throw CheckFileError(c.where + ".scene", e.what());
    }
}

/// Resolves and reads everything a case needs (scenes, presets, goldens) and checks its view, so a
/// bad check file fails before anything renders. Throws CheckFileError.
std::vector<PreparedCase> prepare(const CheckFile& file, const fs::path& folder, const CheckOptions& o,
                                  const std::vector<bool>& selected,
                                  std::map<std::string, geometry::io::SceneFile>& scenes) {
    std::vector<PreparedCase> out;
    std::map<std::string, size_t> goldenOwners; // resolved golden path → the first case naming it
    const auto& builtins = geometry::scene::builtinSceneNames();
    for (const CheckCase& c : file.cases) {
        PreparedCase p;
        p.spec = &c;
        if (!selected[out.size()]) { // another shard's: nothing to read
            out.push_back(std::move(p));
            continue;
        }
        RenderOptions& r = p.render;
        r.backend = o.backend;
        r.size = c.size;
        r.view = c.view;
        r.out = (fs::path(o.out) / c.name).string();
        const bool builtin = std::find(builtins.begin(), builtins.end(), c.scene) != builtins.end();
        r.scene = builtin ? c.scene : resolvePath(folder, c.scene);
        std::error_code ec;
        if (!builtin && !fs::exists(r.scene, ec)) {
            std::string list;
            for (const auto& n : builtins) list += (list.empty() ? "" : ", ") + n;
            throw CheckFileError(c.where + ".scene", "'" + c.scene + "' is neither a built-in scene (" + list +
                                                         ") nor a file (no such file: " + r.scene + ")");
        }
        r.up = c.up;
        const std::string key = r.scene + (c.up ? "|up " + std::string(geometry::io::upAxisName(*c.up)) : "");
        auto it = scenes.find(key);
        if (it == scenes.end()) it = scenes.emplace(key, loadCaseScene(c, r)).first;
        p.scene = &it->second;
        if (!c.viewKeys.empty()) p.viewpoint = caseViewpoint(c, *p.scene);
        const geometry::io::SceneFile& views = p.viewpoint ? *p.viewpoint : *p.scene;
        if (!c.view.empty() && !views.views.contains(c.view))
            throw CheckFileError(c.where + ".view",
                                 "scene '" + c.scene + "' has no view '" + c.view + "' (" + sceneNames(views) + ")");
        r.settings = {};
        for (size_t i = 0; i < c.presets.size(); ++i) {
            const std::string where =
                c.where + ".preset" + (c.presets.size() > 1 ? "[" + std::to_string(i) + "]" : std::string());
            try {
                r.settings = geometry::io::loadPreset(resolvePath(folder, c.presets[i]), r.settings);
            } catch (const std::exception& e) { // std::runtime_error (the file) or std::invalid_argument (a setting)
                throw CheckFileError(where, e.what());
            }
        }
        r.settings = applySet(c, r.settings);
        r.settingsGiven = true;
        if (c.golden) {
            p.golden = resolvePath(folder, c.golden->path);
            p.ownsGolden = goldenOwners.emplace(p.golden, out.size()).second;
            if (fs::exists(p.golden, ec)) {
                try {
                    p.goldenImage = geometry::analysis::readImageFile(p.golden);
                } catch (const std::exception& e) {
                    if (!o.update) throw CheckFileError(c.where + ".golden", e.what()); // --update replaces it
                }
            } else if (!o.update) {
                throw CheckFileError(c.where + ".golden",
                                     "no such file: " + p.golden + " (--update writes the render as the golden)");
            }
        }
        out.push_back(std::move(p));
    }
    return out;
}

// [SECTION] Goldens

bool samePath(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

/// DIR/CASE/golden.png, a copy of the golden for the report (unless the golden is kept there).
void copyGolden(const PreparedCase& p, const Image& golden, const fs::path& caseDir, CaseReport& report) {
    const fs::path copy = caseDir / "golden.png";
    if (!samePath(copy, p.golden)) geometry::analysis::writePng(copy.string(), golden);
    report.golden = p.spec->name + "/golden.png";
}

/// The render against the stored golden: DIR/CASE/golden.png (a copy, for the report) and, when the
/// sizes agree, DIR/CASE/diff.png.
Verdict checkGolden(const PreparedCase& p, const Image& golden, const Image& eye, const fs::path& caseDir,
                    CaseReport& report) {
    const GoldenSpec& g = *p.spec->golden;
    const ImageComparison cmp = compareImages(eye, golden, g.channel);
    copyGolden(p, golden, caseDir, report);
    if (cmp.sameSize) {
        geometry::analysis::writePng((caseDir / "diff.png").string(), diffImage(eye, golden, g.channel));
        report.diff = p.spec->name + "/diff.png";
    }
    return {"golden", cmp.passes(g.fraction), comparisonText(g.path, cmp, g.channel, g.fraction)};
}

/// --update: the render becomes the golden (folders created). Prints "golden new|changed|unchanged:
/// PATH"; a changed golden's diff.png shows what changed (every differing pixel).
Verdict updateGolden(const PreparedCase& p, const Image& eye, const fs::path& caseDir, CaseReport& report) {
    const GoldenSpec& g = *p.spec->golden;
    std::error_code ec;
    const bool existed = fs::exists(p.golden, ec);
    std::string state = existed ? "changed" : "new";
    if (p.goldenImage) {
        const ImageComparison cmp = compareImages(eye, *p.goldenImage, 0);
        if (cmp.sameSize && cmp.differing == 0) state = "unchanged";
        else if (cmp.sameSize) {
            state += " (" + std::to_string(cmp.differing) + " of " + std::to_string(cmp.pixels) + " pixels)";
            geometry::analysis::writePng((caseDir / "diff.png").string(), diffImage(eye, *p.goldenImage, 0));
            report.diff = p.spec->name + "/diff.png";
        } else {
            state += " (was " + std::to_string(cmp.goldenWidth) + "x" + std::to_string(cmp.goldenHeight) + ")";
        }
    }
    if (!state.starts_with("unchanged")) {
        if (const fs::path parent = fs::path(p.golden).parent_path(); !parent.empty()) {
            fs::create_directories(parent, ec);
            if (ec) throw std::runtime_error("cannot create folder " + parent.string() + ": " + ec.message());
        }
        geometry::analysis::writePng(p.golden, eye);
    }
    copyGolden(p, eye, caseDir, report);
    const std::string word = state.substr(0, state.find(' '));
    std::cout << "golden " << word << ": " << p.golden << (state.size() > word.size() ? state.substr(word.size()) : "")
              << '\n';
    return {"golden", true, "golden " + g.path + ": " + state + (word == "unchanged" ? "" : ", written")};
}

std::vector<std::pair<std::string, std::string>> facts(const CheckCase& c, const RenderOutput& r) {
    std::vector<std::pair<std::string, std::string>> f{{"scene", c.scene}};
    if (!c.view.empty()) f.emplace_back("view", c.view);
    f.emplace_back("size", std::to_string(c.size.width) + "x" + std::to_string(c.size.height));
    std::string presets;
    for (const auto& p : c.presets) presets += (presets.empty() ? "" : ", ") + p;
    if (!presets.empty()) f.emplace_back("preset", presets);
    if (!c.set.empty()) f.emplace_back("set", c.set.dump());
    f.emplace_back("truth", !c.truth ? "off"
                            : c.truthSamples > 1
                                ? "on, " + std::to_string(c.truthSamples * c.truthSamples) + " samples per pixel"
                                : "on");
    if (!c.viewKeys.empty()) f.emplace_back("view keys", c.viewKeys.dump());
    if (c.up) f.emplace_back("up", std::string(geometry::io::upAxisName(*c.up)));
    f.emplace_back("renderer", r.metrics.value("renderer", std::string("?")));
    if (const auto gamma = r.metrics.find("gamma_deg"); gamma != r.metrics.end() && gamma->is_number())
        f.emplace_back("gamma", formatFigure(gamma->get<double>()) + " deg");
    for (const auto& w : r.warnings) f.emplace_back("warning", w);
    return f;
}

// [SECTION] Cases

/// What rendering the cases leaves for judging them, by case index.
struct CaseResults {
    explicit CaseResults(size_t n) : reports(n), metrics(n), rendered(n, nullptr), goldens(n), eyes(n), seconds(n) {}
    std::vector<CaseReport> reports;
    std::vector<json> metrics;
    std::vector<const json*> rendered; // &metrics[i] once case i rendered every figure it names
    std::vector<std::optional<Verdict>> goldens;
    std::vector<std::optional<Image>> eyes; // --update: case i's eye view, until its golden verdict is made
    std::vector<double> seconds;
    // --update: a golden shared by several cases is written from the first of them; the others are
    // compared with what it wrote, as a later run would compare them.
    std::map<std::string, Image> updated;
};

/// A rendered case's golden verdict: --update writes the golden (from the case that owns it) when
/// `write`, else it compares with it.
std::optional<Verdict> goldenVerdict(const PreparedCase& p, const Image& eye, const fs::path& caseDir, bool write,
                                     std::map<std::string, Image>& updated, CaseReport& report) {
    const CheckCase& c = *p.spec;
    if (!c.golden) return std::nullopt;
    if (write && p.ownsGolden) {
        Verdict v = updateGolden(p, eye, caseDir, report);
        updated[p.golden] = eye;
        return v;
    }
    const auto it = updated.find(p.golden);
    const Image* golden = it != updated.end() ? &it->second : p.goldenImage ? &*p.goldenImage : nullptr;
    return golden ? checkGolden(p, *golden, eye, caseDir, report)
                  : Verdict{"golden", false,
                            "golden " + c.golden->path + ": not written (the first case naming it did not render)"};
}

/// Renders case i into OUT/CASE/ with its golden verdict; what fails the case goes to its report's error.
void renderCase(const PreparedCase& p, size_t i, const CheckOptions& o, CaseResults& results) {
    const CheckCase& c = *p.spec;
    CaseReport& report = results.reports[i];
    report.name = c.name;
    const auto start = std::chrono::steady_clock::now();
    const fs::path caseDir = fs::path(o.out) / c.name;
    std::error_code ec;
    for (const char* stale : {"diff.png", "golden.png"}) // of an earlier run, unless it is the golden itself
        if (!samePath(caseDir / stale, p.golden)) fs::remove(caseDir / stale, ec);
    ExportOptions exports;
    exports.truth.enabled = c.truth;
    exports.truth.samples = c.truthSamples;
    if (c.truth) exports.views.push_back("truth");
    try {
        geometry::io::SceneFile scene = *p.scene;
        if (p.viewpoint) {
            scene.scene.camera = p.viewpoint->scene.camera;
            scene.scene.lights = p.viewpoint->scene.lights;
            scene.views = p.viewpoint->views;
        }
        applyView(scene, p.render);
        const RenderOutput out = renderInto(std::move(scene.scene), p.render, exports);
        requireKeys(c, out.metrics); // a figure render does not produce: the check file is wrong
        results.metrics[i] = out.metrics;
        results.rendered[i] = &results.metrics[i];
        report.render = c.name + "/eye.png";
        report.facts = facts(c, out);
        if (o.update && c.golden) results.eyes[i] = out.eye; // updateGoldens decides, once expectations are judged
        else results.goldens[i] = goldenVerdict(p, out.eye, caseDir, false, results.updated, report);
    } catch (const CheckFileError&) {
        throw;                          // the check file is wrong: runCheck stops
    } catch (const std::exception& e) { // GL errors, files that cannot be written: this case fails
        report.error = e.what();
    }
    results.seconds[i] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// --update, once every case has rendered: a case whose expectations pass writes its golden; one
/// whose expectations fail keeps the golden it had (a regression must not become the reference)
/// unless --force, and fails. Cases sharing a golden compare with what its owner left.
void updateGoldens(const CheckFile& file, const std::vector<PreparedCase>& cases, const CheckOptions& o,
                   CaseResults& results) {
    for (size_t i = 0; i < cases.size(); ++i) {
        if (!results.eyes[i]) continue;
        const PreparedCase& p = cases[i];
        const std::vector<Verdict> expectations = evaluateCase(file, i, results.rendered);
        const bool passes =
            std::all_of(expectations.begin(), expectations.end(), [](const Verdict& v) { return v.passed; });
        const fs::path caseDir = fs::path(o.out) / p.spec->name;
        CaseReport& report = results.reports[i];
        if (p.ownsGolden && p.spec->golden && !passes && !o.force) {
            const std::string word = p.goldenImage ? "kept" : "not written";
            std::cout << "golden " << word << ": " << p.golden
                      << " (the case's expectations fail; --update --force writes it)\n";
            results.goldens[i] = Verdict{"golden", false,
                                         "golden " + p.spec->golden->path + ": " + word +
                                             ", as the case's expectations fail (--update --force writes it)"};
        } else {
            results.goldens[i] = goldenVerdict(p, *results.eyes[i], caseDir, true, results.updated, report);
        }
        results.eyes[i].reset();
    }
}

/// Judges case i's expectations, adds its golden verdict and time, and prints what failed.
void judgeCase(const CheckFile& file, size_t i, CaseResults& results) {
    CaseReport& report = results.reports[i];
    if (results.rendered[i]) report.verdicts = evaluateCase(file, i, results.rendered);
    if (results.goldens[i]) report.verdicts.push_back(*results.goldens[i]);
    report.seconds = results.seconds[i];
    if (!report.error.empty())
        std::cerr << "shadowscope: check: " << report.name << ": error: " << report.error << '\n';
    for (const Verdict& v : report.verdicts)
        if (!v.passed) std::cerr << "shadowscope: check: " << report.name << ": " << v.text << '\n';
}

/// The cases this run renders: all, or --shard's share. Cases that must render together share a
/// group: a ratio compares two cases of one run, and a golden several cases name is written by the
/// first of them (--update).
std::vector<bool> selectedCases(const CheckFile& file, const std::optional<Shard>& shard) {
    const size_t n = file.cases.size();
    std::vector<size_t> group(n);
    std::iota(group.begin(), group.end(), size_t(0));
    const std::function<size_t(size_t)> root = [&](size_t i) { return group[i] == i ? i : group[i] = root(group[i]); };
    const auto join = [&](size_t a, size_t b) { group[std::max(root(a), root(b))] = std::min(root(a), root(b)); };
    std::map<std::string, size_t> byGolden;
    for (size_t i = 0; i < n; ++i) {
        const CheckCase& c = file.cases[i];
        for (const Expectation& e : c.expect)
            for (const std::string* name : {&e.bound.minRatioTo, &e.bound.maxRatioTo})
                if (const CheckCase* other = name->empty() ? nullptr : file.find(*name))
                    join(i, size_t(other - file.cases.data()));
        if (c.golden) join(i, byGolden.emplace(c.golden->path, i).first->second);
    }
    for (size_t i = 0; i < n; ++i) group[i] = root(i);
    std::vector<bool> selected(n, true);
    if (!shard) return selected;
    const std::vector<size_t> dealt = dealShards(group, shard->count);
    for (size_t i = 0; i < n; ++i) selected[i] = dealt[i] == shard->index;
    return selected;
}

} // namespace

void writeCheckReports(const std::string& out, const std::string& junit, const CheckRun& run) {
    const fs::path html = fs::path(out) / "report.html";
    writeTextFile(html, htmlReport(run.title, run.reports));
    writeTextFile(fs::path(out) / "results.json", checkRunJson(run).dump(1) + "\n");
    std::cout << summaryTable(run.reports) << "report: " << html.string() << '\n';
    if (!junit.empty()) {
        writeTextFile(junit, junitXml(run.suite, run.reports));
        std::cout << "junit: " << junit << '\n';
    }
}

// [SECTION] The command

void addCheckCommand(CLI::App& cmd, CheckOptions& o) {
    cmd.add_option("file", o.file, "Check file (JSON): the cases, each with its expectations and golden image")
        ->required()
        ->type_name("FILE.json");
    cmd.add_option("--out", o.out, "Output folder: DIR/CASE/ per case (eye.png, metrics.json, diff.png), report.html")
        ->capture_default_str();
    cmd.add_option("--junit", o.junit, "Also write the verdicts as a JUnit XML file")->type_name("FILE.xml");
    CLI::Option* update =
        cmd.add_flag("--update", o.update,
                     "Write each case's eye view as its golden image (new, changed or unchanged is printed) where "
                     "the case's expectations pass; a failing case keeps its golden");
    cmd.add_flag("--force", o.force, "With --update: write the goldens of failing cases too")->needs(update);
    addShardOption(cmd, o.shard, "cases (cases compared with each other or sharing a golden stay together)");
    addBackendOption(cmd, o.backend, false);
}

int runCheck(const CheckOptions& o) {
    const auto fail = [](const std::string& line) {
        std::cerr << "shadowscope: check: " << line << '\n';
        return 2;
    };
    CheckFile file;
    std::vector<PreparedCase> cases;
    std::vector<bool> selected;
    std::map<std::string, geometry::io::SceneFile> scenes;
    try {
        file = parseCheckFile(geometry::io::readJsonFile(o.file, o.file, kMaxCheckFileBytes, kMaxCheckFileDepth));
        selected = selectedCases(file, o.shard);
        cases = prepare(file, fs::path(o.file).parent_path(), o, selected, scenes);
    } catch (const CheckFileError& e) {
        return fail(e.path().empty() ? o.file + ": " + e.what() : e.what());
    } catch (const std::runtime_error& e) { // readJsonFile: "FILE: problem"
        return fail(e.what());
    }

    createOutputFolder(o.out);
    CaseResults results(cases.size());
    for (size_t i = 0; i < cases.size(); ++i) {
        if (!selected[i]) continue;
        try {
            renderCase(cases[i], i, o, results);
        } catch (const CheckFileError& e) {
            return fail(e.what());
        }
    }
    // Ratios compare cases with each other, so expectations are judged once every case has rendered.
    try {
        if (o.update) updateGoldens(file, cases, o, results);
    } catch (const CheckFileError& e) { // a case compared with lacks the figure
        return fail(e.what());
    }
    for (size_t i = 0; i < cases.size(); ++i) {
        if (!selected[i]) continue;
        try {
            judgeCase(file, i, results);
        } catch (const CheckFileError& e) { // a case compared with lacks the figure
            return fail(e.what());
        }
    }

    CheckRun run{fs::path(o.file).stem().string(),
                 "shadowscope check " + fs::path(o.file).filename().string(),
                 cases.size(),
                 {},
                 {}};
    for (size_t i = 0; i < cases.size(); ++i)
        if (selected[i]) {
            run.indices.push_back(i);
            run.reports.push_back(std::move(results.reports[i]));
        }
    if (o.shard)
        std::cout << "shard " << o.shard->text() << ": " << run.reports.size() << " of " << cases.size()
                  << " case(s)\n";
    writeCheckReports(o.out, o.junit, run);
    const std::vector<CaseReport>& reports = run.reports;
    return std::all_of(reports.begin(), reports.end(), [](const CaseReport& r) { return r.passed(); }) ? 0 : 1;
}

} // namespace app
