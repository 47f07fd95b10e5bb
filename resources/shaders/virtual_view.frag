#version 430 core
// technique = virtual: the light view (docs/design.md §3.11). A square of the light's plane (the
// allocated pages' extent) as the virtual map holds it: each point from the finest level whose page
// is allocated, its depth as grey tinted with that level's colour, each page outlined in it; points no
// page holds are dark.
#include "virtual.glsl"
in vec2 vUv;
uniform usampler2DArray uPageTable;
uniform sampler2D uPageAtlas;
uniform vec2 uViewCorner; // the view's lower-left point in the plane (relative to the eye)
uniform float uViewSide;  // world units across the view
uniform float uPixel;     // world units per view pixel
layout(location = 0) out vec4 oColor;

/// A hue per level, from red (level 0, the finest) through green to blue (the coarsest).
vec3 levelColour(int k) {
    float h = 0.7 * float(k) / max(float(uVLevels - 1), 1.0);
    return clamp(abs(fract(vec3(h) + vec3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0, 0.0, 1.0);
}

void main() {
    vec2 s = uViewCorner + vUv * uViewSide;
    for (int k = 0; k < uVLevels; ++k) {
        ivec2 page = vPageOf(s, k);
        if (!vInSquare(page)) continue;
        uint entry = texelFetch(uPageTable, ivec3(page, k), 0).r;
        if (entry == 0u) continue;
        float pageWorld = vTexel(k) * float(uVPageSize);
        vec2 inPage = (s - uVOrigin[k]) / pageWorld - vec2(page); // 0..1 across the page
        float edge = min(min(inPage.x, 1.0 - inPage.x), min(inPage.y, 1.0 - inPage.y)) * pageWorld;
        vec3 c = levelColour(k);
        if (edge < uPixel) {
            oColor = vec4(c, 1.0);
            return;
        }
        ivec2 t = clamp(ivec2(floor(inPage * float(uVPageSize))), ivec2(0), ivec2(uVPageSize - 1));
        float d = texelFetch(uPageAtlas, vAtlasTexel(entry, t), 0).r;
        vec3 grey = d >= 1.0 ? vec3(0.08, 0.10, 0.22) : vec3(1.0 - d);
        oColor = vec4(mix(grey, c, 0.3), 1.0);
        return;
    }
    oColor = vec4(0.03, 0.04, 0.09, 1.0);
}
