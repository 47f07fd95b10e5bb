// Index
//   [SECTION] Targets and figures ..... parseTuneTarget, formatTuneTarget, tuneFigures, combineViews, violation
//   [SECTION] The search space ........ defaultTuneSpace, overrideTuneAxis, tuneSpaceSize, settingMatters
//   [SECTION] Tuner ................... next/report (the ask/tell loop), ranking, recommendation

#include "geometry/analysis/tuner.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace geometry::analysis {

using shadow::BiasType;
using shadow::FilterType;
using shadow::ShadowSettings;
using shadow::SplitScheme;
using shadow::WarpMethod;

// ---- [SECTION] Targets and figures ----------------------------------------------------------

namespace {

constexpr double kFractionEpsilon = 1e-4; // violation's ε for fractions (a hundredth of a percent)
constexpr double kP95Epsilon = 1e-2;      // and for m
// Frame times within 10 % are a tie, broken by memory: llvmpipe's medians of three frames on a
// shared machine scatter by about that much.
constexpr double kCostTie = 0.10;

std::string number(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

std::vector<std::string_view> splitList(std::string_view text) {
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
    return out;
}

double costOf(const TuneFigures& f) noexcept {
    return std::isfinite(f.frameMs) ? f.frameMs : std::numeric_limits<double>::infinity();
}

/// -1 when a is cheaper, 1 when b is, 0 for a tie: frame time (3 % is a tie), then memory.
int compareCost(const TuneFigures& a, const TuneFigures& b) noexcept {
    const double ca = costOf(a), cb = costOf(b);
    if (std::isfinite(ca) && std::isfinite(cb)) {
        if (std::abs(ca - cb) > kCostTie * std::min(ca, cb)) return ca < cb ? -1 : 1;
    } else if (std::isfinite(ca) != std::isfinite(cb)) {
        return std::isfinite(ca) ? -1 : 1;
    }
    if (a.memoryBytes != b.memoryBytes) return a.memoryBytes < b.memoryBytes ? -1 : 1;
    return 0;
}

} // namespace

TuneTarget parseTuneTarget(std::string_view text) {
    TuneTarget t;
    const auto bad = [&](const std::string& why) {
        return std::invalid_argument("--target " + std::string(text) + ": " + why);
    };
    if (text.empty()) throw bad("empty (keys: p95, interior, edge, misclassified)");
    for (std::string_view item : splitList(text)) {
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
                                                               : nullptr;
        if (!slot) throw bad("unknown key '" + key + "' (keys: p95, interior, edge, misclassified)");
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
    return out;
}

TuneFigures tuneFigures(const Inspection& in, double frameMs, uint64_t memoryBytes) noexcept {
    TuneFigures f;
    f.p95 = in.aliasing.count ? in.aliasing.p95 : TuneFigures::kNaN;
    if (in.truthClasses && in.truthClasses->count) {
        f.interior = in.truthClasses->interiorFalseShadow + in.truthClasses->interiorFalseLit;
        f.edge = in.truthClasses->edgeError;
    }
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

// ---- [SECTION] The search space -------------------------------------------------------------

std::vector<TuneAxis> defaultTuneSpace() {
    // The strongest levers first: coordinate descent takes the axes in this order.
    return {
        {"bias.type", {"constant", "slope", "slope_normal_offset"}},
        {"filter.type", {"hw2x2", "pcf"}},
        {"shadow_map.resolution", {"1024", "2048", "4096"}},
        {"warp.method", {"uniform", "lispsm", "glispsm"}},
        {"splits.count", {"1", "2", "3", "4"}},
        {"splits.scheme", {"practical", "adaptive"}},
        {"splits.alpha", {"2", "4"}},
        {"bias.constant", {"0.02", "0.05", "0.1"}},
        {"bias.slope", {"1", "2", "4"}},
        {"bias.normal_offset", {"0.5", "1", "2"}},
        {"filter.kernel", {"3", "5"}},
        {"bias.tangent_plane", {"false", "true"}},
    };
}

void overrideTuneAxis(std::vector<TuneAxis>& space, std::string_view spec) {
    const size_t eq = spec.find('=');
    if (eq == std::string_view::npos || eq == 0 || eq + 1 == spec.size())
        throw std::invalid_argument("--space " + std::string(spec) + ": expected KEY=v1,v2,...");
    TuneAxis axis{std::string(spec.substr(0, eq)), {}};
    ShadowSettings probe;
    for (std::string_view v : splitList(spec.substr(eq + 1))) {
        try {
            shadow::applySetting(probe, axis.key, v);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("--space " + std::string(spec) + ": " + e.what());
        }
        if (std::find(axis.values.begin(), axis.values.end(), v) == axis.values.end()) axis.values.emplace_back(v);
    }
    const auto it = std::find_if(space.begin(), space.end(), [&](const TuneAxis& a) { return a.key == axis.key; });
    if (it != space.end()) *it = std::move(axis);
    else space.push_back(std::move(axis));
}

double tuneSpaceSize(const std::vector<TuneAxis>& space) noexcept {
    double n = space.empty() ? 0.0 : 1.0;
    for (const TuneAxis& a : space) n *= double(std::max<size_t>(a.values.size(), 1));
    return n;
}

bool settingMatters(const ShadowSettings& s, std::string_view key) noexcept {
    const BiasType bias = s.bias.type;
    const FilterType filter = s.filter.type;
    const bool split = s.splits.count > 1;
    const bool warped = s.warp.method != WarpMethod::Uniform;
    if (key == "bias.constant") return bias == BiasType::Constant;
    if (key == "bias.slope" || key == "bias.units")
        return bias == BiasType::Slope || bias == BiasType::SlopeNormalOffset;
    if (key == "bias.z_max") return bias == BiasType::DualDepth;
    if (key == "bias.normal_offset") return bias == BiasType::NormalOffset || bias == BiasType::SlopeNormalOffset;
    if (key == "bias.tangent_plane") return filter == FilterType::Pcf || filter == FilterType::Disk;
    if (key == "filter.kernel") return filter == FilterType::Pcf || filter == FilterType::Vsm;
    if (key == "filter.taps" || key == "filter.radius") return filter == FilterType::Disk;
    if (key == "filter.bleed_reduction") return filter == FilterType::Vsm;
    if (key == "filter.eye_blur.falloff") return s.filter.eyeBlurIterations > 0;
    if (key == "warp.direction" || key == "warp.multiplier") return warped;
    if (key == "warp.falloff") return s.warp.method == WarpMethod::Glispsm;
    if (key == "warp.n_prime") return s.warp.method == WarpMethod::Manual;
    if (key == "warp.visible_far") return s.warp.method == WarpMethod::Lispsm;
    if (key == "splits.scheme" || key == "splits.resolution_falloff") return split;
    if (key == "splits.lambda") return split && s.splits.scheme == SplitScheme::Practical;
    if (key == "splits.ratio") return split && s.splits.scheme == SplitScheme::Pssm;
    if (key == "splits.alpha") return split && s.splits.scheme == SplitScheme::Adaptive;
    return true;
}

// ---- [SECTION] Tuner ------------------------------------------------------------------------

Tuner::Tuner(ShadowSettings start, std::vector<TuneAxis> space, TuneTarget target, TuneOptions options)
    : start_(start), space_(std::move(space)), target_(target), options_(options) {
    if (target_.empty())
        throw std::invalid_argument("--target: give at least one of p95, interior, edge, misclassified");
    space_.erase(std::remove_if(space_.begin(), space_.end(), [](const TuneAxis& a) { return a.values.empty(); }),
                 space_.end());
    if (space_.empty()) throw std::invalid_argument("--space: nothing to search");
    if (options_.budgetEvals < 2) throw std::invalid_argument("--budget-evals must be at least 2");
    if (options_.size.width < 1 || options_.size.height < 1) throw std::invalid_argument("--size must be positive");
    options_.confirm = std::clamp(options_.confirm, 1, options_.budgetEvals - 1);
    options_.beam = std::max(options_.beam, 1);
    shadow::validateOrThrow(start_);
    for (const TuneAxis& a : space_)
        for (const std::string& v : a.values) {
            ShadowSettings probe = start_;
            shadow::applySetting(probe, a.key, v); // throws for a value the declaration rejects
        }
}

std::string Tuner::canonical(const ShadowSettings& s) const {
    std::string out;
    for (const auto& info : shadow::settingsDeclaration())
        if (settingMatters(s, info.key)) out += std::string(info.key) + '=' + info.format(s) + ';';
    return out;
}

std::string Tuner::label(const ShadowSettings& s) const {
    std::string out;
    for (const TuneAxis& a : space_) {
        const shadow::SettingInfo* info = shadow::findSetting(a.key);
        if (!info || !settingMatters(s, a.key) || info->format(s) == info->format(start_)) continue;
        out += (out.empty() ? "" : " ") + a.key + "=" + info->format(s);
    }
    return out.empty() ? "start" : out;
}

bool Tuner::better(const TuneEvaluation& a, const TuneEvaluation& b) const noexcept {
    if (a.meets() != b.meets()) return a.meets();
    if (a.meets()) {
        if (const int c = compareCost(a.figures, b.figures); c != 0) return c < 0;
        // As cheap: the one further inside the target has more room to trade for a cheaper setting.
        return targetRatio(a.figures, target_) < targetRatio(b.figures, target_);
    }
    if (a.violation != b.violation) return a.violation < b.violation;
    return compareCost(a.figures, b.figures) < 0;
}

bool Tuner::siblings(const ShadowSettings& a, const ShadowSettings& b) const {
    for (const auto& info : shadow::settingsDeclaration()) {
        if (info.kind == shadow::SettingInfo::Kind::Float) continue;
        const bool ma = settingMatters(a, info.key), mb = settingMatters(b, info.key);
        if (ma != mb || (ma && info.format(a) != info.format(b))) return false;
    }
    return true;
}

std::optional<size_t> Tuner::screened(const std::string& key) const noexcept {
    for (size_t i = 0; i < evaluations_.size(); ++i)
        if (evaluations_[i].request.stage == TuneStage::Screen && keys_[i] == key) return i;
    return std::nullopt;
}

int Tuner::budgetLeft() const noexcept { return options_.budgetEvals - int(evaluations_.size()); }

double Tuner::progress() const noexcept {
    if (phase_ == Phase::Done) return 1.0;
    return std::min(1.0, double(evaluations_.size()) / double(options_.budgetEvals));
}

void Tuner::finishAxis() {
    std::vector<size_t> pool = beam_;
    for (size_t e : axisEvals_)
        if (std::find(pool.begin(), pool.end(), e) == pool.end()) pool.push_back(e);
    std::stable_sort(pool.begin(), pool.end(),
                     [&](size_t a, size_t b) { return better(evaluations_[a], evaluations_[b]); });
    // The best, then the best that is not a sibling (the same but for amounts) of one already
    // taken, so the beam does not fill with bias-amount variants of one configuration.
    std::vector<size_t> beam;
    for (const bool allowSiblings : {false, true})
        for (size_t e : pool) {
            if (beam.size() >= size_t(options_.beam)) break;
            if (std::find(beam.begin(), beam.end(), e) != beam.end()) continue;
            const bool sibling = std::any_of(beam.begin(), beam.end(), [&](size_t b) {
                return siblings(evaluations_[e].candidate, evaluations_[b].candidate);
            });
            if (!sibling || allowSiblings) beam.push_back(e);
        }
    if (beam != beam_) changed_ = true;
    beam_ = std::move(beam);
    axisBeam_ = beam_;
    axisEvals_.clear();
    ++axis_;
    member_ = 0;
    value_ = 0;
}

void Tuner::startConfirm() {
    ranked_.clear();
    for (size_t i = 0; i < evaluations_.size(); ++i)
        if (evaluations_[i].request.stage == TuneStage::Screen) ranked_.push_back(i);
    std::stable_sort(ranked_.begin(), ranked_.end(),
                     [&](size_t a, size_t b) { return better(evaluations_[a], evaluations_[b]); });
    nextConfirm_ = 0;
    phase_ = Phase::Confirm;
}

std::optional<TuneRequest> Tuner::next() {
    if (pending_) return pending_->request;
    const auto request = [&](const ShadowSettings& candidate, TuneStage stage) {
        TuneEvaluation e;
        e.candidate = candidate;
        e.request.settings = candidate;
        e.request.size = options_.size;
        e.request.stage = stage;
        e.request.label = label(candidate);
        if (stage == TuneStage::Screen) {
            // Half the width, height and map resolution: the same texels per pixel, a quarter of the work.
            e.request.settings.resolution = std::max(16, candidate.resolution / 2);
            e.request.size = {std::max(32, options_.size.width / 2), std::max(32, options_.size.height / 2)};
        }
        pending_ = std::move(e);
        pendingKey_ = canonical(candidate);
        return pending_->request;
    };
    const int screenBudget = options_.budgetEvals - options_.confirm;
    while (true) {
        if (phase_ == Phase::Done) return std::nullopt;
        if (phase_ == Phase::Screen) {
            if (beam_.empty()) return request(start_, TuneStage::Screen);
            if (axis_ >= space_.size()) { // the end of a pass
                ++pass_;
                if (!changed_ || pass_ >= options_.maxPasses) {
                    startConfirm();
                    continue;
                }
                changed_ = false;
                axis_ = member_ = value_ = 0;
                axisBeam_ = beam_;
                continue;
            }
            const TuneAxis& axis = space_[axis_];
            if (member_ >= axisBeam_.size()) {
                finishAxis();
                continue;
            }
            if (value_ >= axis.values.size()) {
                ++member_;
                value_ = 0;
                continue;
            }
            ShadowSettings candidate = evaluations_[axisBeam_[member_]].candidate;
            shadow::applySetting(candidate, axis.key, axis.values[value_++]);
            if (const auto seen = screened(canonical(candidate))) {
                axisEvals_.push_back(*seen);
                continue;
            }
            if (int(evaluations_.size()) >= screenBudget) {
                finishAxis();
                startConfirm();
                continue;
            }
            return request(candidate, TuneStage::Screen);
        }
        // Confirm: the best screened candidates at full size; more while none meets the target.
        const int confirmed = fullEvaluations();
        if (budgetLeft() <= 0 || nextConfirm_ >= ranked_.size() || (confirmed >= options_.confirm && recommended())) {
            phase_ = Phase::Done;
            continue;
        }
        return request(evaluations_[ranked_[nextConfirm_++]].candidate, TuneStage::Full);
    }
}

void Tuner::report(const TuneFigures& figures) {
    if (!pending_) throw std::logic_error("Tuner::report without a request from next()");
    TuneEvaluation e = std::move(*pending_);
    pending_.reset();
    e.figures = figures;
    // Edge error is a fraction of pixels along 1-D edges: at half the width the same edges, the
    // same number of pixels wide, cover about twice the fraction. Compare it at full size.
    if (e.request.stage == TuneStage::Screen)
        e.figures.edge *= double(e.request.size.width) / double(options_.size.width);
    e.violation = targetViolation(e.figures, target_);
    evaluations_.push_back(std::move(e));
    keys_.push_back(pendingKey_);
    const size_t index = evaluations_.size() - 1;
    if (evaluations_[index].request.stage != TuneStage::Screen) return;
    if (beam_.empty()) beam_ = axisBeam_ = {index};
    else axisEvals_.push_back(index);
}

int Tuner::fullEvaluations() const noexcept {
    return int(std::count_if(evaluations_.begin(), evaluations_.end(),
                             [](const TuneEvaluation& e) { return e.request.stage == TuneStage::Full; }));
}

std::optional<size_t> Tuner::recommended() const noexcept {
    std::optional<size_t> best;
    for (size_t i = 0; i < evaluations_.size(); ++i) {
        const TuneEvaluation& e = evaluations_[i];
        if (e.request.stage != TuneStage::Full || !e.meets()) continue;
        if (!best || compareCost(e.figures, evaluations_[*best].figures) < 0) best = i;
    }
    return best;
}

std::optional<size_t> Tuner::closest() const noexcept {
    std::optional<size_t> best;
    const bool anyFull = fullEvaluations() > 0;
    for (size_t i = 0; i < evaluations_.size(); ++i) {
        const TuneEvaluation& e = evaluations_[i];
        if (anyFull && e.request.stage != TuneStage::Full) continue;
        if (!best || better(e, evaluations_[*best])) best = i;
    }
    return best;
}

} // namespace geometry::analysis
