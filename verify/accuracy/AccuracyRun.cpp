#include "verify/accuracy/AccuracyRun.h"

#include "render/graph/FrameRenderer.h"
#include "verify/reference/AnalyticFields.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace eikon::accuracy {

const char* integratorName(TracerDesc::Integrator integrator) {
    switch (integrator) {
        case TracerDesc::Integrator::Euler: return "euler";
        case TracerDesc::Integrator::Leapfrog: return "leapfrog";
        case TracerDesc::Integrator::Rk4: return "rk4";
    }
    return "?";
}

const char* stepPolicyName(TracerDesc::StepPolicy policy) {
    return policy == TracerDesc::StepPolicy::Uniform ? "uniform" : "octree";
}

const char* methodName(RenderDesc::Method method) {
    return method == RenderDesc::Method::ImageSpace ? "image_space" : "eikonal";
}

GpuTrace traceOnGpu(const Scene& scene, const FieldSet& fields, TraceRequest request) {
    render::RendererOptions options;
    options.tracePhotons = true;
    options.photons.recordPathVertices = request.pathVertices;
    options.photons.recordedPhotons = request.recordedPhotons;
    options.photons.recordStride = request.recordStride;
    render::FrameRenderer renderer(scene, fields, options);
    renderer.render(fields);  // compiles, uploads, prepares and traces once
    GpuTrace trace;
    // The faster of two relights: the machine is shared, and the slower one
    // measures the neighbours. Same seed, so the same photons both times.
    trace.runtimeSeconds = renderer.relight(trace.stats).milliseconds / 1000.0;
    trace.runtimeSeconds = std::min(trace.runtimeSeconds, renderer.relight(trace.stats).milliseconds / 1000.0);
    if (!scene.receivers.empty()) trace.receiverMap = renderer.receivers().download(0);
    if (request.pathVertices > 0) {
        const std::vector<glm::vec4> vertices = renderer.photonStage()->downloadPaths();
        const std::size_t capacity = static_cast<std::size_t>(request.pathVertices);
        for (std::size_t photon = 0; photon < static_cast<std::size_t>(request.recordedPhotons); ++photon) {
            PhotonPath path;
            for (std::size_t v = 0; v < capacity && vertices[photon * capacity + v].w == 1.0f; ++v)
                path.emplace_back(vertices[photon * capacity + v]);
            if (path.size() == capacity) {
                ++trace.truncatedPaths;  // the end of the path was not recorded
                continue;
            }
            trace.paths.push_back(std::move(path));
            trace.pathIndex.push_back(static_cast<int>(photon));
        }
    }
    return trace;
}

ImageSpaceFrame renderImageSpace(const Scene& scene) {
    const bool caustics = !scene.receivers.empty();
    // Image space draws the scene's sharp objects in a medium of uniform index.
    const FieldSet fields =
        sampleIndexField(reference::UniformField(scene.medium.index), scene.grid.spec(), scene.medium.index);
    render::RendererOptions options;
    options.recordViewExits = !caustics;
    options.drawsImage = !caustics;
    options.temporalMean = false;  // each frame times the caustic maps drawn anew
    render::FrameRenderer renderer(scene, fields, options);
    renderer.render(fields);  // compiles, uploads and draws once
    ImageSpaceFrame frame;
    frame.runtimeSeconds = std::numeric_limits<double>::infinity();
    for (int run = 0; run < 2; ++run) {
        if (caustics) renderer.setLight(0, scene.lights[0]);
        else renderer.setCamera(scene.camera);
        double seconds = 0.0;
        for (const render::StageReport& stage : renderer.render(fields).stages)
            if (stage.ran && stage.name != "post") seconds += stage.milliseconds / 1000.0;  // the tone map is not timed
        frame.runtimeSeconds = std::min(frame.runtimeSeconds, seconds);
    }
    if (caustics) frame.receiverMap = renderer.receivers().download(0);
    else frame.exits = renderer.imageSpaceView()->downloadExits();
    return frame;
}

FieldSet sampleIndexField(const reference::IndexField& field, const GridSpec& grid, double referenceIndex) {
    FieldSet fields;
    fields.grid = grid;
    fields.referenceIndex = referenceIndex;
    fields.deltaIndex.resize(grid.cellCount());
    for (int k = 0; k < grid.resolution.z; ++k)
        for (int j = 0; j < grid.resolution.y; ++j)
            for (int i = 0; i < grid.resolution.x; ++i)
                fields.deltaIndex[grid.linearIndex(i, j, k)] =
                    static_cast<float>(field.index(grid.cellCentre(i, j, k)) - referenceIndex);
    fields.indexVersion = 1;
    return fields;
}

void applySettings(Scene& scene, const RunSettings& settings, glm::ivec3 baseResolution) {
    scene.grid.resolution = glm::max(glm::ivec3(1), glm::ivec3(glm::round(glm::dvec3(baseResolution) * settings.gridScale)));
    scene.grid.smoothingSigmaVoxels = 0.0;  // analytic fields carry their own smoothing
    scene.tracer.integrator = settings.integrator;
    scene.tracer.stepPolicy = settings.stepPolicy;
    scene.tracer.stepVoxels = settings.stepVoxels;
    scene.tracer.maxStepVoxels = std::max(settings.maxStepVoxels, settings.stepVoxels);
    scene.tracer.epsilon = settings.epsilon;
    scene.tracer.epsilonPrime = std::max(settings.epsilonPrime, settings.epsilon);
    if (settings.photons > 0) scene.render.photons = settings.photons;
    scene.tracer.estimator = settings.estimator;
    scene.tracer.wavefront.splitTexels = settings.splitTexels;
    if (settings.estimator == TracerDesc::Estimator::Wavefront)
        for (ReceiverDesc& receiver : scene.receivers) receiver.filter = ReceiverDesc::Filter::None;
}

glm::dvec3 linePlaneIntersection(const glm::dvec3& p, const glm::dvec3& d, const glm::dvec3& point,
                                 const glm::dvec3& normal) {
    return p + (glm::dot(point - p, normal) / glm::dot(d, normal)) * d;
}

}  // namespace eikon::accuracy
