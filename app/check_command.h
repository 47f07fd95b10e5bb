#pragma once
// `shadowscope check FILE.json`: renders each case of a check file (app/check_file.h) as `render`
// would, checks its metrics.json against the case's expectations and its eye view against a golden
// image, and reports: a summary on stdout, one line per failure on stderr, DIR/report.html, and a
// JUnit XML file for CI. Exit 0 when every case passes, 1 when one fails, 2 for a bad check file.
#include "app/check_report.h"
#include "app/shard.h"

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace app {

struct CheckOptions {
    std::string file;              // the check file
    std::string out = "out/check"; // DIR: DIR/CASE/ per case, DIR/report.html
    std::string junit;             // JUnit XML file; empty: none
    bool update = false;           // write each passing case's eye view as its golden
    bool force = false;            // with update: failing cases' too
    std::string backend = "auto";
    std::optional<Shard> shard; // --shard I/N: only this share of the cases
};

/// Adds FILE, --out, --junit, --update, --force, --shard, --backend.
void addCheckCommand(CLI::App& cmd, CheckOptions& options);

int runCheck(const CheckOptions& options);

/// Writes DIR/report.html, DIR/results.json and (`junit` not empty) the JUnit file of `run`, and
/// prints the summary table and where they are: a check run's outputs, or merged shards'.
void writeCheckReports(const std::string& out, const std::string& junit, const CheckRun& run);

} // namespace app
