#pragma once
// Analytic aliasing error along the view axis (Barroso eq 12; Zhang 004 eq 2), docs/design.md §3.3.
namespace geometry::shadow {

struct ErrorModel {
    double n = 1, f = 100, phi = 0.5235987755982988; // eye near, far, vertical half fov
    double gamma = 1.5707963267948966;               // γ, radians
    double screenRes = 1080;                         // res_screen_y
    double mapRes = 2048;                            // res_map
};

/// m_z(z) = ξ·ψ(z)²/z, ψ(z) = n' + a·cosγ + (z − n)·sinγ for γ ≥ φ (n' + b·cosγ + (z − f)·sinγ
/// below), ξ = (res_y/res_map)·1/(2tanφ)·(f'−n')/(n'·f')·1/sinγ. n' = +∞ gives the uniform limit
/// (res_y/res_map)·(f'−n')/(2 tanφ · z · sinγ). sinγ is floored at 1e-6, so m stays finite.
[[nodiscard]] double aliasingErrorZ(const ErrorModel& m, double nPrime, double z) noexcept;

} // namespace geometry::shadow
