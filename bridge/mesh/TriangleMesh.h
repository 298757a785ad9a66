// A triangle mesh as plain data: the form in which meshes cross from the
// reader and the deformers (sim/deform) to the voxelizer and to exporters.
// Triangles index `vertices`; a closed mesh has every edge shared by exactly
// two triangles. Orientation is not relied on (the voxelizer decides inside
// and outside by the parity of row crossings, not by winding).
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace eikon {

struct TriangleMesh {
    std::vector<glm::dvec3> vertices;   // metres, world frame once placed
    std::vector<glm::ivec3> triangles;  // indices into vertices, each in [0, vertices.size())
};

// Edges counted by how many triangles share them (an edge is an unordered
// vertex pair): open edges have one, non-manifold edges more than two.
struct EdgeCensus {
    std::size_t edges = 0;
    std::size_t open = 0;
    std::size_t nonManifold = 0;
    bool closedManifold() const { return open == 0 && nonManifold == 0; }
};

EdgeCensus countEdges(const TriangleMesh& mesh);

// Signed volume enclosed by a closed mesh (divergence theorem), m³; positive
// when the triangles wind counter-clockwise seen from outside.
double enclosedVolume(const TriangleMesh& mesh);

// Axis-aligned bounds of the vertices; min > max when there are none.
void vertexBounds(const TriangleMesh& mesh, glm::dvec3& min, glm::dvec3& max);

}  // namespace eikon
