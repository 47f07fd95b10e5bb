#pragma once
// The LiSPSM family of warps (docs/design.md §3.2): each returns the warp parameter n', the distance from
// the warp frustum P's projection centre to its near plane. n' = +∞ means uniform (no warp).
// Angles in radians; n, f the (sub-)frustum's near and far; φ its vertical half field of view;
// γ = θ ∈ [0, π/2] the angle between light and view directions.
#include "geometry/shadow/named_enum.h"

#include <limits>
#include <string_view>

namespace geometry::shadow {

// warp.method (named_enum.h: value, setting name, help).
#define SHADOWSCOPE_WARP_METHODS(X)                                                                                    \
    X(Uniform, "uniform", "none")                                                                                      \
    X(Psm, "psm", "n' = n / sin(gamma)")                                                                               \
    X(Lispsm, "lispsm", "Wimmer")                                                                                      \
    X(Glispsm, "glispsm", "Barroso eqs 13-18")                                                                         \
    X(Gmnpr, "gmnpr", "Zhang eq 8")                                                                                    \
    X(Manual, "manual", "warp.n_prime")
SHADOWSCOPE_NAMED_ENUM(WarpMethod, "WARP_", SHADOWSCOPE_WARP_METHODS);

// warp.direction: V_P, the view projected onto the light plane, or Scherzer's middle vector.
#define SHADOWSCOPE_WARP_DIRECTIONS(X)                                                                                 \
    X(Standard, "standard", "view projected onto the light plane")                                                     \
    X(Middle, "middle", "Scherzer's middle vector over the focus body")
SHADOWSCOPE_NAMED_ENUM(WarpDirection, "WARP_DIRECTION_", SHADOWSCOPE_WARP_DIRECTIONS);

// warp.falloff: GLiSPSM below gamma_lim.
#define SHADOWSCOPE_GLISPSM_FALLOFFS(X)                                                                                \
    X(Eq18, "eq18", "default")                                                                                         \
    X(Eq17, "eq17", "")
SHADOWSCOPE_NAMED_ENUM(GlispsmFalloff, "GLISPSM_FALLOFF_", SHADOWSCOPE_GLISPSM_FALLOFFS);

inline constexpr double kUniform = std::numeric_limits<double>::infinity();

/// Barroso eq 15: γ_lim = atan((a + b) / (f − n)), a = n·tanφ, b = f·tanφ.
[[nodiscard]] double gammaLimit(double n, double f, double phi) noexcept;
/// Barroso eq 13 (eq 16's first case): n'₁(γ) = (n + √(f·n))·sinγ − a·cosγ, for γ_lim ≤ γ ≤ π/2.
[[nodiscard]] double nPrimeGlispsm1(double n, double f, double phi, double gamma) noexcept;
/// Barroso eqs 16–18: n'₁ above γ_lim; n'₁(γ_lim) / r(γ) below, r from eq 18 (default) or eq 17.
[[nodiscard]] double nPrimeGlispsm(double n, double f, double phi, double gamma,
                                   GlispsmFalloff falloff = GlispsmFalloff::Eq18) noexcept;

/// Zhang 004: depth range of P in the model, f' − n' = (f − n)·sinθ + (f + n)·tanφ·cosθ for θ ≥ φ,
/// 2f·tanφ·cosθ for θ < φ.
[[nodiscard]] double warpDepthRange(double n, double f, double phi, double theta) noexcept;
/// Zhang 004 eq 8 (GMNPR): λ₁(θ) for φ ≤ θ ≤ π/2, λ₂(θ) below; λ = n' / (f' − n').
[[nodiscard]] double lambdaGmnpr(double n, double f, double phi, double theta) noexcept;
[[nodiscard]] double nPrimeGmnpr(double n, double f, double phi, double theta) noexcept;

/// Wimmer's LiSPSM (Scherzer eq 1): n' = (n + √(n·(n + Δz))) / sinγ with Δz = d·sinγ, d the extent
/// of B along the warp direction; `visibleFar` > 0 caps n + Δz at the visible far depth (Scherzer
/// §4: tighter far plane from visibility).
[[nodiscard]] double nPrimeLispsm(double n, double gamma, double d, double visibleFar = 0.0) noexcept;

struct WarpParams {
    WarpMethod method = WarpMethod::Lispsm;
    GlispsmFalloff falloff = GlispsmFalloff::Eq18;
    double manualNPrime = 10.0; // manual: n' at γ = 90°, scaled by 1/sinγ like LiSPSM
    double multiplier = 1.0;    // scales any method's n'
    double visibleFar = 0.0;    // lispsm option, 0 = off
    [[nodiscard]] bool operator==(const WarpParams&) const = default;
};

/// n' for a method. Never NaN: γ is clamped to [0, π/2]; a non-finite or non-positive result
/// falls back to uniform (+∞), and so does γ = 0 for every method (light ∥ view). psm is
/// n / sinγ: PSM strength at γ = 90°, uniform as γ → 0 like the others.
[[nodiscard]] double warpNPrime(const WarpParams& p, double n, double f, double phi, double gamma, double d) noexcept;

/// λ = n' / (f' − n') (Zhang's parameter) for any n'; 0 for uniform.
[[nodiscard]] double lambdaFromNPrime(double nPrime, double n, double f, double phi, double gamma) noexcept;

[[nodiscard]] constexpr std::string_view warpMethodName(WarpMethod m) noexcept { return enumName(m); }

} // namespace geometry::shadow
