#version 430 core
// Eye pass: Lambert + ambient terms and the shadow factor, kept apart so the mask can be blurred
// (Scherzer §4.3) and inspected. Every bias and filter of docs/design.md §3.5–3.6 lives here; what the
// plan derives comes in the shadow block (renderer/shadow_block.inc), the settings as set in the
// settings block (`settings.<key with _ for .>`, renderer/settings_block.h). technique = virtual reads its
// pages in virtual_lookup.glsl.
#include "shadow_block.glsl"
#include "light.glsl"
#include "moments.glsl"
#include "virtual.glsl"
in vec3 vWorldPos;
in vec3 vNormal;
uniform vec3 uColor;

uniform sampler2DArray uShadowMap;          // depth, nearest, no compare
uniform sampler2DArrayShadow uShadowMapCmp; // same texture, linear compare (hw2x2)
uniform sampler2DArray uMoments;            // the moment filters' blurred moments, linear

layout(location = 0) out vec4 oBase;   // rgb albedo·ambient, a view depth
layout(location = 1) out vec4 oDirect; // rgb albedo·(1−ambient)·N·L
layout(location = 2) out vec4 oMask;   // r shadow factor
layout(location = 3) out vec4 oAux;    // map u, v (texels), split index, receiver depth in the map
layout(location = 4) out vec4 oPosition; // world position, aliasing error m
layout(location = 5) out vec4 oNormal;   // facing normal, N·L

const float kAmbient = 0.28;
const float kGoldenAngle = 2.39996323;

/// Map coordinates (u, v in [0,1]) and depth of a world point in a split, in the depth space the map stores.
vec3 mapCoords(vec3 world, int split) {
    vec4 clip = shadow.splits[split].lightViewProj * vec4(world, 1.0);
    vec3 p = clip.xyz / clip.w * 0.5 + 0.5;
    if (shadow.linearDepth == 1) p.z = (lightDistance(world) - shadow.splits[split].linearLo) * shadow.splits[split].linearScale;
    return p;
}

/// World-space size of one texel at `world` (for normal offset): the map's local scale across l.
float texelWorldSize(vec3 world, int split, float res) {
    vec3 l = lightDirAt(world);
    vec3 e1 = normalize(cross(l, abs(l.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0)));
    vec3 e2 = cross(l, e1);
    float h = 0.01 * max(1.0, length(world - shadow.eye));
    vec2 p0 = mapCoords(world, split).xy;
    float du = length(mapCoords(world + e1 * h, split).xy - p0);
    float dv = length(mapCoords(world + e2 * h, split).xy - p0);
    return h / (max(min(du, dv), 1e-12) * res);
}

float hardTest(vec2 texel, float z, int split, float res) {
    ivec2 t = clamp(ivec2(floor(texel)), ivec2(0), ivec2(int(res) - 1));
    return z > texelFetch(uShadowMap, ivec3(t, split), 0).r ? 0.0 : 1.0;
}

/// bias.type = receiver_plane: the tap at `tap` compares against the receiver's plane at the centre of
/// the texel it reads (where the stored depth was rasterized), less half a texel's slope, which
/// covers curved receivers and caster edges inside the texel (Isidoro 2006, with the plane evaluated
/// at texel centres).
float planeSlack(vec2 dzdt) { return 0.5 * (abs(dzdt.x) + abs(dzdt.y)) + 1e-6; }

float planeTest(vec2 texel, vec2 tap, float z, vec2 dzdt, int split, float res) {
    vec2 centre = floor(tap) + 0.5;
    float ref = z + dot(dzdt, centre - texel) - planeSlack(dzdt);
    return hardTest(tap, ref, split, res);
}

/// A point of the Vogel disk: tap k of n, radius 1, rotated by `angle`.
vec2 vogel(int k, int n, float angle) {
    float a = float(k) * kGoldenAngle + angle;
    return sqrt((float(k) + 0.5) / float(n)) * vec2(cos(a), sin(a));
}

/// Interleaved gradient noise (Jimenez 2014): a per-pixel rotation that trades banding for noise
/// (filter.rotate_taps; off: the same pattern at every pixel).
float pixelAngle() {
    if (!settings.filter_rotate_taps) return 0.0;
    return 6.2831853 * fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
}

/// A PCSS tap: the point `offset` (⊥ l) away on the receiver's plane (normal n, nl = n·l < 0), as
/// (its depth in this split's map − eps, the depth the map stores there).
vec2 pcssTap(vec3 receiver, vec3 l, vec3 n, float nl, vec3 offset, int split, float res, vec2 shift, float eps) {
    vec3 q = mapCoords(receiver + offset - l * (dot(n, offset) / nl), split);
    ivec2 t = clamp(ivec2(floor(q.xy * res + shift)), ivec2(0), ivec2(int(res) - 1));
    return vec2(q.z - eps, texelFetch(uShadowMap, ivec3(t, split), 0).r);
}

/// PCSS (Fernando 2005) for a sun of angular radius atan(sunTanHalfAngle) or a positional light of
/// radius lightRadius (its angular radius seen from the blockers), with taps on the receiver's
/// plane in world space, so the kernel keeps its size and shape in scene units under any warp:
/// 1. blocker search over the disk a blocker at the map's near end could shade from;
/// 2. penumbra radius = (receiver - mean blocker distance along l) * tan(half angle);
/// 3. PCF over a disk of that radius (uniform over the disk: a straight edge gives the sun's profile).
float pcss(vec3 receiver, vec3 n, float z, int split, float res) {
    float scale = shadow.splits[split].linearScale; // linear map depth per scene unit along l
    vec3 l = lightDirAt(receiver);
    vec3 e1 = normalize(cross(l, abs(l.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0)));
    vec3 e2 = cross(l, e1);
    float texel = texelWorldSize(receiver, split, res);
    float nl = min(dot(n, l), -0.05); // the receiver faces the light; bounded at grazing
    float slope = sqrt(max(1.0 - nl * nl, 0.0)) / -nl; // scene units along l per unit across it
    float eps = scale * texel * slope + 1e-6;           // one texel of the receiver's slope
    float maxRadius = settings.filter_pcss_max_radius * texel;
    float angle = pixelAngle();
    vec2 shift = vec2(shadow.splits[split].lookupShiftX, shadow.splits[split].lookupShiftY);
    // A positional light's receiver is lightDistance(receiver) from it; blockers half-way set the search.
    float receiverDistance = positionalLight() ? lightDistance(receiver) : 0.0;
    float searchRadius = clamp(z / scale * lightTanHalfAngle(0.5 * receiverDistance), texel, maxRadius);
    float blockers = 0.0, blockerDepth = 0.0;
    for (int k = 0; k < settings.filter_taps; ++k) {
        vec2 o = vogel(k, settings.filter_taps, angle) * searchRadius;
        vec2 tap = pcssTap(receiver, l, n, nl, e1 * o.x + e2 * o.y, split, res, shift, eps);
        if (tap.y < tap.x) {
            blockers += 1.0;
            blockerDepth += tap.y;
        }
    }
    if (blockers == 0.0) return 1.0;
    float distance = max(z - blockerDepth / blockers, 0.0) / scale; // receiver to blockers, scene units
    float radius = clamp(distance * lightTanHalfAngle(receiverDistance - distance), 0.5 * texel, maxRadius);
    float lit = 0.0;
    for (int k = 0; k < settings.filter_taps; ++k) {
        vec2 o = vogel(k, settings.filter_taps, angle + 1.0) * radius;
        vec2 tap = pcssTap(receiver, l, n, nl, e1 * o.x + e2 * o.y, split, res, shift, eps);
        lit += tap.x > tap.y ? 0.0 : 1.0;
    }
    return lit / float(settings.filter_taps);
}

/// k×k box PCF one texel apart (k = settings.filter_kernel, odd), four texels per textureGather: the k×k block
/// is covered by ⌈k/2⌉² gathers and the extra row and column are masked out.
float pcfBox(vec2 texel, float z, int split, vec2 dzdt) {
    vec2 first = floor(texel) - float(settings.filter_kernel / 2); // lower-left texel of the block
    float lit = 0.0;
    for (int j = 0; j < settings.filter_kernel; j += 2)
        for (int i = 0; i < settings.filter_kernel; i += 2) {
            vec2 corner = first + vec2(i, j) + 1.0; // shared corner of texels (i, j)..(i+1, j+1)
            vec4 d = textureGather(uShadowMap, vec3(corner / float(shadow.arrayResolution), float(split)), 0);
            // Gather order: x (i, j+1), y (i+1, j+1), z (i+1, j), w (i, j).
            vec2 o = first + vec2(i, j) + 0.5 - texel; // offset of texel (i, j) from the receiver
            vec4 ref = z + vec4(dot(dzdt, o + vec2(0, 1)), dot(dzdt, o + vec2(1, 1)), dot(dzdt, o + vec2(1, 0)), dot(dzdt, o));
            vec4 inside = vec4(j + 1 < settings.filter_kernel ? 1.0 : 0.0, (i + 1 < settings.filter_kernel && j + 1 < settings.filter_kernel) ? 1.0 : 0.0,
                               i + 1 < settings.filter_kernel ? 1.0 : 0.0, 1.0);
            lit += dot(inside, step(ref, d)); // lit where ref ≤ stored
        }
    return lit / float(settings.filter_kernel * settings.filter_kernel);
}


/// What one split's map says about a receiver: the shadow factor, where the lookup landed, and the
/// texel-space derivatives behind the receiver plane and J.
struct Lookup {
    float s;
    vec2 texel;
    float depth;
    vec2 dTdx, dTdy;
    float det;
    int level; // the split, or the virtual map's level
};

/// Looks `receiver` up in split `split`'s map. The screen derivatives of the receiver's world position
/// come from the caller, taken in uniform control flow; they go through this split's matrix, so a
/// 2×2 block that straddles a split boundary does not mix two maps.
Lookup lookUp(int split, vec3 receiver, vec3 n, vec3 dPdx, vec3 dPdy, float ndotl) {
    float res = float(shadow.arrayResolution) * shadow.splits[split].mapScale;
    vec3 p = mapCoords(receiver, split);
    vec3 px = mapCoords(receiver + dPdx, split), py = mapCoords(receiver + dPdy, split);
    Lookup L;
    L.dTdx = (px.xy - p.xy) * res;
    L.dTdy = (py.xy - p.xy) * res;
    float dzdx = px.z - p.z, dzdy = py.z - p.z;
    L.det = L.dTdx.x * L.dTdy.y - L.dTdx.y * L.dTdy.x;
    // The receiver plane's depth gradient per texel (Barroso §2.2).
    vec2 dzdt = abs(L.det) > 1e-12 ? vec2(dzdx * L.dTdy.y - dzdy * L.dTdx.y, dzdy * L.dTdx.x - dzdx * L.dTdy.x) / L.det
                                   : vec2(0.0);
    bool receiverPlane = settings.bias_type == BIAS_RECEIVER_PLANE;
    if (!settings.bias_tangent_plane && !receiverPlane) dzdt = vec2(0.0);

    p.xy += vec2(shadow.splits[split].lookupShiftX, shadow.splits[split].lookupShiftY) / res; // 0 but in tests
    vec2 texel = p.xy * res; // texel-space position within this split's map
    vec2 uvArray = p.xy * shadow.splits[split].mapScale;

    float s = 1.0;
    bool inside = all(greaterThanEqual(p, vec3(0.0))) && all(lessThanEqual(p.xy, vec2(1.0)));
    if (inside && ndotl > 0.0) {
        if (settings.filter_type == FILTER_NONE) {
            s = receiverPlane ? planeTest(texel, texel, p.z, dzdt, split, res) : hardTest(texel, p.z, split, res);
        } else if (settings.filter_type == FILTER_HW2X2) {
            // One reference for four texels: the receiver plane can only lower it by a texel's slope.
            float ref = receiverPlane ? p.z - 2.0 * planeSlack(dzdt) : p.z;
            s = texture(uShadowMapCmp, vec4(uvArray, float(split), ref));
        } else if (settings.filter_type == FILTER_PCF) {
            s = pcfBox(texel, receiverPlane ? p.z - planeSlack(dzdt) : p.z, split, dzdt);
        } else if (settings.filter_type == FILTER_DISK) {
            // Vogel disk, rotated per pixel to trade banding for noise.
            float angle = pixelAngle();
            float sum = 0.0;
            for (int k = 0; k < settings.filter_taps; ++k) {
                vec2 offset = settings.filter_radius * vogel(k, settings.filter_taps, angle);
                sum += receiverPlane ? planeTest(texel, texel + offset, p.z, dzdt, split, res)
                                     : hardTest(texel + offset, p.z + dot(dzdt, offset), split, res);
            }
            s = sum / float(settings.filter_taps);
        } else if (settings.filter_type == FILTER_PCSS) {
            s = pcss(receiver, n, p.z, split, res);
        } else {
            s = momentLit(texture(uMoments, vec3(uvArray, float(split))), p.z);
        }
    }
    L.s = s;
    L.texel = texel;
    L.depth = p.z;
    L.level = split;
    return L;
}

#include "virtual_lookup.glsl"

/// m = 1/σ_min(J), screen pixels per texel along the worst direction (docs/design.md §4).
float aliasingM(Lookup L) {
    float a = dot(L.dTdx, L.dTdx) + dot(L.dTdy, L.dTdy);
    float sigmaMin2 = 0.5 * (a - sqrt(max(a * a - 4.0 * L.det * L.det, 0.0)));
    return 1.0 / sqrt(max(sigmaMin2, 1e-20));
}

void main() {
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n; // CAD surfaces are seen from both sides
    vec3 l = lightDirAt(vWorldPos);
    float ndotl = max(dot(n, -l), 0.0) * lightReach(vWorldPos); // 0 outside a spot's cone or beyond range
    float viewDepth = dot(vWorldPos - shadow.eye, shadow.viewDir);
    int split = mapOf(vWorldPos, viewDepth);
    float res = float(shadow.arrayResolution) * shadow.splits[split].mapScale;

    vec3 receiver = vWorldPos;
    vec3 dWdx = dFdx(vWorldPos), dWdy = dFdy(vWorldPos); // in uniform control flow
    if (settings.bias_type == BIAS_CONSTANT) receiver -= l * shadow.receiverOffset;
    if (shadow.normalOffset > 0.0)
        receiver += n * shadow.normalOffset *
                    (uVirtual == 1 ? vTexel(vLevelAt(vPlane(vWorldPos), vLevelFor(vFootprint(dWdx, dWdy))))
                                   : texelWorldSize(vWorldPos, split, res));
    vec3 dPdx = dFdx(receiver), dPdy = dFdy(receiver); // in uniform control flow

    Lookup L = uVirtual == 1 ? virtualLookUp(receiver, dPdx, dPdy, ndotl) : lookUp(split, receiver, n, dPdx, dPdy, ndotl);
    float s = L.s;
    float m = aliasingM(L);
    // splits.blend: in the band before this split's far end, fade into the next split's shadow (and
    // its m, the texel density the blend delivers); the next split's map covers the band (the plan
    // focuses it that much earlier).
    float blendStart = shadow.splits[split].blendStart, splitFar = shadow.splits[split].splitFar;
    if (uVirtual == 0 && !positionalLight() && split < shadow.splitCount - 1 && viewDepth > blendStart && splitFar > blendStart) {
        float t = clamp((viewDepth - blendStart) / (splitFar - blendStart), 0.0, 1.0);
        Lookup next = lookUp(split + 1, receiver, n, dPdx, dPdy, ndotl);
        s = mix(s, next.s, t);
        m = mix(m, aliasingM(next), t);
    }
    if (ndotl <= 0.0) s = 0.0; // facing away from the light: in its own shadow

    oBase = vec4(uColor * kAmbient, max(viewDepth, 1e-6));
    oDirect = vec4(uColor * (1.0 - kAmbient) * ndotl, 1.0);
    oMask = vec4(s);
    oAux = vec4(L.texel, float(L.level), L.depth);
    oPosition = vec4(vWorldPos, m);
    oNormal = vec4(n, ndotl);
}
