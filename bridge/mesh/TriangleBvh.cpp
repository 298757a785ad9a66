#include "bridge/mesh/TriangleBvh.h"

#include "bridge/core/Error.h"

#include <glm/common.hpp>

#include <algorithm>

namespace eikon {

namespace {

glm::dvec3 centroid(const TriangleMesh& mesh, int triangle) {
    const glm::ivec3& t = mesh.triangles[static_cast<std::size_t>(triangle)];
    return (mesh.vertices[t.x] + mesh.vertices[t.y] + mesh.vertices[t.z]) / 3.0;
}

}  // namespace

TriangleBvh::TriangleBvh(const TriangleMesh& mesh) {
    EIKON_CHECK_MSG(!mesh.triangles.empty(), "a bounding-volume hierarchy of no triangles");
    order_.resize(mesh.triangles.size());
    for (std::size_t t = 0; t < order_.size(); ++t) order_[t] = static_cast<int>(t);
    nodes_.reserve(2 * (mesh.triangles.size() / kLeafTriangles + 1));
    nodes_.emplace_back();
    build(mesh, 0, static_cast<int>(order_.size()), 0);
    refit(mesh);
}

// Splits order_[begin, end) below `node`; children are appended in pairs.
int TriangleBvh::build(const TriangleMesh& mesh, int begin, int end, int node) {
    if (end - begin <= kLeafTriangles) {
        nodes_[static_cast<std::size_t>(node)].first = begin;
        nodes_[static_cast<std::size_t>(node)].count = end - begin;
        return node;
    }
    glm::dvec3 low(centroid(mesh, order_[static_cast<std::size_t>(begin)])), high(low);
    for (int i = begin; i < end; ++i) {
        const glm::dvec3 c = centroid(mesh, order_[static_cast<std::size_t>(i)]);
        low = glm::min(low, c);
        high = glm::max(high, c);
    }
    const glm::dvec3 extent = high - low;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const int middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](int a, int b) { return centroid(mesh, a)[axis] < centroid(mesh, b)[axis]; });
    const int left = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    nodes_.emplace_back();
    nodes_[static_cast<std::size_t>(node)].first = left;
    nodes_[static_cast<std::size_t>(node)].count = 0;
    build(mesh, begin, middle, left);
    build(mesh, middle, end, left + 1);
    return node;
}

void TriangleBvh::refit(const TriangleMesh& mesh) {
    EIKON_CHECK_MSG(mesh.triangles.size() == order_.size(), "refit with another topology");
    // Children always follow their parent, so a backward sweep meets them first.
    for (std::size_t n = nodes_.size(); n-- > 0;) {
        Node& node = nodes_[n];
        if (node.count > 0) {
            node.min = glm::dvec3(1e300);
            node.max = glm::dvec3(-1e300);
            for (int i = node.first; i < node.first + node.count; ++i) {
                const glm::ivec3& t = mesh.triangles[static_cast<std::size_t>(order_[static_cast<std::size_t>(i)])];
                for (int corner = 0; corner < 3; ++corner) {
                    node.min = glm::min(node.min, mesh.vertices[static_cast<std::size_t>(t[corner])]);
                    node.max = glm::max(node.max, mesh.vertices[static_cast<std::size_t>(t[corner])]);
                }
            }
        } else {
            const Node& a = nodes_[static_cast<std::size_t>(node.first)];
            const Node& b = nodes_[static_cast<std::size_t>(node.first) + 1];
            node.min = glm::min(a.min, b.min);
            node.max = glm::max(a.max, b.max);
        }
    }
}

}  // namespace eikon
