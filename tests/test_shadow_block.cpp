// The shadow and settings uniform blocks: the C++ side and the generated GLSL blocks agree on every
// offset (as GL reports them), shadowBlock() copies the plan's values without deciding anything
// itself, and settingsBlockWords() holds every declared setting as set.
#include "geometry/scene/builtin_scenes.h"
#include "geometry/shadow/shadow_plan.h"
#include "renderer/context.h"
#include "renderer/program.h"
#include "renderer/settings_block.h"
#include "renderer/shadow_block.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using geometry::shadow::kMaxSplits;
using renderer::ShadowBlock;
using renderer::ShadowSplitBlock;

template <class T, class F> GLint byteOffset(const T& object, const F& field) {
    return GLint(reinterpret_cast<const char*>(&field) - reinterpret_cast<const char*>(&object));
}

GLint glOffset(GLuint program, const std::string& member) {
    const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM, member.c_str());
    EXPECT_NE(index, GL_INVALID_INDEX) << member << " is not in the GLSL block";
    if (index == GL_INVALID_INDEX) return -1;
    const GLenum prop = GL_OFFSET;
    GLint offset = -1;
    glGetProgramResourceiv(program, GL_UNIFORM, index, 1, &prop, 1, nullptr, &offset);
    return offset;
}

} // namespace

TEST(ShadowBlock, CppAndGlslAgreeOnEveryOffset) {
    auto context = renderer::createOSMesaContext();
    renderer::Program eye("eye.vert", "eye.frag");
    const ShadowBlock b{};
    int checked = 0;
    // The block's own members, then every split member in the first and the last element.
#define SHADOW_FIELD(glsl, cpp, name)                                                                                  \
    EXPECT_EQ(glOffset(eye.id(), "ShadowBlock." #name), byteOffset(b, b.name)) << #name;                               \
    ++checked;
#include "renderer/shadow_block.inc"
#undef SHADOW_FIELD
    for (const int i : {0, kMaxSplits - 1}) {
        const std::string element = "ShadowBlock.splits[" + std::to_string(i) + "].";
#define SHADOW_SPLIT_FIELD(glsl, cpp, name)                                                                            \
    EXPECT_EQ(glOffset(eye.id(), element + #name), byteOffset(b, b.splits[i].name)) << element << #name;               \
    ++checked;
#include "renderer/shadow_block.inc"
#undef SHADOW_SPLIT_FIELD
    }
    EXPECT_GT(checked, 20);
    const GLuint block = glGetProgramResourceIndex(eye.id(), GL_UNIFORM_BLOCK, "ShadowBlock");
    ASSERT_NE(block, GL_INVALID_INDEX);
    const GLenum prop = GL_BUFFER_DATA_SIZE;
    GLint size = 0;
    glGetProgramResourceiv(eye.id(), GL_UNIFORM_BLOCK, block, 1, &prop, 1, nullptr, &size);
    EXPECT_EQ(size, GLint(sizeof(ShadowBlock)));
    EXPECT_EQ(renderer::takeGlErrors(), "");
}

TEST(ShadowBlock, CopiesThePlanAsItIs) {
    using namespace geometry::shadow;
    const auto scene = geometry::scene::makePlaneScene();
    ShadowSettings s;
    s.resolution = 1024;
    s.splits.count = 3;
    s.splits.resolutionFalloff = true;
    s.bias.type = BiasType::DualDepth;
    s.bias.linearZ = true;
    s.filter.type = FilterType::Pcf;
    s.filter.kernel = 5;
    const ShadowPlan plan = planShadows(s, scene.bounds(), scene.camera, scene.lights[0], Viewport{320, 240});
    ASSERT_EQ(plan.splits.size(), 3u);
    const ShadowBlock b = renderer::shadowBlock(plan, 1024);
    EXPECT_EQ(b.splitCount, 3);
    EXPECT_EQ(b.arrayResolution, 1024);
    EXPECT_EQ(b.linearDepth, 1);
    EXPECT_EQ(b.slopeBias, glm::vec2(0.f)); // slope bias only with bias.type = slope
    for (int i = 0; i < 3; ++i) {
        const auto& split = plan.splits[i];
        const ShadowSplitBlock& g = b.splits[i];
        EXPECT_EQ(g.lightViewProj, split.lightViewProj);
        EXPECT_EQ(g.splitFar, split.far);
        EXPECT_FLOAT_EQ(g.mapScale, 1.f / float(1 << i)) << "resolution falloff halves each split";
        EXPECT_EQ(g.linearLo, split.linearDepthRange.x);
        // Derived in the plan, copied here: linear depth maps [lo, hi] onto [0, 1].
        EXPECT_FLOAT_EQ(g.linearScale * (split.linearDepthRange.y - split.linearDepthRange.x), 1.f);
        EXPECT_FLOAT_EQ(g.dualDepthCap, s.bias.zMax * g.linearScale);
    }
    EXPECT_EQ(b.splits[3].splitFar, 0.f); // unused elements stay zero
    // A smaller array than the plan asks for: the splits' scale follows what is drawn.
    EXPECT_FLOAT_EQ(renderer::shadowBlock(plan, 512).splits[0].mapScale, 1.f);
    EXPECT_FLOAT_EQ(renderer::shadowBlock(plan, 512).splits[1].mapScale, 1.f);
    EXPECT_FLOAT_EQ(renderer::shadowBlock(plan, 512).splits[2].mapScale, 0.5f);
}

TEST(SettingsBlock, EveryDeclaredSettingIsAtItsOffsetInTheGlslBlock) {
    auto context = renderer::createOSMesaContext();
    renderer::Program eye("eye.vert", "eye.frag");
    const auto& rows = geometry::shadow::settingsDeclaration();
    for (size_t i = 0; i < rows.size(); ++i)
        EXPECT_EQ(glOffset(eye.id(), "SettingsBlock." + rows[i].glslName()), GLint(4 * i)) << rows[i].key;
    const GLuint block = glGetProgramResourceIndex(eye.id(), GL_UNIFORM_BLOCK, "SettingsBlock");
    ASSERT_NE(block, GL_INVALID_INDEX);
    const GLenum prop = GL_BUFFER_DATA_SIZE;
    GLint size = 0;
    glGetProgramResourceiv(eye.id(), GL_UNIFORM_BLOCK, block, 1, &prop, 1, nullptr, &size);
    EXPECT_EQ(size, GLint(renderer::settingsBlockWords({}).size() * 4));
    EXPECT_EQ(renderer::takeGlErrors(), "");
}

TEST(SettingsBlock, WordsHoldEveryValueAsSet) {
    using namespace geometry::shadow;
    ShadowSettings s;
    applyAssignment(s, "bias.type=dual_depth");
    applyAssignment(s, "filter.kernel=7");
    applyAssignment(s, "filter.radius=3.5");
    applyAssignment(s, "bias.tangent_plane=true");
    const auto words = renderer::settingsBlockWords(s);
    const auto word = [&](std::string_view key) {
        const auto& rows = settingsDeclaration();
        for (size_t i = 0; i < rows.size(); ++i)
            if (rows[i].key == key) return words.at(i);
        ADD_FAILURE() << key;
        return 0u;
    };
    EXPECT_EQ(word("bias.type"), unsigned(BiasType::DualDepth));
    EXPECT_EQ(word("filter.kernel"), 7u);
    EXPECT_EQ(std::bit_cast<float>(word("filter.radius")), 3.5f);
    EXPECT_EQ(word("bias.tangent_plane"), 1u);
    EXPECT_EQ(word("bias.linear_z"), 0u);
    EXPECT_EQ(words.size() % 4, 0u);
    // The renderer's upload writes over last frame's words: the same words as made fresh.
    std::vector<std::uint32_t> reused(words.size() + 9, 0xdeadbeefu);
    renderer::settingsBlockWords(s, reused);
    EXPECT_EQ(reused, words);
}
