#include "sim/deform/MeshShapes.h"

#include <cmath>
#include <numbers>
#include <utility>

namespace eikon::sim {

namespace {

void addQuad(TriangleMesh& mesh, int a, int b, int c, int d) {
    mesh.triangles.emplace_back(a, b, c);
    mesh.triangles.emplace_back(a, c, d);
}

// Generators below build each surface with one consistent winding; this
// makes it the outward one (positive enclosed volume).
TriangleMesh orientedOutward(TriangleMesh mesh) {
    if (enclosedVolume(mesh) < 0.0)
        for (glm::ivec3& t : mesh.triangles) std::swap(t.y, t.z);
    return mesh;
}

}  // namespace

TriangleMesh sphereMesh(const glm::dvec3& centre, double radius, int rings, int segments) {
    TriangleMesh mesh;
    mesh.vertices.push_back(centre + glm::dvec3(0, radius, 0));
    for (int ring = 1; ring < rings; ++ring) {
        const double polar = std::numbers::pi * ring / rings;
        for (int s = 0; s < segments; ++s) {
            const double azimuth = 2.0 * std::numbers::pi * s / segments;
            mesh.vertices.push_back(centre + radius * glm::dvec3(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                                                                 std::sin(polar) * std::sin(azimuth)));
        }
    }
    mesh.vertices.push_back(centre - glm::dvec3(0, radius, 0));
    const int south = static_cast<int>(mesh.vertices.size()) - 1;
    auto at = [&](int ring, int s) { return 1 + (ring - 1) * segments + (s % segments); };
    for (int s = 0; s < segments; ++s) {
        mesh.triangles.emplace_back(0, at(1, s + 1), at(1, s));
        for (int ring = 1; ring + 1 < rings; ++ring) addQuad(mesh, at(ring, s), at(ring, s + 1), at(ring + 1, s + 1), at(ring + 1, s));
        mesh.triangles.emplace_back(south, at(rings - 1, s), at(rings - 1, s + 1));
    }
    return orientedOutward(std::move(mesh));
}

TriangleMesh torusMesh(const glm::dvec3& centre, double majorRadius, double minorRadius, int majorSegments,
                       int minorSegments) {
    TriangleMesh mesh;
    for (int a = 0; a < majorSegments; ++a)
        for (int b = 0; b < minorSegments; ++b) {
            const double u = 2.0 * std::numbers::pi * a / majorSegments;
            const double v = 2.0 * std::numbers::pi * b / minorSegments;
            const double ring = majorRadius + minorRadius * std::cos(v);
            mesh.vertices.push_back(centre + glm::dvec3(ring * std::cos(u), minorRadius * std::sin(v), ring * std::sin(u)));
        }
    auto at = [&](int a, int b) { return (a % majorSegments) * minorSegments + (b % minorSegments); };
    for (int a = 0; a < majorSegments; ++a)
        for (int b = 0; b < minorSegments; ++b) addQuad(mesh, at(a, b), at(a, b + 1), at(a + 1, b + 1), at(a + 1, b));
    return orientedOutward(std::move(mesh));
}

TriangleMesh boxMesh(const glm::dvec3& min, const glm::dvec3& max, const glm::ivec3& cells) {
    TriangleMesh mesh;
    const glm::ivec3 n = cells;
    std::vector<int> id(static_cast<std::size_t>(n.x + 1) * (n.y + 1) * (n.z + 1), -1);
    auto vertex = [&](glm::ivec3 p) {
        int& slot = id[p.x + (n.x + 1) * (p.y + (n.y + 1) * p.z)];
        if (slot < 0) {
            slot = static_cast<int>(mesh.vertices.size());
            mesh.vertices.push_back(min + (max - min) * glm::dvec3(p) / glm::dvec3(n));
        }
        return slot;
    };
    for (int axis = 0; axis < 3; ++axis) {
        const int b = (axis + 1) % 3, c = (axis + 2) % 3;  // e_b × e_c = e_axis
        for (int side = 0; side < 2; ++side)
            for (int u = 0; u < n[b]; ++u)
                for (int w = 0; w < n[c]; ++w) {
                    auto corner = [&](int du, int dw) {
                        glm::ivec3 p(0);
                        p[axis] = side * n[axis];
                        p[b] = u + du;
                        p[c] = w + dw;
                        return vertex(p);
                    };
                    if (side == 1) addQuad(mesh, corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1));
                    else addQuad(mesh, corner(0, 0), corner(0, 1), corner(1, 1), corner(1, 0));
                }
    }
    return mesh;
}

}  // namespace eikon::sim
