#pragma once
// `shadowscope merge DIR... --out DIR [--junit FILE]`: joins the output folders of `check --shard I/N`
// or `bench --shard I/N` jobs (a CI matrix) into what one unsharded run writes: for check the case
// folders, report.html, results.json and the JUnit file; for bench results.csv, the trade-off chart
// and results.json. Exit 0 (check: every case passed), 1 (check: a case failed), 2 for folders
// that do not fit together (different runs, a case or configuration missing or in two folders).
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace app {

struct MergeOptions {
    std::vector<std::string> inputs; // the shards' output folders
    std::string out = "out/merged";
    std::string junit; // check: also write JUnit XML here
};

void addMergeCommand(CLI::App& cmd, MergeOptions& options);
int runMerge(const MergeOptions& options);

} // namespace app
