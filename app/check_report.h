#pragma once
// What `shadowscope check` reports, as text built from the results (no GL, no files): the summary
// table on stdout, report.html, the JUnit XML file, and results.json (what `merge` reads back).
#include "check_expect.h"
#include "ui/charts/xml_text.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace app {

/// One case's results.
struct CaseReport {
    std::string name;
    std::vector<Verdict> verdicts; // expectations, then the golden
    std::string error;             // why the case could not be rendered or written; empty when it was
    double seconds = 0;            // render and checks, wall clock
    /// Images relative to the report's folder ("NAME/eye.png"); empty when there is none.
    std::string render, golden, diff;
    std::vector<std::pair<std::string, std::string>> facts; // label → value: scene, view, size, renderer, ...

    [[nodiscard]] size_t failed() const noexcept;
    [[nodiscard]] bool passed() const noexcept { return error.empty() && failed() == 0; }
    /// "pass", "FAIL" or "error".
    [[nodiscard]] const char* status() const noexcept;
};

/// Columns case, verdict, failed (checks), time; then "N case(s): P passed, F failed".
[[nodiscard]] std::string summaryTable(const std::vector<CaseReport>& cases);

/// A self-contained page: per case its verdicts and figures, and the render, golden and diff side
/// by side (images by their relative paths). All text escaped.
[[nodiscard]] std::string htmlReport(const std::string& title, const std::vector<CaseReport>& cases);

/// <testsuites><testsuite name=SUITE tests= failures= errors=><testcase name= classname= time=>
/// with a <failure> per failing case (message: its failed checks, body: one per line), an <error>
/// per case with an error, and every verdict in <system-out>.
[[nodiscard]] std::string junitXml(const std::string& suite, const std::vector<CaseReport>& cases);

/// What a check run, or one shard of it, reports: DIR/results.json.
struct CheckRun {
    std::string suite;               // the check file's stem: JUnit's suite name
    std::string title;               // report.html's
    size_t caseCount = 0;            // cases in the check file
    std::vector<size_t> indices;     // each report's case index in the check file, ascending
    std::vector<CaseReport> reports; // in the check file's order
};

/// results.json's content, and back; checkRunFromJson throws std::invalid_argument for anything
/// checkRunJson does not write.
[[nodiscard]] nlohmann::json checkRunJson(const CheckRun& run);
[[nodiscard]] CheckRun checkRunFromJson(const nlohmann::json& j);

/// Text for XML and HTML (shared with the charts' SVG).
using ui::charts::xmlEscape;

} // namespace app
