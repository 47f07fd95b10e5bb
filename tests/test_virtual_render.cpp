// technique = virtual on OSMesa (issue 34; docs/design.md §3.11): pages marked from the depth pre-pass,
// drawn into the pool and read through the page table. Each pixel samples the level its footprint asks
// (m within a factor 2 of 1), no page is allocated where no visible pixel is, an overfull pool falls
// back to coarser levels with a warning, and pages kept from an earlier frame give the same picture
// as drawing every page anew.
#include "geometry/analysis/ground_truth.h"
#include "geometry/scene/builtin_scenes.h"
#include "renderer/context.h"
#include "renderer/measure.h"
#include "renderer/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

using namespace geometry::scene;
using namespace geometry::shadow;

namespace {

constexpr Viewport kView{160, 96};

/// The plane scene seen from 3 m up, looking almost level, the sun 45° high across the view: γ ≈ 90°.
Scene gammaNinetyScene() {
    Scene s = makePlaneScene();
    s.camera.eye = {0.f, 3.f, 18.f};
    s.camera.target = {0.f, 2.f, 0.f};
    s.lights[0].direction = glm::normalize(glm::vec3(1.f, -1.f, 0.f));
    return s;
}

ShadowSettings virtualSettings(int poolPages = 4096) {
    ShadowSettings s;
    s.technique = Technique::Virtual;
    // Levels from 0.4 mm to 20 cm texels: every footprint of this view (2 mm to 20 cm) has its level.
    s.virtualMap.size = 1024;
    s.virtualMap.pageSize = 32;
    s.virtualMap.levels = 10;
    s.virtualMap.poolPages = poolPages;
    s.filter.type = FilterType::None;
    s.bias.type = BiasType::SlopeNormalOffset; // texels as wide as a pixel: a constant bias would not do far off
    return s;
}

struct Bench {
    std::unique_ptr<renderer::GlContext> context = renderer::createOSMesaContext();
    Scene scene;
    std::unique_ptr<renderer::Renderer> r;
    explicit Bench(Scene s) : scene(std::move(s)), r(std::make_unique<renderer::Renderer>(scene)) {}
    ShadowPlan render(const ShadowSettings& settings) { return render(settings, scene.camera, scene.lights[0]); }
    ShadowPlan render(const ShadowSettings& settings, const Camera& camera, const Light& light) {
        context->makeCurrent();
        const ShadowPlan plan = planShadows(settings, scene.bounds(), camera, light, kView);
        r->render(plan, kView, 32);
        return plan;
    }
};

/// Receivers: pixels that see a surface facing the light.
std::vector<size_t> receivers(const renderer::Renderer& r) {
    const auto normals = r.readNormals();
    std::vector<size_t> out;
    for (size_t i = 0; i < normals.size(); ++i)
        if (normals[i].w > 0.f) out.push_back(i);
    return out;
}

} // namespace

TEST(VirtualRender, EachPixelSamplesTheLevelItsFootprintAsks) {
    Bench b(gammaNinetyScene());
    const ShadowPlan plan = b.render(virtualSettings());
    ASSERT_TRUE(plan.virtualMap.enabled);
    EXPECT_NEAR(plan.gammaDeg, 90.f, 5.f);
    const auto& v = b.r->stats().virtualPages;
    ASSERT_TRUE(v.active);
    EXPECT_TRUE(v.warning.empty()) << v.warning;
    EXPECT_EQ(v.uncovered, 0u);
    const auto positions = b.r->readPositions();
    const auto aux = b.r->readAux();
    const std::vector<size_t> lit = receivers(*b.r);
    ASSERT_GT(lit.size(), size_t(kView.width * kView.height / 3));
    size_t within = 0, levelsSeen = 0, fineBelow = 0;
    std::vector<int> perLevel(10, 0);
    for (const size_t i : lit) {
        const float m = positions[i].w;
        const int level = int(aux[i].z);
        within += m >= 0.5f && m <= 2.f;
        fineBelow += m < 0.5f && level < 9; // finer than asked: only the coarsest level may be (its texels cap it)
        perLevel[size_t(std::clamp(level, 0, 9))]++;
    }
    for (const int n : perLevel) levelsSeen += n > 0;
    // Image-border pixels and a pole's silhouette take their footprint from one side: allow 1 %.
    EXPECT_GE(double(within), 0.99 * double(lit.size() - size_t(perLevel[9])))
        << within << " of " << lit.size() << " with m in [0.5, 2]";
    EXPECT_LE(double(fineBelow), 0.01 * double(lit.size()));
    EXPECT_GE(levelsSeen, 3u) << "the ground recedes over several levels";
}

TEST(VirtualRender, PagesAreAllocatedOnlyWhereVisiblePixelsAre) {
    Bench b(gammaNinetyScene());
    ShadowSettings s = virtualSettings();
    s.bias.type = BiasType::Slope; // the receiver is the pixel's own point (no normal offset moves it)
    const ShadowPlan plan = b.render(s);
    const auto& vp = plan.virtualMap;
    const renderer::VirtualShadowMap* map = b.r->virtualMap();
    ASSERT_NE(map, nullptr);
    const auto& table = map->frame().table;
    ASSERT_FALSE(table.empty());
    EXPECT_EQ(table.size(), map->frame().requested);
    // Every visible pixel's world point (back faces too: the pre-pass marks what it sees).
    const auto positions = b.r->readPositions();
    const auto aux = b.r->readAux();
    std::vector<int> hits(table.size(), 0);
    size_t ownPageAllocated = 0, visible = 0;
    for (size_t i = 0; i < positions.size(); ++i) {
        if (aux[i].z < 0.f) continue; // sky
        ++visible;
        const glm::dvec2 s = vp.frame.project(glm::dvec3(positions[i]));
        for (size_t e = 0; e < table.size(); ++e) {
            const auto& key = table[e].key;
            const double w = vp.levels[size_t(key.level)].pageWorld,
                         tol = 2.0 * vp.levels[size_t(key.level)].texelWorld;
            hits[e] += s.x >= double(key.x) * w - tol && s.x <= double(key.x + 1) * w + tol &&
                       s.y >= double(key.y) * w - tol && s.y <= double(key.y + 1) * w + tol;
        }
        const auto own = pageAt(s, int(aux[i].z), vp.levels, vp.config);
        ownPageAllocated +=
            own && std::any_of(table.begin(), table.end(), [&](const auto& e) { return e.key == *own; });
    }
    for (size_t e = 0; e < table.size(); ++e)
        EXPECT_GT(hits[e], 0) << "page (" << table[e].key.level << ", " << table[e].key.x << ", " << table[e].key.y
                              << ") holds no visible pixel";
    EXPECT_EQ(ownPageAllocated, visible) << "every pixel reads a page allocated at the level it samples";
}

TEST(VirtualRender, AnOverfullPoolFallsBackToCoarserLevelsWithAWarning) {
    Bench b(gammaNinetyScene());
    b.render(virtualSettings());
    const auto full = b.r->readShadowMask();
    const int finest = b.r->stats().virtualPages.finestLevel;
    const uint64_t asked = b.r->stats().virtualPages.requested;
    Bench small(gammaNinetyScene());
    small.render(virtualSettings(96));
    const auto& v = small.r->stats().virtualPages;
    ASSERT_GT(asked, 96u);
    EXPECT_EQ(v.requested, asked);
    EXPECT_LE(v.allocated, 96u);
    EXPECT_GT(v.finestLevel, finest);
    EXPECT_NE(v.warning.find("drawn at level"), std::string::npos) << v.warning;
    EXPECT_EQ(v.warning.find("unshadowed"), std::string::npos) << v.warning;
    const auto& warnings = small.r->stats().warnings;
    EXPECT_TRUE(std::find(warnings.begin(), warnings.end(), v.warning) != warnings.end());
    // Coarser, never garbage: every pixel reads its own place at a level the pool kept, and the
    // shadows are the full pool's but for edges a coarser texel moves.
    const auto aux = small.r->readAux();
    const auto mask = small.r->readShadowMask();
    const std::vector<size_t> lit = receivers(*small.r);
    size_t agree = 0;
    for (const size_t i : lit) {
        EXPECT_GE(int(aux[i].z), v.finestLevel);
        agree += (mask[i] > 0.5f) == (full[i] > 0.5f);
    }
    EXPECT_GE(double(agree), 0.97 * double(lit.size()));
}

TEST(VirtualRender, CachedPagesGiveTheSameImageAsAFullRedraw) {
    const Scene scene = gammaNinetyScene();
    Bench moving(scene), fresh(scene);
    Camera later = scene.camera;
    later.eye += glm::vec3(0.6f, 0.f, -0.9f);
    later.target += glm::vec3(0.6f, 0.f, -0.9f);
    moving.render(virtualSettings(), scene.camera, scene.lights[0]);
    moving.render(virtualSettings(), later, scene.lights[0]);
    const auto kept = moving.r->stats().virtualPages;
    EXPECT_GT(kept.cached, 0u);
    EXPECT_LT(kept.drawn, kept.allocated);
    fresh.render(virtualSettings(), later, scene.lights[0]);
    const auto redrawn = fresh.r->stats().virtualPages;
    EXPECT_EQ(redrawn.cached, 0u);
    EXPECT_EQ(redrawn.drawn, redrawn.allocated);
    EXPECT_EQ(redrawn.allocated, kept.allocated);
    EXPECT_EQ(moving.r->readShadowMask(), fresh.r->readShadowMask());

    // The light moves: every kept page is stale and drawn again.
    Light turned = scene.lights[0];
    turned.direction = glm::normalize(glm::vec3(0.2f, -1.f, 0.1f));
    moving.render(virtualSettings(), later, turned);
    EXPECT_EQ(moving.r->stats().virtualPages.cached, 0u);
    EXPECT_EQ(moving.r->stats().virtualPages.drawn, moving.r->stats().virtualPages.allocated);
}

// Against the ray-traced truth, like for like (same view, size, one sample per pixel, same bias): the
// virtual map misclassifies at most 0.1 % of the receivers more than a 4096² uniform map (14 times
// more texels than this view's pixels need), and under 0.5 %.
TEST(VirtualRender, MisclassifiesAsLittleAsAFineUniformMap) {
    Bench b(gammaNinetyScene());
    const geometry::analysis::GroundTruth truth(b.scene);
    const auto missed = [&](const ShadowSettings& s) {
        const auto m = renderer::measure(*b.r, s, b.scene.bounds(), b.scene.camera, b.scene.lights[0], kView,
                                         {.warmup = 0, .frames = 1, .timed = false}, &truth);
        const auto& t = *m.inspection.truth;
        return t.falseLit + t.falseShadow;
    };
    ShadowSettings maps = virtualSettings();
    maps.technique = Technique::Maps;
    maps.resolution = 4096;
    const double virtualMissed = missed(virtualSettings()), mapsMissed = missed(maps);
    EXPECT_LE(virtualMissed, mapsMissed + 0.001);
    EXPECT_LT(virtualMissed, 0.005);
}

TEST(VirtualRender, TheLightViewOutlinesThePagesByLevel) {
    Bench b(gammaNinetyScene());
    b.render(virtualSettings());
    const auto image = b.r->readLight();
    ASSERT_EQ(image.width, 32);
    // Outlines are pure level colours (a saturated hue); page interiors are grey tinted by it.
    size_t saturated = 0, background = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const uint8_t* p = image.at(x, y);
            const int hi = std::max({p[0], p[1], p[2]}), lo = std::min({p[0], p[1], p[2]});
            saturated += hi >= 250 && lo <= 5;
            background += hi < 40;
        }
    EXPECT_GT(saturated, 0u);
    EXPECT_LT(background, size_t(image.width * image.height)) << "the view frames the allocated pages";
}
