// Virtual shadow maps' page planning (geometry/shadow/virtual_pages.h): levels, the level a footprint
// asks for, the pages requested, and the pool's allocation, caching and coarsening; the virtual plan
// (virtual_plan.h) and what planShadows does under technique = virtual.
#include "geometry/shadow/virtual_pages.h"

#include "geometry/shadow/shadow_plan.h"
#include "geometry/shadow/virtual_plan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

using namespace geometry::shadow;

namespace {

VirtualMapConfig smallConfig() {
    VirtualMapConfig c;
    c.virtualSize = 2048;
    c.pageSize = 64; // 32 pages a side
    c.levels = 8;    // level 7: 512 m
    c.poolPages = 64;
    c.side0 = 4.0;
    return c;
}

/// A camera 2 m above the ground plane y = 0 looking along +x and 20° down, the sun straight above
/// (γ = 90° between the light and the view's horizontal): every pixel of a W×H image that hits the
/// ground, with its footprint across the light (the pixel's longer side on the ground).
std::vector<VirtualSample> groundSamples(int w, int h) {
    const double fovY = glm::radians(60.0), pitch = glm::radians(20.0);
    const glm::dvec3 eye(0, 2, 0), fwd(std::cos(pitch), -std::sin(pitch), 0), up(std::sin(pitch), std::cos(pitch), 0),
        right(0, 0, 1);
    const double t = std::tan(fovY / 2), pixel = 2 * t / h; // a pixel's angular size at the centre
    std::vector<VirtualSample> out;
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) {
            const double x = (2 * (i + 0.5) / w - 1) * t * w / h, y = (1 - 2 * (j + 0.5) / h) * t;
            const glm::dvec3 dir = glm::normalize(fwd + x * right + y * up);
            if (dir.y >= -1e-3) continue; // sky
            const double d = eye.y / -dir.y;
            const double across = d * pixel;      // along the ground, across the view
            const double along = across / -dir.y; // stretched along the view by the grazing angle
            out.push_back({eye + d * dir, std::max(across, along)});
        }
    return out;
}

/// The ground view at 320×180 under a sun straight above, and the pages its pixels ask for.
struct GroundView {
    VirtualMapConfig config = smallConfig();
    LightFrame frame = lightFrame({0, -1, 0});
    std::vector<ClipLevel> levels = clipLevels(frame, {0, 2, 0}, config);
    std::vector<VirtualSample> samples = groundSamples(320, 180);
    PageRequests requests = requestPages(samples, frame, levels, config);
};

} // namespace

TEST(VirtualPages, ConfigurationsAreChecked) {
    EXPECT_FALSE(smallConfig().invalid());
    VirtualMapConfig c = smallConfig();
    c.pageSize = 96;
    EXPECT_TRUE(c.invalid());
    c = smallConfig();
    c.pageSize = 4096;
    EXPECT_TRUE(c.invalid());
    c = smallConfig();
    c.side0 = NAN;
    EXPECT_TRUE(c.invalid());
    c = smallConfig();
    c.poolPages = 0;
    EXPECT_TRUE(c.invalid());
}

TEST(VirtualPages, LevelsDoubleAndFollowTheEyeAPageAtATime) {
    const VirtualMapConfig c = smallConfig();
    const LightFrame f = lightFrame({0, -1, 0});
    const double page = c.side0 / c.pagesPerSide();
    const glm::dvec3 eye = f.right * (0.5 * page) + f.up * (0.5 * page) - 5.0 * f.l; // a page's centre
    const std::vector<ClipLevel> a = clipLevels(f, eye, c);
    ASSERT_EQ(a.size(), 8u);
    for (size_t k = 1; k < a.size(); ++k) EXPECT_DOUBLE_EQ(a[k].texelWorld, 2 * a[k - 1].texelWorld);
    EXPECT_DOUBLE_EQ(a[0].pageWorld, page);
    // Less than half a page: the same squares; a page along the plane: level 0's square one page on.
    const std::vector<ClipLevel> b = clipLevels(f, eye + f.right * (0.4 * page), c);
    EXPECT_EQ(b[0].firstPageX, a[0].firstPageX);
    const std::vector<ClipLevel> d = clipLevels(f, eye + f.right * page, c);
    EXPECT_EQ(d[0].firstPageX, a[0].firstPageX + 1);
    EXPECT_EQ(d[0].firstPageY, a[0].firstPageY);
}

TEST(VirtualPages, APixelGetsTheLevelItsFootprintAsksForOneTexelPerPixel) {
    // On the ground at γ = 90°, every sample whose footprint lies within the levels' range reads
    // texels between half a pixel and one pixel wide: m within a factor 2 of 1.
    const VirtualMapConfig c = smallConfig();
    const LightFrame f = lightFrame({0, -1, 0});
    const std::vector<ClipLevel> levels = clipLevels(f, {0, 2, 0}, c);
    const std::vector<VirtualSample> samples = groundSamples(320, 180);
    ASSERT_GT(samples.size(), 5000u);
    size_t inRange = 0, within = 0, coarserForRoom = 0;
    for (const VirtualSample& s : samples) {
        const int k = levelFor(s.footprint, levels);
        if (s.footprint < levels.front().texelWorld || s.footprint >= 2 * levels.back().texelWorld) continue;
        ++inRange;
        const double m = levels[size_t(k)].texelWorld / s.footprint;
        within += m > 0.5 && m <= 1.0;
        coarserForRoom += !pageAt(f.project(s.position), k, levels, c);
    }
    EXPECT_GT(inRange, samples.size() / 2);
    EXPECT_EQ(within, inRange);
    // Near the eye the fine levels' squares hold what the footprints ask for.
    EXPECT_LT(coarserForRoom, inRange / 10);
}

TEST(VirtualPages, OnlyPagesUnderSomePixelAreRequestedAndAllocated) {
    const GroundView g;
    const VirtualMapConfig& c = g.config;
    const LightFrame& f = g.frame;
    const std::vector<ClipLevel>& levels = g.levels;
    const std::vector<VirtualSample>& samples = g.samples;
    const PageRequests& r = g.requests;
    // Each requested page holds a sample; each sample's page was requested; only samples beyond the
    // coarsest square (near the horizon) have none.
    std::set<PageKey> ofSamples;
    uint64_t beyond = 0;
    const double half = c.side0 * std::ldexp(1.0, c.levels - 1) / 2;
    for (const VirtualSample& s : samples) {
        bool found = false;
        for (int k = levelFor(s.footprint, levels); k < c.levels && !found; ++k)
            if (const auto p = pageAt(f.project(s.position), k, levels, c)) {
                ofSamples.insert(*p);
                found = true;
            }
        beyond += !found;
        if (!found) {
            EXPECT_GT(std::max(std::abs(s.position.x), std::abs(s.position.z)), half * 0.9);
        }
    }
    EXPECT_EQ(r.uncovered, beyond);
    EXPECT_LT(beyond, samples.size() / 20);
    EXPECT_EQ(std::set<PageKey>(r.pages.begin(), r.pages.end()), ofSamples);
    // Behind the camera (no pixel there) nothing is asked for at any level.
    for (const PageKey& k : r.pages) EXPECT_GE((k.x + 1) * levels[size_t(k.level)].pageWorld, 0.0);
    PagePool pool(4096);
    const PagePool::Frame frame = pool.update(r.pages, 1, c.levels);
    ASSERT_EQ(frame.table.size(), r.pages.size());
    for (size_t i = 0; i < r.pages.size(); ++i) EXPECT_EQ(frame.table[i].key, r.pages[i]);
    EXPECT_TRUE(frame.warning.empty());
    EXPECT_EQ(pool.occupied(), r.pages.size());
}

TEST(VirtualPages, AnOverfullPoolFallsBackToCoarserLevelsNeverToOtherPages) {
    const GroundView g;
    const VirtualMapConfig& c = g.config;
    const PageRequests& r = g.requests;
    // A pool that holds the request once its finest level is given up, and not before.
    const int finest = r.pages.front().level;
    std::set<PageKey> coarser;
    for (const PageKey& k : r.pages) coarser.insert(ancestor(k, std::max(k.level, finest + 1)));
    const uint32_t capacity = uint32_t(coarser.size());
    ASSERT_LT(capacity, r.pages.size());
    PagePool pool(capacity);
    const PagePool::Frame frame = pool.update(r.pages, 1, c.levels);
    EXPECT_NE(frame.warning.find("drawn at level " + std::to_string(finest + 1)), std::string::npos) << frame.warning;
    EXPECT_EQ(frame.warning.find("unshadowed"), std::string::npos) << frame.warning;
    EXPECT_EQ(frame.finestLevel, finest + 1);
    EXPECT_LE(frame.table.size(), capacity);
    EXPECT_EQ(frame.requested, r.pages.size());
    // Every page asked for is served by itself or by the page of a coarser level over the same place.
    for (const PageKey& k : r.pages) {
        const auto e = frame.resolve(k, c.levels);
        ASSERT_TRUE(e) << "level " << k.level << " page " << k.x << "," << k.y;
        EXPECT_GE(e->key.level, std::max(k.level, frame.finestLevel));
        EXPECT_EQ(e->key, ancestor(k, e->key.level));
    }
}

TEST(VirtualPages, PagesAreKeptAcrossFramesAndDrawnAgainWhenTheirContentChanges) {
    PagePool pool(8);
    const std::vector<PageKey> a = {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}, {1, 0, 0}};
    const PagePool::Frame first = pool.update(a, 7, 4);
    EXPECT_EQ(first.drawn.size(), 4u);
    EXPECT_EQ(first.cached, 0u);
    const PagePool::Frame same = pool.update(a, 7, 4);
    EXPECT_TRUE(same.drawn.empty());
    EXPECT_EQ(same.cached, 4u);
    ASSERT_EQ(same.table.size(), first.table.size());
    for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(same.table[i].physical, first.table[i].physical);
    // The light moved: the same pages, all drawn again in the same slots.
    const PagePool::Frame moved = pool.update(a, 8, 4);
    EXPECT_EQ(moved.drawn.size(), 4u);
    EXPECT_EQ(moved.cached, 0u);
    // One page on: the three kept pages are not drawn; the new one takes a free slot.
    const std::vector<PageKey> b = {{0, 1, 0}, {0, 2, 0}, {0, 3, 0}, {1, 0, 0}};
    const PagePool::Frame on = pool.update(b, 8, 4);
    EXPECT_EQ(on.cached, 3u);
    ASSERT_EQ(on.drawn.size(), 1u);
    EXPECT_EQ(on.resolve({0, 3, 0}, 4)->physical, on.drawn[0]);
    // Full: a new page takes the least recently used slot, never one asked for this frame.
    PagePool small(2);
    small.update({{0, 0, 0}, {0, 1, 0}}, 1, 4);
    small.update({{0, 1, 0}}, 1, 4);
    const PagePool::Frame evict = small.update({{0, 1, 0}, {0, 5, 0}}, 1, 4);
    EXPECT_EQ(evict.cached, 1u);
    ASSERT_TRUE(evict.resolve({0, 5, 0}, 4));
    EXPECT_FALSE(evict.resolve({0, 0, 0}, 4));
}

TEST(VirtualPages, NonFiniteSamplesAreUncoveredNotRequested) {
    const VirtualMapConfig c = smallConfig();
    const LightFrame f = lightFrame({0.3f, -1, 0.2f});
    const std::vector<ClipLevel> levels = clipLevels(f, {0, 2, 0}, c);
    const std::vector<VirtualSample> bad = {{{NAN, 0, 0}, 0.01}, {{1e30, 0, 0}, 0.01}, {{0, 0, 0}, NAN}};
    const PageRequests r = requestPages(bad, f, levels, c);
    EXPECT_EQ(r.uncovered, 2u); // the NaN footprint still gets level 0 at a finite place
    EXPECT_EQ(r.pages.size(), 1u);
}

// planVirtual (virtual_plan.h): a page's projection maps its square to the clip square and S's depth
// range to [−1, 1]; the coarsest level covers S from any eye above it; the content ignores the eye.
TEST(VirtualPlan, PagesProjectTheirSquareAndTheCoarsestLevelCoversTheScene) {
    geometry::scene::Aabb S;
    S.add({-40.f, 0.f, -25.f});
    S.add({60.f, 12.f, 30.f});
    VirtualSettings settings;
    settings.size = 4096;
    settings.pageSize = 128;
    settings.levels = 6;
    const glm::vec3 l = glm::normalize(glm::vec3(-0.5f, -1.f, 0.3f));
    for (const glm::vec3 eye : {glm::vec3(-40.f, 14.f, -25.f), glm::vec3(60.f, 2.f, 30.f), glm::vec3(5.f, 30.f, 0.f)}) {
        const VirtualPlan p = planVirtual(settings, S, eye, l);
        const PageKey k{3, p.levels[3].firstPageX + 5, p.levels[3].firstPageY + 7};
        const glm::dmat4 m = p.pageViewProj(k);
        const double w = p.levels[3].pageWorld;
        // The page's lower-left corner on S's near depth, and its upper-right on S's far depth.
        const glm::dvec3 corner = p.frame.right * (double(k.x) * w) + p.frame.up * (double(k.y) * w);
        const glm::dvec3 nearCorner = corner + p.frame.l * p.depthLo;
        const glm::dvec3 farCorner = corner + (p.frame.right + p.frame.up) * w + p.frame.l * p.depthHi;
        const glm::dvec4 a = m * glm::dvec4(nearCorner, 1.0), b = m * glm::dvec4(farCorner, 1.0);
        EXPECT_NEAR(a.x, -1.0, 1e-9);
        EXPECT_NEAR(a.y, -1.0, 1e-9);
        EXPECT_NEAR(a.z, -1.0, 1e-9);
        EXPECT_NEAR(b.x, 1.0, 1e-9);
        EXPECT_NEAR(b.y, 1.0, 1e-9);
        EXPECT_NEAR(b.z, 1.0, 1e-9);
        EXPECT_NEAR(p.depthOf(nearCorner), 0.0, 1e-12);
        // Every corner of S lies in the coarsest square, whatever the eye above S.
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 c((i & 1) ? S.hi.x : S.lo.x, (i & 2) ? S.hi.y : S.lo.y, (i & 4) ? S.hi.z : S.lo.z);
            EXPECT_TRUE(pageAt(p.frame.project(c), settings.levels - 1, p.levels, p.config).has_value());
        }
        EXPECT_EQ(p.content, planVirtual(settings, S, glm::vec3(0.f), l).content) << "the eye moves no texel";
    }
    EXPECT_NE(planVirtual(settings, S, glm::vec3(0.f), l).content,
              planVirtual(settings, S, glm::vec3(0.f), glm::normalize(l + glm::vec3(0.01f, 0.f, 0.f))).content);
    // A widget dragged between the sizes validate() accepts gives the power of two below, never a
    // configuration the renderer cannot draw.
    VirtualSettings dragged;
    dragged.size = 3000;
    dragged.pageSize = 100;
    const VirtualPlan snapped = planVirtual(dragged, S, glm::vec3(0.f), l);
    EXPECT_EQ(snapped.config.virtualSize, 2048u);
    EXPECT_EQ(snapped.config.pageSize, 64u);
    EXPECT_FALSE(snapped.config.invalid().has_value());
    dragged.size = 65536;
    dragged.pageSize = 16;
    EXPECT_EQ(planVirtual(dragged, S, glm::vec3(0.f), l).config.pagesPerSide(), uint32_t(kMaxVirtualPagesPerSide));
}

// planShadows under technique = virtual: a directional light gets the virtual plan; the biases and
// filters a paged map cannot do become the nearest it can, each with a warning; a spot light keeps
// fitted maps and says so.
TEST(VirtualPlan, WhatAPagedMapCannotDoIsReplacedWithAWarning) {
    geometry::scene::Aabb S;
    S.add({-10.f, 0.f, -10.f});
    S.add({10.f, 5.f, 10.f});
    geometry::scene::Camera camera;
    camera.eye = {0.f, 3.f, 12.f};
    camera.target = {0.f, 0.f, 0.f};
    geometry::scene::Light sun;
    sun.direction = glm::normalize(glm::vec3(0.3f, -1.f, 0.2f));
    ShadowSettings s;
    s.technique = Technique::Virtual;
    s.bias.type = BiasType::DualDepth;
    s.filter.type = FilterType::Evsm4;
    const ShadowPlan plan = planShadows(s, S, camera, sun, Viewport{64, 48});
    ASSERT_TRUE(plan.virtualMap.enabled);
    EXPECT_EQ(plan.settings.bias.type, BiasType::Constant);
    EXPECT_EQ(plan.settings.filter.type, FilterType::Hw2x2);
    EXPECT_FALSE(plan.linearDepth) << "orthographic page depth is linear already";
    const auto warned = [&](std::string_view what) {
        return std::any_of(plan.warnings.begin(), plan.warnings.end(),
                           [&](const std::string& w) { return w.find(what) != std::string::npos; });
    };
    EXPECT_TRUE(warned("bias.type = dual_depth needs a second depth layer"));
    EXPECT_TRUE(warned("filter.type = evsm4 blurs its moments across page borders"));
    s.bias.type = BiasType::SlopeNormalOffset;
    s.filter.type = FilterType::Pcf;
    const ShadowPlan kept = planShadows(s, S, camera, sun, Viewport{64, 48});
    EXPECT_EQ(kept.settings.bias.type, BiasType::SlopeNormalOffset);
    EXPECT_EQ(kept.settings.filter.type, FilterType::Pcf);
    EXPECT_NE(kept.virtualMap.content, plan.virtualMap.content) << "polygon offset changes what a page holds";

    geometry::scene::Light spot = sun;
    spot.type = geometry::scene::LightType::Spot;
    spot.position = {0.f, 20.f, 0.f};
    const ShadowPlan fitted = planShadows(s, S, camera, spot, Viewport{64, 48});
    EXPECT_FALSE(fitted.virtualMap.enabled);
    EXPECT_TRUE(std::any_of(fitted.warnings.begin(), fitted.warnings.end(), [](const std::string& w) {
        return w.find("technique = virtual takes a directional light") != std::string::npos;
    }));
}
