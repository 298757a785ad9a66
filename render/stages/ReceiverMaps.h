// Receivers on the GPU: their geometry (layout::GpuReceiver) and one
// irradiance map each, packed into a single buffer the photon pass fills and
// the view pass reads.
#pragma once

#include "bridge/layout/GpuLayouts.h"
#include "bridge/scene/Scene.h"
#include "render/gl/GlObjects.h"

#include <vector>

namespace eikon::render {

std::vector<layout::GpuReceiver> buildReceivers(const std::vector<ReceiverDesc>& receivers);

class ReceiverMaps {
public:
    explicit ReceiverMaps(const std::vector<ReceiverDesc>& receivers);

    unsigned count() const { return static_cast<unsigned>(receivers_.size()); }
    const layout::GpuReceiver& receiver(unsigned i) const { return receivers_[i]; }
    void clear() { maps_.clearToZero(); }
    void bind() const;
    // Irradiance in W/m², RGB per texel, rows along axisV, texels along axisU.
    std::vector<float> download(unsigned receiver) const;

private:
    std::vector<layout::GpuReceiver> receivers_;
    gl::Buffer geometry_;
    gl::Buffer maps_;
};

}  // namespace eikon::render
