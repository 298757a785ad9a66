// The scene's sharp spheres and boxes as triangles for the raster pipeline
// (the image-space passes), in the layout of the sharp meshes' triangles
// (bridge/grid/FieldSet.h: three corners, then three corner normals, each a
// vec4), the first corner's w holding the shape's number among the scene's
// sharp surfaces (SharpSurfaceBuffer.h). A sphere is an octahedron
// subdivided kSphereSubdivisions times with its corners pushed out to
// kSphereHullScale radii, so that its facets hold the sphere (the raster
// pass then meets the sphere itself in every fragment,
// shaders/surface_layers.frag); a box is its twelve triangles with face
// normals. Every triangle winds counter-clockwise seen from outside its
// shape, so the raster pipeline can tell the faces toward a viewpoint.
#pragma once

#include "bridge/scene/Scene.h"

#include <vector>

namespace eikon::render {

// 8·4⁵ = 8192 triangles, each within 3.2° of its centre on the sphere.
constexpr int kSphereSubdivisions = 5;
// 1/cos 3.2°, rounded up: every facet's plane lies outside the sphere.
constexpr double kSphereHullScale = 1.0016;

std::vector<float> shapeTriangles(const Scene& scene);

// The box that holds a water body however its waves rise: its basin, up to
// a basin's depth above the rest level.
BoxShape waterHull(const WaterDesc& water);

// The hulls of the scene's sharp water bodies as the boxes' triangles, the
// first corner's w holding the body's number among them
// (render/stages/WaterHeightFields.h): the raster pass meets the water's
// height field in each fragment (shaders/surface_layers.frag).
std::vector<float> waterHullTriangles(const Scene& scene);

}  // namespace eikon::render
