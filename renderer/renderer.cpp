#include "renderer.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace renderer {

namespace {
const glm::vec4 kSky{0.62f, 0.72f, 0.85f, 1.f};
}

Renderer::Renderer(const geometry::Scene& scene) : scene_(std::make_unique<GpuScene>(scene)) {
    glGenVertexArrays(1, &emptyVao_);
}

Renderer::~Renderer() { glDeleteVertexArrays(1, &emptyVao_); }

void Renderer::setScene(const geometry::Scene& scene) { scene_ = std::make_unique<GpuScene>(scene); }

void Renderer::render(const geometry::ShadowPlan& plan, const geometry::Viewport& viewport, int lightViewSize,
                      int lightSplit) {
    if (plan.splits.empty()) throw std::runtime_error("shadow plan has no splits");
    stats_.shadowTriangles = stats_.eyeTriangles = 0;
    timers_.begin(Pass::Shadow);
    shadowPass(plan);
    timers_.begin(Pass::Eye);
    eyePass(plan, viewport);
    timers_.begin(Pass::LightView);
    lightViewPass(plan, lightViewSize, std::clamp(lightSplit, 0, int(plan.splits.size()) - 1));
    timers_.endFrame();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    stats_.gpu = timers_.latest();
}

float Renderer::mapScale(const geometry::SplitPlan& split) const noexcept {
    return shadowMaps_.resolution() > 0 ? float(split.resolution) / float(shadowMaps_.resolution()) : 1.f;
}

const PassTimes& Renderer::waitForTimings() noexcept {
    stats_.gpu = timers_.waitForAll();
    return stats_.gpu;
}

void Renderer::shadowPass(const geometry::ShadowPlan& plan) {
    const int layers = static_cast<int>(plan.splits.size());
    int resolution = 1;
    for (const auto& s : plan.splits) resolution = std::max(resolution, s.resolution);
    shadowMaps_.ensure(resolution, layers);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE); // thin CAD parts: both faces cast
    glDisable(GL_BLEND);
    depthProgram_.use();
    for (int i = 0; i < layers; ++i) {
        const auto& split = plan.splits[i];
        shadowMaps_.bindLayer(i);
        glViewport(0, 0, split.resolution, split.resolution);
        glClear(GL_DEPTH_BUFFER_BIT);
        if (split.empty()) continue;
        depthProgram_.set("uLightViewProj", split.lightViewProj);
        for (const auto& m : scene_->meshes()) {
            depthProgram_.set("uModel", m.transform);
            stats_.shadowTriangles += scene_->draw(m);
        }
    }
}

void Renderer::eyePass(const geometry::ShadowPlan& plan, const geometry::Viewport& viewport) {
    eye_.ensure(viewport.width, viewport.height);
    eye_.bind();
    glClearColor(kSky.r, kSky.g, kSky.b, kSky.a);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    eyeProgram_.use();
    eyeProgram_.set("uViewProj", plan.eyeProj * plan.eyeView);
    eyeProgram_.set("uLightDir", plan.l);
    eyeProgram_.set("uEye", glm::vec3(glm::inverse(plan.eyeView)[3]));
    eyeProgram_.set("uViewDir", plan.v);
    const int count = static_cast<int>(plan.splits.size());
    eyeProgram_.set("uSplitCount", count);
    eyeProgram_.set("uReceiverOffset", plan.receiverOffset);
    for (int i = 0; i < count; ++i) {
        const std::string idx = "[" + std::to_string(i) + "]";
        eyeProgram_.set(("uLightViewProj" + idx).c_str(), plan.splits[i].lightViewProj);
        eyeProgram_.set(("uSplitFar" + idx).c_str(), plan.splits[i].far);
        eyeProgram_.set(("uMapScale" + idx).c_str(), mapScale(plan.splits[i]));
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D_ARRAY, shadowMaps_.texture());
    eyeProgram_.set("uShadowMap", 0);
    for (const auto& m : scene_->meshes()) {
        eyeProgram_.set("uModel", m.transform);
        eyeProgram_.set("uColor", m.color);
        stats_.eyeTriangles += scene_->draw(m);
    }
}

void Renderer::lightViewPass(const geometry::ShadowPlan& plan, int size, int split) {
    light_.ensure(size, size);
    light_.bind();
    glDisable(GL_DEPTH_TEST);
    lightViewProgram_.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D_ARRAY, shadowMaps_.texture());
    lightViewProgram_.set("uShadowMap", 0);
    lightViewProgram_.set("uLayer", split);
    lightViewProgram_.set("uMapScale", mapScale(plan.splits[split]));
    lightViewProgram_.set("uDepthRange", plan.splits[split].bodyDepthRange);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

} // namespace renderer
