#include "geometry/analysis/inspection.h"

#include "geometry/analysis/ground_truth.h"
#include "geometry/analysis/penumbra_width.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace geometry::analysis {

namespace {

/// Per-pixel loops check the stop token once per this many pixels: well under a millisecond apart.
constexpr size_t kPixelsPerStopCheck = 4096;

/// The soft truth of addTruth: the sun's visible fraction per receiver and the figures over it.
void addSoftTruth(Inspection& in, const shadow::ShadowPlan& plan, const GroundTruth& truth, std::stop_token stop) {
    in.sunVisibility.clear();
    in.softTruth.reset();
    const TruthLight light = truthLight(plan);
    const float diameterDeg = plan.settings.light.angularDiameterDeg;
    if (light.positional() ? !(light.radius > 0.f) : !(diameterDeg > 0.f)) return;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const double theta = double(diameterDeg) * std::numbers::pi / 180.0;
    // Non-receivers get a zero normal: not traced, then NaN.
    std::vector<glm::vec3> normals = in.geometricNormals;
    for (size_t i = 0; i < normals.size(); ++i)
        if (!in.receiver[i]) normals[i] = glm::vec3(0.f);
    in.sunVisibility =
        truth.sunVisibility(in.positions, normals, light, float(theta), GroundTruth::kSunSamplesPerAxis, 0, stop);
    for (size_t i = 0; i < in.sunVisibility.size(); ++i)
        if (!in.receiver[i]) in.sunVisibility[i] = nan;
    SoftTruthStats soft;
    soft.meanAbs = softMeanAbs(in.shadow, in.sunVisibility, in.receiver);
    soft.angularDiameterDeg = light.positional() ? 0.f : diameterDeg; // a positional emitter's varies per pixel
    soft.raysPerPixel = GroundTruth::kSunSamplesPerAxis * GroundTruth::kSunSamplesPerAxis;
    // The penumbra-width model is the sun's (parallel rays of one angular size).
    if (const auto& edge = truth.occluderEdge(); edge && !light.positional()) {
        throwIfStopped(stop);
        soft.penumbraWidthError = penumbraWidth(in.positions, in.shadow, in.receiver, plan.l, *edge, theta).error;
        soft.penumbraWidthErrorTruth =
            penumbraWidth(in.positions, in.sunVisibility, in.receiver, plan.l, *edge, theta).error;
    }
    in.softTruth = soft;
}

} // namespace

Inspection makeInspection(FrameReadback frame, const shadow::ShadowPlan& plan, const GroundTruth* truth,
                          int truthSamples, std::stop_token stop) {
    Inspection in;
    in.shadow = std::move(frame.shadow);
    in.aux = std::move(frame.aux);
    const size_t n = in.aux.size();
    // Each read-back array goes once split: at plant scale this runs beside the truth's BVH, at the
    // process's peak (docs/performance.md "Scale"), and each is 16 bytes a pixel.
    in.m.resize(n);
    in.positions.resize(n);
    for (size_t i = 0; i < n; ++i) {
        if (i % kPixelsPerStopCheck == 0) throwIfStopped(stop);
        in.positions[i] = glm::vec3(frame.positions[i]);
        in.m[i] = frame.positions[i].w;
    }
    std::vector<glm::vec4>().swap(frame.positions);
    in.normals.resize(n);
    in.receiver.resize(n);
    for (size_t i = 0; i < n; ++i) {
        if (i % kPixelsPerStopCheck == 0) throwIfStopped(stop);
        in.normals[i] = glm::vec3(frame.normals[i]);
        in.receiver[i] = in.aux[i].z >= 0.f && frame.normals[i].w > 0.f;
    }
    std::vector<glm::vec4>().swap(frame.normals);
    if (plan.light.positional()) {
        // Where the light does not reach (outside a spot's cone, beyond the range) it has no shadow
        // to judge: the scene's light decides, not the settings.
        const TruthLight light = truthLight(plan);
        for (size_t i = 0; i < n; ++i)
            if (in.receiver[i] && !light.reaches(in.positions[i])) in.receiver[i] = 0;
    }
    in.width = frame.width;
    in.height = n && in.width ? int(n / size_t(in.width)) : 0;
    throwIfStopped(stop);
    in.aliasing = aliasingStats(in.m, in.receiver);
    in.resolutions = std::move(frame.resolutions);
    if (frame.samplesPerAxis > 1 &&
        frame.sampleShadow.size() == n * size_t(frame.samplesPerAxis * frame.samplesPerAxis))
        in.sampleShadow = std::move(frame.sampleShadow);
    for (int s = 0; s < int(in.resolutions.size()); ++s) {
        throwIfStopped(stop);
        in.utilization.push_back(texelUtilization(in.aux, in.receiver, s, in.resolutions[s]));
    }
    if (truth) addTruth(in, plan, *truth, truthSamples, stop);
    return in;
}

float pixelFootprint(const shadow::ShadowPlan& plan, const glm::vec3& p, int height) noexcept {
    // eyeProj[1][1] = 1 / tan(fovy / 2): one pixel spans 2·d·tan(fovy / 2) / height at view depth d.
    const float depth = glm::dot(p - plan.eye, plan.v);
    const float size = 2.f * depth / (float(std::max(height, 1)) * plan.eyeProj[1][1]);
    return std::isfinite(size) && size > 0.f ? size : std::numeric_limits<float>::quiet_NaN();
}

TruthLight truthLight(const shadow::ShadowPlan& plan) noexcept {
    return plan.light.positional() ? TruthLight(plan.light) : TruthLight(plan.l);
}

std::vector<uint8_t> truthOcclusion(const Inspection& in, const std::vector<glm::vec3>& geometricNormals,
                                    const TruthLight& light, const GroundTruth& truth, std::stop_token stop) {
    std::vector<uint8_t> occluded = truth.occluded(in.positions, geometricNormals, light, 0, stop);
    for (size_t i = 0; i < occluded.size(); ++i)
        if (!in.receiver[i]) occluded[i] = 0;
    return occluded;
}

std::vector<uint8_t> truthOcclusion(const Inspection& in, const glm::vec3& eye, const TruthLight& light,
                                    const GroundTruth& truth, std::stop_token stop) {
    return truthOcclusion(in, truth.surfaceNormals(eye, in.positions, in.normals, 0, nullptr, stop), light, truth,
                          stop);
}

namespace {

/// The truth at every sample: GroundTruth::coverage over an N-times finer image traces exactly the
/// samples of this one (sub-pixel centres), so each can meet the rendered s there; in.coverage gets
/// their mean per pixel (NaN where no sample saw a surface). Returns the per-sample truth.
std::vector<float> sampleCoverage(Inspection& in, const shadow::ShadowPlan& plan, const GroundTruth& truth, int N,
                                  std::stop_token stop) {
    in.coverage.assign(in.positions.size(), 1.f);
    if (N <= 1) return {};
    std::vector<float> sampleTruth =
        truth.coverage(plan.eyeProj * plan.eyeView, in.width * N, in.height * N, truthLight(plan), 1, 0, stop);
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x) {
            double sum = 0;
            int hits = 0;
            for (int sy = 0; sy < N; ++sy)
                for (int sx = 0; sx < N; ++sx) {
                    const float t = sampleTruth[(size_t(y) * N + sy) * size_t(in.width) * N + size_t(x) * N + sx];
                    if (std::isfinite(t)) sum += t, ++hits;
                }
            in.coverage[size_t(y) * size_t(in.width) + size_t(x)] =
                hits ? float(sum / hits) : std::numeric_limits<float>::quiet_NaN();
        }
    return sampleTruth;
}

/// The per-pixel inputs of the truth classes besides s and c.
struct PixelFacts {
    std::vector<float> texelsPerPixel, gap; // 1/m; the occluder's distance within the peter-panning reach
    std::vector<uint8_t> singular;          // J singular: m not measured
    std::vector<int> split;                 // the split each receiver was looked up in
};

/// Per receiver, what the scene alone says: the undecidable pixels (terminator, shading and
/// geometric normals disagreeing, an occluder within one pixel footprint) into in.ambiguity, and
/// c where no sample saw a surface; plus the PixelFacts.
PixelFacts pixelFacts(Inspection& in, const shadow::ShadowPlan& plan, const GroundTruth& truth, int N,
                      std::stop_token stop) {
    const size_t n = in.positions.size();
    const TruthLight light = truthLight(plan);
    PixelFacts f;
    in.ambiguity.assign(n, uint8_t(Ambiguity::None));
    f.texelsPerPixel.assign(n, std::numeric_limits<float>::quiet_NaN());
    std::vector<float> reach(n, std::numeric_limits<float>::quiet_NaN()), footprint(n, 0.f);
    f.singular.assign(n, 0);
    f.split.assign(n, -1);
    for (size_t i = 0; i < n; ++i) {
        if (i % kPixelsPerStopCheck == 0) throwIfStopped(stop);
        const float centre = (*in.occluded)[i] ? 0.f : 1.f;
        if (N == 1 || !std::isfinite(in.coverage[i])) in.coverage[i] = centre; // no sample saw it
        if (in.m[i] > 0.f && in.m[i] < kSingularM) f.texelsPerPixel[i] = 1.f / in.m[i];
        if (!in.receiver[i]) continue;
        f.singular[i] = std::isfinite(in.m[i]) && !(in.m[i] < kSingularM);
        f.split[i] = int(std::lround(in.aux[i].z));
        const glm::vec3 toLight = light.toLight(in.positions[i]);
        const float geometric = glm::dot(in.geometricNormals[i], toLight);
        const float shading = glm::dot(in.normals[i], toLight);
        if (std::abs(geometric) < 0.1f) in.ambiguity[i] = uint8_t(Ambiguity::Terminator);
        else if ((geometric > 0.f) != (shading > 0.f)) in.ambiguity[i] = uint8_t(Ambiguity::NormalFlip);
        else if ((*in.occluded)[i]) {
            footprint[i] = pixelFootprint(plan, in.positions[i], in.height);
            reach[i] = kPeterPanningReach * footprint[i];
        }
    }
    // The occluder's distance where it lies within the peter-panning reach; within one footprint,
    // a contact no map can be judged on.
    f.gap = truth.occluderDistance(in.positions, in.geometricNormals, light, reach, 0, stop);
    for (size_t i = 0; i < n; ++i)
        if (f.gap[i] <= footprint[i]) in.ambiguity[i] = uint8_t(Ambiguity::Contact);
    return f;
}

} // namespace

void addTruth(Inspection& in, const shadow::ShadowPlan& plan, const GroundTruth& truth, int samplesPerAxis,
              std::stop_token stop) {
    if (samplesPerAxis < 1 || samplesPerAxis > GroundTruth::kMaxSamplesPerAxis)
        throw std::invalid_argument("--truth-samples: " + std::to_string(samplesPerAxis) + " is outside 1.." +
                                    std::to_string(GroundTruth::kMaxSamplesPerAxis));
    throwIfStopped(stop);
    const int N = samplesPerAxis;
    in.truthSamples = N;
    in.geometricNormals = truth.surfaceNormals(plan.eye, in.positions, in.normals, 0, &in.mesh, stop);
    in.occluded = truthOcclusion(in, in.geometricNormals, truthLight(plan), truth, stop);
    const std::vector<float> sampleTruth = sampleCoverage(in, plan, truth, N, stop);
    if (in.sampleShadow.size() != sampleTruth.size()) in.sampleShadow.clear(); // not drawn: s against c
    // Where the edges lie, from kEdgeSamplesPerAxis² samples whatever N (truth_classes.h, edgeCoverage).
    std::vector<float> edgeCoverage;
    if (N < kEdgeSamplesPerAxis)
        edgeCoverage = truth.coverage(plan.eyeProj * plan.eyeView, in.width, in.height, truthLight(plan),
                                      kEdgeSamplesPerAxis, 0, stop);
    const PixelFacts facts = pixelFacts(in, plan, truth, N, stop);
    in.truth = truthStats(in.shadow, *in.occluded, in.receiver);
    addSoftTruth(in, plan, truth, stop);
    TruthClassInput input;
    input.width = in.width;
    input.s = in.shadow;
    input.coverage = in.coverage;
    input.receiver = in.receiver;
    input.ambiguity = in.ambiguity;
    input.texelsPerPixel = facts.texelsPerPixel;
    input.samplesPerAxis = N;
    if (!in.sampleShadow.empty()) {
        input.sampleS = in.sampleShadow;
        input.sampleTruth = sampleTruth;
    }
    input.singular = facts.singular;
    input.visibility = in.sunVisibility;
    input.contactGap = facts.gap;
    input.edgeCoverage = edgeCoverage;
    throwIfStopped(stop);
    in.truthClasses = truthClasses(input, &in.classes);
    throwIfStopped(stop);
    in.splitTruthClasses = truthClassesByGroup(input, facts.split, int(in.utilization.size()));
    throwIfStopped(stop);
    in.meshNames = truth.meshNames();
    in.meshTruthClasses = truthClassesByGroup(input, in.mesh, int(in.meshNames.size()));
}

std::vector<PixelLayer> pixelLayers(const Inspection& in, const glm::vec3& eye, const glm::vec3& viewDir,
                                    const TruthLight& light) {
    if (in.classes.size() != in.shadow.size() || in.geometricNormals.size() != in.shadow.size())
        throw std::invalid_argument("the per-pixel layers need ground truth (--truth)");
    const size_t n = in.shadow.size();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<PixelLayer> layers{
        {"view_depth", "distance along the view direction, scene units", {}},
        {"split", "split index (-1: sky)", {}},
        {"normal_x", "geometric normal facing the camera, x", {}},
        {"normal_y", "geometric normal, y", {}},
        {"normal_z", "geometric normal, z", {}},
        {"n_dot_l", "geometric normal · direction to the light", {}},
        {"m", "aliasing error m, screen pixels per texel (NaN: singular J)", {}},
        {"s", "rendered lit fraction", {}},
        {"coverage", "truth's lit fraction c over the pixel's samples", {}},
        {"class",
         "TruthClass: 0 not counted, 1 agrees, 2 interior false shadow, 3 interior false lit, "
         "4 edge error, 5 ambiguous (undecidable), 6 singular J",
         {}},
        {"visibility", "soft truth: fraction of the sun's disk visible (NaN: point sun or not a receiver)", {}}};
    for (auto& layer : layers) layer.values.assign(n, nan);
    enum { ViewDepth, Split, NormalX, NormalY, NormalZ, NDotL, M, S, Coverage, Class, Visibility }; // the order above
    const bool soft = in.sunVisibility.size() == n;
    for (size_t i = 0; i < n; ++i) {
        const bool seen = in.aux[i].z >= 0.f;
        layers[Split].values[i] = seen ? std::round(in.aux[i].z) : -1.f;
        layers[Class].values[i] = float(int(in.classes[i]));
        if (!seen) continue;
        const glm::vec3& g = in.geometricNormals[i];
        layers[ViewDepth].values[i] = glm::dot(in.positions[i] - eye, viewDir);
        layers[NormalX].values[i] = g.x;
        layers[NormalY].values[i] = g.y;
        layers[NormalZ].values[i] = g.z;
        layers[NDotL].values[i] = glm::dot(g, light.toLight(in.positions[i]));
        layers[M].values[i] = in.m[i] > 0.f && in.m[i] < kSingularM ? in.m[i] : nan;
        layers[S].values[i] = in.shadow[i];
        layers[Coverage].values[i] = in.receiver[i] ? in.coverage[i] : nan;
        if (soft) layers[Visibility].values[i] = in.sunVisibility[i];
    }
    return layers;
}

namespace {

nlohmann::json classesJson(const TruthClasses& c) {
    return {{"interior_false_shadow", c.interiorFalseShadow},
            {"interior_false_lit", c.interiorFalseLit},
            {"edge_error", c.edgeError},
            {"edge_displacement_px", {{"median", c.edgeDisplacementPxMedian}, {"p95", c.edgeDisplacementPxP95}}},
            {"edge_displacement_texels",
             {{"median", c.edgeDisplacementTexelsMedian}, {"p95", c.edgeDisplacementTexelsP95}}},
            {"edge_width", {{"px", c.edgeWidthPx}, {"texels", c.edgeWidthTexels}, {"edge_length_px", c.edgeLengthPx}}},
            {"ambiguous", c.ambiguous},
            {"singular", c.singular},
            {"contact_false_lit", c.contactFalseLit},
            {"contact_gap", {{"median", c.contactGapMedian}, {"p95", c.contactGapP95}}},
            {"interior_mean_abs", c.interiorMeanAbs},
            {"penumbra_mean_abs", c.penumbraMeanAbs},
            {"umbra_light", c.umbraLight},
            {"umbra_pixels", c.umbraPixels},
            {"pixels", c.count}};
}

} // namespace

void addInspectionMetrics(nlohmann::json& j, const Inspection& in) {
    const auto& a = in.aliasing;
    j["aliasing"] = {
        {"mean", a.mean},         {"p50", a.p50},     {"p95", a.p95}, {"max", a.max}, {"undersampled", a.undersampled},
        {"singular", a.singular}, {"pixels", a.count}};
    if (in.truth) {
        j["truth"] = {{"false_shadow", in.truth->falseShadow},
                      {"false_lit", in.truth->falseLit},
                      {"mean_abs", in.truth->meanAbs},
                      {"pixels", in.truth->count},
                      {"samples_per_pixel", in.truthSamples * in.truthSamples}};
        if (in.truthClasses) j["truth"].update(classesJson(*in.truthClasses));
        if (const auto& soft = in.softTruth) {
            // NaN figures go in as NaN: nlohmann writes them as null, as elsewhere in metrics.json.
            j["truth"]["soft_mean_abs"] = soft->meanAbs;
            j["truth"]["sun_angular_diameter_deg"] = soft->angularDiameterDeg;
            j["truth"]["sun_rays_per_pixel"] = soft->raysPerPixel;
            if (soft->penumbraWidthError) j["truth"]["penumbra_width_error"] = *soft->penumbraWidthError;
            if (soft->penumbraWidthErrorTruth)
                j["truth"]["penumbra_width_error_truth"] = *soft->penumbraWidthErrorTruth;
        }
        for (size_t s = 0; s < in.splitTruthClasses.size() && s < j["splits"].size(); ++s)
            j["splits"][s]["truth"] = classesJson(in.splitTruthClasses[s]);
        // Meshes the camera sees, by name; a repeated name gets "#index" so no mesh hides another.
        nlohmann::json meshes = nlohmann::json::object();
        for (size_t m = 0; m < in.meshTruthClasses.size() && m < in.meshNames.size(); ++m) {
            if (in.meshTruthClasses[m].count == 0) continue;
            std::string name = in.meshNames[m];
            if (meshes.contains(name)) name += "#" + std::to_string(m);
            meshes[name]["truth"] = classesJson(in.meshTruthClasses[m]);
        }
        j["meshes"] = std::move(meshes);
    }
    for (size_t s = 0; s < in.utilization.size() && s < j["splits"].size(); ++s)
        j["splits"][s]["utilization"] = in.utilization[s];
}

} // namespace geometry::analysis
