#include "geometry/analysis/tune_target.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace geometry::analysis {

namespace {

constexpr double kFractionEpsilon = 1e-4; // violation's ε for fractions (a hundredth of a percent)
constexpr double kP95Epsilon = 1e-2;      // and for m (and texels of edge width)
constexpr const char* kKeys =
    "keys: p95, interior, edge, misclassified, soft, umbra, contact, interior_abs, edge_width";

std::string number(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

} // namespace

std::vector<std::string_view> splitCommas(std::string_view text) {
    std::vector<std::string_view> out;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = text.find(',', start);
        const size_t end = comma == std::string_view::npos ? text.size() : comma;
        out.push_back(text.substr(start, end - start));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return out;
}

namespace {

/// (figure, target, ε, name) for each key the target sets.
struct TargetTerm {
    double value, target, epsilon;
    const char* name;
};

std::vector<TargetTerm> terms(const TuneFigures& f, const TuneTarget& t) {
    std::vector<TargetTerm> out;
    if (t.p95) out.push_back({f.p95, *t.p95, kP95Epsilon, "p95"});
    if (t.interior) out.push_back({f.interior, *t.interior, kFractionEpsilon, "interior"});
    if (t.edge) out.push_back({f.edge, *t.edge, kFractionEpsilon, "edge"});
    if (t.misclassified) out.push_back({f.misclassified, *t.misclassified, kFractionEpsilon, "misclassified"});
    if (t.soft) out.push_back({f.soft, *t.soft, kFractionEpsilon, "soft"});
    if (t.umbra) out.push_back({f.umbra, *t.umbra, kFractionEpsilon, "umbra"});
    if (t.contact) out.push_back({f.contact, *t.contact, kFractionEpsilon, "contact"});
    if (t.interiorAbs) out.push_back({f.interiorAbs, *t.interiorAbs, kFractionEpsilon, "interior_abs"});
    if (t.edgeWidth) out.push_back({f.edgeWidth, *t.edgeWidth, kP95Epsilon, "edge_width"});
    return out;
}

double costOf(const TuneFigures& f) noexcept {
    return std::isfinite(f.costMs) ? f.costMs : std::numeric_limits<double>::infinity();
}

} // namespace

std::optional<double> TuneTarget::tightestFraction() const noexcept {
    std::optional<double> out;
    for (const auto& v : {interior, edge, misclassified, contact})
        if (v && (!out || *v < *out)) out = *v;
    return out;
}

int compareTuneCost(const TuneFigures& a, const TuneFigures& b) noexcept {
    const double ca = costOf(a), cb = costOf(b);
    if (ca != cb) return ca < cb ? -1 : 1;
    if (a.memoryBytes != b.memoryBytes) return a.memoryBytes < b.memoryBytes ? -1 : 1;
    return 0;
}

TuneTarget parseTuneTarget(std::string_view text) {
    TuneTarget t;
    const auto bad = [&](const std::string& why) {
        return std::invalid_argument("--target " + std::string(text) + ": " + why);
    };
    if (text.empty()) throw bad(std::string("empty (") + kKeys + ")");
    for (std::string_view item : splitCommas(text)) {
        const size_t eq = item.find('=');
        if (eq == std::string_view::npos) throw bad("'" + std::string(item) + "' is not KEY=VALUE");
        const std::string key(item.substr(0, eq)), value(item.substr(eq + 1));
        double v = 0;
        size_t used = 0;
        try {
            v = std::stod(value, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != value.size() || !std::isfinite(v) || v < 0)
            throw bad("'" + value + "' is not a finite number >= 0");
        std::optional<double>* slot = key == "p95"             ? &t.p95
                                      : key == "interior"      ? &t.interior
                                      : key == "edge"          ? &t.edge
                                      : key == "misclassified" ? &t.misclassified
                                      : key == "soft"          ? &t.soft
                                      : key == "umbra"         ? &t.umbra
                                      : key == "contact"       ? &t.contact
                                      : key == "interior_abs"  ? &t.interiorAbs
                                      : key == "edge_width"    ? &t.edgeWidth
                                                               : nullptr;
        if (!slot) throw bad("unknown key '" + key + "' (" + kKeys + ")");
        if (*slot) throw bad("'" + key + "' given twice");
        *slot = v;
    }
    return t;
}

std::string formatTuneTarget(const TuneTarget& t) {
    std::string out;
    const auto add = [&](const char* key, const std::optional<double>& v) {
        if (v) out += (out.empty() ? "" : ",") + std::string(key) + "=" + number(*v);
    };
    add("p95", t.p95);
    add("interior", t.interior);
    add("edge", t.edge);
    add("misclassified", t.misclassified);
    add("soft", t.soft);
    add("umbra", t.umbra);
    add("contact", t.contact);
    add("interior_abs", t.interiorAbs);
    add("edge_width", t.edgeWidth);
    return out;
}

TuneFigures tuneFigures(const Inspection& in, double costMs, double frameMs, uint64_t memoryBytes) noexcept {
    TuneFigures f;
    f.p95 = in.aliasing.count ? in.aliasing.p95 : TuneFigures::kNaN;
    if (const auto& c = in.truthClasses; c && c->count) {
        f.interior = c->interiorFalseShadow + c->interiorFalseLit;
        f.edge = c->edgeError;
        f.umbra = c->umbraLight;
        f.contact = c->contactFalseLit;
        f.interiorAbs = c->interiorMeanAbs;
        f.edgeWidth = c->edgeWidthTexels;
    }
    f.costMs = costMs;
    if (in.softTruth) f.soft = in.softTruth->meanAbs;
    if (in.truth && in.truth->count) f.misclassified = in.truth->falseShadow + in.truth->falseLit;
    f.frameMs = frameMs;
    f.memoryBytes = memoryBytes;
    return f;
}

TuneFigures combineViews(const std::vector<TuneFigures>& views) noexcept {
    if (views.empty()) return {};
    TuneFigures out = views.front();
    for (size_t i = 1; i < views.size(); ++i) {
        const TuneFigures& v = views[i];
        // NaN wins: a view without a figure leaves the whole configuration without it.
        const auto worst = [](double a, double b) {
            return std::isnan(a) || std::isnan(b) ? TuneFigures::kNaN : std::max(a, b);
        };
        out.p95 = worst(out.p95, v.p95);
        out.interior = worst(out.interior, v.interior);
        out.edge = worst(out.edge, v.edge);
        out.misclassified = worst(out.misclassified, v.misclassified);
        out.soft = worst(out.soft, v.soft);
        out.umbra = worst(out.umbra, v.umbra);
        out.contact = worst(out.contact, v.contact);
        out.interiorAbs = worst(out.interiorAbs, v.interiorAbs);
        out.edgeWidth = worst(out.edgeWidth, v.edgeWidth);
        out.costMs += v.costMs;
        out.frameMs += v.frameMs;
        out.memoryBytes = std::max(out.memoryBytes, v.memoryBytes);
    }
    return out;
}

double targetViolation(const TuneFigures& f, const TuneTarget& target) noexcept {
    double sum = 0;
    for (const TargetTerm& t : terms(f, target)) {
        if (!std::isfinite(t.value)) return std::numeric_limits<double>::infinity();
        sum += std::max(0.0, std::log2((t.value + t.epsilon) / (t.target + t.epsilon)));
    }
    return sum;
}

double targetRatio(const TuneFigures& f, const TuneTarget& target) noexcept {
    double worst = 0;
    for (const TargetTerm& t : terms(f, target)) {
        if (!std::isfinite(t.value)) return std::numeric_limits<double>::infinity();
        worst = std::max(worst, (t.value + t.epsilon) / (t.target + t.epsilon));
    }
    return worst;
}

std::string describeMisses(const TuneFigures& f, const TuneTarget& target) {
    std::string out;
    for (const TargetTerm& t : terms(f, target))
        if (!(t.value <= t.target))
            out += (out.empty() ? "" : ", ") + std::string(t.name) + " " + number(t.value) + " > " + number(t.target);
    return out;
}

} // namespace geometry::analysis
