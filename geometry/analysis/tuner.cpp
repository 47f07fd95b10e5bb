#include "geometry/analysis/tuner.h"

#include "geometry/shadow/memory_budget.h"

#include <algorithm>
#include <stdexcept>

namespace geometry::analysis {

using shadow::ShadowSettings;

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
    bool sunOfSize = start_.light.angularDiameterDeg > 0.f;
    for (const TuneAxis& a : space_)
        for (const std::string& v : a.values) {
            ShadowSettings probe = start_;
            shadow::applySetting(probe, a.key, v); // throws for a value the declaration rejects
            sunOfSize = sunOfSize || probe.light.angularDiameterDeg > 0.f;
        }
    if (target_.soft && !sunOfSize)
        throw std::invalid_argument("--target soft: soft_mean_abs needs a sun of size; set "
                                    "light.angular_diameter_deg > 0");
    // Half-size screening only where one of its pixels (a quarter of the receivers) is under a
    // tenth of the tightest fractional target: else a single pixel decides a verdict.
    if (const auto tightest = target_.tightestFraction()) halfSize_ = options_.receiverPixels / 4.0 * *tightest >= 10.0;
}

namespace {

/// The configuration as drawn: a resolution beyond the memory budget is the one the plan draws.
ShadowSettings withinBudget(ShadowSettings s) noexcept {
    s.resolution = shadow::budgetedResolution(s);
    return s;
}

} // namespace

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
        if (const int c = compareTuneCost(a.figures, b.figures); c != 0) return c < 0;
        // As cheap: the one further inside the target has more room to trade for a cheaper setting.
        return targetRatio(a.figures, target_) < targetRatio(b.figures, target_);
    }
    if (a.violation != b.violation) return a.violation < b.violation;
    return compareTuneCost(a.figures, b.figures) < 0;
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
        if (stage == TuneStage::Screen && halfSize_) {
            // Half the width, height and map resolution: the same texels per pixel, a quarter of the work.
            e.request.settings.resolution = std::max(16, candidate.resolution / 2);
            e.request.size = {std::max(32, options_.size.width / 2), std::max(32, options_.size.height / 2)};
        }
        pending_ = std::move(e);
        pendingKey_ = canonical(candidate);
        return pending_->request;
    };
    // A sixth of the budget (at least `confirm`) is kept for full size: screening figures are close
    // but not exact, so the first candidates confirmed may just miss and the next ones be needed.
    const int screenBudget = options_.budgetEvals - std::max(options_.confirm, options_.budgetEvals / 6);
    while (true) {
        if (phase_ == Phase::Done) return std::nullopt;
        if (phase_ == Phase::Screen) {
            if (beam_.empty()) return request(withinBudget(start_), TuneStage::Screen);
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
            candidate = withinBudget(candidate);
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
    // Edge error and peter-panning are fractions of pixels along 1-D edges: at half the width (and
    // half the map) the same bands, as many pixels wide, cover about twice the fraction. Compare
    // them at full size.
    if (e.request.stage == TuneStage::Screen) {
        const double ratio = double(e.request.size.width) / double(options_.size.width);
        e.figures.edge *= ratio;
        e.figures.contact *= ratio;
    }
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
        if (!best || compareTuneCost(e.figures, evaluations_[*best].figures) < 0) best = i;
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
