// Receivers on the GPU: their geometry (layout::GpuReceiver, a uniform block
// of layout::kMaxReceivers), the photon pass's fixed-point power tallies per
// texel, and the filtered irradiance maps (shaders/receiver_filter.comp)
// the view passes read, all receivers packed into one buffer each. The
// views read the maps as a buffer texture: each pixel reads the texels
// where its ray landed, which a CPU rasterizer fetches for all lanes at
// once but would load from a storage buffer a lane and a float at a time
// (4 ms of the image-space view of pool_caustics on two cores).
#pragma once

#include "bridge/layout/GpuLayouts.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "gl/ShaderLibrary.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace eikon::render {

std::vector<layout::GpuReceiver> buildReceivers(const std::vector<ReceiverDesc>& receivers);

class ReceiverMaps {
public:
    explicit ReceiverMaps(const std::vector<ReceiverDesc>& receivers);

    unsigned count() const { return static_cast<unsigned>(receivers_.size()); }
    // The program option every shader that reads the receivers takes
    // (shaders/common/receiver_blocks.glsl): their count, a constant there.
    gl::ShaderDefines::value_type countOption() const { return {"EIKON_RECEIVERS", std::to_string(count())}; }
    // Texels of all receivers' maps together.
    unsigned texelCount() const { return texelCount_; }
    // Dispatches `program` (used) once per texel of all the
    // maps, numbered as common/caustic_deposits.glsl's
    // receiver_texel_of_invocation reads them; sets its uniform texel_count.
    void dispatchOverTexels(const gl::Program& program) const;
    const layout::GpuReceiver& receiver(unsigned i) const { return receivers_[i]; }
    void clearTallies() { tallies_.clearToZero(); }
    // The raw tallies, one 64-bit fixed-point number per texel and channel
    // (the shaders' low and high words), for a light pass shared among
    // processes (LightPassShare.h).
    std::vector<std::uint64_t> downloadTallies() const;
    void uploadTallies(const std::vector<std::uint64_t>& tallies);
    // The tallies of `other`, receivers of the same sizes, copied on the GPU.
    void copyTalliesFrom(const ReceiverMaps& other) { tallies_.copyFrom(other.tallies_); }
    void bind() const;
    // Turns the tallies into irradiance maps; powerUnit is W per tally unit.
    void filter(const glm::vec3& powerUnit);
    // Irradiance in W/m², RGB per texel, rows along axisV, texels along axisU.
    std::vector<float> download(unsigned receiver) const;

private:
    std::vector<layout::GpuReceiver> receivers_;
    // Per receiver: 1 the 3×3 binomial, 0 none, kAdaptiveKernel the
    // density-adaptive tent (shaders/receiver_filter.comp), each its own
    // program: a fixed kernel's loops unroll.
    static constexpr int kAdaptiveKernel = -1;
    std::vector<int> kernelRadius_;
    std::map<int, gl::Program> filterPrograms_;  // by kernel radius
    unsigned texelCount_ = 0;
    gl::Buffer geometry_;
    gl::Buffer tallies_;
    gl::Buffer maps_;
    gl::BufferTexture mapTexels_;    // maps_, read by the views
    gl::BufferTexture tallyTexels_;  // tallies_, read by the filter
};

}  // namespace eikon::render
