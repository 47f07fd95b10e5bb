#pragma once
// What `shadowscope sweep gamma --check` fails on, as pure functions over the recorded rows (no GL),
// so the rules are unit-tested on hand-made rows and can re-check a written sweep.csv
// (`shadowscope sweep check FILE`). The thresholds and why they are what they are: docs/stability.md.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace app {

/// One row of sweep.csv: one method at one light-view angle.
struct SweepRecord {
    double angleDeg = 0;                  // light-view angle acos(v·l), 0..180
    std::string method;                   // warp method name
    double nPrime = 0;                    // n' of split 0; +inf = uniform (no warp), the plan's own encoding
    double p95 = 0, max = 0;              // aliasing error m over receiver pixels
    double falseLit = 0, falseShadow = 0; // fractions of receiver pixels (ground truth)
    double gammaDeg = 0;                  // γ = acos(|v·l|)
    double lambda = 0;                    // Zhang's λ of split 0 (0 for uniform)
    double nPrimeMin = 0;                 // smallest n' over the splits (the strongest warp)
    double p50 = 0, mean = 0;
    double receivers = 0;       // receiver pixels the statistics are over
    double glErrors = 0;        // 1 when renderer::takeGlErrors() reported anything after this frame
    double p95Uniform = 0;      // p95 m of uniform shadow mapping at the same angle (the reference)
    double clippedCasters = 0;  // receivers whose caster segment leaves their split's map (caster_coverage.h)
    double falseLitClipped = 0; // receivers false lit with such a segment: shadows lost to the plan
    double singular = 0;        // fraction of receivers with a singular J (not in the m figures); 0 in older CSVs
};

struct SweepThresholds {
    /// Continuity: between consecutive angles at most `continuityStepDeg` apart, the warp's gain
    /// p95 / p95_uniform of a method that promises continuity may change by at most this factor
    /// (either way). Relative to uniform at the same angle, because p95 m itself also moves with
    /// the scene: surfaces turning to grazing light enter and leave the receivers for every method.
    /// Measured on the platform's deck view (docs/stability.md): at 1° steps lispsm, glispsm and
    /// gmnpr change by at most 2.0×, while psm jumps 15× within 0.5° near the dueling frusta; over
    /// 5° the continuity methods themselves change by up to 6.8×, so coarse steps are not judged.
    double maxP95Ratio = 3.0;
    double continuityStepDeg = 1.0;
    /// Lost casters: false_lit_clipped above this fraction of the receivers. Zero would do for a
    /// correct plan (measured: 0 at every angle and method); the margin absorbs a few pixels on
    /// split boundaries, where the eye pass and the plan round depths differently.
    double maxFalseLitClipped = 0.001;
    /// Rows with fewer receiver pixels are too small a sample for the continuity rule.
    double minReceivers = 200;
};

/// lispsm, glispsm and gmnpr: their n'(γ) is continuous in γ (Wimmer; Barroso eqs 14–18; Zhang
/// eq 8), so their error should be too. uniform has nothing to be continuous about; psm is
/// known to jump (Stamminger & Drettakis' inverted frusta), manual follows a slider.
[[nodiscard]] bool promisesContinuity(std::string_view method) noexcept;

/// One line per failure, naming method, angle and value; empty when every rule holds:
/// NaN anywhere, ±Inf anywhere but n' (where +Inf is uniform), GL errors, jumps of p95/p95_uniform
/// beyond maxP95Ratio for continuity methods, false_lit_clipped beyond maxFalseLitClipped. Rows
/// may come in any order.
[[nodiscard]] std::vector<std::string> checkSweep(const std::vector<SweepRecord>& rows, const SweepThresholds& t = {});

/// The sweep.csv header: angle_deg,method,n_prime,p95,max,false_lit,false_shadow, then the rest.
[[nodiscard]] std::string sweepCsvHeader();
[[nodiscard]] std::string sweepCsvRow(const SweepRecord& r);
/// Parses sweep.csv text (columns found by header name; unknown extra columns are ignored).
/// Throws std::runtime_error with a one-line reason (missing column, bad number, wrong field count).
[[nodiscard]] std::vector<SweepRecord> parseSweepCsv(std::string_view text);

/// Shortest text that reads back as the same double; "inf", "-inf", "nan" for the others.
[[nodiscard]] std::string formatCsvNumber(double v);

} // namespace app
