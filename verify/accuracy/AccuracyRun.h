// One accuracy run: the tracer knobs it sweeps, the GPU trace it times, and
// the error it measured against ground truth (a closed form or the reference
// tracer, verify/reference).
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/scene/Scene.h"
#include "verify/reference/IndexField.h"
#include "render/stages/PhotonStage.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <map>
#include <string>
#include <vector>

namespace eikon::accuracy {

// The knobs of one run (Scene's TracerDesc and GridDesc, in voxels).
struct RunSettings {
    TracerDesc::Integrator integrator = TracerDesc::Integrator::Leapfrog;
    TracerDesc::StepPolicy stepPolicy = TracerDesc::StepPolicy::Uniform;
    double stepVoxels = 0.5;         // uniform Δs, or the octree's Δs_min
    double maxStepVoxels = 8.0;      // octree step cap
    double epsilon = 0.002, epsilonPrime = 0.002;
    double gridScale = 1.0;          // resolution relative to the case's base grid
    double smoothingVoxels = 0.0;    // width of the case's interface smoothing, where it has one
    long long photons = 0;           // 0: the case's default
    // The light pass: photons, or the wavefront with this refinement
    // (tracer.wavefront.split_texels); receiver cases only.
    TracerDesc::Estimator estimator = TracerDesc::Estimator::Photons;
    double splitTexels = 1.5;
    // How the light and the view are formed (render.method). Image space has
    // none of the knobs above; its own is the size of what it rasterizes:
    // the caustic map's edge (render.caustic_map_texels) or the camera
    // image's (render.width = height).
    RenderDesc::Method method = RenderDesc::Method::Eikonal;
    int causticMapTexels = 0;
    int imagePixels = 0;
    // Which knob this run varies: step, grid, smoothing, photons, octree,
    // wavefront; caustic_map, view (image space).
    std::string sweep = "step";
};

const char* integratorName(TracerDesc::Integrator integrator);
const char* stepPolicyName(TracerDesc::StepPolicy policy);
const char* methodName(RenderDesc::Method method);  // as render.method spells it

// Error of one run by one measure.
struct Measurement {
    std::string caseName;
    std::string metric;                // what `error` is, in words
    double error = 0.0;                // dimensionless (relative) error
    double errorVoxels = -1.0;         // the same as a length in voxels, where it is one; < 0: not a length
    int samples = 0;                   // photons (or texels) the error was taken over
};

struct RunRecord {
    RunSettings settings;
    std::string grid;                  // e.g. 64x64x64
    long long photons = 0;
    double runtimeSeconds = 0.0;       // the photon pass, faster of two relights after a first frame, wall time with glFinish
    render::PhotonStats stats;
    Measurement measurement;
    // Uniform steps: each recorded photon's position (in voxels) and unit
    // tangent at a fixed arc length s from where it starts in the grid —
    // vertex s/Δs, no interpolation — for the self-convergence of the step.
    struct ArcSample {
        glm::dvec3 position, tangent;
    };
    std::map<int, ArcSample> positionsAtArc;
    // RMS distance of those positions from the same photons' paths in the
    // finest-step RK4 run on the same grid and field, across that path (along
    // it the arc-length label may drift: leapfrog steps dσ = Δs/n with n from
    // the step's start); the integrator's own error, free of the grid's floor.
    // < 0 where not measured.
    double stepErrorVoxels = -1.0;
};

// A photon's recorded vertices, in order (emission point first).
using PhotonPath = std::vector<glm::dvec3>;

struct GpuTrace {
    render::PhotonStats stats;
    double runtimeSeconds = 0.0;
    std::vector<float> receiverMap;    // receiver 0, RGB per texel, if any
    std::vector<PhotonPath> paths;     // complete paths of the recorded photons (truncated ones dropped)
    std::vector<int> pathIndex;        // which recorded photon each path is (the same photon in every run)
    int truncatedPaths = 0;
};

struct TraceRequest {
    int recordedPhotons = 0;
    int pathVertices = 0;              // capacity per recorded photon
    int recordStride = 1;              // record every stride-th photon (spreads them over a stratified emitter)
};

// Traces `fields` on the GPU (the current OpenGL context): one frame, then
// two timed relights, keeping the faster (photon pass only; shader
// compilation and the per-frame prepare and step-structure stages are not
// timed). Same seed: same photons.
GpuTrace traceOnGpu(const Scene& scene, const FieldSet& fields, TraceRequest request = {});

// One image-space frame (render.method "image_space") of `scene`, timed as
// the eikonal traces are: a first frame (compilation, upload), then two
// frames after touching what the measure needs drawn anew, keeping the
// faster one's stages (the tone map not timed) — with receivers, the light
// (the caustic maps: one frame of their temporal mean,
// ImageSpaceCaustics); without, the camera (the view, ImageSpaceView).
struct ImageSpaceFrame {
    double runtimeSeconds = 0.0;
    std::vector<float> receiverMap;   // receiver 0, RGB per texel, if any
    std::vector<glm::vec4> exits;     // without receivers: each pixel's exit direction
};
ImageSpaceFrame renderImageSpace(const Scene& scene);

// δn = n − n_ref of `field` sampled at the cell centres of `grid`.
FieldSet sampleIndexField(const reference::IndexField& field, const GridSpec& grid, double referenceIndex);

// The scene's tracer and grid set from `settings` (resolution: base × gridScale).
void applySettings(Scene& scene, const RunSettings& settings, glm::ivec3 baseResolution);

// Where the line x(t) = p + t·d meets the plane through `point` with `normal`.
glm::dvec3 linePlaneIntersection(const glm::dvec3& p, const glm::dvec3& d, const glm::dvec3& point,
                                 const glm::dvec3& normal);

}  // namespace eikon::accuracy
