// std::nth_element by a float key, with partitions that do not branch on the data (docs/design.md
// §2.1 "Median splits"). Chunking's median splits of centroids compare coordinates in an order the
// branch predictor cannot learn: libstdc++'s partition mispredicts about every other element.
// Partitioning blocks of 64 elements, first noting which elements are on the wrong side (a
// comparison added to a count, no branch) and then swapping those pairs, as BlockQuicksort does
// (Edelkamp and Weiß 2016), took the 4 M piperack's splits from 0.36 to 0.27 s on one thread.
// Large ranges are cut by two pivots read from a sample (Floyd and Rivest 1975), which bracket the
// median's rank closely: about 1.5 passes where a pivot per round takes about 2.5.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

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

/// Ranges above this are cut by two sampled pivots (below it the sample costs more than it saves:
/// 2^10 and 2^12 alike, 2^14 slower).
inline constexpr ptrdiff_t kSampledSelect = 1 << 12;

/// Two keys of [first, last) that bracket the key of rank k (0 ≤ k < n) with high probability, read
/// from an evenly spaced sample of s = 2^e keys, e = min(14, ⌊2·bit_width(n)/3⌋) (s ≈ n^(2/3), as
/// Floyd and Rivest choose): the sample's ranks k·s/n ± 2^⌈e/2⌉. A sampled rank's spread is at most
/// √s/2, so that is two to three standard deviations either way, and about 2n/√s to 3n/√s keys lie
/// between the two (1.6 % of n at 2^14). False when a sampled key is NaN.
template <class T, class Key>
bool sampledPivots(const T* first, ptrdiff_t n, ptrdiff_t k, const Key& key, std::vector<float>& sample, float& lo,
                   float& hi) {
    const int e = std::min(14, int(2 * std::bit_width(uint64_t(n)) / 3));
    const ptrdiff_t s = ptrdiff_t(1) << e, stride = n / s;
    sample.resize(size_t(s));
    for (ptrdiff_t i = 0; i < s; ++i) sample[size_t(i)] = key(first[i * stride]);
    if (std::any_of(sample.begin(), sample.end(), [](float x) { return x != x; })) return false;
    const ptrdiff_t d = ptrdiff_t(1) << ((e + 1) / 2), ks = k * s / n;
    const auto l = sample.begin() + std::max<ptrdiff_t>(ks - d, 0), h = sample.begin() + std::min(ks + d, s - 1);
    std::nth_element(sample.begin(), l, sample.end());
    std::nth_element(l, h, sample.end());
    lo = *l;
    hi = *h;
    return true;
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
    std::vector<float> sample;
    for (int rounds = 0; last - first > 64; ++rounds) {
        if (rounds == 128) break; // a pathological order: std::nth_element finishes it
        const ptrdiff_t n = last - first, s = n / 8;
        float lo = 0.f, hi = 0.f;
        if (n > detail::kSampledSelect && detail::sampledPivots(first, n, nth - first, key, sample, lo, hi) &&
            (!bounded || lower < lo)) {
            // Keys below lo to the left, then of the rest those up to hi: nth is mostly between.
            T* const below = detail::blockPartition(first, last, [&](const T& x) { return key(x) < lo; });
            if (nth < below) {
                last = below;
                continue;
            }
            T* const upTo = detail::blockPartition(below, last, [&](const T& x) { return !(hi < key(x)); });
            first = below;
            lower = lo;
            bounded = true;
            if (nth >= upTo) {
                first = upTo;
                lower = hi; // every key left is above it
            } else {
                last = upTo;
                if (!(lo < hi)) return; // every key in [below, upTo) equals lo
            }
            continue;
        }
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
