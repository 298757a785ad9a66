#include "bridge/mesh/TriangleMesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace eikon {

EdgeCensus countEdges(const TriangleMesh& mesh) {
    std::unordered_map<unsigned long long, int> sharing;
    sharing.reserve(3 * mesh.triangles.size());
    for (const glm::ivec3& t : mesh.triangles)
        for (int corner = 0; corner < 3; ++corner) {
            const auto a = static_cast<unsigned long long>(t[corner]);
            const auto b = static_cast<unsigned long long>(t[(corner + 1) % 3]);
            ++sharing[(std::min(a, b) << 32) | std::max(a, b)];
        }
    EdgeCensus census;
    census.edges = sharing.size();
    for (const auto& [edge, count] : sharing) {
        if (count == 1) ++census.open;
        if (count > 2) ++census.nonManifold;
    }
    return census;
}

double enclosedVolume(const TriangleMesh& mesh) {
    double sixTimesVolume = 0.0;
    for (const glm::ivec3& t : mesh.triangles)
        sixTimesVolume += glm::dot(mesh.vertices[t.x], glm::cross(mesh.vertices[t.y], mesh.vertices[t.z]));
    return sixTimesVolume / 6.0;
}

void vertexBounds(const TriangleMesh& mesh, glm::dvec3& min, glm::dvec3& max) {
    min = glm::dvec3(std::numeric_limits<double>::infinity());
    max = -min;
    for (const glm::dvec3& v : mesh.vertices) {
        min = glm::min(min, v);
        max = glm::max(max, v);
    }
}

}  // namespace eikon
