// clipOverlap (geometry/shadow/culling.h): boxes against a clip volume, orthographic and
// perspective, by hand.
#include "geometry/shadow/culling.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <limits>

using geometry::scene::Aabb;
using geometry::shadow::ClipOverlap;
using geometry::shadow::clipOverlap;

namespace {

Aabb box(glm::vec3 lo, glm::vec3 hi) {
    Aabb b;
    b.add(lo);
    b.add(hi);
    return b;
}

} // namespace

TEST(Culling, ClipOverlapOfAnOrthographicVolume) {
    const glm::mat4 unit(1.f); // the clip volume is the cube [-1, 1]³
    EXPECT_EQ(clipOverlap(box({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}), unit), ClipOverlap::Inside);
    EXPECT_EQ(clipOverlap(box({-1, -1, -1}, {1, 1, 1}), unit), ClipOverlap::Inside) << "the boundary is inside";
    EXPECT_EQ(clipOverlap(box({0.5f, 0, 0}, {1.5f, 0.5f, 0.5f}), unit), ClipOverlap::Partly);
    EXPECT_EQ(clipOverlap(box({-3, -3, -3}, {3, 3, 3}), unit), ClipOverlap::Partly) << "encloses the volume";
    EXPECT_EQ(clipOverlap(box({2, 0, 0}, {3, 1, 1}), unit), ClipOverlap::Outside);
    EXPECT_EQ(clipOverlap(box({0, 0, -5}, {0.5f, 0.5f, -1.01f}), unit), ClipOverlap::Outside);
    EXPECT_EQ(clipOverlap(Aabb{}, unit), ClipOverlap::Outside) << "empty";
}

TEST(Culling, ABoxBeyondACornerIsKept) {
    // The volume turned 45° about z is the diamond |x − y| ≤ √2, |x + y| ≤ √2 with a vertex at
    // (√2, 0); a box just beyond that vertex misses it but lies wholly outside neither of the two
    // planes through it: kept (the test is conservative, never wrong the other way).
    const glm::mat4 turned = glm::rotate(glm::mat4(1.f), glm::radians(45.f), glm::vec3(0, 0, 1));
    EXPECT_EQ(clipOverlap(box({1.5f, -0.3f, 0}, {2, 0.3f, 0}), turned), ClipOverlap::Partly);
    EXPECT_EQ(clipOverlap(box({1.2f, 1.2f, 0}, {2, 2, 0}), turned), ClipOverlap::Outside);
}

TEST(Culling, ClipOverlapOfAPerspectiveFrustum) {
    // Looking down −z from the origin, 90° field of view, near 1, far 10.
    const glm::mat4 viewProj = glm::perspective(glm::radians(90.f), 1.f, 1.f, 10.f);
    EXPECT_EQ(clipOverlap(box({-0.5f, -0.5f, -5}, {0.5f, 0.5f, -4}), viewProj), ClipOverlap::Inside);
    EXPECT_EQ(clipOverlap(box({-0.5f, -0.5f, -5}, {0.5f, 0.5f, 2}), viewProj), ClipOverlap::Partly)
        << "reaches behind the eye";
    EXPECT_EQ(clipOverlap(box({-1, -1, 1}, {1, 1, 3}), viewProj), ClipOverlap::Outside) << "behind the eye";
    EXPECT_EQ(clipOverlap(box({6, -1, -5}, {7, 1, -4}), viewProj), ClipOverlap::Outside) << "beyond the right plane";
    EXPECT_EQ(clipOverlap(box({-1, -1, -12}, {1, 1, -11}), viewProj), ClipOverlap::Outside) << "beyond far";
}

TEST(Culling, ANonFiniteBoxIsNeverInside) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Aabb b = box({0, 0, 0}, {0.5f, 0.5f, 0.5f});
    b.hi.x = nan; // a box corrupted after the fact
    EXPECT_NE(clipOverlap(b, glm::mat4(1.f)), ClipOverlap::Inside);
}
