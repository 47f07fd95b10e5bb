#pragma once
// Comparing headless dashboard images region by region.
#include "renderer/image.h"
#include "ui/dashboard_layout.h"

#include <cstring>

namespace testutil {

/// Pixels that differ (any of R, G, B) between two images inside r.
inline size_t differing(const geometry::analysis::Image& a, const geometry::analysis::Image& b, const ui::Rect& r) {
    size_t n = 0;
    for (int y = int(r.y); y < int(r.bottom()); ++y)
        for (int x = int(r.x); x < int(r.right()); ++x)
            if (std::memcmp(a.at(x, y), b.at(x, y), 3) != 0) ++n;
    return n;
}

} // namespace testutil
