#version 430 core
// Shadow pass fragment. Variants (defines): LINEAR_Z stores linear light depth (Scherzer §4.2),
// PEEL keeps only surfaces behind the first layer (second depth for midpoint / dual depth),
// MOMENTS writes the moment filter's moments of linear depth (vsm, esm, evsm2, evsm4, msm:
// docs/filters.md); EYE_DEPTH is the eye pass's depth pre-pass.
#include "shadow_block.glsl"
#include "light.glsl"
#if defined(LINEAR_Z) || defined(MOMENTS)
in vec3 vWorldPos;
#endif
#ifndef EYE_DEPTH
uniform int uSplit;
#endif
#ifdef PEEL
uniform sampler2DArray uFirstLayer;
#endif
#ifdef MOMENTS
layout(location = 0) out vec4 oMoments;
#include "moments.glsl"
#endif

#if defined(LINEAR_Z) || defined(MOMENTS)
float linearDepth() { return (lightDistance(vWorldPos) - shadow.splits[uSplit].linearLo) * shadow.splits[uSplit].linearScale; }
#endif

void main() {
#ifdef LINEAR_Z
    float z = linearDepth();
    z += shadow.slopeBias.x * max(abs(dFdx(z)), abs(dFdy(z))) + shadow.slopeBias.y * 1e-7; // by hand: polygon offset cannot
#else
    float z = gl_FragCoord.z;
#endif
#ifdef PEEL
    float first = texelFetch(uFirstLayer, ivec3(gl_FragCoord.xy, uSplit), 0).r;
    if (z <= first + 1e-6) discard;
#endif
#ifdef MOMENTS
    float m = linearDepth();
    if (settings.filter_type == FILTER_VSM) {
        float dx = dFdx(m), dy = dFdy(m);
        oMoments = vec4(m, m * m + 0.25 * (dx * dx + dy * dy), 0.0, 0.0); // Donnelly & Lauritzen's slope term
    } else {
        oMoments = momentsOf(m);
    }
#endif
#if defined(LINEAR_Z)
    gl_FragDepth = clamp(z, 0.0, 1.0);
#endif
}
