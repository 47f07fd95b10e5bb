#include "virtual_map.h"

#include "geometry/scene/invariant.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace renderer {

using geometry::shadow::PageKey;
using geometry::shadow::PagePool;
using geometry::shadow::VirtualMapConfig;
using geometry::shadow::VirtualPlan;

namespace {
constexpr int kMaxLevels = 16; // virtual.glsl's and page_mark.comp's uVOrigin[]
}

VirtualShadowMap::VirtualShadowMap() { glGenBuffers(1, &marks_); }

VirtualShadowMap::~VirtualShadowMap() {
    release();
    glDeleteBuffers(1, &marks_);
}

void VirtualShadowMap::release() noexcept {
    if (fbo_) glDeleteFramebuffers(1, &fbo_);
    if (atlas_) glDeleteTextures(1, &atlas_);
    if (table_) glDeleteTextures(1, &table_);
    fbo_ = atlas_ = table_ = 0;
    columns_ = rows_ = 0;
}

void VirtualShadowMap::ensure(const VirtualMapConfig& config, uint32_t poolPages, int maxTextureSize) {
    const int page = int(config.pageSize), pps = int(config.pagesPerSide());
    const int levels = std::clamp(config.levels, 1, kMaxLevels);
    const int maxColumns = std::max(maxTextureSize / std::max(page, 1), 1);
    const int columns = std::min(int(std::ceil(std::sqrt(double(poolPages)))), maxColumns);
    const int rows = std::min(int((poolPages + uint32_t(columns) - 1) / uint32_t(columns)), maxColumns);
    poolPages = std::min(poolPages, uint32_t(columns) * uint32_t(rows));
    if (pool_ && pool_->capacity() == poolPages && page == pageSize_ && pps == pagesPerSide_ && levels == levels_ &&
        config.side0 == config_.side0)
        return;
    release();
    config_ = config;
    pageSize_ = page;
    pagesPerSide_ = pps;
    levels_ = levels;
    columns_ = columns;
    rows_ = rows;
    pool_ = std::make_unique<PagePool>(poolPages);
    frame_ = {};
    drawnTotal_ = 0;
    glGenTextures(1, &atlas_);
    glBindTexture(GL_TEXTURE_2D, atlas_);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT32F, columns * page, rows * page);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenFramebuffers(1, &fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, atlas_, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("virtual shadow map: the page atlas framebuffer is incomplete");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGenTextures(1, &table_);
    glBindTexture(GL_TEXTURE_2D_ARRAY, table_);
    glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_R32UI, pps, pps, levels);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    tableWords_.assign(size_t(pps) * size_t(pps) * size_t(levels), 0u);
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, pps, pps, levels, GL_RED_INTEGER, GL_UNSIGNED_INT,
                    tableWords_.data());
    const size_t bits = tableWords_.size();
    words_.assign(1 + (bits + 31) / 32, 0u);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, marks_);
    glBufferData(GL_SHADER_STORAGE_BUFFER, GLsizeiptr(words_.size() * sizeof(uint32_t)), nullptr, GL_DYNAMIC_READ);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void VirtualShadowMap::invalidate() {
    if (pool_) pool_ = std::make_unique<PagePool>(pool_->capacity());
    frame_ = {};
    drawnTotal_ = 0;
}

void VirtualShadowMap::setUniforms(Program& program, const VirtualPlan& plan) const {
    program.set("uVEye", glm::vec3(plan.eye));
    program.set("uVRight", glm::vec3(plan.frame.right));
    program.set("uVUp", glm::vec3(plan.frame.up));
    program.set("uVLight", glm::vec3(plan.frame.l));
    std::array<glm::vec2, kMaxLevels> origins{};
    for (int k = 0; k < levels_ && size_t(k) < plan.levels.size(); ++k)
        origins[size_t(k)] = glm::vec2(plan.levelOrigin(k));
    glUniform2fv(program.location("uVOrigin"), kMaxLevels, &origins[0][0]);
    program.set("uVTexel0", float(plan.levels.empty() ? 1.0 : plan.levels[0].texelWorld));
    program.set("uVLevels", levels_);
    program.set("uVPagesPerSide", pagesPerSide_);
    program.set("uVPageSize", pageSize_);
    program.set("uVColumns", columns_);
    program.set("uVDepthLo", float(plan.depthLo));
    program.set("uVDepthScale", float(1.0 / std::max(plan.depthHi - plan.depthLo, 1e-9)));
}

const PagePool::Frame& VirtualShadowMap::update(const VirtualPlan& plan, GLuint depthTexture, int width, int height,
                                                const glm::mat4& eyeViewProj) {
    SHADOWSCOPE_EXPECTS(pool_ != nullptr);
    // 1. Mark: one bit per page of every level, set by the pixels that ask for it (page_mark.comp).
    std::fill(words_.begin(), words_.end(), 0u);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, marks_);
    glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(words_.size() * sizeof(uint32_t)), words_.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, marks_);
    mark_.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, depthTexture);
    glBindSampler(0, 0);
    mark_.set("uDepth", 0);
    // NDC → world relative to the eye, in double then float: neighbouring pixels' positions differ
    // by far less than the world coordinates' size.
    const glm::dmat4 toEye = glm::inverse(glm::dmat4(eyeViewProj) * glm::translate(glm::dmat4(1.0), plan.eye));
    mark_.set("uNdcToEye", glm::mat4(toEye));
    mark_.set("uSize", glm::ivec2(width, height));
    setUniforms(mark_, plan);
    glDispatchCompute(GLuint((width + 15) / 16), GLuint((height + 15) / 16), 1); // page_mark.comp: 16 × 16
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, GLsizeiptr(words_.size() * sizeof(uint32_t)), words_.data());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    uncovered_ = words_[0];
    std::vector<PageKey> requests;
    const size_t perLevel = size_t(pagesPerSide_) * size_t(pagesPerSide_);
    for (size_t w = 1; w < words_.size(); ++w)
        for (uint32_t bits = words_[w]; bits != 0; bits &= bits - 1) {
            const size_t index = (w - 1) * 32 + size_t(std::countr_zero(bits));
            const int level = int(index / perLevel);
            const size_t inLevel = index % perLevel;
            const auto& c = plan.levels[size_t(level)];
            requests.push_back(PageKey{level, c.firstPageX + int64_t(inLevel % size_t(pagesPerSide_)),
                                       c.firstPageY + int64_t(inLevel / size_t(pagesPerSide_))});
        }
    // 2. The pool decides what is kept, drawn and given up (geometry/shadow/virtual_pages.h).
    frame_ = pool_->update(std::move(requests), plan.content, levels_);
    drawnTotal_ += frame_.drawn.size();
    // 3. The page table for this frame's squares: the entries the pool allocated.
    std::fill(tableWords_.begin(), tableWords_.end(), 0u);
    for (const PagePool::Entry& e : frame_.table) {
        const auto& c = plan.levels[size_t(e.key.level)];
        const int64_t x = e.key.x - c.firstPageX, y = e.key.y - c.firstPageY;
        if (x < 0 || y < 0 || x >= pagesPerSide_ || y >= pagesPerSide_) continue;
        tableWords_[size_t(e.key.level) * perLevel + size_t(y) * size_t(pagesPerSide_) + size_t(x)] = e.physical + 1;
    }
    glBindTexture(GL_TEXTURE_2D_ARRAY, table_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, pagesPerSide_, pagesPerSide_, levels_, GL_RED_INTEGER,
                    GL_UNSIGNED_INT, tableWords_.data());
    return frame_;
}

void VirtualShadowMap::bindPage(uint32_t physical) const noexcept {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    const int x = int(physical % uint32_t(columns_)) * pageSize_, y = int(physical / uint32_t(columns_)) * pageSize_;
    glViewport(x, y, pageSize_, pageSize_);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, y, pageSize_, pageSize_);
}

std::vector<float> VirtualShadowMap::readAtlas() const {
    const glm::ivec2 size = atlasSize();
    std::vector<float> out(size_t(size.x) * size_t(size.y));
    if (out.empty()) return out;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(atlas_, 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(out.size() * sizeof(float)), out.data());
    return out;
}

} // namespace renderer
