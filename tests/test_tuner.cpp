// The tune search (geometry/analysis/tuner.h) against a synthetic measurement whose best answer a
// brute-force pass over the whole space finds: targets, the space, relevance, the search itself.
#include "geometry/analysis/tuner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>

using namespace geometry::analysis;
using namespace geometry::shadow;

namespace {

/// A made-up measurement: resolution and warp set p95, a constant bias leaves acne, hw2x2 leaves
/// ragged edges (a fraction that doubles at half the size, as 1-D edges do); PCF, resolution and
/// the warp cost time. The screening size quarters the time.
TuneFigures model(const ShadowSettings& s, Viewport size) {
    TuneFigures f;
    const bool warped = s.warp.method == WarpMethod::Lispsm;
    const double fullRes = double(s.resolution) * (size.width < 640 ? 2.0 : 1.0); // screening halves it
    f.p95 = 2048.0 / fullRes * (warped ? 0.5 : 1.0);
    f.interior = s.bias.type == BiasType::Constant ? 0.01 : 0.0;
    f.edge = (s.filter.type == FilterType::Pcf ? 0.001 : 0.004) * 640.0 / size.width; // 1-D edges: ∝ 1/size
    f.misclassified = f.interior + f.edge;
    f.frameMs = fullRes / 1024.0 * (s.filter.type == FilterType::Pcf ? 1.5 : 1.0) * (warped ? 1.1 : 1.0) *
                (size.width < 640 ? 0.25 : 1.0);
    f.costMs = f.frameMs; // the model's cost is its time: measured and modelled agree here
    f.memoryBytes = uint64_t(fullRes * fullRes * 4);
    return f;
}

std::vector<TuneAxis> smallSpace() {
    return {{"bias.type", {"constant", "slope"}},
            {"filter.type", {"hw2x2", "pcf"}},
            {"shadow_map.resolution", {"1024", "2048", "4096"}},
            {"warp.method", {"uniform", "lispsm"}},
            {"bias.constant", {"0.02", "0.05"}}};
}

ShadowSettings startSettings() {
    ShadowSettings s;
    s.bias.type = BiasType::Constant;
    s.filter.type = FilterType::Hw2x2;
    s.resolution = 2048;
    s.warp.method = WarpMethod::Uniform;
    return s;
}

/// Runs the tuner against the model; returns the number of measurements it asked for.
int run(Tuner& t) {
    int n = 0;
    while (const auto r = t.next()) {
        t.report(model(r->settings, r->size));
        ++n;
    }
    return n;
}

/// Every configuration of the space (all combinations), for the brute-force answer.
void forEachConfiguration(const std::vector<TuneAxis>& space, const ShadowSettings& start,
                          const std::function<void(const ShadowSettings&)>& fn, size_t axis = 0) {
    if (axis == space.size()) {
        fn(start);
        return;
    }
    for (const auto& v : space[axis].values) {
        ShadowSettings s = start;
        applySetting(s, space[axis].key, v);
        forEachConfiguration(space, s, fn, axis + 1);
    }
}

} // namespace

TEST(TuneTarget, ParsesAndRejects) {
    const TuneTarget t = parseTuneTarget("p95=2,interior=0.001,edge=0.02");
    EXPECT_EQ(t.p95, 2.0);
    EXPECT_EQ(t.interior, 0.001);
    EXPECT_EQ(t.edge, 0.02);
    EXPECT_FALSE(t.misclassified);
    EXPECT_EQ(formatTuneTarget(t), "p95=2,interior=0.001,edge=0.02");
    for (const char* bad :
         {"", "p95", "p95=", "p95=x", "p95=-1", "p95=nan", "p95=inf", "speed=1", "p95=1,p95=2", "p95=1,", "p95=1e999"})
        EXPECT_THROW((void)parseTuneTarget(bad), std::invalid_argument) << bad;
}

TEST(TuneTarget, ViolationRatioAndMisses) {
    const TuneTarget t = parseTuneTarget("p95=2,edge=0.01");
    TuneFigures f;
    f.p95 = 1.5;
    f.edge = 0.01;
    EXPECT_EQ(targetViolation(f, t), 0.0);
    EXPECT_LE(targetRatio(f, t), 1.0);
    EXPECT_EQ(describeMisses(f, t), "");
    f.edge = 0.0201;
    EXPECT_NEAR(targetViolation(f, t), 1.0, 1e-9) << "twice the target (with ε) is one doubling";
    EXPECT_NEAR(targetRatio(f, t), 2.0, 1e-9);
    EXPECT_EQ(describeMisses(f, t), "edge 0.0201 > 0.01");
    f.p95 = NAN;
    EXPECT_TRUE(std::isinf(targetViolation(f, t)));
}

// The soft-shadow keys: soft (soft_mean_abs against the sun's disk) and umbra (umbra_light); a figure
// the measurement could not give (no sun size) misses the target instead of meeting it.
TEST(TuneTarget, SoftAndUmbraKeys) {
    const TuneTarget t = parseTuneTarget("soft=0.01,umbra=0.02");
    EXPECT_EQ(t.soft, 0.01);
    EXPECT_EQ(t.umbra, 0.02);
    EXPECT_FALSE(t.empty());
    EXPECT_EQ(formatTuneTarget(t), "soft=0.01,umbra=0.02");
    TuneFigures f;
    f.soft = 0.005;
    f.umbra = 0.0401;
    EXPECT_EQ(describeMisses(f, t), "umbra 0.0401 > 0.02");
    f.soft = NAN; // a point sun: no soft truth
    EXPECT_TRUE(std::isinf(targetViolation(f, t)));
    EXPECT_THROW((void)parseTuneTarget("soft=1,soft=2"), std::invalid_argument);
}

// The keys of the verdicts no setting can game: contact (peter-panning), interior_abs (a filter's
// darkening), edge_width (texels); the tightest fraction decides the screening size; the cost that
// ranks is the modelled one, never the measured time.
TEST(TuneTarget, ContactInteriorAbsEdgeWidthAndTheModelledCost) {
    const TuneTarget t = parseTuneTarget("contact=0.002,interior_abs=0.01,edge_width=0.25,edge=0.004");
    EXPECT_EQ(formatTuneTarget(t), "edge=0.004,contact=0.002,interior_abs=0.01,edge_width=0.25");
    EXPECT_EQ(t.tightestFraction(), 0.002);
    EXPECT_FALSE(parseTuneTarget("p95=2").tightestFraction());
    TuneFigures f;
    f.edge = 0.001;
    f.contact = 0.003;
    f.interiorAbs = 0.005;
    f.edgeWidth = 0.5;
    EXPECT_EQ(describeMisses(f, t), "contact 0.003 > 0.002, edge_width 0.5 > 0.25");
    TuneFigures a, b;
    a.costMs = 2, b.costMs = 3;
    a.frameMs = 30, b.frameMs = 1; // a loaded machine measured a as slow: it is still the cheaper
    EXPECT_EQ(compareTuneCost(a, b), -1);
    b.costMs = 2;
    b.memoryBytes = 1;
    a.memoryBytes = 2;
    EXPECT_EQ(compareTuneCost(a, b), 1) << "as costly: the smaller maps";
    try {
        (void)parseTuneTarget("speed=1");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("edge_width"), std::string::npos) << e.what();
    }
}

// Screening at half size only where one of its pixels is under a tenth of the tightest fraction;
// a soft target needs a sun of size; a resolution beyond the memory budget is measured as drawn.
TEST(Tuner, ScreeningSizeSoftTargetsAndTheBudget) {
    TuneOptions o{.size = {640, 360}, .budgetEvals = 10};
    o.receiverPixels = 100000; // a quarter of that at half size: 25000 pixels, one is 4e-5
    EXPECT_TRUE(Tuner(startSettings(), smallSpace(), parseTuneTarget("interior=0.001"), o).screensAtHalfSize());
    EXPECT_FALSE(Tuner(startSettings(), smallSpace(), parseTuneTarget("interior=0.0001"), o).screensAtHalfSize());
    EXPECT_TRUE(Tuner(startSettings(), smallSpace(), parseTuneTarget("p95=1"), o).screensAtHalfSize());
    o.receiverPixels = 0;
    Tuner full(startSettings(), smallSpace(), parseTuneTarget("edge=0.01"), o);
    EXPECT_FALSE(full.screensAtHalfSize());
    const auto first = full.next();
    ASSERT_TRUE(first);
    EXPECT_EQ(first->size.width, 640);
    EXPECT_EQ(first->settings.resolution, startSettings().resolution);
    EXPECT_THROW(Tuner(startSettings(), smallSpace(), parseTuneTarget("soft=0.01"), o), std::invalid_argument);
    std::vector<TuneAxis> sun = smallSpace();
    sun.push_back({"light.angular_diameter_deg", {"0", "0.5"}});
    EXPECT_NO_THROW(Tuner(startSettings(), sun, parseTuneTarget("soft=0.01"), o));
    ShadowSettings huge = startSettings();
    huge.splits.count = 8;
    huge.resolution = 8192;
    Tuner budget(huge, {{"shadow_map.resolution", {"8192", "4096"}}}, parseTuneTarget("p95=0.1"),
                 {.size = {640, 360}, .budgetEvals = 10});
    int measured = 0;
    while (const auto r = budget.next()) {
        EXPECT_LE(r->settings.resolution, 4096) << "8 × 8192² is over the budget";
        budget.report(model(r->settings, r->size));
        ++measured;
    }
    EXPECT_EQ(measured - budget.fullEvaluations(), 1) << "8192 and 4096 are drawn alike: screened once";
}

TEST(TuneFigures, CombiningViewsTakesTheWorstAccuracyAndTheSummedTime) {
    TuneFigures a, b;
    a.p95 = 1;
    a.interior = 0.01;
    a.edge = 0.002;
    a.misclassified = 0.02;
    a.frameMs = 10;
    a.memoryBytes = 5;
    b = a;
    b.p95 = 3;
    b.edge = 0.001;
    b.frameMs = 5;
    b.memoryBytes = 7;
    const TuneFigures c = combineViews({a, b});
    EXPECT_EQ(c.p95, 3);
    EXPECT_EQ(c.edge, 0.002);
    EXPECT_EQ(c.frameMs, 15);
    EXPECT_EQ(c.memoryBytes, 7u);
    a.costMs = 4;
    b.costMs = 6;
    a.contact = 0.001;
    b.contact = 0.003;
    a.edgeWidth = 0.2;
    b.edgeWidth = 0.1;
    EXPECT_EQ(combineViews({a, b}).costMs, 10);
    EXPECT_EQ(combineViews({a, b}).contact, 0.003);
    EXPECT_EQ(combineViews({a, b}).edgeWidth, 0.2);
    b.interior = NAN;
    EXPECT_TRUE(std::isnan(combineViews({a, b}).interior));
}

TEST(TuneSpace, OverridesValidateAndAdd) {
    std::vector<TuneAxis> space = defaultTuneSpace();
    EXPECT_GT(tuneSpaceSize(space), 1000.0);
    overrideTuneAxis(space, "shadow_map.resolution=512,1024");
    const auto res =
        std::find_if(space.begin(), space.end(), [](const TuneAxis& a) { return a.key == "shadow_map.resolution"; });
    ASSERT_NE(res, space.end());
    EXPECT_EQ(res->values, (std::vector<std::string>{"512", "1024"}));
    const size_t axes = space.size();
    overrideTuneAxis(space, "warp.multiplier=0.5,1");
    EXPECT_EQ(space.size(), axes + 1);
    for (const char* bad : {"nokey", "=1", "shadow_map.resolution=", "bogus.key=1", "shadow_map.resolution=3",
                            "filter.kernel=4", "bias.type=sideways"})
        EXPECT_THROW(overrideTuneAxis(space, bad), std::invalid_argument) << bad;
}

TEST(TuneSpace, SettingsMatterOnlyWhereTheOthersUseThem) {
    ShadowSettings s;
    s.bias.type = BiasType::Slope;
    s.splits.count = 1;
    s.filter.type = FilterType::Hw2x2;
    EXPECT_FALSE(settingMatters(s, "bias.constant"));
    EXPECT_TRUE(settingMatters(s, "bias.slope"));
    EXPECT_FALSE(settingMatters(s, "bias.normal_offset"));
    EXPECT_FALSE(settingMatters(s, "splits.alpha"));
    EXPECT_FALSE(settingMatters(s, "filter.kernel"));
    EXPECT_TRUE(settingMatters(s, "shadow_map.resolution"));
    s.bias.type = BiasType::SlopeNormalOffset;
    s.splits.count = 3;
    s.splits.scheme = SplitScheme::Adaptive;
    s.filter.type = FilterType::Pcf;
    EXPECT_TRUE(settingMatters(s, "bias.normal_offset"));
    EXPECT_TRUE(settingMatters(s, "splits.alpha"));
    EXPECT_FALSE(settingMatters(s, "splits.lambda"));
    EXPECT_TRUE(settingMatters(s, "filter.kernel"));
}

// The search finds the brute-force answer of the small space: the cheapest configuration that
// meets the target. Reaching it takes two changes at once (the warp pays off only with a lower
// resolution), which a plain coordinate descent misses and the beam does not. It measures far
// fewer configurations than the space holds, confirms at full size, and never measures a
// configuration twice at one stage (bias.constant is irrelevant under a slope bias).
TEST(Tuner, FindsTheCheapestConfigurationThatMeetsTheTarget) {
    const TuneTarget target = parseTuneTarget("p95=0.6,interior=0.001,edge=0.002");
    const std::vector<TuneAxis> space = smallSpace();
    std::optional<ShadowSettings> best;
    double bestMs = INFINITY;
    forEachConfiguration(space, startSettings(), [&](const ShadowSettings& s) {
        const TuneFigures f = model(s, {640, 360});
        if (targetViolation(f, target) == 0 && f.frameMs < bestMs) {
            bestMs = f.frameMs;
            best = s;
        }
    });
    ASSERT_TRUE(best);
    ASSERT_EQ(best->warp.method, WarpMethod::Lispsm);
    ASSERT_EQ(best->resolution, 2048);

    Tuner t(startSettings(), space, target, {.size = {640, 360}, .budgetEvals = 40, .receiverPixels = 640.0 * 360.0});
    const int measured = run(t);
    EXPECT_TRUE(t.done());
    EXPECT_EQ(t.progress(), 1.0);
    EXPECT_LE(measured, 40);
    EXPECT_LT(t.fullEvaluations(), int(tuneSpaceSize(space)));
    EXPECT_GE(t.fullEvaluations(), 1);
    const auto rec = t.recommended();
    ASSERT_TRUE(rec);
    const TuneEvaluation& e = t.evaluations()[*rec];
    EXPECT_EQ(e.request.stage, TuneStage::Full);
    EXPECT_TRUE(e.meets());
    EXPECT_NEAR(e.figures.frameMs, bestMs, 1e-9) << e.request.label;
    EXPECT_EQ(e.candidate.warp.method, WarpMethod::Lispsm);
    EXPECT_EQ(e.candidate.resolution, 2048);
    EXPECT_EQ(e.request.size.width, 640);
    // Screening measured at half size and half resolution; its edge error compared at full size.
    for (const TuneEvaluation& s : t.evaluations())
        if (s.request.stage == TuneStage::Screen) {
            EXPECT_EQ(s.request.size.width, 320);
            EXPECT_EQ(s.request.settings.resolution * 2, s.candidate.resolution);
            EXPECT_DOUBLE_EQ(s.figures.edge, model(s.candidate, {640, 360}).edge);
        }
    for (const TuneEvaluation& s : t.evaluations())
        EXPECT_EQ(s.violation, targetViolation(s.figures, target)) << "judged on the figures it keeps";
    // No configuration screened twice once irrelevant settings are ignored.
    std::vector<std::string> seen;
    for (const TuneEvaluation& s : t.evaluations()) {
        if (s.request.stage != TuneStage::Screen) continue;
        ShadowSettings c = s.candidate;
        if (c.bias.type != BiasType::Constant) c.bias.constant = 0.05f;
        const std::string key = std::to_string(int(c.bias.type)) + std::to_string(int(c.filter.type)) +
                                std::to_string(c.resolution) + std::to_string(int(c.warp.method)) +
                                std::to_string(c.bias.constant);
        EXPECT_EQ(std::count(seen.begin(), seen.end(), key), 0) << s.request.label;
        seen.push_back(key);
    }
}

// Nothing meets: no recommendation, the closest full-size evaluation instead; the budget holds.
TEST(Tuner, ReportsTheClosestWhenNothingMeets) {
    const TuneTarget target = parseTuneTarget("p95=0.01");
    Tuner t(startSettings(), smallSpace(), target, {.size = {640, 360}, .budgetEvals = 12});
    EXPECT_EQ(run(t), 12);
    EXPECT_FALSE(t.recommended());
    const auto near = t.closest();
    ASSERT_TRUE(near);
    const TuneEvaluation& e = t.evaluations()[*near];
    EXPECT_EQ(e.request.stage, TuneStage::Full);
    EXPECT_FALSE(e.meets());
    EXPECT_NE(describeMisses(e.figures, target).find("p95"), std::string::npos);
    for (const TuneEvaluation& other : t.evaluations()) {
        if (other.request.stage == TuneStage::Full) {
            EXPECT_GE(other.violation, e.violation);
        }
    }
}

TEST(Tuner, RejectsBadSetupsAndReportsOutOfTurn) {
    const TuneTarget target = parseTuneTarget("p95=1");
    EXPECT_THROW(Tuner(startSettings(), smallSpace(), TuneTarget{}, {}), std::invalid_argument);
    EXPECT_THROW(Tuner(startSettings(), {}, target, {}), std::invalid_argument);
    EXPECT_THROW(Tuner(startSettings(), smallSpace(), target, {.budgetEvals = 1}), std::invalid_argument);
    ShadowSettings bad = startSettings();
    bad.resolution = 3;
    EXPECT_THROW(Tuner(bad, smallSpace(), target, {}), std::invalid_argument);
    Tuner t(startSettings(), smallSpace(), target, {});
    EXPECT_THROW(t.report({}), std::logic_error);
    const auto first = t.next();
    ASSERT_TRUE(first);
    EXPECT_EQ(t.next()->label, first->label) << "asking again repeats the pending request";
    t.report(model(first->settings, first->size));
    EXPECT_EQ(t.evaluations().size(), 1u);
    EXPECT_EQ(t.evaluations()[0].request.label, "start");
}
