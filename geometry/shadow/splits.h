#pragma once
// Z-partitioning of [n, f] into k splits (docs/design.md §3.4).
#include "geometry/shadow/named_enum.h"

#include <string_view>
#include <vector>

namespace geometry::shadow {

// splits.scheme (named_enum.h: value, setting name, help).
#define SHADOWSCOPE_SPLIT_SCHEMES(X)                                                                                   \
    X(Uniform, "uniform", "")                                                                                          \
    X(Log, "log", "Lloyd")                                                                                             \
    X(Practical, "practical", "log/uniform blend")                                                                     \
    X(Pssm, "pssm", "geometric lengths")                                                                               \
    X(Adaptive, "adaptive", "Barroso eq 19")
SHADOWSCOPE_NAMED_ENUM(SplitScheme, "SPLIT_", SHADOWSCOPE_SPLIT_SCHEMES);

/// The most splits a plan holds: the settings' range, the renderer's texture array and the
/// shaders' split arrays (generated from this constant) all follow it.
inline constexpr int kMaxSplits = 8;

struct SplitParams {
    int count = 1; // k, 1..kMaxSplits
    SplitScheme scheme = SplitScheme::Practical;
    double lambda = 0.5;            // practical: weight of the log scheme
    double ratio = 2.0;             // pssm: each split this much longer than the one before
    double alpha = 2.0;             // adaptive: f_i / n_i at γ = 0 (Barroso eq 19)
    bool resolutionFalloff = false; // res_i = res_1 / 2^(i−1)
    double blend = 0.0;             // fraction of a split's depth range before its far end blended into the next
    [[nodiscard]] bool operator==(const SplitParams&) const = default;
};

/// The k + 1 boundaries C_0 = n < C_1 < … < C_k = f. γ in radians (adaptive only).
/// Boundaries never leave [n, f]; a scheme that would (adaptive with a large α at small γ) is
/// clamped at n, which can leave leading splits empty (zero length).
[[nodiscard]] std::vector<double> splitDistances(const SplitParams& p, double n, double f, double gamma);

/// Resolution of split i (0-based) for a first-split resolution.
[[nodiscard]] int splitResolution(const SplitParams& p, int resolution, int i) noexcept;

[[nodiscard]] constexpr std::string_view splitSchemeName(SplitScheme s) noexcept { return enumName(s); }

} // namespace geometry::shadow
