#pragma once
// Order statistics, one implementation for every figure the tool reports (aliasing percentiles,
// seam medians, frame-time medians).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

namespace geometry::analysis {

/// Nearest-rank percentile: of the n values, the ⌈pct·n/100⌉-th smallest (the smallest for pct 0).
/// Integer rank arithmetic, because 0.95·n in floating point can land just above an integer and
/// pick the next rank. Reorders `values`; NaN when empty; pct above 100 counts as 100.
template <class T> [[nodiscard]] double percentile(std::span<T> values, unsigned pct) noexcept {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const size_t n = values.size();
    const size_t rank = std::clamp<size_t>((size_t(std::min(pct, 100u)) * n + 99) / 100, 1, n);
    const auto nth = values.begin() + std::ptrdiff_t(rank - 1);
    std::nth_element(values.begin(), nth, values.end());
    return double(*nth);
}

/// The median: the middle value, or the mean of the two middle values for an even count.
/// Reorders `values`; NaN when empty.
template <class T> [[nodiscard]] double median(std::span<T> values) noexcept {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const size_t n = values.size();
    const auto upper = values.begin() + std::ptrdiff_t(n / 2);
    std::nth_element(values.begin(), upper, values.end());
    if (n % 2) return double(*upper);
    const double lower = double(*std::max_element(values.begin(), upper)); // the largest of the lower half
    return 0.5 * (lower + double(*upper));
}

} // namespace geometry::analysis
