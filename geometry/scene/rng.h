#pragma once
// Seeded randomness for the built-in scenes.
#include <cstdint>
#include <random>

namespace geometry::scene {

/// mt19937 with hand-rolled mappings: the std distributions differ between standard libraries,
/// and a built-in scene must be the same everywhere for a given seed.
class Rng {
public:
    explicit Rng(uint32_t seed) : gen_(seed) {}
    float uniform(float lo, float hi) {
        return lo + (hi - lo) * (static_cast<float>(gen_() >> 8) * (1.f / 16777216.f));
    }
    int below(int n) { return static_cast<int>(gen_() % static_cast<uint32_t>(n)); }
    bool chance(int percent) { return below(100) < percent; }

private:
    std::mt19937 gen_;
};

} // namespace geometry::scene
