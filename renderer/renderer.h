#pragma once
// Draws one frame from a shadow plan: shadow pass per split (with peeling or VSM moments when the
// plan's bias/filter need them), eye pass, eye-space blur, composition, light view. Makes no
// shadow-math decisions: every matrix, range and choice comes from the plan.
#include "geometry/shadow/shadow_plan.h"
#include "gpu_scene.h"
#include "gpu_timers.h"
#include "image.h"
#include "line_renderer.h"
#include "program.h"
#include "render_targets.h"
#include "sample_reduction.h"
#include "settings_block.h"
#include "shadow_block.h"
#include "shadow_map_key.h"
#include "virtual_map.h"

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace renderer {

struct FrameStats {
    uint64_t shadowTriangles = 0; // over all splits (and peeling passes)
    uint64_t eyeTriangles = 0;
    std::vector<uint64_t> splitTriangles;     // per split
    std::vector<uint64_t> splitTrianglesFull; // per split, as many as without caster LOD
    int shadowResolution = 0;                 // of the array actually allocated
    uint64_t shadowMemoryBytes = 0;           // every shadow texture (depth layers, peeling, moments)
    int eyeWidth = 0, eyeHeight = 0;
    PassTimes gpu;                     // from an earlier frame (see GpuTimers)
    std::vector<std::string> warnings; // e.g. resolution clamped to the GL limit
    bool shadowMapsReused = false;     // the last render() kept the maps of an earlier one
    uint64_t shadowPasses = 0;         // render() calls that drew the maps, since construction
    uint64_t eyePasses = 0;            // render() calls (each draws the eye view), since construction
    VirtualPageStats virtualPages;     // technique = virtual: the pages of the last frame
};

/// What the light views show.
struct ViewOptions {
    int lightViewSize = 0;      // edge of the square light-view images; 0: the caller's default
    int lightSplit = 0;         // which split's map the warped light view shows
    bool overlays = true;       // frusta, B_i, P, S drawn over the light views
    bool unwarped = true;       // also render the unwarped light view
    glm::vec2 depthRange{-1.f}; // light view's black and white points; x < 0: auto-fit to B_i
    /// Keep the maps drawn by the previous render() when the plan's shadowMapKey() is unchanged
    /// (the dashboard); off for measurements, which time every pass of every frame.
    bool reuseShadowMaps = false;
    /// Draw the eye's depth pre-pass (else the eye pass writes depth itself: the dashboard's coarse
    /// frames, where the vertices cost more than the overdraw). focus.mode = samples always has one.
    bool depthPrePass = true;
};

struct RendererLimits {
    double shadowMemoryBytes = 1.5 * 1024 * 1024 * 1024; // all shadow textures together
    double viewMemoryBytes = 4.0 * 1024 * 1024 * 1024;   // the eye pass's buffers (beyond: an error)
};

class Renderer {
public:
    /// Needs a current GL context; uploads the scene.
    explicit Renderer(const geometry::scene::Scene& scene, RendererLimits limits = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    void setScene(const geometry::scene::Scene& scene);
    /// The scene's simplified caster levels (geometry/lod), for plans with casters.lod = auto.
    /// Until they are given, such plans draw every triangle (with a warning).
    void setCasterLod(const geometry::lod::SceneLod& lod);
    [[nodiscard]] bool hasCasterLod() const noexcept { return scene_->hasCasterLod(); }
    /// focus.mode = samples: draws the eye's depth pre-pass for `plan`'s camera at `viewport` and
    /// reduces its samples on the GPU (sample_reduction.h). The next render() with the same camera
    /// and viewport reuses that pre-pass, so the frame draws it once.
    [[nodiscard]] geometry::shadow::SampleBounds eyeSamples(const geometry::shadow::ShadowPlan& plan,
                                                            const geometry::shadow::Viewport& viewport);
    /// Renders the eye view at `viewport` and the light views into textures.
    void render(const geometry::shadow::ShadowPlan& plan, const geometry::shadow::Viewport& viewport,
                const ViewOptions& views);
    /// Several lights (docs/design.md §3.10), one plan each, all for the same camera: each light's
    /// maps and eye pass in turn, their direct terms added. The light `inspected` is drawn last, so
    /// the read-backs (mask, aux, positions, maps), the light views and the per-split stats describe
    /// it; shadowTriangles counts every light's. Never reuses maps across frames.
    void render(std::span<const geometry::shadow::ShadowPlan> plans, const geometry::shadow::Viewport& viewport,
                const ViewOptions& views, size_t inspected = 0);
    void render(const geometry::shadow::ShadowPlan& plan, const geometry::shadow::Viewport& viewport,
                int lightViewSize) {
        ViewOptions v;
        v.lightViewSize = lightViewSize;
        render(plan, viewport, v);
    }

    [[nodiscard]] GLuint eyeTexture() const noexcept { return eyeImage().texture(); }
    [[nodiscard]] GLuint lightTexture() const noexcept { return light_.texture(); }
    [[nodiscard]] geometry::analysis::Image readEye() const {
        return readTexture(eyeImage().texture(), eyeImage().width(), eyeImage().height());
    }
    [[nodiscard]] geometry::analysis::Image readLight() const {
        return readTexture(light_.texture(), light_.width(), light_.height());
    }
    [[nodiscard]] GLuint unwarpedLightTexture() const noexcept { return lightUnwarped_.texture(); }
    [[nodiscard]] geometry::analysis::Image readUnwarpedLight() const {
        return readTexture(lightUnwarped_.texture(), lightUnwarped_.width(), lightUnwarped_.height());
    }
    /// Per pixel (world position, aliasing error m); m is meaningful on receivers only.
    [[nodiscard]] std::vector<glm::vec4> readPositions() const;
    /// Per pixel (facing normal, N·L); N·L > 0 marks a receiver, 0 for sky.
    [[nodiscard]] std::vector<glm::vec4> readNormals() const;
    /// The eye pass's per-pixel shadow factor s ∈ [0, 1] (top row first; sky pixels are 1).
    [[nodiscard]] std::vector<float> readShadowMask() const;
    /// Per pixel (map texel u, v, split index, map depth); split −1 for sky.
    [[nodiscard]] std::vector<glm::vec4> readAux() const;
    /// The depth the eye pass compares against in split `split`'s map at texel (x, y) (x right, y up
    /// from the map's bottom row, as the texel coordinates in readAux()); NaN outside the map.
    [[nodiscard]] float readShadowDepth(int split, int x, int y) const;
    /// Split `split`'s whole map as the eye pass reads it: `resolution` × `resolution` depths (the
    /// split's drawn resolution, at most the array's), top row (v = 1) first. Empty for a split or
    /// resolution the last frame did not draw.
    [[nodiscard]] std::vector<float> readShadowMap(int split, int resolution) const;
    /// The eye pass's s at the truth's sample positions (docs/design.md §4 "Like for like"): for the
    /// plan last drawn, the eye pass alone again at (width·n) × (height·n) with the maps already
    /// drawn, so sub-pixel (x, y) of pixel (X, Y) lies where GroundTruth::coverage traces sample
    /// (x, y). NaN where that sample sees no receiver. The frame drawn before stays readable (it keeps
    /// its own eye targets); stats() keep describing it. Throws std::runtime_error as render() for a
    /// size beyond the view memory limit, std::invalid_argument for n < 1 or no frame drawn.
    [[nodiscard]] std::vector<float> readShadowSamples(const geometry::shadow::ShadowPlan& plan, int n);
    [[nodiscard]] const FrameStats& stats() const noexcept { return stats_; }
    /// technique = virtual: the virtual map as the last frame left it (null before the first such frame).
    [[nodiscard]] const VirtualShadowMap* virtualMap() const noexcept { return virtual_.get(); }
    /// Takes the GPU times that arrived since the last frame into stats().gpu, drawing nothing;
    /// true while some are still in flight.
    bool pollGpuTimes() noexcept {
        const bool inFlight = timers_.poll();
        stats_.gpu = timers_.latest();
        return inFlight;
    }
    /// GPU milliseconds of `pass` in the newest timed frame that ran it (NaN: none yet).
    [[nodiscard]] double lastDrawnGpuMs(Pass pass) const noexcept { return timers_.lastDrawn(pass); }
    /// Blocks until the GPU times of every rendered frame are in; for one-shot exports.
    const PassTimes& waitForTimings() noexcept;

private:
    /// The plan's maps, unless `reuse` and the maps drawn last are this plan's; `countAlone`: the
    /// triangle count restarts (one light per frame).
    void drawMaps(const geometry::shadow::ShadowPlan& plan, bool reuse, bool countAlone);
    void shadowPass(const geometry::shadow::ShadowPlan& plan);
    void drawCasters(const geometry::shadow::ShadowPlan& plan, int index, Program& program, bool backFacesOnly);
    void peelAndCombine(const geometry::shadow::ShadowPlan& plan);
    void momentsPass(const geometry::shadow::ShadowPlan& plan);
    /// technique = virtual: marks the pages the pre-pass asks for and draws those the pool says to.
    void virtualPass(const geometry::shadow::ShadowPlan& plan);
    void virtualViewPass(const geometry::shadow::ShadowPlan& plan, const ViewOptions& views);
    void depthPrePass(const geometry::shadow::ShadowPlan& plan, const geometry::shadow::Viewport& viewport,
                      bool draw = true);
    void eyePass(const geometry::shadow::ShadowPlan& plan);
    /// The eye pass's shadow factor, blurred in eye space when the plan asks (Scherzer §4.3).
    [[nodiscard]] GLuint blurredMask(const geometry::shadow::ShadowPlan& plan);
    /// Adds this light's direct term · `mask` to the lights' sum (several lights).
    void addLight(GLuint mask);
    /// The eye image: ambient + direct · `mask` (+ the other lights' sum when `addLights`).
    void compose(GLuint mask, bool addLights);
    void lightViewPass(const geometry::shadow::ShadowPlan& plan, const ViewOptions& views);
    void unwarpedViewPass(const geometry::shadow::ShadowPlan& plan, const ViewOptions& views);
    [[nodiscard]] std::vector<glm::vec4> readFloat4(EyeBuffers::Attachment a) const;
    void fullscreen() const noexcept;
    [[nodiscard]] int splitResolution(const geometry::shadow::SplitPlan& split) const noexcept;
    void uploadShadowBlock(const geometry::shadow::ShadowPlan& plan);
    Program& depthProgram(const std::string& defines);
    void warnOnce(const std::string& message);

    std::unique_ptr<GpuScene> scene_;
    std::map<std::string, std::unique_ptr<Program>> depthPrograms_;
    Program eyeProgram_{"eye.vert", "eye.frag"};
    Program combineProgram_{"fullscreen.vert", "combine_depth.frag"};
    Program momentsBlurProgram_{"fullscreen.vert", "moments_blur.frag"};
    Program eyeBlurProgram_{"fullscreen.vert", "eye_blur.frag"};
    Program composeProgram_{"fullscreen.vert", "compose.frag"};
    Program addLightProgram_{"fullscreen.vert", "add_light.frag"};
    Program lightViewProgram_{"fullscreen.vert", "light_view.frag"};
    Program unlitProgram_{"eye.vert", "unlit.frag"};
    Program virtualViewProgram_{"fullscreen.vert", "virtual_view.frag"};
    std::unique_ptr<VirtualShadowMap> virtual_; // made on the first virtual frame
    LineRenderer lines_;
    GLuint emptyVao_ = 0;
    GLuint shadowBlockBuffer_ = 0;   // ShadowBlock (renderer/shadow_block.h), bound at kShadowBlockBinding
    GLuint settingsBlockBuffer_ = 0; // settingsBlockWords (renderer/settings_block.h), at kSettingsBlockBinding
    GLuint nearestSampler_ = 0, compareSampler_ = 0, linearSampler_ = 0;
    GLint maxTextureSize_ = 0;
    RendererLimits limits_;
    LayeredTarget firstDepth_, secondDepth_, combinedDepth_, moments_, momentsTemp_;
    GLuint sampledDepth_ = 0; // the depth array the eye pass reads this frame
    /// The eye pass's buffers and image per view size: the dashboard alternates a coarse size while
    /// the user drags and the full size when input pauses, and each size keeps its textures.
    struct EyeTargets {
        EyeBuffers buffers;
        ColorTarget image;
    };
    std::array<EyeTargets, 2> eyeTargets_;
    int eyeSlot_ = 0;
    void selectEyeTargets(int width, int height) noexcept;
    [[nodiscard]] EyeBuffers& eyeBuffers() noexcept { return eyeTargets_[eyeSlot_].buffers; }
    [[nodiscard]] const EyeBuffers& eyeBuffers() const noexcept { return eyeTargets_[eyeSlot_].buffers; }
    [[nodiscard]] ColorTarget& eyeImage() noexcept { return eyeTargets_[eyeSlot_].image; }
    [[nodiscard]] const ColorTarget& eyeImage() const noexcept { return eyeTargets_[eyeSlot_].image; }
    std::optional<ShadowMapKey> drawnMaps_;            // what the maps hold now; empty: nothing reusable
    ShadowMapKey frameKey_;                            // this frame's key, filled in place (no allocation)
    std::vector<std::uint32_t> settingsWords_;         // the settings block's upload, filled in place
    std::unique_ptr<SampleReduction> sampleReduction_; // made on first use
    bool prepassDrawn_ = true;                         // this frame's eye buffers hold the pre-pass depth
    bool prepassReady_ = false;                        // eyeSamples drew the pre-pass for this camera:
    glm::mat4 prepassViewProj_{1.f};                   // …
    glm::ivec2 prepassSize_{0};                        // … at this size
    ColorTarget light_, lightUnwarped_;
    ColorTarget lightSum_; // several lights: Σ direct · s of the lights drawn before the inspected one (linear)
    GpuTimers timers_;
    FrameStats stats_;
};

} // namespace renderer
