#version 430 core
// Shadow pass: world → shadow clip space of one split.
layout(location = 0) in vec3 aPosition;
invariant gl_Position; // the eye pass's depth pre-pass (depth.vert) must match eye.vert bit for bit
uniform mat4 uModel;
uniform mat4 uLightViewProj;
#if defined(LINEAR_Z) || defined(MOMENTS)
out vec3 vWorldPos; // only the variants that compute linear depth need it
#endif
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
#if defined(LINEAR_Z) || defined(MOMENTS)
    vWorldPos = world.xyz;
#endif
    gl_Position = uLightViewProj * world;
}
