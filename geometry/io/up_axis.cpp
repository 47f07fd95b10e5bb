#include "geometry/io/up_axis.h"

namespace geometry::io {

std::optional<UpAxis> parseUpAxis(std::string_view t) noexcept {
    if (t.starts_with('+')) t.remove_prefix(1);
    if (t == "y") return UpAxis::Y;
    if (t == "z") return UpAxis::Z;
    if (t == "-y") return UpAxis::NegY;
    if (t == "-z") return UpAxis::NegZ;
    if (t == "x") return UpAxis::X;
    if (t == "-x") return UpAxis::NegX;
    return std::nullopt;
}

std::string_view upAxisName(UpAxis axis) noexcept {
    switch (axis) {
    case UpAxis::Y: return "y";
    case UpAxis::Z: return "z";
    case UpAxis::NegY: return "-y";
    case UpAxis::NegZ: return "-z";
    case UpAxis::X: return "x";
    case UpAxis::NegX: return "-x";
    }
    return "y";
}

UpAxis defaultUpAxis(std::string_view format) noexcept { return format == "stl" ? UpAxis::Z : UpAxis::Y; }

glm::mat4 rotationToYUp(UpAxis axis) noexcept {
    // Columns are the images of x, y, z; each matrix is a rotation (determinant +1).
    const auto m = [](glm::vec3 x, glm::vec3 y, glm::vec3 z) {
        return glm::mat4(glm::vec4(x, 0.f), glm::vec4(y, 0.f), glm::vec4(z, 0.f), glm::vec4(0.f, 0.f, 0.f, 1.f));
    };
    switch (axis) {
    case UpAxis::Y: return glm::mat4(1.f);
    case UpAxis::Z: return m({1, 0, 0}, {0, 0, -1}, {0, 1, 0});     // −90° about x: z → y
    case UpAxis::NegZ: return m({1, 0, 0}, {0, 0, 1}, {0, -1, 0});  // +90° about x: −z → y
    case UpAxis::NegY: return m({1, 0, 0}, {0, -1, 0}, {0, 0, -1}); // 180° about x
    case UpAxis::X: return m({0, 1, 0}, {-1, 0, 0}, {0, 0, 1});     // +90° about z: x → y
    case UpAxis::NegX: return m({0, -1, 0}, {1, 0, 0}, {0, 0, 1});  // −90° about z: −x → y
    }
    return glm::mat4(1.f);
}

} // namespace geometry::io
