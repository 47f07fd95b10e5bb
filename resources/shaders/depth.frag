#version 430 core
// Shadow pass fragment. Variants (defines): LINEAR_Z stores linear light depth (Scherzer §4.2),
// PEEL keeps only surfaces behind the first layer (second depth for midpoint / dual depth),
// MOMENTS writes VSM moments of linear depth.
#if defined(LINEAR_Z) || defined(MOMENTS)
in vec3 vWorldPos;
#endif
uniform vec3 uLightDir;
uniform vec2 uLinearRange;   // (lo, 1 / (hi − lo)) of l·x for this split
uniform vec2 uSlopeBias;     // LINEAR_Z: (slope factor, units) applied by hand (polygon offset cannot)
#ifdef PEEL
uniform sampler2DArray uFirstLayer;
uniform int uLayer;
#endif
#ifdef MOMENTS
layout(location = 0) out vec2 oMoments;
#endif

#if defined(LINEAR_Z) || defined(MOMENTS)
float linearDepth() { return (dot(vWorldPos, uLightDir) - uLinearRange.x) * uLinearRange.y; }
#endif

void main() {
#ifdef LINEAR_Z
    float z = linearDepth();
    z += uSlopeBias.x * max(abs(dFdx(z)), abs(dFdy(z))) + uSlopeBias.y * 1e-7;
#else
    float z = gl_FragCoord.z;
#endif
#ifdef PEEL
    float first = texelFetch(uFirstLayer, ivec3(gl_FragCoord.xy, uLayer), 0).r;
    if (z <= first + 1e-6) discard;
#endif
#ifdef MOMENTS
    float m = linearDepth();
    float dx = dFdx(m), dy = dFdy(m);
    oMoments = vec2(m, m * m + 0.25 * (dx * dx + dy * dy)); // Donnelly & Lauritzen's slope term
#endif
#if defined(LINEAR_Z)
    gl_FragDepth = clamp(z, 0.0, 1.0);
#endif
}
