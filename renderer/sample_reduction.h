#pragma once
// The GPU reduction of the eye's depth pre-pass into geometry::shadow::SampleBounds (docs/design.md
// §3.7): one compute dispatch over the depth texture, then a read-back of the bins alone
// (kSampleBins × 11 words), never of the pixels.
#include "geometry/shadow/sample_bounds.h"
#include "program.h"

#include <cstdint>
#include <vector>

namespace renderer {

struct SampleView {
    glm::mat4 view{1.f}, proj{1.f}; // the camera's, as the pre-pass drew with
    float n = 0.f, f = 0.f;         // the camera's near and far
    glm::vec3 l{0.f, -1.f, 0.f};
};

class SampleReduction {
public:
    SampleReduction();
    ~SampleReduction();
    SampleReduction(const SampleReduction&) = delete;
    SampleReduction& operator=(const SampleReduction&) = delete;

    /// Reduces the `width` × `height` depth texture (window depth, 1 = nothing drawn).
    [[nodiscard]] geometry::shadow::SampleBounds reduce(GLuint depthTexture, int width, int height,
                                                        const SampleView& view);

private:
    Program program_{Program::Compute{}, "sample_reduce.comp"};
    GLuint buffer_ = 0;
    std::vector<uint32_t> words_; // the read-back, reused every frame
};

} // namespace renderer
