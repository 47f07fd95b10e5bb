#version 430 core
// Depth only: the shadow passes draw into split uSplit's map (world → that split's shadow clip
// space); PAGE draws one page of the virtual map; EYE_DEPTH is the eye pass's depth pre-pass through the camera's uViewProj.
#include "shadow_block.glsl"
layout(location = 0) in vec3 aPosition;
invariant gl_Position; // the eye pass's depth pre-pass (depth.vert) must match eye.vert bit for bit
// Object → world: per instance (GpuScene draws instanced meshes so), else one value per draw.
layout(location = 2) in mat4 aModel;
// Compact positions (GpuScene): the chunk's grid origin and step, one value per draw; (0, 0, 0, 1)
// for float positions. origin + step · q is exact in float (geometry/scene/compact_vertices.h).
layout(location = 6) in vec4 aDecode;
#ifdef EYE_DEPTH
uniform mat4 uViewProj;
#elif defined(PAGE)
uniform mat4 uPageViewProj; // technique = virtual: world → the page's clip space (VirtualPlan::pageViewProj)
#else
uniform int uSplit;
#endif
#if defined(LINEAR_Z) || defined(MOMENTS)
out vec3 vWorldPos; // only the variants that compute linear depth need it
#endif
void main() {
    vec4 world = aModel * vec4(aDecode.xyz + aDecode.w * aPosition, 1.0);
#if defined(LINEAR_Z) || defined(MOMENTS)
    vWorldPos = world.xyz;
#endif
#ifdef EYE_DEPTH
    gl_Position = uViewProj * world;
#elif defined(PAGE)
    gl_Position = uPageViewProj * world;
#else
    gl_Position = shadow.splits[uSplit].lightViewProj * world;
#endif
}
