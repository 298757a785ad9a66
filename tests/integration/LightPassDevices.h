// The light pass of one frame on a chosen render.device, as the device
// tests compare it: the frame's photon figures, the receiver tallies as
// integers, and the device the "photons" stage reports with its reason.
#pragma once

#include "gl/GlContext.h"
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace eikon::test {

struct LightPassOutputs {
    render::PhotonStats stats;
    std::vector<std::uint64_t> tallies;  // receiver texels, per channel, in power units
    render::StageDevice device = render::StageDevice::Gpu;
    std::string deviceReason;
};

inline LightPassOutputs traceLightPass(Scene scene, ComputeDevice device) {
    glContext();
    scene.render.device = device;
    const FieldSet fields = sim::voxelizeScene(scene);
    render::RendererOptions options;
    options.drawsImage = false;
    render::FrameRenderer renderer(scene, fields, options);
    const render::FrameResult frame = renderer.render(fields);
    const auto photons = std::find_if(frame.stages.begin(), frame.stages.end(),
                                      [](const render::StageReport& stage) { return stage.name == "photons"; });
    EXPECT_NE(photons, frame.stages.end());
    LightPassOutputs out;
    if (photons != frame.stages.end()) {
        EXPECT_TRUE(photons->ran);
        out.device = photons->device;
        out.deviceReason = photons->deviceReason;
    }
    out.stats = frame.photons;
    out.tallies = renderer.receivers().downloadTallies();
    return out;
}

// Whether OpenGL renders on the CPU here (llvmpipe, as in CI), where the
// two devices' figures are asserted to be the same integers.
inline bool rendersOnCpu() {
    gl::GlInfo renderer;
    renderer.renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return renderer.rendersOnCpu();
}

}  // namespace eikon::test
