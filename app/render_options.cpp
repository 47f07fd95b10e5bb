#include "render_options.h"

#include "app/resources.h"

#include "geometry/analysis/ground_truth.h"
#include "geometry/io/preset.h"

#include "geometry/io/scene_file.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace app {

namespace {

/// Parses "a,b,c,..." into exactly `n` finite floats.
std::vector<float> parseFloats(const std::string& text, size_t n, const char* what) {
    std::vector<float> out;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        try {
            size_t used = 0;
            const float v = std::stof(item, &used);
            if (used != item.size() || !std::isfinite(v)) throw std::invalid_argument(item);
            out.push_back(v);
        } catch (const std::exception&) {
            throw std::invalid_argument(std::string(what) + ": '" + item + "' is not a finite number");
        }
    }
    if (out.size() != n)
        throw std::invalid_argument(std::string(what) + " needs " + std::to_string(n) + " comma-separated numbers");
    return out;
}

} // namespace

geometry::shadow::Viewport parseSize(const std::string& text) {
    const auto x = text.find_first_of("xX");
    try {
        if (x == std::string::npos) throw std::invalid_argument(text);
        size_t a = 0, b = 0;
        const int w = std::stoi(text.substr(0, x), &a), h = std::stoi(text.substr(x + 1), &b);
        if (a != x || b != text.size() - x - 1) throw std::invalid_argument(text);
        if (w < 1 || h < 1 || w > 16384 || h > 16384)
            throw std::out_of_range("--size: each side must be within 1..16384, got " + text);
        return {w, h};
    } catch (const std::out_of_range& e) {
        throw std::invalid_argument(e.what());
    } catch (const std::invalid_argument&) {
        throw std::invalid_argument("--size: expected WxH (e.g. 1280x720), got '" + text + "'");
    }
}

namespace {

/// Declares --set once for both addRenderOptions and addSettingOption.
CLI::Option* addSetOption(CLI::App& cmd, std::function<void(const std::vector<std::string>&)> apply) {
    std::string keys;
    for (const auto& info : geometry::shadow::settingsDeclaration())
        keys += "\n  " + std::string(info.key) + ": " + std::string(info.help) + " (" + info.rangeText() + ")";
    return cmd
        .add_option_function<std::vector<std::string>>("--set", std::move(apply),
                                                       "Shadow setting key=value (repeatable). Keys:" + keys)
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
}

/// Where a command's shadow settings come from, lowest precedence first. CLI11 runs option
/// callbacks after the whole command line is parsed, in declaration order, not command-line
/// order. Rather than lean on that, each of the three callbacks rebuilds the settings from the
/// raw values of all three options: the result is the same whichever callback runs first or
/// last, and whatever the order of the options on the command line. Rebuilding is idempotent,
/// so running it once per given option (a preset file is then read up to three times) is harmless.
struct SettingSources {
    RenderOptions* target = nullptr;
    geometry::shadow::ShadowSettings base; // target->settings when the options were declared
    CLI::Option* presets = nullptr;        // --preset FILE, in command-line order
    CLI::Option* shadowRes = nullptr;      // --shadow-res N
    CLI::Option* assignments = nullptr;    // --set key=value, in command-line order

    void rebuild() const {
        geometry::shadow::ShadowSettings s = base;
        for (const auto& path : presets->results()) s = geometry::io::loadPreset(findResource(path), s);
        if (shadowRes->count() > 0)
            geometry::shadow::applySetting(s, "shadow_map.resolution", std::to_string(shadowRes->as<int>()));
        for (const auto& a : assignments->results()) geometry::shadow::applyAssignment(s, a);
        geometry::shadow::validateOrThrow(s); // what one value alone cannot say (virtual.* sizes)
        target->settings = s;
        target->settingsGiven = true;
    }
};

void addSettingSources(CLI::App& cmd, RenderOptions& o) {
    auto sources = std::make_shared<SettingSources>();
    sources->target = &o;
    sources->base = o.settings;
    const auto rebuild = [sources](const auto&) { sources->rebuild(); };
    sources->presets =
        cmd.add_option_function<std::vector<std::string>>(
               "--preset", rebuild,
               "Shadow settings from a JSON preset (repeatable; e.g. resources/presets/paper.json). Presets apply "
               "first, in order, then --shadow-res, then --set, wherever they appear")
            ->type_name("FILE")
            ->allow_extra_args(false);
    sources->shadowRes = cmd.add_option_function<int>(
        "--shadow-res", rebuild, "Shadow map resolution in texels (= --set shadow_map.resolution=N; default 2048)");
    sources->assignments = addSetOption(cmd, rebuild);
}

/// Shows "loading NAME: STAGE NN%" on stderr, rewriting one line, once a load has taken half a
/// second (quick loads stay silent) and at most ten times a second, then "loaded NAME in T s".
/// Only on a terminal: captured output and logs keep their one-line errors.
class LoadProgress {
public:
    explicit LoadProgress(std::string label) : label_(std::move(label)), terminal_(isatty(STDERR_FILENO) == 1) {}
    LoadProgress(const LoadProgress&) = delete;
    LoadProgress& operator=(const LoadProgress&) = delete;
    ~LoadProgress() {
        if (!shown_) return;
        // A failed load clears the line, so its error message stands alone.
        if (std::uncaught_exceptions() > 0) std::cerr << "\r\033[K" << std::flush;
        else std::cerr << "\r\033[Kloaded " << label_ << " in " << seconds(Clock::now()) << " s\n" << std::flush;
    }

    void operator()(float fraction, std::string_view stage) {
        if (!terminal_) return;
        const auto now = Clock::now();
        if (now - start_ < std::chrono::milliseconds(500) || now - last_ < std::chrono::milliseconds(100)) return;
        last_ = now;
        shown_ = true;
        const int percent = static_cast<int>(std::lround(100.f * std::clamp(fraction, 0.f, 1.f)));
        std::cerr << "\r\033[Kloading " << label_ << ": " << stage << ' ' << percent << '%' << std::flush;
    }

private:
    using Clock = std::chrono::steady_clock;
    std::string seconds(Clock::time_point now) const {
        char text[32];
        std::snprintf(text, sizeof text, "%.1f", std::chrono::duration<double>(now - start_).count());
        return text;
    }
    std::string label_;
    bool terminal_;
    bool shown_ = false;
    Clock::time_point start_ = Clock::now();
    Clock::time_point last_{};
};

std::string unknownView(const RenderOptions& o, const geometry::io::SceneFile& file) {
    std::string names;
    for (const auto& [name, view] : file.views) names += (names.empty() ? "" : ", ") + name;
    return "--view " + o.view + ": scene '" + o.scene + "' has no such view (" +
           (names.empty() ? std::string("it has none") : "available: " + names) + ")";
}

} // namespace

void addUpOption(CLI::App& cmd, std::optional<geometry::io::UpAxis>& up, const std::string& help) {
    cmd.add_option_function<std::string>(
        "--up",
        [&up](const std::string& text) {
            up = geometry::io::parseUpAxis(text);
            if (!up) throw std::invalid_argument("--up: expected one of y, z, -y, -z, x, -x, got '" + text + "'");
        },
        help);
}

namespace {

bool isLightIndex(const std::string& s) { return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos; }

/// A --light N within kMaxLights (whether the scene has that many is checked once it is loaded).
size_t parseLightIndex(const std::string& s) {
    if (s.size() > 2 || std::stoul(s) >= geometry::scene::kMaxLights)
        throw std::invalid_argument("--light " + s + ": a scene holds at most " +
                                    std::to_string(geometry::scene::kMaxLights) + " lights, numbered from 0");
    return std::stoul(s);
}

} // namespace

void addRenderOptions(CLI::App& cmd, RenderOptions& o, OptionUse use) {
    const bool bench = use == OptionUse::Bench;
    cmd.add_option(
           "--scene", o.scene,
           "Scene: a built-in name (platform, piperack, plane, overlap), a scene file (resources/scenes/*.json) or "
           "a model file (.obj, .stl, .off, .ply, .gltf, .glb; shown on a ground plane with a framed camera)")
        ->capture_default_str();
    addUpOption(cmd, o.up,
                "Up axis of model files (y, z, -y, -z, x, -x; default: z for STL, the CAD convention, y for the "
                "others); in a scene file, the default for entries without \"up\"");
    if (bench)
        cmd.add_option("--view", o.views,
                       "Canonical view (camera and light) named in the scene file to measure "
                       "(repeatable; default: every view of the scene)");
    else
        cmd.add_option("--view", o.view,
                       "Canonical view (camera and light) named in the scene file, e.g. deck, "
                       "overview (default: the scene's camera and light)");
    cmd.add_option_function<std::string>(
        "--size", [&o](const std::string& s) { o.size = parseSize(s); },
        "Image size WxH (default " + std::to_string(o.size.width) + "x" + std::to_string(o.size.height) + ")");
    cmd.add_option("--out", o.out, "Output folder")->capture_default_str();
    addBackendOption(cmd, o.backend, !bench);
    if (bench) {
        cmd.add_option("--preset", o.presets, "A configuration from a JSON preset (repeatable; default: the defaults)")
            ->type_name("FILE");
        addSetOption(cmd, [&o](const std::vector<std::string>& a) { o.assignments = a; });
        cmd.add_option_function<std::string>(
            "--light",
            [&o](const std::string& s) {
                if (!isLightIndex(s)) throw std::invalid_argument("--light " + s + ": expected a light's number");
                o.lightIndex = parseLightIndex(s);
            },
            "N: the light whose shadows are measured (default 0); every light of the scene is drawn");
        return;
    }
    cmd.add_option_function<std::string>(
        "--camera",
        [&o](const std::string& s) {
            const auto v = parseFloats(s, 6, "--camera");
            geometry::scene::Camera c;
            c.eye = {v[0], v[1], v[2]};
            c.target = {v[3], v[4], v[5]};
            if (glm::length(c.target - c.eye) <= 0.f)
                throw std::invalid_argument("--camera: eye and target must differ");
            o.camera = c;
        },
        "Camera eye and target: ex,ey,ez,tx,ty,tz (default: the scene's)");
    cmd.add_option_function<std::string>(
        "--light",
        [&o](const std::string& s) {
            if (isLightIndex(s)) {
                o.lightIndex = parseLightIndex(s);
                return;
            }
            const auto v = parseFloats(s, 3, "--light");
            const glm::vec3 l(v[0], v[1], v[2]);
            if (!(glm::length(l) > 0.f)) throw std::invalid_argument("--light: direction must not be zero");
            o.light = l;
        },
        "N: the light to inspect (light view, reports; default 0), or dx,dy,dz: the light's direction, from the "
        "light into the scene (default: the scene's)");
    addSettingSources(cmd, o);
}

void addBackendOption(CLI::App& cmd, std::string& backend, bool window) {
    if (window)
        cmd.add_option("--backend", backend, "GL backend: auto (EGL on a GPU, else OSMesa), osmesa, egl, glfw")
            ->capture_default_str()
            ->check(CLI::IsMember({"auto", "osmesa", "egl", "glfw"}));
    else
        cmd.add_option("--backend", backend, "GL backend: auto (EGL on a GPU, else OSMesa), osmesa, egl")
            ->capture_default_str()
            ->check(CLI::IsMember({"auto", "osmesa", "egl"}));
}

void addTruthOptions(CLI::App& cmd, TruthOptions& truth, const std::string& truthHelp) {
    if (!truthHelp.empty()) cmd.add_flag("--truth", truth.enabled, truthHelp);
    cmd.add_option("--truth-samples", truth.samples,
                   "Truth rays per pixel per axis: N x N samples over the pixel's footprint give its lit fraction "
                   "c (reports use 4)")
        ->check(CLI::Range(1, geometry::analysis::GroundTruth::kMaxSamplesPerAxis))
        ->capture_default_str();
}

void addSettingOption(CLI::App& cmd, geometry::shadow::ShadowSettings& settings) {
    addSetOption(cmd, [&settings](const std::vector<std::string>& assignments) {
        for (const auto& a : assignments) geometry::shadow::applyAssignment(settings, a);
    });
}

geometry::io::SceneFile resolveSceneFile(const RenderOptions& o) {
    LoadProgress progress(std::filesystem::path(o.scene).filename().string());
    return geometry::io::resolveScene(findResource(o.scene), std::ref(progress), o.up);
}

void checkLightIndex(size_t index, const geometry::scene::Scene& scene) {
    if (index >= scene.lights.size())
        throw std::invalid_argument("--light " + std::to_string(index) + ": the scene has " +
                                    std::to_string(scene.lights.size()) + " light(s), numbered from 0");
}

void applyView(geometry::io::SceneFile& file, const RenderOptions& o) {
    geometry::scene::Scene& scene = file.scene;
    if (!o.view.empty()) {
        const auto it = file.views.find(o.view);
        if (it == file.views.end()) throw std::invalid_argument(unknownView(o, file));
        scene.camera = it->second.camera;
        scene.lights[0] = it->second.light;
    }
    if (o.camera) {
        scene.camera.eye = o.camera->eye;
        scene.camera.target = o.camera->target;
    }
    checkLightIndex(o.lightIndex, scene);
    if (o.light) scene.lights[o.lightIndex].direction = *o.light;
}

geometry::io::SceneFile loadSceneFile(const RenderOptions& o) {
    geometry::io::SceneFile file = resolveSceneFile(o);
    applyView(file, o);
    return file;
}

geometry::scene::Scene loadScene(const RenderOptions& o) { return loadSceneFile(o).scene; }

} // namespace app
