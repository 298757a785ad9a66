#include "sim/SharpMeshSurfaces.h"

#include "bridge/core/Error.h"
#include "bridge/grid/FieldSet.h"
#include "bridge/mesh/Creases.h"

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace eikon::sim {

namespace {

// Node and triangle indices travel as floats, exact below 2²⁴.
constexpr std::size_t kLargestIndex = std::size_t{1} << 24;

const glm::dvec3& corner(const TriangleMesh& mesh, int triangle, int c) {
    return mesh.vertices[static_cast<std::size_t>(mesh.triangles[static_cast<std::size_t>(triangle)][c])];
}

// The unit normal of a triangle (zero for a degenerate one).
glm::dvec3 unitNormal(const TriangleMesh& mesh, int triangle) {
    const glm::dvec3 n = glm::cross(corner(mesh, triangle, 1) - corner(mesh, triangle, 0),
                                    corner(mesh, triangle, 2) - corner(mesh, triangle, 0));
    const double length = glm::length(n);
    return length > 0.0 ? n / length : glm::dvec3(0.0);
}

// The triangle's angles at its three corners, radians.
glm::dvec3 cornerAngles(const TriangleMesh& mesh, int triangle) {
    glm::dvec3 angles(0.0);
    for (int c = 0; c < 3; ++c) {
        const glm::dvec3 a = corner(mesh, triangle, (c + 1) % 3) - corner(mesh, triangle, c);
        const glm::dvec3 b = corner(mesh, triangle, (c + 2) % 3) - corner(mesh, triangle, c);
        const double la = glm::length(a), lb = glm::length(b);
        angles[c] = la > 0.0 && lb > 0.0 ? std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0)) : 0.0;
    }
    return angles;
}

// The angle of `triangle` at its corner on vertex v.
double angleAt(const TriangleMesh& mesh, const std::vector<glm::dvec3>& angles, int triangle, int v) {
    const glm::ivec3& t = mesh.triangles[static_cast<std::size_t>(triangle)];
    return angles[static_cast<std::size_t>(triangle)][t.x == v ? 0 : t.y == v ? 1 : 2];
}

void put(float* out, const glm::dvec3& v, float w) {
    out[0] = static_cast<float>(v.x);
    out[1] = static_cast<float>(v.y);
    out[2] = static_cast<float>(v.z);
    out[3] = w;
}

}  // namespace

SharpMeshSurface::SharpMeshSurface(const TriangleMesh& mesh) : bvh_(mesh) {
    EIKON_CHECK_MSG(bvh_.nodes().size() < kLargestIndex && mesh.triangles.size() < kLargestIndex,
                    "a sharp mesh of more than 2^24 triangles");
    cornerStart_.assign(mesh.vertices.size() + 1, 0);
    for (const glm::ivec3& t : mesh.triangles)
        for (int corner = 0; corner < 3; ++corner) ++cornerStart_[static_cast<std::size_t>(t[corner]) + 1];
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) cornerStart_[v + 1] += cornerStart_[v];
    cornerTriangles_.resize(3 * mesh.triangles.size());
    std::vector<int> filled(cornerStart_.begin(), cornerStart_.end() - 1);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int corner = 0; corner < 3; ++corner)
            cornerTriangles_[static_cast<std::size_t>(filled[static_cast<std::size_t>(mesh.triangles[t][corner])]++)] =
                static_cast<int>(t);
}

void SharpMeshSurface::write(const TriangleMesh& mesh, std::size_t root, std::size_t firstNode,
                             std::size_t firstTriangle, float* nodes, float* triangles) {
    EIKON_CHECK_MSG(root < firstNode || nodeCount() == 1, "a root among the other nodes");
    EIKON_CHECK_MSG(firstNode + nodeCount() < kLargestIndex && firstTriangle + triangleCount() < kLargestIndex,
                    "sharp meshes of more than 2^24 nodes or triangles");
    bvh_.refit(mesh);
    auto nodeSlot = [&](int local) { return local == 0 ? root : firstNode + static_cast<std::size_t>(local) - 1; };
    const std::vector<TriangleBvh::Node>& tree = bvh_.nodes();
    for (std::size_t n = 0; n < tree.size(); ++n) {
        const TriangleBvh::Node& node = tree[n];
        const double first = node.count > 0 ? static_cast<double>(firstTriangle + static_cast<std::size_t>(node.first))
                                            : static_cast<double>(nodeSlot(node.first));
        float* out = nodes + nodeSlot(static_cast<int>(n)) * kSurfaceNodeFloats;
        put(out, node.min, static_cast<float>(first));
        put(out + 4, node.max, static_cast<float>(node.count));
    }
    std::vector<glm::dvec3> faceNormals(mesh.triangles.size()), angles(mesh.triangles.size());
    tbb::parallel_for(std::size_t{0}, faceNormals.size(), [&](std::size_t t) {
        faceNormals[t] = unitNormal(mesh, static_cast<int>(t));
        angles[t] = cornerAngles(mesh, static_cast<int>(t));
    });
    const double crease = creaseCosine();
    const std::vector<int>& order = bvh_.order();
    tbb::parallel_for(std::size_t{0}, order.size(), [&](std::size_t slot) {
        const int t = order[slot];
        const glm::ivec3& corners = mesh.triangles[static_cast<std::size_t>(t)];
        const glm::dvec3 own = faceNormals[static_cast<std::size_t>(t)];
        float* out = triangles + (firstTriangle + slot) * kSurfaceTriangleFloats;
        for (int corner = 0; corner < 3; ++corner) {
            const auto v = static_cast<std::size_t>(corners[corner]);
            // The first corner's w: the mesh's ordinal among the scene's
            // meshes (its root node), for passes that draw the triangles.
            put(out + 4 * corner, mesh.vertices[v], corner == 0 ? static_cast<float>(root) : 0.0f);
            // Orientation is not relied on: each neighbour's normal is turned
            // to this triangle's side before the crease test.
            glm::dvec3 sum(0.0);
            for (int i = cornerStart_[v]; i < cornerStart_[v + 1]; ++i) {
                const int neighbour = cornerTriangles_[static_cast<std::size_t>(i)];
                glm::dvec3 other = faceNormals[static_cast<std::size_t>(neighbour)];
                if (glm::dot(own, other) < 0.0) other = -other;
                if (glm::dot(own, other) >= crease)
                    sum += angleAt(mesh, angles, neighbour, static_cast<int>(v)) * other;
            }
            const double length = glm::length(sum);
            put(out + 12 + 4 * corner, length > 0.0 ? sum / length : glm::dvec3(0.0), 0.0f);
        }
    });
}

}  // namespace eikon::sim
