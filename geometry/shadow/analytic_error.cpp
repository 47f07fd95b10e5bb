#include "geometry/shadow/analytic_error.h"

#include "geometry/shadow/warp.h"

#include <algorithm>
#include <cmath>

namespace geometry::shadow {

double aliasingErrorZ(const ErrorModel& m, double nPrime, double z) noexcept {
    const double s = std::max(std::sin(m.gamma), 1e-6), c = std::cos(m.gamma), t = std::tan(m.phi);
    const double depth = warpDepthRange(m.n, m.f, m.phi, m.gamma); // f' − n'
    const double scale = (m.screenRes / m.mapRes) / (2.0 * t) / s;
    if (!(z > 0.0)) return 0.0;
    if (!std::isfinite(nPrime)) return scale * depth / z;                       // n' → ∞
    const double psi = m.gamma >= m.phi ? nPrime + m.n * t * c + (z - m.n) * s  // a = n·tanφ
                                        : nPrime + m.f * t * c + (z - m.f) * s; // b = f·tanφ
    const double fPrime = nPrime + depth;
    return scale * depth / (nPrime * fPrime) * psi * psi / z; // Barroso eq 12
}

} // namespace geometry::shadow
