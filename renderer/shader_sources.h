#pragma once
#include <string_view>

namespace renderer {
/// Source of a shader in resources/shaders/ (compiled into the binary), or of the generated
/// "shadow_block.glsl"; throws if unknown.
[[nodiscard]] std::string_view shaderSource(std::string_view name);
/// The shadow uniform block and the constants the shaders share, generated at build time from the
/// C++ declarations (renderer/shadow_glsl_gen.cpp).
extern const std::string_view kShadowBlockGlsl;
} // namespace renderer
