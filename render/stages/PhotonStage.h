// The photon pass (shaders/photon_trace.comp): emission, fixed-step Euler
// marching, Beer–Lambert attenuation, fluence and receiver deposits, and the
// frame's energy balance.
#pragma once

#include "bridge/scene/Scene.h"
#include "render/gl/GlObjects.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/ReceiverMaps.h"

#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace eikon::render {

struct PhotonSettings {
    long long photons = 1 << 20;
    unsigned seed = 1;
    double stepLength = 0.0;      // Δs in metres
    unsigned maxSteps = 0;        // trapped-ray cap
    double powerCutoff = 1e-4;    // relative to a photon's emitted power
    int recordPathVertices = 0;   // per recorded photon; 0 records nothing
    int recordedPhotons = 64;
};

// Where the emitted power went, in W per channel, and the step figures.
struct PhotonStats {
    Rgb emitted{0.0}, absorbed{0.0}, escaped{0.0}, received{0.0}, cutOff{0.0}, blocked{0.0};
    std::uint64_t photonsEscaped = 0, photonsReceived = 0, photonsCutOff = 0, photonsBlocked = 0;
    std::uint64_t steps = 0;
    double maxInvariantError = 0.0;  // max over photons and steps of | |v| − n | / n

    // |emitted − (absorbed + escaped + received + cutOff + blocked)| / emitted, worst channel.
    double balanceError() const;
};

class PhotonStage {
public:
    PhotonStage(const Scene& scene, const FieldTextures& fields, ReceiverMaps& receivers, int recordPathVertices = 0,
                int recordedPhotons = 64);

    PhotonStats run(const FieldTextures& fields, const PhotonSettings& settings);

    // Fluence φ (W/m², RGB per cell); empty buffer unless the scene scatters.
    const gl::Buffer& fluence() const { return fluence_; }
    // Recorded vertices (xyz, w = 1 where written) of the first photons.
    std::vector<glm::vec4> downloadPaths() const;

private:
    ReceiverMaps& receivers_;
    gl::Program program_;
    gl::Buffer emitters_;
    unsigned emitterCount_ = 0;
    glm::vec3 powerUnit_{0.0f};  // W per fixed-point tally unit, per channel
    gl::Buffer fluence_;
    gl::Buffer stats_;
    gl::Buffer paths_;
};

// Default trapped-ray cap: four crossings of the grid along all three axes.
unsigned defaultMaxSteps(const GridSpec& grid, double stepLength);

}  // namespace eikon::render
