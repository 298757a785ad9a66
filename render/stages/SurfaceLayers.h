// What a viewpoint sees of the scene's sharp surfaces, drawn with the raster
// pipeline ([Hu07] §2.1; [Wyman05]'s two-sided refraction): the nearest
// surfaces, and by depth peeling the next surfaces behind them, each texel
// holding normal, distance and surface number (shaders/common/
// surface_layers.glsl). Spheres and boxes are drawn from their tessellation
// (ShapeTriangles.h), meshes from the triangles the field buffers carry,
// frame by frame, and a water body as its hull, in which each fragment
// finds the body's surface on its height field (WaterHeightFields.h): a
// pool's 40 000 triangles cost a CPU rasterizer's single thread of vertex
// work more than 20 ms a frame. The image-space camera view and
// caustics read these layers to find where a ray leaves a refractor.
#pragma once

#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "gl/RasterTarget.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/SharpSurfaceBuffer.h"
#include "render/stages/WaterHeightFields.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace eikon::render {

struct Viewpoint {
    glm::mat4 viewProjection{1.0f};
    glm::vec3 eye{0.0f};   // perspective: the eye; orthographic: a point of the near plane
    glm::vec3 axis{0.0f};  // orthographic: the direction of view
    bool orthographic = false;
};

// The camera's viewpoint: the pinhole of ViewStage's cameraBlock, its
// texel (x, H−1−y) the image's pixel (x, y).
Viewpoint cameraViewpoint(const CameraDesc& camera, const RenderDesc& render, double nearPlane, double farPlane);

class SurfaceLayers {
public:
    SurfaceLayers(int width, int height, const gl::GpuResource& resource);
    int width() const { return near_.width(); }
    int height() const { return near_.height(); }
    void bind() const;  // near layer → kNearLayerTexture, far layer → kFarLayerTexture
    // Draws and is read in its first edge × edge texels only (LightFrames.h).
    void useCorner(int edge) {
        near_.useCorner(edge, edge);
        far_.useCorner(edge, edge);
    }

private:
    friend class SurfaceRaster;
    gl::RasterTarget near_, far_;
};

class SurfaceRaster {
public:
    explicit SurfaceRaster(const Scene& scene);
    // Draws the layers of `layers` as `view` sees the surfaces now: the
    // near, and the far where a surface other than water is there.
    void draw(const Viewpoint& view, SurfaceLayers& layers, const FieldTextures& fields);
    // Gathers the water's height fields from `fields` as `draw` does, for
    // passes that walk them with no layers drawn.
    void updateWater(const FieldTextures& fields) { water_.update(fields); }
    // Binds what the passes reading the layers need of the surfaces: their
    // shapes and optics (kSharpSurfaces), the extinction inside each and
    // its water body (kImageSpaceSurfaces), and the water's height fields
    // as last gathered.
    void bindSurfaces() const;
    // Whether `view` may draw the surfaces by their faces toward it alone on
    // the near layer and away from it on the far. So it may when the
    // scene's surfaces are all spheres, boxes and water bodies (closed, and
    // wound counter-clockwise seen from outside), none within another's
    // bounds, and the viewpoint is outside every one of them: along any ray
    // the faces it crosses then alternate toward and away, so the first two
    // are one surface's entry and exit, and a sphere's facets toward the
    // viewpoint, enclosing it, cover its entries. An orthographic viewpoint
    // (a directional light's) always is outside: its near plane lies before
    // all the refractors. A CPU rasterizer then shades half the fragments.
    bool drawsFacingFaces(const Viewpoint& view) const;
    // Whether a sharp surface other than water is there
    // (WaterHeightFields::hasLayerSurfaces): exits are then searched in the
    // layers, which reads the far layer and the viewpoint's view_projection.
    bool hasLayerSurfaces() const { return layerSurfaces_; }

private:
    void drawTriangles(const gl::Program& program, const Viewpoint& view, std::size_t triangles,
                       const gl::BufferTexture& texels, const std::vector<int>& surfaceOfOrdinal) const;

    SharpSurfaceBuffer surfaces_;
    gl::Buffer extinction_;  // per sharp surface, κ rgb (1/m) inside it; w its water body, or −1
    WaterHeightFields water_;
    bool layerSurfaces_;  // WaterHeightFields::hasLayerSurfaces: the far layer is drawn
    // [0: meshes; 1: exact shapes, spheres and boxes; 2: water hulls][0:
    // near layer; 1: far, peeled behind the near; 2: far, the faces away
    // alone (water: none, its peel always reads the near layer)]
    gl::Program programs_[3][3];
    gl::EmptyVertexArray vertexArray_;
    gl::Buffer shapes_;                     // the spheres' and boxes' triangles
    gl::BufferTexture shapeTexels_;         // the same, read by the vertex shader
    std::vector<int> shapeSurfaces_;        // identity: a shape's w is its surface number
    std::vector<int> meshSurfaces_;         // the k-th mesh's surface number
    std::size_t waterTriangles_ = 0;        // the water bodies', which follow the meshes' (sim/SceneFields)
    gl::Buffer waterHulls_;                 // the water bodies' hulls' triangles
    gl::BufferTexture waterHullTexels_;
    std::vector<int> waterSurfaces_;        // the k-th water body's surface number
    std::vector<int> waterOfSurface_;       // a surface's water body, or −1
    // The spheres' hulls', the boxes' and the water bodies' bounds, where
    // the scene's surfaces are all of these and apart; empty otherwise.
    std::vector<BoxShape> apartShapeBounds_;
};

}  // namespace eikon::render
