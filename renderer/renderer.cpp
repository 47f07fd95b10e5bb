// Index
//   [SECTION] GL helpers ................ makeSampler, bindTexture, needsPeeling
//   [SECTION] Set-up and shared state ... Renderer, ~Renderer, setScene, warnOnce, depthProgram, uploadShadowBlock
//                                         (the shadow and settings blocks)
//   [SECTION] The frame ................. render, eyeSamples, waitForTimings
//   [SECTION] Shadow maps ............... drawMaps, drawCasters, shadowPass, peelAndCombine, momentsPass,
//                                         virtualPass (technique = virtual)
//   [SECTION] Eye view .................. depthPrePass, eyePass, blurredMask, addLight, compose
//   [SECTION] Light views ............... lightViewPass, virtualViewPass, unwarpedViewPass
//   [SECTION] Reading back .............. readShadowMask, readShadowDepth, readShadowMap, readShadowSamples,
//                                         readAux, readPositions, readNormals

#include "renderer.h"

#include "geometry/scene/invariant.h"
#include "geometry/shadow/caster_detail.h"
#include "geometry/shadow/culling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace renderer {

using geometry::shadow::BiasType;
using geometry::shadow::FilterType;

namespace {
const glm::vec3 kSky{0.62f, 0.72f, 0.85f};

// ---- [SECTION] GL helpers -------------------------------------------------------------------

GLuint makeSampler(GLenum filter, bool compare) {
    GLuint s = 0;
    glGenSamplers(1, &s);
    glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, filter);
    glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, filter);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(s, GL_TEXTURE_COMPARE_MODE, compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glSamplerParameteri(s, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    return s;
}

void bindTexture(int unit, GLenum target, GLuint texture, GLuint sampler) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(target, texture);
    glBindSampler(unit, sampler);
}

/// Which faces cast (CAD meshes are wound counter-clockwise as seen from the light; the plan's maps
/// never mirror): second depth draws back faces only; solids their faces towards the light; open
/// surfaces both.
void cullForCasting(bool twoSided, bool backFacesOnly) noexcept {
    if (backFacesOnly) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_FRONT);
    } else if (!twoSided) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
    } else {
        glDisable(GL_CULL_FACE);
    }
}

bool needsPeeling(const geometry::shadow::ShadowPlan& plan) {
    return plan.settings.bias.type == BiasType::Midpoint || plan.settings.bias.type == BiasType::DualDepth;
}

/// The moments of linear depth 1 (nothing between the light and the far end), as depth.frag's
/// MOMENTS variant would write them for each filter.
std::array<float, 4> emptyTexelMoments(const geometry::shadow::ShadowPlan& plan) noexcept {
    const auto& f = plan.settings.filter;
    switch (f.type) {
    case FilterType::Esm: return {std::exp(f.esmExponent), 0.f, 0.f, 0.f};
    case FilterType::Evsm2:
    case FilterType::Evsm4: {
        const float pos = std::exp(f.evsmPositive), neg = -std::exp(-f.evsmNegative); // warped depth 1
        return {pos, pos * pos, neg, neg * neg};
    }
    default: return {1.f, 1.f, 1.f, 1.f}; // vsm (z, z²), msm (z, z², z³, z⁴)
    }
}
} // namespace

// ---- [SECTION] Set-up and shared state ------------------------------------------------------

Renderer::Renderer(const geometry::scene::Scene& scene, RendererLimits limits)
    : scene_(std::make_unique<GpuScene>(scene)), limits_(limits) {
    glGenVertexArrays(1, &emptyVao_);
    glGenBuffers(1, &shadowBlockBuffer_);
    glBindBuffer(GL_UNIFORM_BUFFER, shadowBlockBuffer_);
    glBufferData(GL_UNIFORM_BUFFER, sizeof(ShadowBlock), nullptr, GL_DYNAMIC_DRAW);
    glGenBuffers(1, &settingsBlockBuffer_);
    glBindBuffer(GL_UNIFORM_BUFFER, settingsBlockBuffer_);
    glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(settingsBlockWords({}).size() * sizeof(std::uint32_t)), nullptr,
                 GL_DYNAMIC_DRAW);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    nearestSampler_ = makeSampler(GL_NEAREST, false);
    compareSampler_ = makeSampler(GL_LINEAR, true);
    linearSampler_ = makeSampler(GL_LINEAR, false);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize_);
}

Renderer::~Renderer() {
    glDeleteVertexArrays(1, &emptyVao_);
    glDeleteBuffers(1, &shadowBlockBuffer_);
    glDeleteBuffers(1, &settingsBlockBuffer_);
    const GLuint samplers[] = {nearestSampler_, compareSampler_, linearSampler_};
    glDeleteSamplers(3, samplers);
}

void Renderer::setScene(const geometry::scene::Scene& scene) {
    scene_ = std::make_unique<GpuScene>(scene);
    drawnMaps_.reset();
    if (virtual_) virtual_->invalidate(); // no page drawn from the old scene is valid
}

void Renderer::setCasterLod(const geometry::lod::SceneLod& lod) {
    scene_->setCasterLod(lod);
    drawnMaps_.reset(); // the same plan now draws other triangles
}

void Renderer::selectEyeTargets(int width, int height) noexcept {
    const auto fits = [&](int slot) {
        return eyeTargets_[slot].buffers.width() == width && eyeTargets_[slot].buffers.height() == height;
    };
    if (fits(eyeSlot_) || width < 1 || height < 1) return; // (a degenerate size is refused by ensure())
    eyeSlot_ ^= 1; // the other size, or the least recently used slot for a new one
}

void Renderer::warnOnce(const std::string& message) {
    if (std::find(stats_.warnings.begin(), stats_.warnings.end(), message) == stats_.warnings.end())
        stats_.warnings.push_back(message);
}

Program& Renderer::depthProgram(const std::string& defines) {
    auto& p = depthPrograms_[defines];
    if (!p) p = std::make_unique<Program>("depth.vert", "depth.frag", defines);
    return *p;
}

void Renderer::fullscreen() const noexcept {
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

int Renderer::splitResolution(const geometry::shadow::SplitPlan& split) const noexcept {
    return std::min(split.resolution, firstDepth_.resolution());
}

void Renderer::uploadShadowBlock(const geometry::shadow::ShadowPlan& plan) {
    // technique = virtual reads no split map (its frame may come before any was drawn): the splits'
    // scale is then taken against a 1-texel array, and never read.
    const int arrayResolution =
        plan.virtualMap.enabled ? std::max(firstDepth_.resolution(), 1) : firstDepth_.resolution();
    const ShadowBlock block = shadowBlock(plan, arrayResolution);
    glBindBuffer(GL_UNIFORM_BUFFER, shadowBlockBuffer_);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof block, &block);
    settingsBlockWords(plan.settings, settingsWords_);
    glBindBuffer(GL_UNIFORM_BUFFER, settingsBlockBuffer_);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, GLsizeiptr(settingsWords_.size() * sizeof settingsWords_[0]),
                    settingsWords_.data());
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, kShadowBlockBinding, shadowBlockBuffer_);
    glBindBufferBase(GL_UNIFORM_BUFFER, kSettingsBlockBinding, settingsBlockBuffer_);
}

// ---- [SECTION] The frame --------------------------------------------------------------------

void Renderer::render(const geometry::shadow::ShadowPlan& plan, const geometry::shadow::Viewport& viewport,
                      const ViewOptions& options) {
    render(std::span<const geometry::shadow::ShadowPlan>(&plan, 1), viewport, options, 0);
}

void Renderer::render(std::span<const geometry::shadow::ShadowPlan> plans, const geometry::shadow::Viewport& viewport,
                      const ViewOptions& options, size_t inspected) {
    ViewOptions views = options;
    if (views.lightViewSize <= 0) views.lightViewSize = 1024;
    if (plans.empty()) throw std::runtime_error("no light to render");
    if (inspected >= plans.size()) throw std::invalid_argument("the inspected light is not among the plans");
    for (const auto& plan : plans)
        if (plan.splits.empty()) throw std::runtime_error("shadow plan has no splits");
    const bool several = plans.size() > 1;
    if (several) views.depthPrePass = true; // every light's eye pass tests against the pre-pass depth
    for (const auto& plan : plans)
        if (plan.virtualMap.enabled) views.depthPrePass = true; // the virtual map's pages come from it
    const geometry::shadow::ShadowPlan& shown = plans[inspected];
    stats_.eyeTriangles = 0;
    const glm::mat4 viewProj = shown.eyeProj * shown.eyeView;
    if (!prepassReady_ || prepassViewProj_ != viewProj || prepassSize_ != glm::ivec2(viewport.width, viewport.height) ||
        (several && !prepassDrawn_)) {
        timers_.begin(Pass::Prepass);
        depthPrePass(shown, viewport, views.depthPrePass);
    }
    prepassReady_ = false;
    if (several) {
        stats_.shadowTriangles = 0;
        lightSum_.ensure(viewport.width, viewport.height, GL_RGBA16F);
        lightSum_.bind();
        const float zero[4] = {0.f, 0.f, 0.f, 0.f};
        glClearBufferfv(GL_COLOR, 0, zero);
    }
    // The other lights first, the inspected one last: the maps, eye buffers and light views it leaves
    // are what every read-back describes (docs/design.md §3.10).
    uint64_t memory = 0;
    for (size_t k = 0; k < plans.size(); ++k) {
        const size_t i = k + 1 == plans.size() ? inspected : (k < inspected ? k : k + 1);
        const geometry::shadow::ShadowPlan& plan = plans[i];
        drawMaps(plan, views.reuseShadowMaps && !several, !several);
        memory = std::max(memory, stats_.shadowMemoryBytes);
        timers_.begin(Pass::Eye);
        eyePass(plan);
        const GLuint mask = blurredMask(plan);
        if (i != inspected) addLight(mask);
        else compose(mask, several);
    }
    stats_.shadowMemoryBytes = memory;
    ++stats_.eyePasses;
    timers_.begin(Pass::LightView);
    lightViewPass(shown, views);
    if (views.unwarped) unwarpedViewPass(shown, views);
    timers_.endFrame();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    for (int unit = 0; unit < 6; ++unit) glBindSampler(unit, 0);
    stats_.gpu = timers_.latest();
}

geometry::shadow::SampleBounds Renderer::eyeSamples(const geometry::shadow::ShadowPlan& plan,
                                                    const geometry::shadow::Viewport& viewport) {
    timers_.begin(Pass::Prepass);
    depthPrePass(plan, viewport);
    if (!sampleReduction_) sampleReduction_ = std::make_unique<SampleReduction>();
    const SampleView view{plan.eyeView, plan.eyeProj, plan.cameraNear, plan.cameraFar, plan.l};
    auto bounds = sampleReduction_->reduce(eyeBuffers().depthTexture(), viewport.width, viewport.height, view);
    prepassReady_ = true;
    prepassViewProj_ = plan.eyeProj * plan.eyeView;
    prepassSize_ = {viewport.width, viewport.height};
    return bounds;
}

const PassTimes& Renderer::waitForTimings() noexcept {
    stats_.gpu = timers_.waitForAll();
    return stats_.gpu;
}

// ---- [SECTION] Shadow maps ------------------------------------------------------------------

void Renderer::drawMaps(const geometry::shadow::ShadowPlan& plan, bool reuse, bool countAlone) {
    shadowMapKey(plan, frameKey_);
    stats_.virtualPages = {};
    if (plan.virtualMap.enabled) { // the pool keeps what it can: every frame marks and draws what changed
        if (countAlone) stats_.shadowTriangles = 0;
        stats_.splitTriangles.assign(plan.splits.size(), 0);
        stats_.splitTrianglesFull.assign(plan.splits.size(), 0);
        stats_.shadowMapsReused = false;
        drawnMaps_.reset();
        timers_.begin(Pass::Shadow);
        virtualPass(plan);
        drawnMaps_ = frameKey_;
        ++stats_.shadowPasses;
        return;
    }
    stats_.shadowMapsReused = reuse && drawnMaps_ && *drawnMaps_ == frameKey_;
    if (stats_.shadowMapsReused) {
        uploadShadowBlock(plan); // the eye-side values changed; the maps and their triangle counts stay
        return;
    }
    if (countAlone) stats_.shadowTriangles = 0; // several lights: render() sums over them
    stats_.splitTriangles.assign(plan.splits.size(), 0);
    stats_.splitTrianglesFull.assign(plan.splits.size(), 0);
    drawnMaps_.reset(); // until the new maps are complete
    timers_.begin(Pass::Shadow);
    shadowPass(plan);
    drawnMaps_ = frameKey_; // a copy only when the maps were drawn, which costs far more
    ++stats_.shadowPasses;
}

void Renderer::drawCasters(const geometry::shadow::ShadowPlan& plan, int index, Program& program, bool backFacesOnly) {
    const geometry::shadow::SplitPlan& split = plan.splits[size_t(index)];
    const bool lod = plan.casterLodTexels > 0.f;
    if (lod && !scene_->hasCasterLod())
        warnOnce("casters.lod = auto: the caster levels are not built; drawing every triangle");
    program.set("uSplit", index);
    for (const auto& m : scene_->meshes()) {
        cullForCasting(m.twoSided, backFacesOnly);
        const auto inMap = [&](const geometry::scene::Aabb& b) {
            return geometry::shadow::clipOverlap(b, split.lightViewProj);
        };
        // casters.lod = auto: per chunk, the coarsest level the map cannot tell from the original.
        const auto level = [&](size_t chunk, const geometry::scene::Aabb& b) {
            return geometry::lod::coarsestLevelWithin(m.lod.chunkLevels[chunk],
                                                      geometry::shadow::casterErrorBudget(plan, index, b));
        };
        const DrawCount n = lod ? scene_->drawLevels(m, inMap, level) : DrawCount{scene_->draw(m, inMap), 0};
        stats_.shadowTriangles += n.drawn;
        stats_.splitTriangles[size_t(index)] += n.drawn;
        stats_.splitTrianglesFull[size_t(index)] += lod ? n.full : n.drawn;
    }
}

void Renderer::shadowPass(const geometry::shadow::ShadowPlan& plan) {
    const int layers = static_cast<int>(plan.splits.size());
    int resolution = 16;
    for (const auto& s : plan.splits) resolution = std::max(resolution, s.resolution);
    if (resolution > maxTextureSize_) {
        warnOnce("shadow_map.resolution " + std::to_string(resolution) + " exceeds GL_MAX_TEXTURE_SIZE " +
                 std::to_string(maxTextureSize_) + "; using " + std::to_string(maxTextureSize_));
        resolution = maxTextureSize_;
    }
    // Depth arrays (one, or three when peeling) and the moments (map and blur target, 32-bit float
    // each): halve until they fit the budget.
    const int moments = geometry::shadow::momentCount(plan.settings.filter.type);
    const double bytesPerTexel = moments > 0 ? 4.0 + 2.0 * 4.0 * moments : (needsPeeling(plan) ? 12.0 : 4.0);
    const int requested = resolution;
    while (resolution > 16 && double(resolution) * resolution * layers * bytesPerTexel > limits_.shadowMemoryBytes)
        resolution /= 2;
    if (resolution != requested)
        warnOnce("shadow maps of " + std::to_string(requested) + "² exceed the " +
                 std::to_string(int(limits_.shadowMemoryBytes / (1 << 20))) + " MiB budget; resolution reduced to " +
                 std::to_string(resolution));
    stats_.shadowResolution = resolution;
    stats_.shadowMemoryBytes = uint64_t(double(resolution) * resolution * layers * bytesPerTexel);
    firstDepth_.ensure(resolution, layers, 0, true);
    uploadShadowBlock(plan);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    if (moments > 0) { // the moment filters read only their moments pass: no depth layers, no peeling
        momentsPass(plan);
        return;
    }
    const bool slope = plan.polygonOffset != glm::vec2(0.f);
    const bool linear = plan.linearDepth; // bias.linear_z, and PCSS (blocker distances in scene units)
    if (slope && !linear) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(plan.polygonOffset.x, plan.polygonOffset.y);
    }
    Program& program = depthProgram(linear ? "#define LINEAR_Z\n" : "");
    program.use();
    for (int i = 0; i < layers; ++i) {
        const auto& split = plan.splits[i];
        firstDepth_.bindLayer(i, splitResolution(split));
        glClear(GL_DEPTH_BUFFER_BIT);
        if (split.empty()) continue;
        drawCasters(plan, i, program, plan.settings.bias.type == BiasType::SecondDepth);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
    sampledDepth_ = firstDepth_.depthTexture();
    if (needsPeeling(plan)) peelAndCombine(plan);
}

void Renderer::peelAndCombine(const geometry::shadow::ShadowPlan& plan) {
    const int layers = firstDepth_.layers(), res = firstDepth_.resolution();
    secondDepth_.ensure(res, layers, 0, true);
    combinedDepth_.ensure(res, layers, 0, true);
    const bool linear = plan.linearDepth;
    Program& peel = depthProgram(linear ? "#define LINEAR_Z\n#define PEEL\n" : "#define PEEL\n");
    peel.use();
    bindTexture(0, GL_TEXTURE_2D_ARRAY, firstDepth_.depthTexture(), nearestSampler_);
    peel.set("uFirstLayer", 0);
    for (int i = 0; i < layers; ++i) {
        const auto& split = plan.splits[i];
        secondDepth_.bindLayer(i, splitResolution(split));
        glClear(GL_DEPTH_BUFFER_BIT);
        if (split.empty()) continue;
        drawCasters(plan, i, peel, false);
    }
    combineProgram_.use();
    bindTexture(0, GL_TEXTURE_2D_ARRAY, firstDepth_.depthTexture(), nearestSampler_);
    bindTexture(1, GL_TEXTURE_2D_ARRAY, secondDepth_.depthTexture(), nearestSampler_);
    combineProgram_.set("uFirst", 0);
    combineProgram_.set("uSecond", 1);
    glDepthFunc(GL_ALWAYS);
    for (int i = 0; i < layers; ++i) {
        const auto& split = plan.splits[i];
        combinedDepth_.bindLayer(i, splitResolution(split));
        combineProgram_.set("uSplit", i);
        fullscreen();
    }
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    sampledDepth_ = combinedDepth_.depthTexture();
}

void Renderer::momentsPass(const geometry::shadow::ShadowPlan& plan) {
    const int layers = firstDepth_.layers(), res = firstDepth_.resolution();
    const int moments = geometry::shadow::momentCount(plan.settings.filter.type);
    SHADOWSCOPE_EXPECTS(moments >= 1 && moments <= 4);                             // called for the moment filters only
    const GLenum formats[] = {GL_R32F, GL_R32F, GL_RG32F, GL_RGBA32F, GL_RGBA32F}; // by moment count
    const GLenum format = formats[moments];
    moments_.ensure(res, layers, format, true);
    momentsTemp_.ensure(res, layers, format, false);
    Program& program = depthProgram("#define MOMENTS\n");
    program.use();
    const std::array<float, 4> far = emptyTexelMoments(plan); // empty texels: at the far end, fully lit
    for (int i = 0; i < layers; ++i) {
        const auto& split = plan.splits[i];
        moments_.bindLayer(i, splitResolution(split));
        glClearBufferfv(GL_COLOR, 0, far.data());
        glClear(GL_DEPTH_BUFFER_BIT);
        if (split.empty()) continue;
        drawCasters(plan, i, program, false);
    }
    glDisable(GL_CULL_FACE);
    const int radius = plan.settings.filter.kernel / 2;
    if (radius > 0) {
        glDisable(GL_DEPTH_TEST);
        momentsBlurProgram_.use();
        momentsBlurProgram_.set("uMoments", 0);
        for (int i = 0; i < layers; ++i) {
            const int size = splitResolution(plan.splits[i]);
            momentsBlurProgram_.set("uSplit", i);
            momentsTemp_.bindLayer(i, size);
            bindTexture(0, GL_TEXTURE_2D_ARRAY, moments_.colourTexture(), nearestSampler_);
            momentsBlurProgram_.set("uStep", glm::ivec2(1, 0));
            fullscreen();
            moments_.bindLayer(i, size);
            bindTexture(0, GL_TEXTURE_2D_ARRAY, momentsTemp_.colourTexture(), nearestSampler_);
            momentsBlurProgram_.set("uStep", glm::ivec2(0, 1));
            fullscreen();
        }
        glEnable(GL_DEPTH_TEST);
    }
    sampledDepth_ = moments_.depthTexture();
}

void Renderer::virtualPass(const geometry::shadow::ShadowPlan& plan) {
    const geometry::shadow::VirtualPlan& v = plan.virtualMap;
    if (!virtual_) virtual_ = std::make_unique<VirtualShadowMap>();
    // The pool within the shadow-memory budget and the largest texture.
    const double pageBytes = 4.0 * double(v.config.pageSize) * double(v.config.pageSize);
    const uint32_t fits = uint32_t(std::clamp(limits_.shadowMemoryBytes / pageBytes, 1.0, 1e9));
    const uint32_t asked = std::min(v.config.poolPages, fits);
    virtual_->ensure(v.config, asked, maxTextureSize_);
    if (virtual_->poolPages() < v.config.poolPages)
        warnOnce("virtual.pool_pages " + std::to_string(v.config.poolPages) + " of " +
                 std::to_string(v.config.pageSize) + "² exceed the " +
                 std::to_string(int(limits_.shadowMemoryBytes / (1 << 20))) + " MiB budget or the largest texture; " +
                 std::to_string(virtual_->poolPages()) + " pages");
    uploadShadowBlock(plan);
    const auto& frame = virtual_->update(v, eyeBuffers().depthTexture(), eyeBuffers().width(), eyeBuffers().height(),
                                         plan.eyeProj * plan.eyeView);
    if (!frame.warning.empty()) warnOnce(frame.warning);
    // Draw the pages the pool says to, each through its own projection, casters culled to the page.
    std::vector<const geometry::shadow::PageKey*> keyOf(virtual_->poolPages(), nullptr);
    for (const auto& e : frame.table) keyOf[e.physical] = &e.key;
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    if (plan.polygonOffset != glm::vec2(0.f)) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(plan.polygonOffset.x, plan.polygonOffset.y);
    }
    Program& program = depthProgram("#define PAGE\n");
    program.use();
    const bool backFaces = plan.settings.bias.type == BiasType::SecondDepth;
    uint64_t triangles = 0;
    for (const uint32_t physical : frame.drawn) {
        virtual_->bindPage(physical);
        glClear(GL_DEPTH_BUFFER_BIT);
        const glm::mat4 viewProj(v.pageViewProj(*keyOf[physical]));
        program.set("uPageViewProj", viewProj);
        for (const auto& m : scene_->meshes()) {
            cullForCasting(m.twoSided, backFaces);
            triangles += scene_->draw(
                m, [&](const geometry::scene::Aabb& b) { return geometry::shadow::clipOverlap(b, viewProj); });
        }
    }
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_CULL_FACE);
    stats_.shadowTriangles += triangles;
    sampledDepth_ = 0; // no split maps this frame
    geometry::shadow::VirtualMapConfig drawn = v.config;
    drawn.poolPages = virtual_->poolPages();
    stats_.shadowResolution = int(v.config.virtualSize);
    stats_.shadowMemoryBytes = geometry::shadow::virtualMemoryBytes(drawn);
    VirtualPageStats& p = stats_.virtualPages;
    p.active = true;
    p.requested = frame.requested;
    p.allocated = frame.table.size();
    p.drawn = frame.drawn.size();
    p.cached = frame.cached;
    p.drawnTotal = virtual_->drawnTotal();
    p.poolPages = virtual_->poolPages();
    p.occupied = virtual_->occupied();
    p.memoryBytes = stats_.shadowMemoryBytes;
    p.finestLevel = frame.finestLevel;
    p.uncovered = virtual_->uncovered();
    p.pageTriangles = triangles;
    p.warning = frame.warning;
}

// ---- [SECTION] Eye view ---------------------------------------------------------------------

/// The eye's depth pre-pass: the heavy eye shader (filter taps, six targets) then runs once per
/// pixel instead of once per overlapping surface, and focus.mode = samples reduces its depths.
void Renderer::depthPrePass(const geometry::shadow::ShadowPlan& plan, const geometry::shadow::Viewport& viewport,
                            bool draw) {
    // 58 bytes per pixel over eight targets; refuse before the driver fails (or swaps) on a huge size.
    const double bytes = 58.0 * viewport.width * viewport.height;
    if (viewport.width > maxTextureSize_ || viewport.height > maxTextureSize_ || bytes > limits_.viewMemoryBytes)
        throw std::runtime_error("view " + std::to_string(viewport.width) + "x" + std::to_string(viewport.height) +
                                 " is too large (needs " + std::to_string(int(bytes / (1 << 20))) +
                                 " MiB of eye buffers; the limit is " +
                                 std::to_string(int(limits_.viewMemoryBytes / (1 << 20))) + " MiB and " +
                                 std::to_string(maxTextureSize_) + " pixels a side)");
    selectEyeTargets(viewport.width, viewport.height);
    eyeBuffers().ensure(viewport.width, viewport.height);
    stats_.eyeWidth = viewport.width;
    stats_.eyeHeight = viewport.height;
    eyeBuffers().bind();
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    prepassDrawn_ = draw;
    if (!draw) return; // the eye pass writes the depth itself (coarse frames: fewer vertices beat less overdraw)
    const glm::mat4 viewProj = plan.eyeProj * plan.eyeView;
    Program& depthOnly = depthProgram("#define EYE_DEPTH\n");
    depthOnly.use();
    depthOnly.set("uViewProj", viewProj);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    for (const auto& m : scene_->meshes()) {
        scene_->draw(m, [&](const geometry::scene::Aabb& box) { return geometry::shadow::clipOverlap(box, viewProj); });
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void Renderer::eyePass(const geometry::shadow::ShadowPlan& plan) {
    eyeBuffers().bind();
    const float zero[4] = {0.f, 0.f, 0.f, 0.f}, lit[4] = {1.f, 1.f, 1.f, 1.f}, sky[4] = {0.f, 0.f, -1.f, 0.f};
    glClearBufferfv(GL_COLOR, EyeBuffers::Base, zero);
    glClearBufferfv(GL_COLOR, EyeBuffers::Direct, zero);
    glClearBufferfv(GL_COLOR, EyeBuffers::Mask, lit);
    glClearBufferfv(GL_COLOR, EyeBuffers::Aux, sky);
    glClearBufferfv(GL_COLOR, EyeBuffers::Position, zero);
    glClearBufferfv(GL_COLOR, EyeBuffers::Normal, zero);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    const glm::mat4 viewProj = plan.eyeProj * plan.eyeView;
    const auto inView = [&](const geometry::scene::Aabb& box) { return geometry::shadow::clipOverlap(box, viewProj); };
    glDepthFunc(prepassDrawn_ ? GL_LEQUAL : GL_LESS);
    glDepthMask(prepassDrawn_ ? GL_FALSE : GL_TRUE);
    eyeProgram_.use();
    eyeProgram_.set("uViewProj", viewProj);
    const auto& f = plan.settings.filter;
    bindTexture(0, GL_TEXTURE_2D_ARRAY, sampledDepth_, nearestSampler_);
    bindTexture(1, GL_TEXTURE_2D_ARRAY, sampledDepth_, compareSampler_);
    bindTexture(2, GL_TEXTURE_2D_ARRAY, geometry::shadow::isMomentFilter(f.type) ? moments_.colourTexture() : 0,
                linearSampler_);
    eyeProgram_.set("uShadowMap", 0);
    eyeProgram_.set("uShadowMapCmp", 1);
    eyeProgram_.set("uMoments", 2);
    // technique = virtual: the page table and the physical pages (units of their own: a unit holds
    // one sampler type).
    const bool virtualMap = plan.virtualMap.enabled && virtual_;
    eyeProgram_.set("uVirtual", virtualMap ? 1 : 0);
    bindTexture(4, GL_TEXTURE_2D_ARRAY, virtualMap ? virtual_->pageTable() : 0, nearestSampler_);
    bindTexture(5, GL_TEXTURE_2D, virtualMap ? virtual_->atlas() : 0, nearestSampler_);
    eyeProgram_.set("uPageTable", 4);
    eyeProgram_.set("uPageAtlas", 5);
    if (virtualMap) virtual_->setUniforms(eyeProgram_, plan.virtualMap);
    for (const auto& m : scene_->meshes()) {
        eyeProgram_.set("uColor", m.color);
        stats_.eyeTriangles += scene_->draw(m, inView);
    }
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

GLuint Renderer::blurredMask(const geometry::shadow::ShadowPlan& plan) {
    glDisable(GL_DEPTH_TEST);
    GLuint mask = eyeBuffers().texture(EyeBuffers::Mask);
    const int w = eyeBuffers().width(), h = eyeBuffers().height();
    if (plan.settings.filter.eyeBlurIterations > 0) {
        eyeBlurProgram_.use();
        eyeBlurProgram_.set("uMask", 0);
        eyeBlurProgram_.set("uBase", 1);
        bindTexture(1, GL_TEXTURE_2D, eyeBuffers().texture(EyeBuffers::Base), nearestSampler_);
        int target = 0;
        for (int it = 0; it < plan.settings.filter.eyeBlurIterations; ++it)
            for (const glm::vec2 step : {glm::vec2(1.f / w, 0.f), glm::vec2(0.f, 1.f / h)}) {
                eyeBuffers().bindBlur(target);
                bindTexture(0, GL_TEXTURE_2D, mask, linearSampler_);
                eyeBlurProgram_.set("uStep", step);
                fullscreen();
                mask = eyeBuffers().blurTexture(target);
                target ^= 1;
            }
    }
    glEnable(GL_DEPTH_TEST);
    return mask;
}

void Renderer::addLight(GLuint mask) {
    lightSum_.bind();
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    addLightProgram_.use();
    bindTexture(0, GL_TEXTURE_2D, eyeBuffers().texture(EyeBuffers::Direct), nearestSampler_);
    bindTexture(1, GL_TEXTURE_2D, mask, nearestSampler_);
    addLightProgram_.set("uDirect", 0);
    addLightProgram_.set("uMask", 1);
    fullscreen();
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
}

void Renderer::compose(GLuint mask, bool addLights) {
    glDisable(GL_DEPTH_TEST);
    const int w = eyeBuffers().width(), h = eyeBuffers().height();
    eyeImage().ensure(w, h);
    eyeImage().bind();
    composeProgram_.use();
    bindTexture(0, GL_TEXTURE_2D, eyeBuffers().texture(EyeBuffers::Base), nearestSampler_);
    bindTexture(1, GL_TEXTURE_2D, eyeBuffers().texture(EyeBuffers::Direct), nearestSampler_);
    bindTexture(2, GL_TEXTURE_2D, mask, nearestSampler_);
    composeProgram_.set("uBase", 0);
    composeProgram_.set("uDirect", 1);
    composeProgram_.set("uMask", 2);
    composeProgram_.set("uSky", kSky);
    bindTexture(3, GL_TEXTURE_2D, addLights ? lightSum_.texture() : 0, nearestSampler_);
    composeProgram_.set("uOtherLights", 3);
    composeProgram_.set("uAddOtherLights", addLights ? 1 : 0);
    fullscreen();
    glEnable(GL_DEPTH_TEST);
}

// ---- [SECTION] Light views ------------------------------------------------------------------

void Renderer::lightViewPass(const geometry::shadow::ShadowPlan& plan, const ViewOptions& views) {
    if (plan.virtualMap.enabled && virtual_) {
        virtualViewPass(plan, views);
        return;
    }
    const int split = std::clamp(views.lightSplit, 0, int(plan.splits.size()) - 1);
    light_.ensure(views.lightViewSize, views.lightViewSize);
    light_.bind();
    glDisable(GL_DEPTH_TEST);
    lightViewProgram_.use();
    bindTexture(0, GL_TEXTURE_2D_ARRAY, sampledDepth_, nearestSampler_);
    lightViewProgram_.set("uShadowMap", 0);
    lightViewProgram_.set("uSplit", split);
    const auto& s = plan.splits[split];
    glm::vec2 range = views.depthRange;
    if (range.x < 0.f) range = plan.linearDepth ? glm::vec2(0.f, 1.f) : s.bodyDepthRange;
    lightViewProgram_.set("uDepthRange", range);
    fullscreen();
    if (views.overlays) lines_.draw(geometry::shadow::warpedViewOverlays(plan, split), s.lightViewProj);
    glEnable(GL_DEPTH_TEST);
}

void Renderer::virtualViewPass(const geometry::shadow::ShadowPlan& plan, const ViewOptions& views) {
    const geometry::shadow::VirtualPlan& v = plan.virtualMap;
    light_.ensure(views.lightViewSize, views.lightViewSize);
    light_.bind();
    glDisable(GL_DEPTH_TEST);
    // Framed on the allocated pages (the coarsest square when there are none), as a square.
    glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const auto& e : virtual_->frame().table) {
        const double w = v.levels[size_t(e.key.level)].pageWorld;
        const glm::dvec2 corner = glm::dvec2(double(e.key.x), double(e.key.y)) * w - v.frame.project(v.eye);
        lo = glm::min(lo, corner);
        hi = glm::max(hi, corner + w);
    }
    if (!(lo.x <= hi.x)) {
        lo = v.levelOrigin(v.config.levels - 1);
        hi = lo + v.levels.back().pageWorld * double(v.config.pagesPerSide());
    }
    const double side = std::max(hi.x - lo.x, hi.y - lo.y);
    const glm::dvec2 corner = 0.5 * (lo + hi) - 0.5 * side;
    virtualViewProgram_.use();
    bindTexture(0, GL_TEXTURE_2D_ARRAY, virtual_->pageTable(), nearestSampler_);
    bindTexture(1, GL_TEXTURE_2D, virtual_->atlas(), nearestSampler_);
    virtualViewProgram_.set("uPageTable", 0);
    virtualViewProgram_.set("uPageAtlas", 1);
    virtual_->setUniforms(virtualViewProgram_, v);
    virtualViewProgram_.set("uViewCorner", glm::vec2(corner));
    virtualViewProgram_.set("uViewSide", float(side));
    virtualViewProgram_.set("uPixel", float(side / views.lightViewSize));
    fullscreen();
    glEnable(GL_DEPTH_TEST);
}

void Renderer::unwarpedViewPass(const geometry::shadow::ShadowPlan& plan, const ViewOptions& views) {
    lightUnwarped_.ensure(views.lightViewSize, views.lightViewSize);
    lightUnwarped_.bind();
    const float background[4] = {0.08f, 0.10f, 0.22f, 1.f};
    glClearBufferfv(GL_COLOR, 0, background);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    unlitProgram_.use();
    unlitProgram_.set("uViewProj", plan.unwarpedViewProj);
    for (const auto& m : scene_->meshes()) {
        unlitProgram_.set("uColor", m.color);
        scene_->draw(
            m, [&](const geometry::scene::Aabb& b) { return geometry::shadow::clipOverlap(b, plan.unwarpedViewProj); });
    }
    if (views.overlays) lines_.draw(geometry::shadow::unwarpedViewOverlays(plan), plan.unwarpedViewProj);
}

// ---- [SECTION] Reading back -----------------------------------------------------------------

std::vector<float> Renderer::readShadowMask() const {
    const int w = eyeBuffers().width(), h = eyeBuffers().height();
    std::vector<float> out(size_t(w) * h);
    glBindTexture(GL_TEXTURE_2D, eyeBuffers().texture(EyeBuffers::Mask));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_FLOAT, out.data());
    flipRows(out, size_t(w), h);
    return out;
}

std::vector<glm::vec4> Renderer::readFloat4(EyeBuffers::Attachment a) const {
    const int w = eyeBuffers().width(), h = eyeBuffers().height();
    std::vector<glm::vec4> out(size_t(w) * h);
    glBindTexture(GL_TEXTURE_2D, eyeBuffers().texture(a));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out.data());
    flipRows(out, size_t(w), h);
    return out;
}

float Renderer::readShadowDepth(int split, int x, int y) const {
    const int res = stats_.shadowResolution;
    if (sampledDepth_ == 0 || split < 0 || split >= firstDepth_.layers() || x < 0 || y < 0 || x >= res || y >= res)
        return std::numeric_limits<float>::quiet_NaN();
    float depth = std::numeric_limits<float>::quiet_NaN();
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureSubImage(sampledDepth_, 0, x, y, split, 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, sizeof depth, &depth);
    return depth;
}

std::vector<float> Renderer::readShadowMap(int split, int resolution) const {
    if (sampledDepth_ == 0 || split < 0 || split >= firstDepth_.layers() || resolution < 1 ||
        resolution > stats_.shadowResolution)
        return {};
    const size_t side = size_t(resolution);
    std::vector<float> out(side * side);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureSubImage(sampledDepth_, 0, 0, 0, split, resolution, resolution, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                         GLsizei(out.size() * sizeof(float)), out.data());
    flipRows(out, side, resolution);
    return out;
}

std::vector<float> Renderer::readShadowSamples(const geometry::shadow::ShadowPlan& plan, int n) {
    const int width = int(stats_.eyeWidth), height = int(stats_.eyeHeight);
    if (n < 1 || width < 1 || height < 1 || !drawnMaps_)
        throw std::invalid_argument("readShadowSamples: needs a drawn frame and n >= 1");
    const int slot = eyeSlot_;
    const FrameStats kept = stats_;
    // The pre-pass then the eye pass alone, into the other slot's targets: the maps are the frame's.
    depthPrePass(plan, {width * n, height * n}, true);
    uploadShadowBlock(plan);
    eyePass(plan);
    std::vector<float> s = readShadowMask();
    const std::vector<glm::vec4> normals = readNormals(), aux = readAux();
    for (size_t i = 0; i < s.size(); ++i)
        if (!(normals[i].w > 0.f) || aux[i].z < 0.f) s[i] = std::numeric_limits<float>::quiet_NaN();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    for (int unit = 0; unit < 4; ++unit) glBindSampler(unit, 0);
    eyeSlot_ = slot;
    stats_ = kept;
    prepassReady_ = false;
    return s;
}

std::vector<glm::vec4> Renderer::readAux() const { return readFloat4(EyeBuffers::Aux); }
std::vector<glm::vec4> Renderer::readPositions() const { return readFloat4(EyeBuffers::Position); }
std::vector<glm::vec4> Renderer::readNormals() const { return readFloat4(EyeBuffers::Normal); }

} // namespace renderer
