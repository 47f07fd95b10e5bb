#include "check_report.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace app {

size_t CaseReport::failed() const noexcept {
    return size_t(std::count_if(verdicts.begin(), verdicts.end(), [](const Verdict& v) { return !v.passed; }));
}

const char* CaseReport::status() const noexcept {
    if (!error.empty()) return "error";
    return failed() ? "FAIL" : "pass";
}

namespace {

std::string seconds(double s, const char* format) {
    char buf[32];
    std::snprintf(buf, sizeof buf, format, s);
    return buf;
}

double totalSeconds(const std::vector<CaseReport>& cases) {
    double t = 0;
    for (const auto& c : cases) t += c.seconds;
    return t;
}

} // namespace

std::string summaryTable(const std::vector<CaseReport>& cases) {
    size_t width = 4; // "case"
    for (const auto& c : cases) width = std::max(width, c.name.size());
    std::ostringstream out;
    const auto row = [&](const std::string& name, const std::string& verdict, const std::string& failed,
                         const std::string& time) {
        out << name << std::string(width - name.size() + 2, ' ') << verdict
            << std::string(verdict.size() < 9 ? 9 - verdict.size() : 1, ' ') << failed
            << std::string(failed.size() < 8 ? 8 - failed.size() : 1, ' ') << time << '\n';
    };
    row("case", "verdict", "failed", "time");
    size_t passed = 0;
    for (const auto& c : cases) {
        row(c.name, c.status(), c.error.empty() ? std::to_string(c.failed()) : "-", seconds(c.seconds, "%.2f s"));
        passed += c.passed();
    }
    out << cases.size() << " case(s): " << passed << " passed, " << cases.size() - passed << " failed\n";
    return out.str();
}

std::string htmlReport(const std::string& title, const std::vector<CaseReport>& cases) {
    std::ostringstream out;
    size_t passed = 0;
    for (const auto& c : cases) passed += c.passed();
    out << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" << xmlEscape(title) << "</title>\n"
        << "<style>body{font-family:sans-serif;margin:1.5em}table{border-collapse:collapse}"
           "td,th{border:1px solid #ccc;padding:2px 8px;text-align:left}.pass{color:#070}.FAIL,.error{color:#b00}"
           "figure{display:inline-block;margin:0 1em 1em 0;vertical-align:top}img{max-width:480px;"
           "image-rendering:pixelated;border:1px solid #999}section{margin-bottom:2em}</style></head><body>\n"
        << "<h1>" << xmlEscape(title) << "</h1>\n<p>" << cases.size() << " case(s): " << passed << " passed, "
        << cases.size() - passed << " failed</p>\n<table><tr><th>case</th><th>verdict</th><th>failed checks</th>"
        << "<th>time</th></tr>\n";
    for (const auto& c : cases)
        out << "<tr><td><a href=\"#" << xmlEscape(c.name) << "\">" << xmlEscape(c.name) << "</a></td><td class=\""
            << c.status() << "\">" << c.status() << "</td><td>" << c.failed() << "</td><td>"
            << seconds(c.seconds, "%.2f s") << "</td></tr>\n";
    out << "</table>\n";
    for (const auto& c : cases) {
        out << "<section id=\"" << xmlEscape(c.name) << "\"><h2>" << xmlEscape(c.name) << " <span class=\""
            << c.status() << "\">" << c.status() << "</span></h2>\n";
        if (!c.facts.empty()) {
            out << "<p>";
            for (size_t i = 0; i < c.facts.size(); ++i)
                out << (i ? " · " : "") << xmlEscape(c.facts[i].first) << ": " << xmlEscape(c.facts[i].second);
            out << "</p>\n";
        }
        if (!c.error.empty()) out << "<p class=\"error\">error: " << xmlEscape(c.error) << "</p>\n";
        if (!c.verdicts.empty()) {
            out << "<table><tr><th>check</th><th>verdict</th><th>figures</th></tr>\n";
            for (const auto& v : c.verdicts)
                out << "<tr><td>" << xmlEscape(v.what) << "</td><td class=\"" << (v.passed ? "pass" : "FAIL") << "\">"
                    << (v.passed ? "pass" : "FAIL") << "</td><td>" << xmlEscape(v.text) << "</td></tr>\n";
            out << "</table>\n";
        }
        for (const auto& [label, image] : {std::pair<const char*, const std::string&>{"render", c.render},
                                           {"golden", c.golden},
                                           {"diff (magenta: pixels beyond the tolerance)", c.diff}})
            if (!image.empty())
                out << "<figure><a href=\"" << xmlEscape(image) << "\"><img src=\"" << xmlEscape(image) << "\" alt=\""
                    << label << "\"></a><figcaption>" << label << "</figcaption></figure>\n";
        out << "</section>\n";
    }
    out << "</body></html>\n";
    return out.str();
}

namespace {

nlohmann::json caseReportJson(const CaseReport& c) {
    nlohmann::json verdicts = nlohmann::json::array(), facts = nlohmann::json::array();
    for (const Verdict& v : c.verdicts) verdicts.push_back({{"what", v.what}, {"passed", v.passed}, {"text", v.text}});
    for (const auto& [label, value] : c.facts) facts.push_back({label, value});
    return {{"name", c.name},     {"status", c.status()}, {"verdicts", verdicts},
            {"error", c.error},   {"seconds", c.seconds}, {"render", c.render},
            {"golden", c.golden}, {"diff", c.diff},       {"facts", facts}};
}

CaseReport caseReportFromJson(const nlohmann::json& j) {
    try {
        CaseReport c;
        c.name = j.at("name").get<std::string>();
        for (const auto& v : j.at("verdicts"))
            c.verdicts.push_back(
                {v.at("what").get<std::string>(), v.at("passed").get<bool>(), v.at("text").get<std::string>()});
        c.error = j.at("error").get<std::string>();
        c.seconds = j.at("seconds").get<double>();
        c.render = j.at("render").get<std::string>();
        c.golden = j.at("golden").get<std::string>();
        c.diff = j.at("diff").get<std::string>();
        for (const auto& f : j.at("facts"))
            c.facts.emplace_back(f.at(0).get<std::string>(), f.at(1).get<std::string>());
        return c;
    } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(std::string("not a case report: ") + e.what());
    }
}

} // namespace

nlohmann::json checkRunJson(const CheckRun& run) {
    nlohmann::json cases = nlohmann::json::array();
    for (size_t i = 0; i < run.reports.size(); ++i) {
        nlohmann::json c = caseReportJson(run.reports[i]);
        c["index"] = run.indices.at(i);
        cases.push_back(std::move(c));
    }
    return {{"kind", "check"},
            {"suite", run.suite},
            {"title", run.title},
            {"case_count", run.caseCount},
            {"cases", std::move(cases)}};
}

CheckRun checkRunFromJson(const nlohmann::json& j) {
    try {
        if (j.at("kind") != "check") throw std::invalid_argument("not a check run's results");
        CheckRun run;
        run.suite = j.at("suite").get<std::string>();
        run.title = j.at("title").get<std::string>();
        run.caseCount = j.at("case_count").get<size_t>();
        for (const auto& c : j.at("cases")) {
            run.indices.push_back(c.at("index").get<size_t>());
            run.reports.push_back(caseReportFromJson(c));
        }
        return run;
    } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(std::string("not a check run's results: ") + e.what());
    }
}

std::string junitXml(const std::string& suite, const std::vector<CaseReport>& cases) {
    size_t failures = 0, errors = 0;
    for (const auto& c : cases) {
        if (!c.error.empty()) ++errors;
        else if (c.failed()) ++failures;
    }
    const std::string counts = "tests=\"" + std::to_string(cases.size()) + "\" failures=\"" + std::to_string(failures) +
                               "\" errors=\"" + std::to_string(errors) + "\" time=\"" +
                               seconds(totalSeconds(cases), "%.3f") + "\"";
    std::ostringstream out;
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<testsuites name=\"shadowscope check\" " << counts << ">\n"
        << "  <testsuite name=\"" << xmlEscape(suite) << "\" " << counts << " skipped=\"0\">\n";
    for (const auto& c : cases) {
        out << "    <testcase name=\"" << xmlEscape(c.name) << "\" classname=\""
            << xmlEscape("shadowscope.check." + suite) << "\" time=\"" << seconds(c.seconds, "%.3f") << "\">\n";
        if (!c.error.empty()) {
            out << "      <error message=\"" << xmlEscape(c.error) << "\" type=\"render\">" << xmlEscape(c.error)
                << "</error>\n";
        } else if (c.failed()) {
            std::string message, body;
            for (const auto& v : c.verdicts)
                if (!v.passed) {
                    message += (message.empty() ? "" : "; ") + v.text;
                    body += v.text + "\n";
                }
            out << "      <failure message=\"" << xmlEscape(message) << "\" type=\"check\">" << xmlEscape(body)
                << "</failure>\n";
        }
        if (!c.verdicts.empty()) {
            std::string all;
            for (const auto& v : c.verdicts) all += std::string(v.passed ? "pass " : "FAIL ") + v.text + "\n";
            out << "      <system-out>" << xmlEscape(all) << "</system-out>\n";
        }
        out << "    </testcase>\n";
    }
    out << "  </testsuite>\n</testsuites>\n";
    return out.str();
}

} // namespace app
