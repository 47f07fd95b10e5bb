// std::nth_element by a float key, with partitions that do not branch on the data (docs/design.md
// §2.1 "Median splits"). Chunking's median splits of centroids compare coordinates in an order the
// branch predictor cannot learn: libstdc++'s partition mispredicts about every other element.
// Partitioning blocks of 64 elements, first noting which elements are on the wrong side (a
// comparison added to a count, no branch) and then swapping those pairs, as BlockQuicksort does
// (Edelkamp and Weiß 2016), took the 4 M piperack's splits from 0.36 to 0.27 s on one thread.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace geometry::scene {

namespace detail {

inline constexpr ptrdiff_t kSelectBlock = 64;

/// Reorders [first, last) so that the elements for which left(x) holds come first; returns the
/// first of the others. Not stable.
template <class T, class Left> T* blockPartition(T* first, T* last, const Left& left) {
    uint8_t offLeft[kSelectBlock], offRight[kSelectBlock]; // misplaced elements of the current blocks
    ptrdiff_t numLeft = 0, numRight = 0, startLeft = 0, startRight = 0;
    // [first, l) holds left elements, [r, last) right ones; a block in progress at each end.
    T *l = first, *r = last;
    while (r - l > 2 * kSelectBlock) {
        if (numLeft == 0) {
            startLeft = 0;
            for (ptrdiff_t i = 0; i < kSelectBlock; ++i) {
                offLeft[numLeft] = uint8_t(i);
                numLeft += !left(l[i]);
            }
        }
        if (numRight == 0) {
            startRight = 0;
            for (ptrdiff_t i = 0; i < kSelectBlock; ++i) {
                offRight[numRight] = uint8_t(i);
                numRight += left(*(r - 1 - i));
            }
        }
        const ptrdiff_t swaps = std::min(numLeft, numRight);
        for (ptrdiff_t k = 0; k < swaps; ++k) std::swap(l[offLeft[startLeft + k]], *(r - 1 - offRight[startRight + k]));
        numLeft -= swaps;
        numRight -= swaps;
        startLeft += swaps;
        startRight += swaps;
        if (numLeft == 0) l += kSelectBlock;
        if (numRight == 0) r -= kSelectBlock;
    }
    // What lies between (a block in progress included) is partitioned plainly: at most three blocks.
    return std::partition(l, r, left);
}

inline float median3(float x, float y, float z) noexcept {
    return std::max(std::min(x, y), std::min(std::max(x, y), z));
}

template <class T, class Key> float medianOf3(const T* a, const T* b, const T* c, const Key& key) {
    return median3(key(*a), key(*b), key(*c));
}

} // namespace detail

/// As std::nth_element(first, nth, last) ordered by key(x) < key(y): afterwards no element before nth
/// has a larger key than nth's and none after it a smaller one. Elements are moved otherwise than
/// std::nth_element moves them (so equal keys may land on other sides), deterministically. Keys
/// that are NaN end it early without harm (the order is then unspecified, as for std::nth_element).
template <class T, class Key> void blockSelect(T* first, T* nth, T* last, const Key& key) {
    if (nth >= last) return;
    // Every key in [first, last) is at least `lower` once the range has been cut from below; a pivot
    // equal to it takes the equal keys off the bottom instead, so many equal keys (CAD models'
    // coordinates repeat) cannot make a cut that removes nothing.
    bool bounded = false;
    float lower = 0.f;
    for (int rounds = 0; last - first > 64; ++rounds) {
        if (rounds == 128) break; // a pathological order: std::nth_element finishes it
        const ptrdiff_t n = last - first, s = n / 8;
        T* const mid = first + n / 2;
        // Median of 3, or of three medians of 3 for large ranges (Tukey's ninther).
        const float p = n <= 1024 ? detail::medianOf3(first, mid, last - 1, key) : [&] {
            const float a = detail::medianOf3(first, first + s, first + 2 * s, key);
            const float b = detail::medianOf3(mid - s, mid, mid + s, key);
            const float c = detail::medianOf3(last - 1 - 2 * s, last - 1 - s, last - 1, key);
            return detail::median3(a, b, c);
        }();
        if (bounded && !(lower < p)) {
            T* const cut = detail::blockPartition(first, last, [&](const T& x) { return !(p < key(x)); });
            if (nth < cut) return; // every key up to cut equals p
            first = cut;
            continue;
        }
        T* const cut = detail::blockPartition(first, last, [&](const T& x) { return key(x) < p; });
        if (nth < cut) {
            last = cut;
        } else {
            first = cut;
            lower = p;
            bounded = true;
        }
    }
    std::nth_element(first, nth, last, [&](const T& a, const T& b) { return key(a) < key(b); });
}

} // namespace geometry::scene
