#include "app/merge_command.h"

#include "app/bench_command.h"
#include "app/check_command.h"
#include "app/output_folder.h"

#include "geometry/io/json_file.h"

#include <CLI/CLI.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <stdexcept>

namespace app {

namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxResultsBytes = size_t(256) << 20; // thousands of cases or rows
constexpr int kMaxResultsDepth = 16;

/// Check shards: the cases in the check file's order, each case folder copied into OUT.
int mergeCheck(const std::vector<nlohmann::json>& shards, const MergeOptions& o) {
    CheckRun merged;
    std::map<size_t, std::pair<CaseReport, size_t>> byIndex; // case index → report, folder
    for (size_t s = 0; s < shards.size(); ++s) {
        CheckRun run = checkRunFromJson(shards[s]);
        if (s == 0) merged = CheckRun{run.suite, run.title, run.caseCount, {}, {}};
        else if (run.suite != merged.suite || run.title != merged.title || run.caseCount != merged.caseCount)
            throw std::invalid_argument("merge: " + o.inputs[s] + " comes from another check file (" + run.title + ")");
        for (size_t i = 0; i < run.reports.size(); ++i)
            if (!byIndex.emplace(run.indices[i], std::pair{std::move(run.reports[i]), s}).second)
                throw std::invalid_argument("merge: case " + std::to_string(run.indices[i]) + " is in two folders");
    }
    for (size_t i = 0; i < merged.caseCount; ++i)
        if (!byIndex.contains(i))
            throw std::invalid_argument("merge: case " + std::to_string(i) + " of " + std::to_string(merged.caseCount) +
                                        " is in no folder (a shard missing?)");
    if (byIndex.size() != merged.caseCount) throw std::invalid_argument("merge: a case index beyond the check file");
    createOutputFolder(o.out);
    std::error_code ec;
    for (auto& [index, entry] : byIndex) {
        const fs::path from = fs::path(o.inputs[entry.second]) / entry.first.name,
                       to = fs::path(o.out) / entry.first.name;
        if (fs::exists(from, ec) && !fs::equivalent(fs::path(o.inputs[entry.second]), fs::path(o.out), ec)) {
            fs::copy(from, to, fs::copy_options::recursive | fs::copy_options::overwrite_existing, ec);
            if (ec) throw std::runtime_error("merge: cannot copy " + from.string() + ": " + ec.message());
        }
        merged.indices.push_back(index);
        merged.reports.push_back(std::move(entry.first));
    }
    writeCheckReports(o.out, o.junit, merged);
    const auto& reports = merged.reports;
    return std::all_of(reports.begin(), reports.end(), [](const CaseReport& r) { return r.passed(); }) ? 0 : 1;
}

} // namespace

void addMergeCommand(CLI::App& cmd, MergeOptions& o) {
    cmd.add_option("folders", o.inputs, "The shards' output folders (check --out or bench --out of each job)")
        ->required()
        ->check(CLI::ExistingDirectory);
    cmd.add_option("--out", o.out, "Output folder: what one unsharded run would have written")->capture_default_str();
    cmd.add_option("--junit", o.junit, "check: also write the merged verdicts as a JUnit XML file")
        ->type_name("FILE.xml");
}

int runMerge(const MergeOptions& o) {
    std::vector<nlohmann::json> shards;
    for (const std::string& dir : o.inputs) {
        const std::string path = (fs::path(dir) / "results.json").string();
        if (!fs::exists(path))
            throw std::invalid_argument("merge: " + dir + " has no results.json (not a check or bench output folder)");
        shards.push_back(geometry::io::readJsonFile(path, path, kMaxResultsBytes, kMaxResultsDepth));
    }
    const nlohmann::json kind = shards.front().value("kind", nlohmann::json());
    for (size_t s = 0; s < shards.size(); ++s)
        if (shards[s].value("kind", nlohmann::json()) != kind)
            throw std::invalid_argument("merge: " + o.inputs[s] + " holds another kind of results than " + o.inputs[0]);
    try {
        if (kind == "check") return mergeCheck(shards, o);
        if (kind == "bench") {
            if (!o.junit.empty()) throw std::invalid_argument("merge: --junit is for check folders");
            return mergeBench(shards, o.out);
        }
    } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(std::string("merge: a results.json is not as check or bench writes it: ") +
                                    e.what());
    }
    throw std::invalid_argument("merge: " + o.inputs[0] + "/results.json is neither a check's nor a bench's");
}

} // namespace app
