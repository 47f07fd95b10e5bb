#pragma once
// The median of the last N values added: a timing shown in the stats panel that neither jumps with
// one cold call nor hides a lasting change.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ui {

class RecentMedian {
public:
    explicit RecentMedian(std::size_t capacity = 15) : capacity_(std::max<std::size_t>(capacity, 1)) {}

    /// Adds a value; NaN and infinities are ignored.
    void add(double v) {
        if (!std::isfinite(v)) return;
        if (values_.size() < capacity_) values_.push_back(v);
        else values_[next_] = v;
        next_ = (next_ + 1) % capacity_;
    }
    [[nodiscard]] std::size_t count() const noexcept { return values_.size(); }
    /// The median of the values kept (the mean of the middle two for an even count); NaN when empty.
    [[nodiscard]] double median() const {
        if (values_.empty()) return NAN;
        std::vector<double> v = values_;
        const std::size_t mid = v.size() / 2;
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(mid), v.end());
        const double upper = v[mid];
        if (v.size() % 2) return upper;
        return 0.5 * (upper + *std::max_element(v.begin(), v.begin() + std::ptrdiff_t(mid)));
    }

private:
    std::size_t capacity_;
    std::size_t next_ = 0;
    std::vector<double> values_;
};

} // namespace ui
