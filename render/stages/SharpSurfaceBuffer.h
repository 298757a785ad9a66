// The scene's sharp surfaces on the GPU (layout::GpuSharpSurface, read by
// shaders/common/sharp_surface_blocks.glsl): every object whose `surface` is
// sharp, in scene order, with the index offset its inside adds to the graded
// field. Spheres and boxes are exact shapes; a mesh or water surface is its
// tree of triangles, which the field buffers carry frame by frame
// (FieldTextures, FieldSet::surfaceNodes). Photons and camera rays refract
// and reflect there exactly; the voxelized fields hold none of their index
// (sim/voxelize/Compositor.h).
#pragma once

#include "bridge/layout/GpuLayouts.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "gl/ShaderLibrary.h"

#include <cstdint>
#include <vector>

namespace eikon::render {

// The scene's sharp objects as surfaces (empty when it has none; at most
// layout::kMaxSharpObjects, which the scene parser checks). Mesh and water surfaces
// get their root node: the k-th such object in scene order has node k.
std::vector<layout::GpuSharpSurface> buildSharpSurfaces(const Scene& scene);

// Whether a mesh or water surface (kSharpTriangles) is among `surfaces`.
bool hasTriangleSurfaces(const std::vector<layout::GpuSharpSurface>& surfaces);

class SharpSurfaceBuffer {
public:
    explicit SharpSurfaceBuffer(const Scene& scene);
    explicit SharpSurfaceBuffer(std::vector<layout::GpuSharpSurface> surfaces);

    unsigned count() const { return static_cast<unsigned>(surfaces_.size()); }
    bool empty() const { return surfaces_.empty(); }
    // The tracers' program option EIKON_SHARP_SURFACES: 0 none, 1 spheres
    // and boxes only, 2 meshes or water too. The triangle trees' traversal
    // is most of a tracer's compile on llvmpipe (docs/benchmarks-cpu.md), so
    // a scene without them does not compile it.
    gl::ShaderDefines::value_type kindsOption() const {
        return {"EIKON_SHARP_SURFACES", empty() ? "0" : (hasTriangleSurfaces(surfaces_) ? "2" : "1")};
    }
    const std::vector<layout::GpuSharpSurface>& surfaces() const { return surfaces_; }
    void bind() const;

private:
    std::vector<layout::GpuSharpSurface> surfaces_;
    gl::Buffer buffer_;
};

}  // namespace eikon::render
