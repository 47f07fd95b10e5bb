// End-to-end tests of the GUI: the real shadowscope window on an Xvfb server, driven with xdotool
// (mouse and keyboard through the X server, like a user) at the widget rectangles the app publishes
// with SHADOWSCOPE_WIDGET_MAP. The tests assert on the screenshots' pixels, the status line, the
// saved config and the process staying alive.
//
// Needs Xvfb and xdotool (scripts/setup installs them); without them the tests fail, unless
// SHADOWSCOPE_SKIP_GUI_TESTS=1 (then they are skipped). A failing test keeps its temp folder
// (app stdout/stderr, Xvfb log, widget map, screenshots) and prints where it is; so does every
// test with SHADOWSCOPE_E2E_KEEP=1. SHADOWSCOPE_E2E_TRACE=1 logs each xdotool command.
//
// Synchronisation: the widget map is rewritten every frame, and with the hook set the app runs a
// frame at least every 0.1 s (it otherwise sleeps until input), so "n more frames have run" means
// the map's frame counter passed its last value + 1 (the frame under way may have polled its events
// before the input was sent) + n - 1 (waitFrames). Everything else waits on what the app shows
// (status line, map, pass counters, files), with deadlines.
#include "gui_e2e_util.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <set>
#include <thread>

namespace {

using namespace e2e;
using nlohmann::json;

constexpr int kWidth = 1600, kHeight = 900;
const char* const kShotFiles[] = {"eye.png", "light.png", "heatmap.png", "dashboard.png"};

struct Shots {
    fs::path dir;
    geometry::analysis::Image eye, light, heatmap, dashboard;
};

std::string toString(double v) { return std::to_string(long(std::lround(v))); }

/// The app under test: this build's, or SHADOWSCOPE_E2E_EXE (e.g. a sanitizer build's).
std::string appExe() {
    const char* e = std::getenv("SHADOWSCOPE_E2E_EXE");
    return e && *e ? e : SHADOWSCOPE_EXE;
}

class GuiE2E : public ::testing::Test {
protected:
    void SetUp() override {
        if (const char* skip = std::getenv("SHADOWSCOPE_SKIP_GUI_TESTS"); skip && std::string(skip) == "1")
            GTEST_SKIP() << "SHADOWSCOPE_SKIP_GUI_TESTS=1";
        xvfbExe_ = findOnPath("Xvfb");
        xdotoolExe_ = findOnPath("xdotool");
        if (xvfbExe_.empty() || xdotoolExe_.empty())
            FAIL() << (xvfbExe_.empty() ? "Xvfb" : "xdotool")
                   << " is not installed (not on PATH): the GUI end-to-end tests need Xvfb and xdotool; run "
                      "scripts/setup to install them, or set SHADOWSCOPE_SKIP_GUI_TESTS=1 to skip these tests";
        std::string pattern = (fs::temp_directory_path() / "shadowscope_e2e_XXXXXX").string();
        if (!::mkdtemp(pattern.data())) FAIL() << "mkdtemp failed: " << std::strerror(errno);
        tmp_ = pattern;
        shots_ = tmp_ / "shots";
        configHome_ = tmp_ / "config";
        configFile_ = configHome_ / "shadowscope" / "dashboard.json";
        mapFile_ = tmp_ / "map.json";
        fs::create_directories(configHome_);
        try {
            xvfb_.start(xvfbExe_, tmp_ / "xvfb.log", kWidth, kHeight);
        } catch (const std::exception& e) {
            FAIL() << e.what();
        }
    }

    void TearDown() override {
        app_.stop();
        xvfb_.stop();
        if (tmp_.empty()) return;
        const char* keep = std::getenv("SHADOWSCOPE_E2E_KEEP");
        if (HasFailure() || (keep && std::string(keep) == "1")) {
            std::cerr << "[ e2e ] kept " << tmp_.string() << " (app.out, app.err, xvfb.log, map.json, screenshots)\n";
        } else {
            std::error_code ec;
            fs::remove_all(tmp_, ec);
        }
    }

    // ---- context for failure messages -------------------------------------------------------

    std::string context() {
        std::ostringstream s;
        if (auto m = readWidgetMap(mapFile_))
            s << "status line: \"" << m->status << "\" (map frame " << m->frame << ")\n";
        else s << "no widget map yet\n";
        if (app_.started()) {
            if (!app_.alive()) s << "the app has exited with code " << app_.exitCode() << "\n";
            s << "app stderr (last lines):\n" << lastLines(readText(tmp_ / "app.err"), 15);
        }
        return s.str();
    }
    std::function<std::string()> ctx() {
        return [this] { return context(); };
    }

    void requireAlive(const std::string& when) {
        if (!app_.alive()) throw std::runtime_error("the app is not running (" + when + ")\n" + context());
    }

    // ---- the app ----------------------------------------------------------------------------

    std::vector<std::string> xEnvironment() {
        return environmentWith({{"DISPLAY", xvfb_.display()}, {"WAYLAND_DISPLAY", std::nullopt}});
    }

    void launch() {
        const auto env = environmentWith({{"DISPLAY", xvfb_.display()},
                                          {"WAYLAND_DISPLAY", std::nullopt},
                                          {"XDG_CONFIG_HOME", configHome_.string()},
                                          {"SHADOWSCOPE_WIDGET_MAP", mapFile_.string()}});
        const int out = ::open((tmp_ / "app.out").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        const int err = ::open((tmp_ / "app.err").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        app_.start(appExe(), {"--scene", "plane", "--out", shots_.string()}, env, out, err);
        ::close(out);
        ::close(err);
        long first = -1;
        waitUntil(
            "the app's first frames (the widget map appearing and its frame counter advancing)", scaled(120),
            [&] {
                requireAlive("starting");
                const auto m = readWidgetMap(mapFile_);
                if (!m) return false;
                if (first < 0) first = m->frame;
                return m->frame > first && m->has("screenshot");
            },
            ctx());
        // The window: without a window manager it sits at the screen's origin; read it anyway.
        const RunResult found = xdo({"search", "--sync", "--onlyvisible", "--name", "^shadowscope"}, scaled(60));
        window_ = std::strtoul(found.output.c_str(), nullptr, 10);
        if (window_ == 0) throw std::runtime_error("xdotool found no shadowscope window: " + found.output);
        const std::string geometry = xdo({"getwindowgeometry", std::to_string(window_)}).output;
        const auto pos = geometry.find("Position: ");
        if (pos == std::string::npos) throw std::runtime_error("unexpected getwindowgeometry output: " + geometry);
        std::sscanf(geometry.c_str() + pos, "Position: %d,%d", &originX_, &originY_);
        focus();
        const WidgetMap m = currentMap();
        if (m.width != kWidth || m.height != kHeight)
            throw std::runtime_error("the dashboard is " + std::to_string(m.width) + "x" + std::to_string(m.height) +
                                     ", expected the default " + std::to_string(kWidth) + "x" +
                                     std::to_string(kHeight));
    }

    void focus() { xdo({"windowfocus", "--sync", std::to_string(window_)}, scaled(30)); }

    /// Closes the window like a window manager's close button and waits for a clean exit.
    void closeGracefully() {
        requestWindowClose(xvfb_.display(), window_);
        if (!app_.waitExit(scaled(60)))
            throw std::runtime_error("the app did not exit after WM_DELETE_WINDOW\n" + context());
        if (app_.exitCode() != 0)
            throw std::runtime_error("the app exited with code " + std::to_string(app_.exitCode()) + "\n" + context());
    }

    // ---- xdotool ----------------------------------------------------------------------------

    RunResult xdo(const std::vector<std::string>& args, Seconds timeout = scaled(30), bool mayFail = false) {
        if (trace()) {
            const auto m = readWidgetMap(mapFile_);
            std::cerr << "[ e2e ] " << Seconds(Clock::now() - started_).count() << " s, map frame "
                      << (m ? m->frame : -1) << ": xdotool";
            for (const auto& a : args) std::cerr << ' ' << a;
            std::cerr << '\n';
        }
        RunResult r = runProgram(xdotoolExe_, args, xEnvironment(), timeout);
        if (!mayFail && (r.timedOut || r.exitCode != 0)) {
            std::string cmd = "xdotool";
            for (const auto& a : args) cmd += " " + a;
            throw std::runtime_error(cmd +
                                     (r.timedOut ? " timed out" : " failed (exit " + std::to_string(r.exitCode) + ")") +
                                     ": " + r.output + "\n" + context());
        }
        return r;
    }

    std::string screenX(double x) { return toString(originX_ + x); }
    std::string screenY(double y) { return toString(originY_ + y); }

    // ---- the widget map ---------------------------------------------------------------------

    WidgetMap currentMap() {
        std::optional<WidgetMap> m;
        waitUntil(
            "a readable widget map", scaled(30), [&] { return bool(m = readWidgetMap(mapFile_)); }, ctx());
        return *m;
    }

    /// Waits until the map satisfies `pred` (the app alive throughout).
    WidgetMap waitForMap(const std::string& what, const std::function<bool(const WidgetMap&)>& pred,
                         Seconds timeout = scaled(120)) {
        std::optional<WidgetMap> m;
        waitUntil(
            what, timeout,
            [&] {
                requireAlive("waiting for " + what);
                m = readWidgetMap(mapFile_);
                return m && pred(*m);
            },
            [&] { return (m ? m->describe() + "\n" : std::string()) + context(); });
        return *m;
    }

    /// The dashboard's pass counters: shadow, eye full, eye coarse, inspections.
    static std::array<double, 4> passes(const WidgetMap& m) {
        return {m.counter("passes.shadow"), m.counter("passes.eye_full"), m.counter("passes.eye_coarse"),
                m.counter("passes.inspections")};
    }
    static std::string describePasses(const WidgetMap& m) {
        const auto p = passes(m);
        return std::to_string(long(p[0])) + " shadow, " + std::to_string(long(p[1])) + " full, " +
               std::to_string(long(p[2])) + " coarse, " + std::to_string(long(p[3])) + " inspections";
    }

    /// Waits until the dashboard has settled: full resolution, its statistics in, no pass for 0.5 s.
    WidgetMap settle(const std::string& what) {
        WidgetMap last = currentMap();
        auto since = std::chrono::steady_clock::now();
        return waitForMap("the dashboard to settle " + what, [&](const WidgetMap& m) {
            if (passes(m) != passes(last)) {
                last = m;
                since = std::chrono::steady_clock::now();
                return false;
            }
            return m.counter("coarse") == 0 && m.counter("statistics_pending") == 0 &&
                   m.counter("passes.inspections") >= 1 &&
                   std::chrono::steady_clock::now() - since > std::chrono::milliseconds(500);
        });
    }

    /// Waits until at least `n` frames have started after the call, i.e. have seen the input sent
    /// before it. The map read says frame F finished; frame F + 1 may have polled its events already.
    void waitFrames(int n) {
        const long last = currentMap().frame;
        const long target = last + 1 + n;
        waitForMap(
            std::to_string(n) + " more frames", [&](const WidgetMap& m) { return m.frame >= target; }, scaled(240));
    }

    Rect widget(const std::string& id) {
        return waitForMap("widget " + id + " in the map", [&](const WidgetMap& m) { return m.has(id); }).widgets.at(id);
    }

    void click(const std::string& id) {
        const Rect r = widget(id);
        xdo({"mousemove", screenX(r.cx()), screenY(r.cy()), "click", "1"});
    }

    /// Clicks a text field and waits until it takes the keys (as ctrlClick, up to 3 clicks).
    void clickField(const std::string& id) {
        for (int attempt = 0; attempt < 3; ++attempt) {
            click(id);
            waitFrames(2);
            if (currentMap().counter("text_input") == 1.0) return;
        }
        throw std::runtime_error("a click on " + id + " gave it no keyboard focus\n" + context());
    }

    /// Ctrl+click: turns a slider into a text field. Ctrl stays down until a frame after the click:
    /// ImGui 1.86 reads the modifier from key events, and a release in the same frame would turn
    /// this into a plain click (which sets the slider to the clicked position). Typed keys must not
    /// reach the app before the field is open (WASD would fly the camera), so this waits for it,
    /// clicking again (up to 3 times) where a loaded machine let the click land on a stale position.
    /// `greyed`: the widget takes no input, one click and no field expected.
    void ctrlClick(const std::string& id, bool greyed = false) {
        for (int attempt = 0; attempt < 3; ++attempt) {
            const Rect r = widget(id);
            xdo({"mousemove", screenX(r.cx()), screenY(r.cy()), "keydown", "ctrl", "click", "1"});
            waitFrames(1);
            xdo({"keyup", "ctrl"});
            waitFrames(1);
            if (greyed || currentMap().counter("text_input") == 1.0) return;
        }
        throw std::runtime_error("ctrl+click on " + id + " opened no text field\n" + context());
    }

    /// Holds a key (or chord such as ctrl+a) until a frame has seen it: ImGui 1.86 misses a key
    /// pressed and released between two frames.
    void pressKey(const std::string& key) {
        xdo({"keydown", key});
        waitFrames(1);
        xdo({"keyup", key});
    }

    void typeText(const std::string& text) { xdo({"type", "--delay", "30", "--", text}); }

    /// Scrolls the controls panel (mouse wheel over it) until `id` is fully in its upper part.
    Rect scrollIntoView(const std::string& id) {
        const auto visible = [&](const WidgetMap& m) {
            if (!m.has(id)) return false;
            const Rect& r = m.widgets.at(id);
            return r.y >= 0 && r.y + r.h <= m.height * 0.8;
        };
        const auto scroll = [&](const char* button) {
            // The pointer reaches the panel a frame before the wheel turns: the dashboard routes the
            // wheel by where the pointer was (over the eye view it would dolly the camera).
            xdo({"mousemove", screenX(12), screenY(currentMap().height * 0.5)});
            waitFrames(1);
            const WidgetMap before = currentMap();
            xdo({"click", button});
            // The map changes when the panel scrolls; at either end nothing changes, so also stop once
            // a frame has seen the wheel (as in waitFrames).
            const long seen = before.frame + 2;
            const auto moved = [&](const WidgetMap& m) {
                if (m.widgets.size() != before.widgets.size()) return true;
                for (const auto& [id, r] : m.widgets) {
                    const auto it = before.widgets.find(id);
                    if (it == before.widgets.end() || it->second.y != r.y) return true;
                }
                return false;
            };
            waitForMap("the controls panel to scroll", [&](const WidgetMap& m) { return moved(m) || m.frame >= seen; });
        };
        WidgetMap m = currentMap();
        if (visible(m)) return m.widgets.at(id);
        // To the top first (the screenshot button is the panel's first item), then down.
        for (int i = 0; i < 30 && !(m.has("screenshot") && m.widgets.at("screenshot").y >= 0); ++i) {
            scroll("4");
            m = currentMap();
        }
        for (int i = 0; i < 40; ++i) {
            m = currentMap();
            if (visible(m)) return m.widgets.at(id);
            scroll("5");
        }
        throw std::runtime_error("could not scroll " + id + " into view\n" + m.describe() + "\n" + context());
    }

    /// Opens a settings combo and picks `choice` ("KEY=CHOICE" in the map while it is open).
    void chooseInCombo(const std::string& key, const std::string& choice) {
        scrollIntoView(key);
        click(key);
        const std::string item = key + "=" + choice;
        widget(item);
        click(item);
        waitForMap("the " + key + " combo to close", [&](const WidgetMap& m) { return !m.has(item); });
    }

    // ---- quick hands and drops (issue 32) ----------------------------------------------------

    /// A key held for about 10 ms, as a quick hand does, in one xdotool call (unlike pressKey,
    /// nothing waits for a frame to see it).
    void tapKey(const std::string& key) { xdo({"keydown", key, "sleep", "0.01", "keyup", key}); }

    /// Runs `send` with the app stopped (SIGSTOP, then SIGCONT), so that all it sends reaches the app
    /// between two of its frames, as when one frame takes long on a loaded machine.
    void betweenTwoFrames(const std::function<void()>& send) {
        app_.signal(SIGSTOP);
        try {
            send();
        } catch (...) {
            app_.signal(SIGCONT);
            throw;
        }
        app_.signal(SIGCONT);
    }

    /// A small model at tmp/NAME: a 1 m box on a 6 m ground, 14 triangles facing out.
    fs::path writeModel(const std::string& name) {
        const fs::path path = tmp_ / name;
        writeText(path, "v -3 0 -3\nv 3 0 -3\nv 3 0 3\nv -3 0 3\n"
                        "v -0.5 0 -0.5\nv 0.5 0 -0.5\nv 0.5 0 0.5\nv -0.5 0 0.5\n"
                        "v -0.5 1 -0.5\nv 0.5 1 -0.5\nv 0.5 1 0.5\nv -0.5 1 0.5\n"
                        "f 1 4 3\nf 1 3 2\n"                          // ground, up
                        "f 9 12 11\nf 9 11 10\nf 5 6 7\nf 5 7 8\n"    // top, bottom
                        "f 5 9 10\nf 5 10 6\nf 8 7 11\nf 8 11 12\n"   // -z, +z
                        "f 5 8 12\nf 5 12 9\nf 6 10 11\nf 6 11 7\n"); // -x, +x
        return path;
    }

    /// Drops files onto the window as a file manager does (XDND; tests/xdnd_drop.cpp).
    void dropFiles(const std::vector<fs::path>& files) {
        std::vector<std::string> args{std::to_string(window_)};
        for (const auto& f : files) args.push_back(f.string());
        const RunResult r = runProgram(SHADOWSCOPE_XDND_DROP, args, xEnvironment(), scaled(60));
        if (r.timedOut || r.exitCode != 0)
            throw std::runtime_error(std::string("xdnd_drop ") + (r.timedOut ? "timed out" : "failed") + ": " +
                                     r.output + "\n" + context());
    }

    // ---- config and screenshots -------------------------------------------------------------

    std::optional<json> config() {
        std::error_code ec;
        if (!fs::exists(configFile_, ec)) return std::nullopt;
        json j = json::parse(readText(configFile_), nullptr, false);
        if (j.is_discarded()) return std::nullopt;
        return j;
    }

    std::string configSetting(const std::string& key) {
        const auto c = config();
        if (!c || !c->contains("settings")) return "(no config)";
        const json* v = settingIn((*c)["settings"], key);
        return v ? v->dump() : "(missing)";
    }

    /// Waits until the saved config (written about once a second when something changed) holds
    /// settings.KEY == value.
    void waitForConfig(const std::string& key, const json& value) {
        waitUntil(
            "the config to have " + key + " = " + value.dump(), scaled(60),
            [&] {
                requireAlive("waiting for the config");
                return configSetting(key) == value.dump();
            },
            [&] { return "config has " + key + " = " + configSetting(key) + "\n" + context(); });
    }

    long linesMentioning(const std::string& file, const std::string& needle) {
        const std::string text = readText(tmp_ / file);
        long n = 0;
        for (size_t p = text.find(needle); p != std::string::npos; p = text.find(needle, p + 1)) ++n;
        return n;
    }

    /// F12 (or the button when `button`): waits for the app to print the paths and show
    /// "saved …", checks that every file was written anew and copies them to tmp/NAME.
    Shots screenshot(const std::string& name, bool button = false) {
        const long before = linesMentioning("app.out", "dashboard.png");
        if (button) click("screenshot");
        else xdo({"key", "F12"});
        // Each screenshot goes to a new numbered folder (shots/001, 002, …): the last path printed names it.
        const auto lastFolder = [&] {
            const std::string out = readText(tmp_ / "app.out");
            const size_t end = out.rfind("dashboard.png"), start = out.rfind('\n', end);
            const size_t from = start == std::string::npos ? 0 : start + 1;
            return end == std::string::npos ? std::string() : out.substr(from, end - from); // "…/shots/002/"
        };
        // The map is written once a frame: it must show this save's status, not the one before it (a
        // second screenshot's wait once passed on the first's "saved …/001/" still in the map).
        waitForMap("the screenshot (" + name + ")", [&](const WidgetMap& m) {
            return linesMentioning("app.out", "dashboard.png") > before && m.status.rfind("saved ", 0) == 0 &&
                   m.status.find(lastFolder()) != std::string::npos;
        });
        const fs::path folder = lastFolder();
        Shots s;
        s.dir = tmp_ / name;
        fs::create_directories(s.dir);
        for (const char* f : kShotFiles) {
            if (!fs::exists(folder / f))
                throw std::runtime_error(std::string("the screenshot did not write ") + f + "\n" + context());
            fs::copy_file(folder / f, s.dir / f, fs::copy_options::overwrite_existing);
        }
        s.eye = geometry::analysis::readImageFile((s.dir / "eye.png").string());
        s.light = geometry::analysis::readImageFile((s.dir / "light.png").string());
        s.heatmap = geometry::analysis::readImageFile((s.dir / "heatmap.png").string());
        s.dashboard = geometry::analysis::readImageFile((s.dir / "dashboard.png").string());
        return s;
    }

    /// SHADOWSCOPE_E2E_TRACE=1 logs every xdotool command with the time and map frame.
    static bool trace() {
        const char* t = std::getenv("SHADOWSCOPE_E2E_TRACE");
        return t && std::string(t) == "1";
    }

    Clock::time_point started_ = Clock::now();
    std::string xvfbExe_, xdotoolExe_;
    fs::path tmp_, shots_, configHome_, configFile_, mapFile_;
    Xvfb xvfb_;
    Process app_;
    unsigned long window_ = 0;
    int originX_ = 0, originY_ = 0;
};

std::array<int, 4> pixelRect(const Rect& r) {
    return {int(std::lround(r.x)), int(std::lround(r.y)), int(std::lround(r.w)), int(std::lround(r.h))};
}

// Changing warp.method re-warps the light's view; changing the filter changes only the eye view.
TEST_F(GuiE2E, DrivenSettingsChangeScreenshotsAsPredicted) {
    launch();
    const Shots base = screenshot("base");
    EXPECT_EQ(base.dashboard.width, kWidth);
    EXPECT_EQ(base.dashboard.height, kHeight);

    chooseInCombo("warp.method", "lispsm");
    waitForConfig("warp.method", "lispsm");
    const Shots lispsm = screenshot("lispsm");
    const ImageDiff lightChange = diffImages(base.light, lispsm.light);
    std::cout << "[ e2e ] light view uniform -> lispsm: " << lightChange.describe() << '\n';
    EXPECT_GT(lightChange.fraction(), 0.05) << "the warp should change the light view: " << lightChange.describe();
    const ImageDiff eyeSame = diffImages(base.eye, lispsm.eye);
    std::cout << "[ e2e ] eye view uniform -> lispsm: " << eyeSame.describe() << '\n';

    // Under hw2x2 the kernel does nothing: its slider is greyed and takes no typed value.
    scrollIntoView("filter.kernel");
    ctrlClick("filter.kernel", /*greyed=*/true);
    typeText("5");
    pressKey("Return");
    chooseInCombo("filter.type", "pcf");
    waitForConfig("filter.type", "pcf");
    EXPECT_EQ(configSetting("filter.kernel"), "3") << "a greyed setting was edited\n" << context();
    scrollIntoView("filter.kernel");
    ctrlClick("filter.kernel");
    typeText("7");
    pressKey("Return");
    waitForConfig("filter.kernel", 7);
    EXPECT_EQ(currentMap().status.find("refused"), std::string::npos) << context();
    const Shots pcf = screenshot("pcf7");
    const ImageDiff eyeChange = diffImages(lispsm.eye, pcf.eye);
    const ImageDiff lightSame = diffImages(lispsm.light, pcf.light);
    std::cout << "[ e2e ] eye view hw2x2 -> pcf 7x7: " << eyeChange.describe() << '\n';
    std::cout << "[ e2e ] light view hw2x2 -> pcf 7x7: " << lightSame.describe() << '\n';
    EXPECT_GT(eyeChange.differing, 500) << "PCF 7x7 should soften the shadow edges: " << eyeChange.describe();
    EXPECT_EQ(lightSame.differing, 0) << "filtering must not change the shadow map: " << lightSame.describe();

    // A change just before closing: saved by the exit, not by the once-a-second save.
    chooseInCombo("warp.direction", "middle");
    closeGracefully();
    const auto saved = config();
    ASSERT_TRUE(saved) << "no config at " << configFile_;
    EXPECT_EQ(configSetting("warp.method"), "\"lispsm\"");
    EXPECT_EQ(configSetting("filter.type"), "\"pcf\"");
    EXPECT_EQ(configSetting("filter.kernel"), "7");
    EXPECT_EQ(configSetting("warp.direction"), "\"middle\"");
}

// Degenerate window sizes, unmapping, invalid typed values and a missing scene file: the app
// stays up, keeps its state and still takes screenshots.
TEST_F(GuiE2E, SurvivesAbuse) {
    launch();
    const Shots base = screenshot("base");
    const std::string wid = std::to_string(window_);

    // 1x1. X has no 0x0 windows; xdotool takes a 0 as "keep that side", so 0 0 is tried but changes nothing.
    xdo({"windowsize", wid, "1", "1"});
    waitForMap("a 1x1 dashboard", [](const WidgetMap& m) { return m.width == 1 && m.height == 1; });
    const Shots tiny = screenshot("tiny");
    EXPECT_EQ(tiny.dashboard.width, 1);
    EXPECT_EQ(tiny.dashboard.height, 1);
    const RunResult zero = xdo({"windowsize", wid, "0", "0"}, scaled(30), /*mayFail=*/true);
    std::cout << "[ e2e ] xdotool windowsize 0 0: exit " << zero.exitCode << " " << zero.output << '\n';
    requireAlive("after a 0x0 resize request");
    xdo({"windowsize", wid, std::to_string(kWidth), std::to_string(kHeight)});
    waitForMap("the dashboard back at full size",
               [](const WidgetMap& m) { return m.width == kWidth && m.height == kHeight; });
    const Shots restored = screenshot("restored");
    EXPECT_EQ(restored.dashboard.width, kWidth);
    EXPECT_EQ(restored.dashboard.height, kHeight);
    const ImageDiff afterResize = diffImages(base.eye, restored.eye);
    std::cout << "[ e2e ] eye view before vs after the 1x1 round trip: " << afterResize.describe() << '\n';
    EXPECT_EQ(afterResize.differing, 0) << afterResize.describe();

    // Unmap and map again (the nearest to minimise/restore without a window manager).
    xdo({"windowunmap", "--sync", wid});
    waitFrames(1);
    requireAlive("while unmapped");
    xdo({"windowmap", "--sync", wid});
    focus();
    screenshot("remapped");
    // (No windowminimize: without a window manager nothing can de-iconify the window again, and a
    // minimised dashboard rightly draws nothing; unmap and map above is what Xvfb can test.)

    // An out-of-range resolution: refused, the old value stays. "-999999" is out of range at every
    // prefix ("-", "-9", "-99", …), so the outcome does not depend on how the typing splits into frames.
    scrollIntoView("shadow_map.resolution");
    ctrlClick("shadow_map.resolution");
    typeText("-999999");
    pressKey("Return");
    const WidgetMap refused = waitForMap("the refusal in the status line", [](const WidgetMap& m) {
        return m.status.find("shadow_map.resolution") != std::string::npos &&
               m.status.find("refused") != std::string::npos;
    });
    EXPECT_NE(refused.status.find("kept 2048"), std::string::npos) << refused.status;
    screenshot("after_refusal"); // the status line now says "saved …"

    // Letters into a numeric field: the field takes digits only, nothing changes.
    ctrlClick("shadow_map.resolution");
    typeText("abc");
    pressKey("Return"); // a frame has run since the letters were typed
    const WidgetMap afterLetters = currentMap();
    EXPECT_EQ(afterLetters.status.rfind("saved ", 0), 0u) << "status: " << afterLetters.status;

    // A scene file that does not exist: the previous scene stays and keeps rendering.
    const std::string missing = (tmp_ / "no_such_scene.obj").string();
    scrollIntoView("scene.file");
    clickField("scene.file");
    pressKey("ctrl+a");
    typeText(missing);
    click("scene.load");
    const WidgetMap notLoaded = waitForMap("the failed scene load in the status line", [](const WidgetMap& m) {
        return m.status.find("scene not loaded (the previous one stays)") != std::string::npos;
    });
    EXPECT_NE(notLoaded.status.find("no_such_scene.obj"), std::string::npos) << notLoaded.status;
    const Shots afterLoad = screenshot("after_failed_load");
    const ImageDiff sameScene = diffImages(base.eye, afterLoad.eye);
    std::cout << "[ e2e ] eye view after the abuse vs the start: " << sameScene.describe() << '\n';
    EXPECT_EQ(sameScene.differing, 0) << "same scene, camera and settings: " << sameScene.describe();

    closeGracefully();
    EXPECT_EQ(configSetting("shadow_map.resolution"), "2048");
}

// A corrupt config file is reported and ignored; the app starts with defaults and works.
TEST_F(GuiE2E, CorruptConfigIsIgnored) {
    fs::create_directories(configFile_.parent_path());
    std::string garbage = "{\"settings\": {\"warp\": [1, 2,, \xff\xfe garbage";
    garbage.push_back('\0');
    garbage += "\n\x01\x02 not json at all }}}";
    writeText(configFile_, garbage);
    launch();
    waitUntil(
        "the app to report the config on stderr", scaled(30),
        [&] { return readText(tmp_ / "app.err").find("ignored the config file") != std::string::npos; }, ctx());
    EXPECT_NE(currentMap().status.find("ignored the config file"), std::string::npos) << context();
    const Shots shots = screenshot("corrupt_config", /*button=*/true);
    EXPECT_EQ(shots.dashboard.width, kWidth);
    EXPECT_EQ(shots.dashboard.height, kHeight);
    closeGracefully();
    // The defaults it ran with replace the corrupt file, which is kept beside it.
    EXPECT_TRUE(fs::exists(configFile_.string() + ".bad"));
    const auto saved = config();
    ASSERT_TRUE(saved) << "the config was not rewritten: " << readText(configFile_);
    EXPECT_EQ(configSetting("warp.method"), "\"uniform\"");
}

// Drawing only what changed (issue 18), counted by the passes the dashboard publishes in the
// widget map: hovering for 2 s draws nothing; a slider change draws one refinement sequence (coarse
// frames while it moves, then exactly one full frame); Reset camera restores the view pixel for
// pixel; a near/far edit changes the heatmap.
TEST_F(GuiE2E, DrawsOnlyWhatChanged) {
    launch();
    xdo({"mousemove", screenX(5), screenY(kHeight - 5)});
    const WidgetMap start = settle("after start-up");
    ASSERT_GE(start.counter("passes.eye_full"), 1) << start.describe();
    const Shots base = screenshot("base");

    // Hover over the eye view, moving, for 2 s.
    const Rect eye = start.widgets.at("eye_image");
    const WidgetMap beforeHover = currentMap();
    for (int i = 0; i < 20; ++i) {
        xdo({"mousemove", screenX(eye.x + eye.w * 0.3 + 8 * i), screenY(eye.cy())});
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    waitFrames(2);
    const WidgetMap afterHover = currentMap();
    std::cout << "[ e2e ] hover 2 s: " << describePasses(beforeHover) << " -> " << describePasses(afterHover) << '\n';
    EXPECT_EQ(passes(afterHover), passes(beforeHover)) << "hovering must draw no pass";

    // A slider dragged in one gesture: at most coarse frames while it moves, then one full frame.
    // One step per frame: ImGui 1.86 keeps only the latest mouse state of a frame, so a press, moves
    // and release that all arrive while the app sleeps or lags would be no drag at all.
    const Rect az = scrollIntoView("sun.azimuth");
    xdo({"mousemove", screenX(az.x + az.w * 0.5), screenY(az.cy()), "mousedown", "1"});
    waitFrames(1);
    for (const double t : {0.55, 0.6, 0.65}) {
        xdo({"mousemove", screenX(az.x + az.w * t), screenY(az.cy())});
        waitFrames(1);
    }
    xdo({"mouseup", "1"});
    const WidgetMap beforeSlider = afterHover;
    const WidgetMap afterSlider = settle("after the slider");
    std::cout << "[ e2e ] slider drag: " << describePasses(beforeSlider) << " -> " << describePasses(afterSlider)
              << '\n';
    // Exactly one full frame when the drag's steps come in consecutive frames; a slow frame (the
    // sanitizer build on a loaded machine) can make a step arrive after kRefinePause, and the pause
    // is refined as designed. What must hold either way: the last value is drawn at full resolution,
    // and every full frame refines coarse ones (a dashboard redrawing every frame draws no coarse
    // frames). tests/test_dashboard_interaction.cpp checks the exact sequence, driving the frames.
    const double fullAdded = afterSlider.counter("passes.eye_full") - beforeSlider.counter("passes.eye_full");
    const double coarseAdded = afterSlider.counter("passes.eye_coarse") - beforeSlider.counter("passes.eye_coarse");
    EXPECT_GE(fullAdded, 1.0) << "the slider's last value drawn at full resolution";
    EXPECT_GE(coarseAdded, 1.0) << "the drag drew coarse frames";
    EXPECT_LE(fullAdded, coarseAdded) << "each full frame refines coarse ones";
    EXPECT_GT(afterSlider.counter("passes.shadow"), beforeSlider.counter("passes.shadow")) << "the sun moved";

    xdo({"mousemove", screenX(5), screenY(kHeight - 5)});
    const Shots home = screenshot("home");

    // Orbit, then Reset camera: the views are those from before the orbit again.
    // (One step per frame: ImGui sees a press and release within one frame as a click, not a drag.)
    xdo({"mousemove", screenX(eye.cx()), screenY(eye.cy()), "mousedown", "1"});
    waitFrames(1);
    for (int dx : {20, 40, 60, 80}) {
        xdo({"mousemove", screenX(eye.cx() + dx), screenY(eye.cy() + dx / 8)});
        waitFrames(1);
    }
    xdo({"mouseup", "1"});
    settle("after the orbit");
    xdo({"mousemove", screenX(5), screenY(kHeight - 5)});
    const Shots orbited = screenshot("orbited");
    const ImageDiff moved = diffImages(home.eye, orbited.eye);
    std::cout << "[ e2e ] eye view after the orbit: " << moved.describe() << '\n';
    EXPECT_GT(moved.fraction(), 0.05) << moved.describe();
    scrollIntoView("camera.reset");
    click("camera.reset");
    settle("after Reset camera");
    xdo({"mousemove", screenX(5), screenY(kHeight - 5)});
    const Shots reset = screenshot("reset");
    const ImageDiff back = diffImages(home.eye, reset.eye);
    std::cout << "[ e2e ] eye view after Reset camera vs before the orbit: " << back.describe() << '\n';
    EXPECT_EQ(back.differing, 0) << back.describe();

    // near, far: type a new near into the first field; the heatmap (statistics of the new frusta) follows.
    const Rect nearFar = scrollIntoView("camera.near_far");
    xdo({"mousemove", screenX(nearFar.x + nearFar.w * 0.15), screenY(nearFar.cy()), "click", "1"});
    waitFrames(1);
    pressKey("ctrl+a");
    typeText("3");
    pressKey("Return");
    settle("after the near/far edit");
    xdo({"mousemove", screenX(5), screenY(kHeight - 5)});
    const Shots edited = screenshot("near_far");
    const ImageDiff heat = diffImages(reset.heatmap, edited.heatmap);
    std::cout << "[ e2e ] heatmap after near = 3: " << heat.describe() << '\n';
    EXPECT_GT(heat.fraction(), 0.01) << "the heatmap should follow the new near plane: " << heat.describe();
    EXPECT_EQ(currentMap().status.find("refused"), std::string::npos) << context();
    closeGracefully();
}

// The GUI and `shadowscope render --views dashboard` draw the same views with the same pixels.
TEST_F(GuiE2E, SamePixelsAsHeadless) {
    launch();
    // The cursor on the status bar: no hover highlight over the views. (The frame that sees F12
    // also sees the pointer there: X delivers the events in order.) The statistics behind the
    // heatmap come from a worker thread: wait for them, as the headless render does.
    xdo({"mousemove", screenX(5), screenY(kHeight - 5)});
    settle("before the screenshot");
    const Shots gui = screenshot("gui");
    const WidgetMap m = currentMap();
    const fs::path headlessDir = tmp_ / "headless";
    const RunResult r = runProgram(
        appExe(),
        {"render", "--scene", "plane", "--views", "dashboard", "--size",
         std::to_string(kWidth) + "x" + std::to_string(kHeight), "--backend", "osmesa", "--out", headlessDir.string()},
        environmentWith(
            {{"DISPLAY", std::nullopt}, {"WAYLAND_DISPLAY", std::nullopt}, {"SHADOWSCOPE_WIDGET_MAP", std::nullopt}}),
        scaled(300));
    ASSERT_FALSE(r.timedOut) << r.output;
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const geometry::analysis::Image headless =
        geometry::analysis::readImageFile((headlessDir / "dashboard.png").string());
    ASSERT_EQ(headless.width, kWidth);
    ASSERT_EQ(headless.height, kHeight);
    for (const char* id : {"eye_image", "light_image", "heatmap_image"}) {
        ASSERT_TRUE(m.has(id)) << m.describe();
        const std::array<int, 4> area = pixelRect(m.widgets.at(id));
        const ImageDiff d = diffImages(gui.dashboard, headless, area);
        std::cout << "[ e2e ] GUI vs headless " << id << " (" << area[0] << "," << area[1] << " " << area[2] << "x"
                  << area[3] << "): " << d.describe() << '\n';
        if (std::string(id) == "heatmap_image") {
            // Computed on the CPU from the GL inspection pass: a few pixels differ by one level.
            EXPECT_LE(d.maxAbs, 2) << id << ": " << d.describe();
            EXPECT_LT(d.fraction(), 0.001) << id << ": " << d.describe();
        } else {
            EXPECT_EQ(d.differing, 0) << id << ": " << d.describe();
        }
    }
    const ImageDiff whole = diffImages(gui.dashboard, headless);
    std::cout << "[ e2e ] GUI vs headless, whole dashboard: " << whole.describe() << '\n';
    // The controls panel (left of the eye panel, above the status bar): same layout and text. Its
    // translucent background shows the clear colour beneath, which differs by a level or two.
    const Rect eye = m.widgets.at("eye_image");
    const std::array<int, 4> controls{0, 0, int(eye.x) - 14, kHeight - 22};
    const ImageDiff panel = diffImages(gui.dashboard, headless, controls);
    std::cout << "[ e2e ] GUI vs headless, controls panel: " << panel.describe() << '\n';
    EXPECT_LE(panel.maxAbs, 2) << "the controls panel should look the same: " << panel.describe();
}

// Issue 32: input that reaches the window between two frames reaches ImGui. Each gesture below has
// about 10 ms between press and release, as a quick hand makes them, and is sent while the app is
// stopped (betweenTwoFrames), so that it all arrives between two frames whatever the machine's
// load. ImGui 1.86 sees one state per frame: before the input queue (ui/input_queue.h) each of
// these tests failed. They wait on the effect (config, status line, widgets), never on a number of
// frames: the queue feeds the events a frame at a time, how many frames depends on the split.

// Return held for 10 ms right after typing into a ctrl+clicked slider applies the typed value.
TEST_F(GuiE2E, QuickReturnAfterTypingAppliesTheValue) {
    launch();
    scrollIntoView("shadow_map.resolution");
    ctrlClick("shadow_map.resolution");
    betweenTwoFrames([&] {
        typeText("1024");
        tapKey("Return");
    });
    waitForConfig("shadow_map.resolution", 1024);
    const WidgetMap closed =
        waitForMap("the text field to close", [](const WidgetMap& m) { return m.counter("text_input") == 0.0; });
    EXPECT_EQ(closed.status.find("refused"), std::string::npos) << closed.status;
    closeGracefully();
    EXPECT_EQ(configSetting("shadow_map.resolution"), "1024");
}

// Ctrl+A held for 10 ms in the file field selects its text ("plane"), so the typed path replaces
// it rather than being appended, and Load loads that file.
TEST_F(GuiE2E, QuickCtrlAInTheFileFieldMakesTypingReplaceTheText) {
    const fs::path model = writeModel("typed_box.obj");
    launch();
    scrollIntoView("scene.file");
    clickField("scene.file");
    betweenTwoFrames([&] {
        xdo({"keydown", "ctrl", "keydown", "a", "sleep", "0.01", "keyup", "a", "keyup", "ctrl"});
        typeText(model.string());
    });
    click("scene.load");
    const WidgetMap done = waitForMap("the typed path's load to end", [](const WidgetMap& m) {
        return m.status.find("typed_box.obj") != std::string::npos &&
               (m.status.rfind("loaded ", 0) == 0 || m.status.find("not loaded") != std::string::npos);
    });
    EXPECT_EQ(done.status.rfind("loaded " + model.string(), 0), 0u) << "the path typed over \"plane\": " << done.status;
    closeGracefully();
}

// A click with a 10 ms press on the Trade-off tab, the pointer coming from the Stats tab and moving
// on to the status bar at once, opens the tab at the first click: the press is seen where it
// happened, not where the pointer is when the frame polls it.
TEST_F(GuiE2E, QuickClickOnATabOpensItAtOnce) {
    launch();
    const Rect stats = widget("tab.stats");
    xdo({"mousemove", screenX(stats.cx()), screenY(stats.cy())});
    waitFrames(2);
    ASSERT_FALSE(currentMap().has("tradeoff.x")) << "the Trade-off tab is open before the click";
    const Rect tab = widget("tab.tradeoff");
    betweenTwoFrames([&] {
        xdo({"mousemove", screenX(tab.cx()), screenY(tab.cy()), "mousedown", "1", "sleep", "0.01", "mouseup", "1",
             "mousemove", screenX(5), screenY(kHeight - 5)});
    });
    waitForMap("the Trade-off tab's controls after one quick click",
               [](const WidgetMap& m) { return m.has("tradeoff.x"); });
    closeGracefully();
}

// Model files dropped onto the window (XDND, as from a file manager) load as the scene: the first
// of them (one scene at a time), drawn anew.
TEST_F(GuiE2E, DroppedFileLoadsAsTheScene) {
    const fs::path first = writeModel("dropped box.obj"), second = writeModel("second.obj");
    launch();
    const WidgetMap before = settle("before the drop");
    dropFiles({first, second});
    const WidgetMap done = waitForMap("the dropped file's load to end", [](const WidgetMap& m) {
        return m.status.find(".obj") != std::string::npos &&
               (m.status.rfind("loaded ", 0) == 0 || m.status.find("not loaded") != std::string::npos);
    });
    EXPECT_EQ(done.status.rfind("loaded " + first.string(), 0), 0u) << done.status;
    EXPECT_EQ(done.status.find("second.obj"), std::string::npos) << "only the first file loads: " << done.status;
    const WidgetMap after = settle("after the drop");
    std::cout << "[ e2e ] drop: " << describePasses(before) << " -> " << describePasses(after) << '\n';
    EXPECT_GT(after.counter("passes.shadow"), before.counter("passes.shadow")) << "the new scene's maps drawn";
    EXPECT_GT(after.counter("passes.eye_full"), before.counter("passes.eye_full")) << "the new scene drawn";
    closeGracefully();
}

// Ctrl+Q held for 10 ms closes the window cleanly (exit 0), as a close button does.
TEST_F(GuiE2E, QuickCtrlQQuits) {
    launch();
    betweenTwoFrames([&] { xdo({"keydown", "ctrl", "keydown", "q", "sleep", "0.01", "keyup", "q", "keyup", "ctrl"}); });
    ASSERT_TRUE(app_.waitExit(scaled(60))) << "the app still runs after Ctrl+Q\n" << context();
    EXPECT_EQ(app_.exitCode(), 0) << context();
}

// Nothing stale (issue 32, item 3): the stats panel's GPU rows are filled from the first frames,
// before any input, and a pinned pixel shows the current view's values after the camera moves
// (the repro: pin, move the camera, hover the same pixel; the pin kept the old depth).
TEST_F(GuiE2E, GpuTimesShowFromTheStartAndAPinFollowsTheCamera) {
    launch();
    xdo({"mousemove", screenX(5), screenY(kHeight - 5)});
    const WidgetMap start = settle("after start-up");
    EXPECT_GT(start.counter("gpu.eye_ms"), 0.0) << "GPU rows filled without any input: " << start.describe();
    EXPECT_GT(start.counter("gpu.shadow_ms"), 0.0) << "the shadow row too: " << start.describe();

    // Shift+click pins the pixel under the pointer (on the ground, below the middle of the view).
    const Rect eye = start.widgets.at("eye_image");
    const double x = eye.x + eye.w * 0.5, y = eye.y + eye.h * 0.75;
    xdo({"mousemove", screenX(x), screenY(y)});
    waitFrames(2);
    xdo({"keydown", "shift"});
    waitFrames(1);
    xdo({"click", "1"});
    waitFrames(1);
    xdo({"keyup", "shift"});
    const WidgetMap pinned =
        waitForMap("a pinned pixel", [](const WidgetMap& m) { return m.counter("pin.view_depth") > 0.0; });
    const double before = pinned.counter("pin.view_depth");

    // Orbit up: a drag upwards (a sideways one turns about the vertical axis and leaves a ground
    // pixel's depth as it was), one step a frame, starting 40 px away so that its press cannot make a
    // double-click (which fits the camera) with the pin's click; then back over the same pixel.
    xdo({"mousemove", screenX(x + 40.0), screenY(y)});
    waitFrames(1);
    xdo({"mousedown", "1"});
    waitFrames(1);
    for (int step = 1; step <= 4; ++step) {
        xdo({"mousemove", screenX(x + 40.0), screenY(y - 15.0 * step)});
        waitFrames(1);
    }
    xdo({"mouseup", "1"});
    settle("after the orbit");
    xdo({"mousemove", screenX(x), screenY(y)});
    const WidgetMap after = waitForMap("the pointer over the pinned pixel", [](const WidgetMap& m) {
        return m.counter("hover.x") == m.counter("pin.x") && m.counter("hover.y") == m.counter("pin.y") &&
               m.counter("hover.view_depth") > 0.0 && m.counter("pin.view_depth") > 0.0;
    });
    const double pin = after.counter("pin.view_depth"), hover = after.counter("hover.view_depth");
    std::cout << "[ e2e ] pinned depth " << before << " -> " << pin << " after the orbit; hover " << hover << '\n';
    EXPECT_GT(std::abs(pin - before), 1e-3 * before) << "the orbit changed the pinned pixel's depth";
    EXPECT_NEAR(pin, hover, 1e-4 * hover) << "the pin reads the current view, as hovering the same pixel does";
    closeGracefully();
}

// (Disabled until issue 32: it saw no refusal in 1 of 3 runs on a loaded machine. Not X losing
// keystrokes: when the last digit and Return reached ImGui in one frame, the field closed in the
// frame that took the digit and the value stored at the keystroke before ("9999", in range) was
// applied. The input queue gives Return a frame after the typed characters.)
TEST_F(GuiE2E, TypedValueIsAppliedOnlyWhenComplete) {
    launch();
    scrollIntoView("shadow_map.resolution");
    ctrlClick("shadow_map.resolution");
    typeText("99");
    waitFrames(1); // a user typing at normal speed: the prefix is on screen for a frame or more
    typeText("9999");
    pressKey("Return");
    const WidgetMap refused = waitForMap("the refusal in the status line", [](const WidgetMap& m) {
        // Under load X may drop a repeated keystroke ("99999"): any out-of-range number will do,
        // what matters is that no in-range prefix was applied on the way.
        return m.status.find("shadow_map.resolution: 9999") != std::string::npos &&
               m.status.find("refused") != std::string::npos;
    });
    EXPECT_NE(refused.status.find("kept 2048"), std::string::npos) << refused.status;
    closeGracefully();
    EXPECT_EQ(configSetting("shadow_map.resolution"), "2048");
}

// ---- findable, documentation screenshots (issue 32, items 5 and 6) -----------------------------

/// The ids the widget map lists as greyed (recorded under ImGui::BeginDisabled).
std::set<std::string> greyedIn(const fs::path& mapFile) {
    std::set<std::string> ids;
    const json j = json::parse(readText(mapFile), nullptr, false);
    if (!j.is_discarded() && j.contains("disabled"))
        for (const auto& id : j["disabled"]) ids.insert(id.get<std::string>());
    return ids;
}

// Two F12 presses write two numbered folders, and the first keeps its files.
TEST_F(GuiE2E, TwoScreenshotsKeepBothFolders) {
    launch();
    const Shots first = screenshot("first");
    const Shots second = screenshot("second");
    EXPECT_TRUE(fs::is_directory(shots_ / "001")) << context();
    EXPECT_TRUE(fs::is_directory(shots_ / "002")) << context();
    for (const char* f : kShotFiles) {
        EXPECT_TRUE(fs::exists(shots_ / "001" / f)) << f;
        EXPECT_TRUE(fs::exists(shots_ / "002" / f)) << f;
    }
    EXPECT_NE(currentMap().status.find("002"), std::string::npos) << "the status bar names the folder\n" << context();
    EXPECT_EQ(second.dashboard.width, kWidth);
    closeGracefully();
}

// The export dialog writes the eye view at 1920x1080, whatever the panel's size.
TEST_F(GuiE2E, AnExportAt1920x1080HasThatSize) {
    launch();
    click("export");
    widget("export.go");
    click("export.view=eye_a");
    click("export.size=0"); // 1920x1080
    click("export.go");
    const WidgetMap done = waitForMap("the export to be written", [](const WidgetMap& m) {
        return m.status.rfind("exported ", 0) == 0 || m.status.find("export not written") != std::string::npos;
    });
    ASSERT_EQ(done.status.rfind("exported ", 0), 0u) << done.status;
    const fs::path file = done.status.substr(9);
    EXPECT_EQ(file.filename(), "eye_a_1920x1080.png");
    const geometry::analysis::Image img = geometry::analysis::readImageFile(file.string());
    EXPECT_EQ(img.width, 1920);
    EXPECT_EQ(img.height, 1080);
    closeGracefully();
}

// bias.constant under slope_normal_offset is greyed (the issue saw it active), and active again
// under the constant bias; F1 shows the help.
TEST_F(GuiE2E, ASettingThatDoesNotApplyIsGreyedAndF1ShowsTheHelp) {
    launch();
    chooseInCombo("bias.type", "slope_normal_offset");
    waitForConfig("bias.type", "slope_normal_offset");
    scrollIntoView("bias.constant");
    waitForMap("bias.constant greyed", [&](const WidgetMap& m) {
        return m.has("bias.constant") && greyedIn(mapFile_).count("bias.constant") == 1;
    });
    const std::set<std::string> greyed = greyedIn(mapFile_);
    EXPECT_EQ(greyed.count("bias.slope"), 0u);
    EXPECT_EQ(greyed.count("bias.normal_offset"), 0u);
    chooseInCombo("bias.type", "constant");
    waitForMap("bias.constant active", [&](const WidgetMap& m) {
        return m.has("bias.constant") && greyedIn(mapFile_).count("bias.constant") == 0;
    });
    EXPECT_EQ(greyedIn(mapFile_).count("bias.slope"), 1u);
    pressKey("F1");
    waitForMap("the help overlay", [](const WidgetMap& m) { return m.has("help") && m.has("help:Keys:F12"); });
    pressKey("F1");
    waitForMap("the help overlay to close", [](const WidgetMap& m) { return !m.has("help"); });
    closeGracefully();
}

} // namespace
