// A water object's frames made on the GPU (shaders/sim/water_*.comp): the
// damped wave equation of its height field (sim/deform/WaterSurface.h), the
// triangles and tree of its sharp surface in FieldSet's layout
// (sim/SharpMeshSurfaces.h), and its coverage of the render grid with the
// attenuation it paints (sim/voxelize/HeightFieldCoverage.h and
// Compositor.h's paintObjects), each repeating the host's arithmetic in
// float64 where the host uses it. After its construction nothing crosses
// between host and GPU: the renderer copies these buffers into its own on
// the GPU.
//
// It takes the place of the host path for a scene whose only object is a
// water body with a sharp surface (`fits`); the host keeps frame 0's fields.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "bridge/mesh/TriangleBvh.h"
#include "sim/deform/WaterSurface.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace eikon::sim::gpu {

// The water body's sharp surface as sim/SharpMeshSurfaces.h keeps it: its
// tree, the triangles at each vertex (those of vertex v are
// cornerTriangles[cornerStart[v] .. cornerStart[v + 1])), and the cosine of
// the crease angle within which corner normals are smoothed.
struct SharpSurfaceTopology {
    const TriangleBvh& bvh;
    const std::vector<int>& cornerStart;
    const std::vector<int>& cornerTriangles;
    double creaseCosine;
};

class GpuWaterBody {
public:
    // Disturbances that may push at once (the step pass's uniforms).
    static constexpr int kMaxMovers = 8;

    // Why `scene` cannot keep its water on the GPU, or "" when it can: its
    // only object is a water body with a sharp surface, with at most
    // kMaxMovers disturbances, under no fluid solver, volume or paint, and
    // no field is exported (exports read the host's fields).
    static std::string unfit(const Scene& scene);

    // Takes over `water` at time 0. `surface` is its sharp surface,
    // `frame0` the scene's fields at time 0 (the layout
    // of the surface arrays, the fields present), `medium` the fields under
    // the water (the medium alone). Writes frame 0's outputs.
    GpuWaterBody(const ObjectDesc& object, const WaterSurface& water, const SharpSurfaceTopology& surface,
                 const FieldSet& frame0, const FieldSet& medium);
    ~GpuWaterBody();
    GpuWaterBody(const GpuWaterBody&) = delete;
    GpuWaterBody& operator=(const GpuWaterBody&) = delete;

    // GL timer queries around the passes of one advanceTo, ms.
    struct PassTimes {
        double surface = 0.0;   // the steps and the surface ("deform")
        double coverage = 0.0;  // the coverage and attenuation ("voxelize")
    };

    // Steps to `time`, s, as WaterSurface::advanceTo does (drops applied
    // when their time comes, disturbances pushing while active), then
    // writes the surface and, with `coverage`, the attenuation.
    PassTimes advanceTo(double time, bool coverage);
    double time() const { return time_; }

    // The outputs, in FieldSet's layouts (0 where the scene lacks the field).
    const gl::Buffer& surfaceNodes() const { return surfaceNodes_; }
    const gl::Buffer& surfaceTriangles() const { return surfaceTriangles_; }
    GLuint extinction() const { return painted_[0].painted.id(); }
    GLuint scattering() const { return painted_[1].painted.id(); }
    GLuint anisotropy() const { return painted_[2].painted.id(); }

    // The bytes its construction uploaded: the initial heights and the
    // tables of the surface and the medium (frame 0's share of the bus).
    std::uint64_t setupBytes() const { return setupBytes_; }
    // h^n per node, read back (tests).
    std::vector<double> downloadHeights() const;

private:
    void step(double dt);
    void writeSurface();
    void writeCoverage();

    WaterDesc desc_;
    Material material_;
    GridSpec grid_;
    double time_ = 0.0;
    double stableStep_;  // WaterSurface::stableStep
    std::vector<bool> dropApplied_;
    int nodeCount_ = 0, triangleCount_ = 0;
    gl::Buffer height_[2], velocity_, vertices_, triangles_, slots_, cornerStart_, corners_, faceNormals_,
        faceAngles_, treeNodes_, levelNodes_, surfaceNodes_, surfaceTriangles_;
    std::vector<gl::Buffer> drops_;
    std::vector<int> levelFirst_;  // level d's nodes: levelNodes_[levelFirst_[d] .. levelFirst_[d + 1])
    // An attenuation field the water paints: the values under the water, and the painted ones.
    struct PaintedField {
        gl::Buffer base, painted;
        GLuint baseBinding = 0, paintedBinding = 0;
    };
    std::array<PaintedField, 3> painted_;  // κ, σs, g
    std::uint64_t setupBytes_ = 0;
    int current_ = 0;  // height_[current_] holds h^n
    std::array<GLuint, 3> timestamps_{};  // before the steps, after the surface, after the coverage
    gl::Program step_, drop_, faces_, cornerNormals_, refit_, coverage_;
};

}  // namespace eikon::sim::gpu
