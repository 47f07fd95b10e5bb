#version 430 core
layout(location = 0) in vec3 aPosition;
invariant gl_Position; // the eye pass's depth pre-pass (depth.vert) must match eye.vert bit for bit
layout(location = 1) in vec3 aNormal;
uniform mat4 uModel;
uniform mat4 uViewProj;
out vec3 vWorldPos;
out vec3 vNormal;
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = mat3(transpose(inverse(uModel))) * aNormal;
    gl_Position = uViewProj * world;
}
