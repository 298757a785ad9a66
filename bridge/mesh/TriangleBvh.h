// A bounding-volume hierarchy over a mesh's triangles, for finding where a
// ray segment first meets the mesh (shaders/common/sharp_triangle_surfaces.glsl).
//
// The tree is built once per topology, by splitting the triangles at the
// median of their centroids along the longest axis of the centroids' bounds
// until a leaf holds at most kLeafTriangles; a deforming mesh keeps the tree
// and only refits the boxes to its new vertices each frame (O(triangles),
// no sorting), which keeps a tree valid for any motion and tight for the
// smooth motions of deformers and water.
//
// Node 0 is the root. An interior node's children are nodes `first` and
// `first + 1` (never 0); a leaf holds the triangles order[first ...
// first + count).
#pragma once

#include "bridge/mesh/TriangleMesh.h"

#include <glm/vec3.hpp>

#include <vector>

namespace eikon {

class TriangleBvh {
public:
    static constexpr int kLeafTriangles = 4;

    struct Node {
        glm::dvec3 min{0.0}, max{0.0};
        int first = 0;  // interior: the first child; leaf: the first entry of order()
        int count = 0;  // triangles in a leaf; 0 for an interior node
    };

    // The tree of `mesh`'s triangles at their current positions (at least one).
    explicit TriangleBvh(const TriangleMesh& mesh);

    // Refits every box to `mesh`, which must have the topology the tree was
    // built for (same triangles, any vertex positions).
    void refit(const TriangleMesh& mesh);

    const std::vector<Node>& nodes() const { return nodes_; }
    // Triangle indices of `mesh` in leaf order.
    const std::vector<int>& order() const { return order_; }

private:
    int build(const TriangleMesh& mesh, int begin, int end, int node);

    std::vector<Node> nodes_;
    std::vector<int> order_;
};

}  // namespace eikon
