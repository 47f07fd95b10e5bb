#version 430 core
// Overlay lines: world (or map NDC) positions through a matrix; depth is clamped, not clipped.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColor;
uniform mat4 uMatrix;
out vec4 vColor;
void main() {
    vColor = aColor;
    gl_Position = uMatrix * vec4(aPosition, 1.0);
}
