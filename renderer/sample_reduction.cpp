#include "sample_reduction.h"

#include <array>
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
    // sample_reduce.comp's rows: with M = inverse(P V), h = M q for a pixel's NDC q, d·x = (D·q)/(W·q)
    // for D = Σ_i d_i row_i(M), W = row_3(M); view depth z = −(row_2(V)·(x, 1)) = (Z·q)/(W·q).
    const glm::dmat4 M = glm::inverse(glm::dmat4(view.proj) * glm::dmat4(view.view));
    const auto row = [&](int i) { return glm::dvec4(M[0][i], M[1][i], M[2][i], M[3][i]); };
    const glm::dvec4 W = row(3);
    const auto along = [&](const glm::dvec3& d) { return d.x * row(0) + d.y * row(1) + d.z * row(2); };
    const glm::dvec3 viewZ(view.view[0][2], view.view[1][2], view.view[2][2]);
    program_.set("uZRow", glm::vec4(-(along(viewZ) + double(view.view[3][2]) * W)));
    program_.set("uWRow", glm::vec4(W));
    const auto directions = geometry::shadow::sampleDirections(view.l);
    std::array<glm::vec4, kSampleDirections> dirRows{};
    for (int k = 0; k < kSampleDirections; ++k)
        dirRows[size_t(k)] = glm::vec4(along(glm::dvec3(directions[size_t(k)])));
    program_.set("uDirRows", dirRows.data(), kSampleDirections);
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
