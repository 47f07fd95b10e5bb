#include "sweep_command.h"

#include "geometry/shadow/warp.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace app {

namespace {

void addThresholdOptions(CLI::App& cmd, SweepThresholds& t) {
    cmd.add_option("--max-p95-ratio", t.maxP95Ratio,
                   "check: largest factor p95 m of lispsm/glispsm/gmnpr may change by between neighbouring angles")
        ->check(CLI::Range(1.0, 1e9))
        ->capture_default_str();
    cmd.add_option("--continuity-step", t.continuityStepDeg,
                   "check: the p95 rule applies to neighbouring angles at most this many degrees apart")
        ->check(CLI::Range(0.0, 180.0))
        ->capture_default_str();
    cmd.add_option("--max-false-lit-clipped", t.maxFalseLitClipped,
                   "check: largest fraction of receiver pixels rendered lit where the truth is shadowed and the "
                   "path to the light leaves the split's light frustum (lost casters)")
        ->check(CLI::Range(0.0, 1.0))
        ->capture_default_str();
    cmd.add_option("--min-receivers", t.minReceivers,
                   "check: rows with fewer receiver pixels are not judged by the continuity rule")
        ->check(CLI::Range(0.0, 1e9))
        ->capture_default_str();
}

std::string methodList() {
    std::string s;
    for (int m = 0; m < int(geometry::shadow::kEnumCount<geometry::shadow::WarpMethod>); ++m)
        s += (s.empty() ? "" : ", ") + std::string(geometry::shadow::warpMethodName(geometry::shadow::WarpMethod(m)));
    return s;
}

} // namespace

CLI::App* addSweepCommand(CLI::App& cli, SweepOptions& o) {
    CLI::App* sweep =
        cli.add_subcommand("sweep", "Stability sweeps: light-view angle, camera/light paths (docs/stability.md)");
    sweep->require_subcommand(1);

    CLI::App* gamma = sweep->add_subcommand(
        "gamma", "Turn the light about the eye through light-view angles 0..180 (180: dueling frusta) and record n', "
                 "aliasing m and truth per warp method: DIR/sweep.csv and charts");
    o.gamma.render.size = {320, 180};
    addRenderOptions(*gamma, o.gamma.render);
    gamma->get_option("--size")->description("Image size WxH (default 320x180)");
    gamma->get_option("--light")->description(
        "Reference light direction dx,dy,dz: the light turns in the plane of the view direction and this one "
        "(default: the scene's light)");
    gamma->add_option("--from", o.gamma.fromDeg, "First light-view angle, degrees (0: light behind the eye, l = v)")
        ->capture_default_str();
    gamma->add_option("--to", o.gamma.toDeg, "Last light-view angle, degrees (180: light facing the camera, l = -v)")
        ->capture_default_str();
    gamma->add_option("--step", o.gamma.stepDeg, "Angle step, degrees (> 0)")->capture_default_str();
    gamma->add_option("--methods", o.gamma.methods, "Warp methods, comma-separated: " + methodList())
        ->delimiter(',')
        ->capture_default_str();
    gamma->add_flag("--check", o.gamma.check,
                    "Exit 1 on NaN/Inf, GL errors, p95 jumps of continuity methods or lost casters (one line each on "
                    "stderr)");
    addThresholdOptions(*gamma, o.gamma.thresholds);

    CLI::App* path = sweep->add_subcommand(
        "path",
        "Walk a camera/light path of a scene file and record flicker and seams per frame: DIR/path.csv and a chart");
    o.path.render.size = {320, 180};
    addRenderOptions(*path, o.path.render);
    path->get_option("--size")->description("Image size WxH (default 320x180)");
    path->add_option("--path", o.path.path, "Path name in the scene file's \"paths\"")->required();
    path->add_option("--frames", o.path.frames,
                     "Frames covering the whole path (1.." + std::to_string(kMaxPathFrames) + ")")
        ->capture_default_str();

    CLI::App* check = sweep->add_subcommand("check", "Apply sweep gamma's --check rules to a sweep.csv");
    check->add_option("file", o.check.file, "sweep.csv written by sweep gamma")->required();
    addThresholdOptions(*check, o.check.thresholds);
    return sweep;
}

int runSweep(const CLI::App& sweep, const SweepOptions& o) {
    if (sweep.get_subcommand("gamma")->parsed()) return runSweepGamma(o.gamma);
    if (sweep.get_subcommand("path")->parsed()) return runSweepPath(o.path);
    return runSweepCheck(o.check);
}

std::vector<double> sweepAngles(double from, double to, double step) {
    const auto text = [](double v) { return formatCsvNumber(v); };
    if (!std::isfinite(from) || !std::isfinite(to) || from < 0 || to > 180)
        throw std::invalid_argument("--from/--to: the range must lie within 0..180 degrees, got " + text(from) + ".." +
                                    text(to));
    if (from > to) throw std::invalid_argument("--from " + text(from) + " is beyond --to " + text(to));
    if (!(step > 0) || !std::isfinite(step)) throw std::invalid_argument("--step: " + text(step) + " must be > 0");
    const double count = std::floor((to - from) / step + 1e-9) + 1;
    const auto tooMany = [&](double n) {
        return std::invalid_argument("--step " + text(step) + " over " + text(from) + ".." + text(to) + " gives " +
                                     text(n) + " angles; at most " + std::to_string(kMaxSweepAngles) +
                                     " (use a larger step)");
    };
    if (count > kMaxSweepAngles) throw tooMany(count);
    std::vector<double> angles;
    for (int i = 0; i < int(count); ++i) angles.push_back(from + i * step); // i·step: no drift
    // `to` is always the last angle: appended when the steps fall short of it, snapped when they land on it.
    if (to - angles.back() > 1e-9 * std::max(1.0, to)) angles.push_back(to);
    else angles.back() = to;
    if (int(angles.size()) > kMaxSweepAngles) throw tooMany(double(angles.size()));
    return angles;
}

int runSweepCheck(const SweepCheckOptions& o) {
    std::ifstream in(o.file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + o.file);
    std::ostringstream text;
    text << in.rdbuf();
    std::vector<SweepRecord> rows;
    try {
        rows = parseSweepCsv(text.str());
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(o.file + ": " + e.what());
    }
    const auto failures = checkSweep(rows, o.thresholds);
    for (const auto& f : failures) std::cerr << "shadowscope: check failed: " << f << '\n';
    std::cout << o.file << ": " << rows.size() << " rows, " << failures.size() << " failure(s)\n";
    return failures.empty() ? 0 : 1;
}

} // namespace app
