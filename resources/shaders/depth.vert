#version 430 core
// Shadow pass: world → shadow clip space of one split.
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uLightViewProj;
out vec3 vWorldPos;
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    gl_Position = uLightViewProj * world;
}
