// Closed triangle meshes of simple solids, generated to a given fineness:
// test and benchmark subjects for the voxelizer and the deformers, with
// triangles counter-clockwise seen from outside.
#pragma once

#include "bridge/mesh/TriangleMesh.h"

namespace eikon::sim {

// Latitude–longitude sphere: `rings` bands by `segments` slices, 2·segments·(rings − 1) triangles.
TriangleMesh sphereMesh(const glm::dvec3& centre, double radius, int rings, int segments);

// Torus about the y axis: major radius R (centre to tube centre), minor radius r.
TriangleMesh torusMesh(const glm::dvec3& centre, double majorRadius, double minorRadius, int majorSegments,
                       int minorSegments);

// Box [min, max] with each face split into a grid of cells·cells quads (two triangles each).
TriangleMesh boxMesh(const glm::dvec3& min, const glm::dvec3& max, const glm::ivec3& cells);

}  // namespace eikon::sim
