// The sharp mesh and water surfaces of a scene as the tracers read them
// (FieldSet::surfaceNodes, surfaceTriangles; shaders/common/
// sharp_triangle_surfaces.glsl): each object's triangles in a
// bounding-volume hierarchy (bridge/mesh/TriangleBvh.h), built once for
// its topology and refitted to the deformed vertices every frame, and at
// each triangle corner the normal of the smooth surface the facets stand
// for: the mean of the normals of the corner's triangles that meet this
// one at less than kCreaseDegrees (bridge/mesh/Creases.h), weighted by
// their angles at the corner (Thürmer and Wüthrich 1998: unlike area
// weights, it does not depend on how the surface was cut into triangles).
// Triangles are exact: crossings lie on the mesh, and a
// step needs one traversal of the tree along its chord.
#pragma once

#include "bridge/mesh/TriangleBvh.h"
#include "bridge/mesh/TriangleMesh.h"

#include <cstddef>
#include <vector>

namespace eikon::sim {

class SharpMeshSurface {
public:
    explicit SharpMeshSurface(const TriangleMesh& mesh);

    std::size_t nodeCount() const { return bvh_.nodes().size(); }
    std::size_t triangleCount() const { return bvh_.order().size(); }
    // The tree (its topology: nodes' first and count, the leaf order), and
    // the triangles at each vertex: those of vertex v are
    // cornerTriangles()[cornerStart()[v] .. cornerStart()[v + 1]), for a
    // refit elsewhere (sim/gpu/GpuWaterBody.h).
    const TriangleBvh& bvh() const { return bvh_; }
    const std::vector<int>& cornerStart() const { return cornerStart_; }
    const std::vector<int>& cornerTriangles() const { return cornerTriangles_; }

    // Refits the tree to `mesh` (the topology it was built for) and writes
    // it: its root as node `root`, its other nodes from node `firstNode` on,
    // its triangles from triangle `firstTriangle` on (counted in nodes and
    // triangles of the FieldSet layout, into arrays large enough).
    void write(const TriangleMesh& mesh, std::size_t root, std::size_t firstNode, std::size_t firstTriangle,
               float* nodes, float* triangles);

private:
    TriangleBvh bvh_;
    std::vector<int> cornerStart_;
    std::vector<int> cornerTriangles_;
};

}  // namespace eikon::sim
