#version 430 core
layout(location = 0) in vec3 aPosition;
invariant gl_Position; // the eye pass's depth pre-pass (depth.vert) must match eye.vert bit for bit
layout(location = 1) in vec3 aNormal;
// Object → world: per instance (GpuScene draws instanced meshes so), else one value per draw.
layout(location = 2) in mat4 aModel;
// Compact positions (GpuScene): the chunk's grid origin and step, one value per draw; (0, 0, 0, 1)
// for float positions. origin + step · q is exact in float (geometry/scene/compact_vertices.h).
layout(location = 6) in vec4 aDecode;
uniform mat4 uViewProj;
out vec3 vWorldPos;
out vec3 vNormal;
void main() {
    vec4 world = aModel * vec4(aDecode.xyz + aDecode.w * aPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = mat3(transpose(inverse(aModel))) * aNormal;
    gl_Position = uViewProj * world;
}
