#pragma once
// Which axis of a model file points up. shadowscope's world is Y-up; CAD exports are often Z-up
// (STL from OpenSCAD and most CAD tools), so a model is turned onto its base on load.
#include <glm/glm.hpp>

#include <optional>
#include <string_view>

namespace geometry::io {

enum class UpAxis { Y, Z, NegY, NegZ, X, NegX };

/// "y", "z", "-y", "-z", "x", "-x" (also "+y" …); nullopt for anything else.
[[nodiscard]] std::optional<UpAxis> parseUpAxis(std::string_view text) noexcept;
[[nodiscard]] std::string_view upAxisName(UpAxis axis) noexcept;
/// The defaults by format: glTF Y-up (the spec), STL Z-up (the CAD convention), OBJ/OFF/PLY Y-up.
[[nodiscard]] UpAxis defaultUpAxis(std::string_view format) noexcept;
/// The proper rotation taking `axis` to +Y (a quarter or half turn about x or z).
[[nodiscard]] glm::mat4 rotationToYUp(UpAxis axis) noexcept;

} // namespace geometry::io
