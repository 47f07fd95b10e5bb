#include "caster_lod_setup.h"

#include "geometry/lod/caster_lod.h"

#include <chrono>
#include <cmath>
#include <iostream>

namespace app {

void ensureCasterLod(renderer::Renderer& r, const geometry::scene::Scene& scene,
                     const geometry::shadow::ShadowSettings& settings) {
    if (settings.casters.lod != geometry::shadow::CasterLod::Auto || r.hasCasterLod()) return;
    const auto t0 = std::chrono::steady_clock::now();
    int shown = -1;
    const geometry::lod::SceneLod lod = geometry::lod::buildCasterLod(scene, {}, [&](float done) {
        const int percent = int(std::floor(done * 10.f)) * 10;
        if (percent > shown) std::cerr << "\rcaster LOD: " << (shown = percent) << " %" << std::flush;
        return true;
    });
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cerr << "\rcaster LOD: " << lod.sourceTriangles << " triangles, " << lod.lodTriangles
              << " in simplified levels, built in " << s << " s\n";
    r.setCasterLod(lod);
}

} // namespace app
