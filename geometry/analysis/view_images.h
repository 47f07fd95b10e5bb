#pragma once
// The inspection views as images: split colouring, texel grid, aliasing and truth heatmaps. The
// views with a legend draw it into the image, or, given `legend`, hand it back instead (the
// dashboard draws it in its UI font at the UI scale).
#include "geometry/analysis/heatmap.h"
#include "geometry/analysis/image.h"
#include "geometry/analysis/inspection.h"

#include <string>
#include <vector>

namespace geometry::analysis {

/// The eye image tinted by the split each pixel uses, with a legend of the splits' ranges.
[[nodiscard]] Image splitsView(const Image& eye, const Inspection& in, const geometry::shadow::ShadowPlan& plan,
                               Legend* legend = nullptr);
/// The shadow map's texel grid (every `every` texels) drawn over the receivers of the eye image.
[[nodiscard]] Image texelsView(const Image& eye, const Inspection& in, int every = 1);
/// log2 m heatmap with a legend (docs/design.md §4); `blend` > 0 mixes the eye image in (0 heatmap alone).
[[nodiscard]] Image aliasingView(const Inspection& in, const Image& eye, float blend = 0.f, Legend* legend = nullptr);
/// The truth classes, each its own colour (interior false shadow red, interior false lit blue, edge
/// errors amber, ambiguous teal) over the grey scene, with a legend of the colours shown; needs
/// in.occluded (falls back to false shadow / false lit alone without in.classes).
[[nodiscard]] Image truthView(const Inspection& in, const Image& eye, float blend = 0.f, Legend* legend = nullptr);

/// The soft truth (inspection with a sun of non-zero size): s − v per receiver, the rendered lit
/// fraction against the fraction of the sun's disk the pixel sees, on the diverging scale over
/// [−0.5, 0.5] (red: rendered darker than the sun allows, blue: lighter, white: equal), with a legend.
/// Throws std::invalid_argument without a soft truth.
[[nodiscard]] Image softView(const Inspection& in, const Image& eye, float blend = 0.f, Legend* legend = nullptr);

/// A/B comparison (Barroso Fig 8): log2(m_A / m_B) on the diverging scale where both frames see a
/// receiver (red: A undersamples more than B; blue: A is finer), grey elsewhere, with a legend.
/// Throws std::invalid_argument when the two inspections differ in size.
[[nodiscard]] Image differenceView(const Inspection& a, const Inspection& b, Legend* legend = nullptr);

/// Tints, in a light-view image of split `split` (resolution `res` texels), every texel that some
/// visible receiver pixel samples (docs/design.md §4 texel utilization, shown).
void tintSampledTexels(Image& light, const Inspection& in, int split, int res);

} // namespace geometry::analysis
