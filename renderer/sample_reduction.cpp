#include "sample_reduction.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace renderer {

namespace {

using geometry::shadow::kSampleBins;
using geometry::shadow::kSampleDirections;

constexpr int kStride = 1 + 2 * kSampleDirections; // count, lo[], hi[]: sample_reduce.comp's layout
constexpr size_t kWords = 2 + size_t(kSampleBins) * kStride;

/// Inverse of sample_reduce.comp's orderedKey.
float fromKey(uint32_t key) noexcept {
    const uint32_t u = (key & 0x80000000u) ? (key & 0x7FFFFFFFu) : ~key;
    float f;
    static_assert(sizeof f == sizeof u);
    std::memcpy(&f, &u, sizeof f);
    return f;
}

std::vector<uint32_t> initialWords() {
    std::vector<uint32_t> w(kWords, 0u);
    w[0] = 0xFFFFFFFFu;
    for (int b = 0; b < kSampleBins; ++b)
        for (int k = 0; k < kSampleDirections; ++k) w[2 + size_t(b) * kStride + 1 + size_t(k)] = 0xFFFFFFFFu;
    return w;
}

} // namespace

SampleReduction::SampleReduction() {
    glGenBuffers(1, &buffer_);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer_);
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(kWords * sizeof(uint32_t)), nullptr, GL_DYNAMIC_READ);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

SampleReduction::~SampleReduction() { glDeleteBuffers(1, &buffer_); }

geometry::shadow::SampleBounds SampleReduction::reduce(GLuint depthTexture, int width, int height,
                                                       const SampleView& view) {
    static const std::vector<uint32_t> initial = initialWords();
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer_);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(kWords * sizeof(uint32_t)), initial.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer_);
    program_.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, depthTexture);
    glBindSampler(0, 0);
    program_.set("uDepth", 0);
    program_.set("uInvViewProj", glm::inverse(view.proj * view.view));
    program_.set("uView", view.view);
    const auto directions = geometry::shadow::sampleDirections(view.l);
    program_.set("uDirections", directions.data(), kSampleDirections);
    program_.set("uLogNear", std::log(view.n));
    program_.set("uBinScale", float(kSampleBins / std::log(double(view.f) / double(view.n))));
    program_.set("uSize", glm::ivec2(width, height));
    glDispatchCompute(GLuint((width + 15) / 16), GLuint((height + 127) / 128), 1); // sample_reduce.comp: 16 × 128
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<uint32_t>& words = words_;
    words.resize(kWords);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(kWords * sizeof(uint32_t)), words.data());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);

    geometry::shadow::SampleBounds out;
    out.n = view.n;
    out.f = view.f;
    out.l = view.l;
    out.bins.resize(kSampleBins);
    for (int b = 0; b < kSampleBins; ++b) {
        const uint32_t* w = &words[2 + size_t(b) * kStride];
        auto& bin = out.bins[size_t(b)];
        bin.count = w[0];
        out.count += w[0];
        for (int k = 0; k < kSampleDirections; ++k) {
            bin.lo[size_t(k)] = w[0] ? fromKey(w[1 + k]) : 0.f;
            bin.hi[size_t(k)] = w[0] ? fromKey(w[1 + kSampleDirections + k]) : 0.f;
        }
    }
    if (out.count > 0) out.zMin = fromKey(words[0]), out.zMax = fromKey(words[1]);
    return out;
}

} // namespace renderer
