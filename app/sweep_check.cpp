#include "sweep_check.h"

#include "ui/charts/analytic_charts.h"

#include "geometry/analysis/stability_metrics.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

namespace app {

namespace {

std::string fixed(double v, int digits) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

std::string where(const SweepRecord& r) { return "method " + r.method + " at " + fixed(r.angleDeg, 2) + " deg"; }

/// The numeric columns, in CSV order after angle_deg and method, with their record members.
struct Column {
    const char* name;
    double SweepRecord::*member;
};
constexpr Column kColumns[] = {
    {"n_prime", &SweepRecord::nPrime},
    {"p95", &SweepRecord::p95},
    {"max", &SweepRecord::max},
    {"false_lit", &SweepRecord::falseLit},
    {"false_shadow", &SweepRecord::falseShadow},
    {"gamma_deg", &SweepRecord::gammaDeg},
    {"lambda", &SweepRecord::lambda},
    {"n_prime_min", &SweepRecord::nPrimeMin},
    {"p50", &SweepRecord::p50},
    {"mean", &SweepRecord::mean},
    {"receivers", &SweepRecord::receivers},
    {"gl_errors", &SweepRecord::glErrors},
    {"p95_uniform", &SweepRecord::p95Uniform},
    {"clipped_casters", &SweepRecord::clippedCasters},
    {"false_lit_clipped", &SweepRecord::falseLitClipped},
    {"singular", &SweepRecord::singular},
};
/// Columns an older sweep.csv may lack (read as 0).
bool optionalColumn(std::string_view name) { return name == "singular"; }

/// The warp's gain over uniform shadow mapping at the same angle (< 1: fewer pixels per texel).
double gain(const SweepRecord& r) { return r.p95 / r.p95Uniform; }

bool isNPrime(const Column& c) { return c.member == &SweepRecord::nPrime || c.member == &SweepRecord::nPrimeMin; }

double parseNumber(std::string_view s, const std::string& what) {
    if (s == "nan" || s == "-nan") return std::nan("");
    if (s == "inf") return INFINITY;
    if (s == "-inf") return -INFINITY;
    double v = 0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (r.ec != std::errc() || r.ptr != s.data() + s.size())
        throw std::runtime_error(what + ": '" + std::string(s) + "' is not a number");
    return v;
}

std::vector<std::string_view> splitFields(std::string_view line) {
    std::vector<std::string_view> out;
    size_t start = 0;
    for (;;) {
        const size_t comma = line.find(',', start);
        out.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) return out;
        start = comma + 1;
    }
}

} // namespace

bool promisesContinuity(std::string_view method) noexcept {
    return method == "lispsm" || method == "glispsm" || method == "gmnpr";
}

std::vector<std::string> checkSweep(const std::vector<SweepRecord>& rows, const SweepThresholds& t) {
    std::vector<std::string> failures;
    for (const SweepRecord& r : rows) {
        if (!std::isfinite(r.angleDeg)) failures.push_back(where(r) + ": angle_deg is " + formatCsvNumber(r.angleDeg));
        for (const Column& c : kColumns) {
            const double v = r.*(c.member);
            if (std::isnan(v) || (std::isinf(v) && !(isNPrime(c) && v > 0)))
                failures.push_back(where(r) + ": " + c.name + " is " + formatCsvNumber(v));
        }
        if (r.glErrors > 0) failures.push_back(where(r) + ": GL error after the frame");
        if (r.falseLitClipped > t.maxFalseLitClipped)
            failures.push_back(where(r) + ": false_lit_clipped " + fixed(r.falseLitClipped, 4) + " exceeds " +
                               fixed(t.maxFalseLitClipped, 4) +
                               " (casters outside the light frustum; clipped_casters " + fixed(r.clippedCasters, 4) +
                               ", false_lit " + fixed(r.falseLit, 4) + ")");
    }
    std::map<std::string, std::vector<const SweepRecord*>> byMethod;
    for (const SweepRecord& r : rows)
        if (promisesContinuity(r.method) && std::isfinite(r.angleDeg)) byMethod[r.method].push_back(&r);
    for (auto& [method, list] : byMethod) {
        std::stable_sort(list.begin(), list.end(), [](auto* a, auto* b) { return a->angleDeg < b->angleDeg; });
        for (size_t i = 1; i < list.size(); ++i) {
            const SweepRecord& a = *list[i - 1];
            const SweepRecord& b = *list[i];
            const double step = b.angleDeg - a.angleDeg;
            if (!(step > 0 && step <= t.continuityStepDeg)) continue;
            if (!(a.receivers >= t.minReceivers && b.receivers >= t.minReceivers)) continue;
            // Frames where more than 5 % of the receivers have a singular J (edge-on to the light, e.g.
            // the sea as the sun crosses the horizon) measure the scene's geometry, not the warp: not
            // judged. (Older CSVs, whose p95 still included those pixels, show them as a p95 at the cap.)
            const auto capped = [](const SweepRecord& r) {
                return r.singular > 0.05 || r.p95 >= geometry::analysis::kSingularM ||
                       r.p95Uniform >= geometry::analysis::kSingularM;
            };
            if (capped(a) || capped(b)) continue;
            const double ga = gain(a), gb = gain(b);
            if (!(ga > 0 && gb > 0 && std::isfinite(ga) && std::isfinite(gb))) continue;
            const double ratio = std::max(ga, gb) / std::min(ga, gb);
            if (ratio > t.maxP95Ratio)
                failures.push_back(where(b) + ": p95 m / uniform's jumped " + fixed(ratio, 2) + "x (" + fixed(ga, 4) +
                                   " at " + fixed(a.angleDeg, 2) + " deg -> " + fixed(gb, 4) + "; p95 " +
                                   fixed(a.p95, 3) + " -> " + fixed(b.p95, 3) + ") over " + fixed(step, 2) +
                                   " deg, limit " + fixed(t.maxP95Ratio, 2) + "x");
        }
    }
    return failures;
}

std::string sweepCsvHeader() {
    std::string h = "angle_deg,method";
    for (const Column& c : kColumns) h += std::string(",") + c.name;
    return h;
}

std::string sweepCsvRow(const SweepRecord& r) {
    std::string s = formatCsvNumber(r.angleDeg) + "," + r.method;
    for (const Column& c : kColumns) s += "," + formatCsvNumber(r.*(c.member));
    return s;
}

std::vector<SweepRecord> parseSweepCsv(std::string_view text) {
    std::vector<std::string_view> lines;
    for (size_t start = 0; start < text.size();) {
        size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (!line.empty()) lines.push_back(line);
        start = end + 1;
    }
    if (lines.empty()) throw std::runtime_error("empty sweep CSV: expected a header line");
    const auto header = splitFields(lines[0]);
    const auto column = [&](std::string_view name) {
        const auto it = std::find(header.begin(), header.end(), name);
        if (it == header.end()) throw std::runtime_error("sweep CSV has no column '" + std::string(name) + "'");
        return size_t(it - header.begin());
    };
    const size_t angle = column("angle_deg"), method = column("method");
    std::vector<std::pair<size_t, double SweepRecord::*>> numeric;
    for (const Column& c : kColumns)
        if (!optionalColumn(c.name) || std::find(header.begin(), header.end(), c.name) != header.end())
            numeric.emplace_back(column(c.name), c.member);
    std::vector<SweepRecord> rows;
    for (size_t i = 1; i < lines.size(); ++i) {
        const auto f = splitFields(lines[i]);
        const std::string line = "sweep CSV line " + std::to_string(i + 1);
        if (f.size() != header.size())
            throw std::runtime_error(line + ": " + std::to_string(f.size()) + " fields, the header has " +
                                     std::to_string(header.size()));
        SweepRecord r;
        r.angleDeg = parseNumber(f[angle], line + " angle_deg");
        r.method = std::string(f[method]);
        for (const auto& [index, member] : numeric)
            r.*member = parseNumber(f[index], line + " " + std::string(header[index]));
        rows.push_back(std::move(r));
    }
    return rows;
}

std::string formatCsvNumber(double v) { return ui::charts::formatNumber(v); }

} // namespace app
