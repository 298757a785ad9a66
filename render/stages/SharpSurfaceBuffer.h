// The scene's sharp surfaces on the GPU (layout::GpuSharpSurface, read by
// shaders/common/sharp_surface_blocks.glsl): every object whose `surface` is
// sharp, in scene order, with the index offset its inside adds to the graded
// field. Spheres and boxes are exact shapes; a mesh or water surface is its
// layer of signed distance in the field textures, with bounds that follow
// the deforming mesh frame by frame. Photons and camera rays refract and
// reflect there exactly; the voxelized fields hold none of their index
// (sim/voxelize/Compositor.h).
#pragma once

#include "bridge/layout/GpuLayouts.h"
#include "bridge/scene/Scene.h"
#include "render/gl/GlObjects.h"
#include "render/stages/FieldTextures.h"

#include <cstdint>
#include <vector>

namespace eikon::render {

// The scene's sharp objects as surfaces (empty when it has none; at most
// kMaxSharpObjects, which the scene parser checks). Distance surfaces get
// their layer, in scene order; their bounds are set by SharpSurfaceBuffer.
std::vector<layout::GpuSharpSurface> buildSharpSurfaces(const Scene& scene);

class SharpSurfaceBuffer {
public:
    explicit SharpSurfaceBuffer(const Scene& scene);

    unsigned count() const { return static_cast<unsigned>(surfaces_.size()); }
    bool empty() const { return surfaces_.empty(); }
    // Brings the distance surfaces' bounds up to date with `fields` and binds
    // the buffer and the distance layers.
    void bind(const FieldTextures& fields);

private:
    std::vector<layout::GpuSharpSurface> surfaces_;
    gl::Buffer buffer_;
    std::uint64_t boundsVersion_ = ~0ull;
};

}  // namespace eikon::render
