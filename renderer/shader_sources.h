#pragma once
#include <string_view>

namespace renderer {
/// Source of a shader in resources/shaders/ (compiled into the binary); throws if unknown.
[[nodiscard]] std::string_view shaderSource(std::string_view name);
} // namespace renderer
