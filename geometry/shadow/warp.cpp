#include "geometry/shadow/warp.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace geometry::shadow {

namespace {
constexpr double kHalfPi = std::numbers::pi / 2.0;
double clampGamma(double g) noexcept { return std::isfinite(g) ? std::clamp(g, 0.0, kHalfPi) : 0.0; }
double finitePositiveOrUniform(double v) noexcept { return std::isfinite(v) && v > 0.0 ? v : kUniform; }
} // namespace

double gammaLimit(double n, double f, double phi) noexcept {
    const double a = n * std::tan(phi), b = f * std::tan(phi);
    return std::atan((a + b) / (f - n));
}

double nPrimeGlispsm1(double n, double f, double phi, double gamma) noexcept {
    const double a = n * std::tan(phi);
    return (n + std::sqrt(f * n)) * std::sin(gamma) - a * std::cos(gamma);
}

double nPrimeGlispsm(double n, double f, double phi, double gamma, GlispsmFalloff falloff) noexcept {
    const double gLim = gammaLimit(n, f, phi);
    if (gamma >= gLim) return nPrimeGlispsm1(n, f, phi, gamma);
    const double t = gamma / gLim;
    const double r = falloff == GlispsmFalloff::Eq18 ? std::pow(1.0 + std::sin((t - 1.0) * kHalfPi), 2.0) // eq 18
                                                     : std::sin(t * kHalfPi);                             // eq 17
    return nPrimeGlispsm1(n, f, phi, gLim) / r; // eq 16; r → 0 as γ → 0 gives n' → ∞
}

double warpDepthRange(double n, double f, double phi, double theta) noexcept {
    const double t = std::tan(phi);
    if (theta >= phi) return (f - n) * std::sin(theta) + (f + n) * t * std::cos(theta);
    return 2.0 * f * t * std::cos(theta);
}

double lambdaGmnpr(double n, double f, double phi, double theta) noexcept {
    if (theta >= phi) {
        // Zhang eq 8, λ₁ (the extraction of eq 4 prints tanφ/tanφ; tanφ/tanθ is right).
        const double k = std::tan(phi) / std::tan(theta);
        return (n + std::sqrt(f * n) - n * k) / (f - n + (f + n) * k);
    }
    return (std::sqrt(f * n) / (2.0 * f)) / std::tan(theta * std::numbers::pi / (4.0 * phi)); // λ₂
}

double nPrimeGmnpr(double n, double f, double phi, double theta) noexcept {
    return lambdaGmnpr(n, f, phi, theta) * warpDepthRange(n, f, phi, theta);
}

double nPrimeLispsm(double n, double gamma, double d, double visibleFar) noexcept {
    const double s = std::sin(gamma);
    double dz = d * s;
    if (visibleFar > n) dz = std::min(dz, visibleFar - n);
    return (n + std::sqrt(n * (n + dz))) / s; // Scherzer eq 1 (Wimmer)
}

double warpNPrime(const WarpParams& p, double n, double f, double phi, double gamma, double d) noexcept {
    gamma = clampGamma(gamma);
    if (gamma <= 0.0 || !(n > 0.0) || !(f > n)) return kUniform;
    double v = kUniform;
    switch (p.method) {
    case WarpMethod::Uniform: return kUniform;
    case WarpMethod::Psm: v = n / std::sin(gamma); break;
    case WarpMethod::Lispsm: v = nPrimeLispsm(n, gamma, d, p.visibleFar); break;
    case WarpMethod::Glispsm: v = nPrimeGlispsm(n, f, phi, gamma, p.falloff); break;
    case WarpMethod::Gmnpr: v = nPrimeGmnpr(n, f, phi, gamma); break;
    case WarpMethod::Manual: v = p.manualNPrime / std::sin(gamma); break;
    }
    return finitePositiveOrUniform(v * p.multiplier);
}

double lambdaFromNPrime(double nPrime, double n, double f, double phi, double gamma) noexcept {
    if (!std::isfinite(nPrime)) return 0.0;
    const double range = warpDepthRange(n, f, phi, clampGamma(gamma));
    return range > 0.0 ? nPrime / range : 0.0;
}

} // namespace geometry::shadow
