// shadowscope: inspect, tune and document real-time shadows on CAD models.
#include "bench_command.h"
#include "check_command.h"
#include "curves_command.h"
#include "gui_command.h"
#include "merge_command.h"
#include "mesh_command.h"
#include "render_command.h"
#include "sweep_command.h"
#include "tune_command.h"
#include "version.h"

#include "geometry/io/scene_file.h"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <iostream>
#include <stdexcept>
#include <string>

int main(int argc, char** argv) {
    CLI::App cli{"shadowscope: inspect and tune real-time shadows on CAD models.\n"
                 "Without a command, opens the GUI (or renders headless into ./out when there is no display)."};
    cli.set_help_all_flag("--help-all", "Help for every command");
    cli.set_version_flag("--version",
                         "shadowscope " + std::string(app::kVersion) + " (" + std::string(app::kRevision) + ")",
                         "Print the version and the git revision it was built from");
    cli.require_subcommand(0, 1);

    app::RenderOptions guiOptions;
    app::addRenderOptions(cli, guiOptions);

    app::RenderOptions renderOptions;
    CLI::App* render = cli.add_subcommand("render", "Render the eye and light views headless to PNG + metrics.json");
    app::addRenderOptions(*render, renderOptions);
    app::ExportOptions exportOptions;
    app::addExportOptions(*render, exportOptions);

    app::CurvesOptions curvesOptions;
    CLI::App* curves = cli.add_subcommand("curves", "Write the analytic curves (warp n', aliasing error m_z, split "
                                                    "boundaries) as CSV + SVG charts, without rendering");
    app::addCurvesCommand(*curves, curvesOptions);

    app::MeshOptions meshOptions;
    CLI::App* mesh = app::addMeshCommand(cli, meshOptions);

    app::BenchOptions benchOptions;
    CLI::App* bench = cli.add_subcommand("bench", "Time configurations (presets x --sweep values) on canonical views: "
                                                  "results.csv and the speed/accuracy chart with its Pareto front");
    app::addBenchCommand(*bench, benchOptions);

    app::SweepOptions sweepOptions;
    CLI::App* sweep = app::addSweepCommand(cli, sweepOptions);

    app::TuneCommandOptions tuneOptions;
    CLI::App* tune = cli.add_subcommand("tune", "Find the cheapest settings that meet an accuracy target: screening "
                                                "at half size, then full-size confirmation; recommended.json, "
                                                "tune.csv, tune.svg/png");
    app::addTuneCommand(*tune, tuneOptions);

    app::CheckOptions checkOptions;
    CLI::App* check = cli.add_subcommand("check", "Render the cases of a check file and test their metrics.json "
                                                  "against bounds and their eye view against golden images "
                                                  "(exit 0 all pass, 1 a case fails, 2 a bad check file)");
    app::addCheckCommand(*check, checkOptions);

    app::MergeOptions mergeOptions;
    CLI::App* merge = cli.add_subcommand("merge", "Join the output folders of check or bench jobs run with --shard I/N "
                                                  "into what one run writes (report.html, JUnit, results.csv, the "
                                                  "trade-off chart)");
    app::addMergeCommand(*merge, mergeOptions);

    try {
        cli.parse(argc, argv);
        if (mesh->parsed()) return app::runMesh(*mesh, meshOptions);
        if (render->parsed()) return app::runRender(renderOptions, exportOptions);
        if (curves->parsed()) return app::runCurves(curvesOptions);
        if (sweep->parsed()) return app::runSweep(*sweep, sweepOptions);
        if (bench->parsed()) return app::runBench(benchOptions);
        if (tune->parsed()) return app::runTune(tuneOptions);
        if (check->parsed()) return app::runCheck(checkOptions);
        if (merge->parsed()) return app::runMerge(mergeOptions);
        return app::runGuiOrHeadless(guiOptions);
    } catch (const CLI::CallForHelp& e) {
        return cli.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return cli.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return cli.exit(e);
    } catch (const CLI::ParseError& e) { // exit codes: 0 done, 1 failed, 2 bad arguments (3: tune found nothing)
        std::cerr << "shadowscope: error: " << e.what() << '\n';
        return 2;
    } catch (const std::invalid_argument& e) {
        std::cerr << "shadowscope: error: " << e.what() << '\n';
        return 2;
    } catch (const geometry::io::SceneFileError& e) { // a bad scene file is bad input too
        std::cerr << "shadowscope: error: " << e.what() << '\n';
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "shadowscope: error: " << e.what() << '\n';
        return 1;
    }
}
