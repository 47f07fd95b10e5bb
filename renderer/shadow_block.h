#pragma once
// The per-frame shadow uniform block (std140, binding kShadowBlockBinding), declared once in
// shadow_block.inc, and the one function that fills it from the plan.
#include "geometry/shadow/shadow_plan.h"

#include <glm/glm.hpp>

#include <array>

namespace renderer {

inline constexpr unsigned kShadowBlockBinding = 0;

struct ShadowSplitBlock {
#define SHADOW_SPLIT_FIELD(glsl, cpp, name) cpp name{};
#include "renderer/shadow_block.inc"
#undef SHADOW_SPLIT_FIELD
};

struct ShadowBlock {
    std::array<ShadowSplitBlock, geometry::shadow::kMaxSplits> splits{};
#define SHADOW_FIELD(glsl, cpp, name) cpp name{};
#include "renderer/shadow_block.inc"
#undef SHADOW_FIELD
};

static_assert(sizeof(ShadowSplitBlock) % 16 == 0, "std140 rounds an array element up to 16 bytes");
static_assert(sizeof(ShadowBlock) % 16 == 0, "shadow_block.inc must keep every 16-byte row full");

/// The block for one frame: the plan's values as they are (the plan derives everything), and the
/// split resolutions as drawn into an array of `arrayResolution` texels.
[[nodiscard]] ShadowBlock shadowBlock(const geometry::shadow::ShadowPlan& plan, int arrayResolution) noexcept;

} // namespace renderer
