// Small scenes and a one-frame trace for the photon tests.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/mesh/TriangleMesh.h"
#include "bridge/scene/Scene.h"
#include "render/graph/FrameRenderer.h"
#include "render/stages/PhotonStage.h"

#include <glm/vec4.hpp>

#include <string>
#include <vector>

namespace eikon::test {

// A grid with no objects, lights or receivers, and a tiny image.
Scene emptyScene(glm::dvec3 boundsMin, glm::dvec3 boundsMax, int resolution);
ReceiverDesc floorReceiver(double y, double size, int resolution);
LightDesc directionalLight(glm::dvec3 direction, double irradiance);
// A point light of intensity 1 W/sr 1 m above the centre of a 1 m square
// receiver of 32² texels, in clear air on a 24³ grid.
Scene inverseSquareScene();

struct TraceResult {
    render::PhotonStats stats;
    std::vector<float> map;      // receiver 0, RGB per texel
    std::vector<float> fluence;  // RGB per cell, when stored
    std::vector<glm::vec4> paths;
    std::vector<glm::vec4> pathPower;  // RGB W at each recorded vertex
};

inline const TracerDesc::Integrator kIntegrators[] = {TracerDesc::Integrator::Euler, TracerDesc::Integrator::Leapfrog,
                                                      TracerDesc::Integrator::Rk4};
inline const char* const kIntegratorNames[] = {"euler", "leapfrog", "rk4"};

// Traces one frame of `fields`; every scene must balance its energy to 0.1%
// and write only finite values (checked here, as test expectations).
TraceResult traceFields(const Scene& scene, const FieldSet& fields, render::PhotonProgramOptions options = {});
// The same with every renderer option given (a photon stage is always made).
TraceResult traceFields(const Scene& scene, const FieldSet& fields, render::RendererOptions options);
// The same for the scene's own voxelized fields.
TraceResult trace(const Scene& scene, render::PhotonProgramOptions options = {});

double channelMean(const std::vector<float>& rgb, int channel);

// A sharp glass object of `index` whose shape is `mesh`, written as an OBJ
// file `name` into the test's temporary folder.
ObjectDesc meshObject(const TriangleMesh& mesh, const std::string& name, double index);

}  // namespace eikon::test
