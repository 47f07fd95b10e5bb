#pragma once
// Caster levels of detail for the headless commands: built once per scene, the first time a
// configuration asks for them (casters.lod = auto), with progress on stderr.
#include "geometry/scene/scene.h"
#include "geometry/shadow/settings.h"
#include "renderer/renderer.h"

namespace app {

/// Gives `r` the scene's simplified caster levels if `settings` wants them and `r` has none yet.
void ensureCasterLod(renderer::Renderer& r, const geometry::scene::Scene& scene,
                     const geometry::shadow::ShadowSettings& settings);

} // namespace app
