#include "render/stages/ShapeTriangles.h"

#include "bridge/grid/FieldSet.h"

#include <glm/geometric.hpp>

#include <array>

namespace eikon::render {

namespace {

using Corners = std::array<glm::dvec3, 3>;

void append(std::vector<float>& out, const Corners& corners, const Corners& normals, int surface) {
    for (int c = 0; c < 3; ++c) {
        for (int axis = 0; axis < 3; ++axis) out.push_back(static_cast<float>(corners[c][axis]));
        out.push_back(c == 0 ? static_cast<float>(surface) : 0.0f);
    }
    for (int c = 0; c < 3; ++c) {
        for (int axis = 0; axis < 3; ++axis) out.push_back(static_cast<float>(normals[c][axis]));
        out.push_back(0.0f);
    }
}

// One spherical triangle of unit directions, split `levels` more times.
void appendSphereFacet(std::vector<float>& out, const SphereShape& sphere, const Corners& unit, int levels,
                       int surface) {
    if (levels == 0) {
        Corners corners;
        for (int c = 0; c < 3; ++c) corners[c] = sphere.center + kSphereHullScale * sphere.radius * unit[c];
        append(out, corners, unit, surface);
        return;
    }
    const glm::dvec3 ab = glm::normalize(unit[0] + unit[1]);
    const glm::dvec3 bc = glm::normalize(unit[1] + unit[2]);
    const glm::dvec3 ca = glm::normalize(unit[2] + unit[0]);
    appendSphereFacet(out, sphere, {unit[0], ab, ca}, levels - 1, surface);
    appendSphereFacet(out, sphere, {ab, unit[1], bc}, levels - 1, surface);
    appendSphereFacet(out, sphere, {ca, bc, unit[2]}, levels - 1, surface);
    appendSphereFacet(out, sphere, {ab, bc, ca}, levels - 1, surface);
}

void appendSphere(std::vector<float>& out, const SphereShape& sphere, int surface) {
    for (int octant = 0; octant < 8; ++octant) {
        const glm::dvec3 sign((octant & 1) ? -1.0 : 1.0, (octant & 2) ? -1.0 : 1.0, (octant & 4) ? -1.0 : 1.0);
        // Counter-clockwise seen from outside: an octant mirrored an odd number of times swaps two corners.
        const glm::dvec3 x(sign.x, 0, 0), y(0, sign.y, 0), z(0, 0, sign.z);
        appendSphereFacet(out, sphere, sign.x * sign.y * sign.z > 0.0 ? Corners{x, y, z} : Corners{y, x, z},
                          kSphereSubdivisions, surface);
    }
}

void appendBox(std::vector<float>& out, const BoxShape& box, int surface) {
    const auto corner = [&](int bits) {
        return glm::dvec3((bits & 1) ? box.max.x : box.min.x, (bits & 2) ? box.max.y : box.min.y,
                          (bits & 4) ? box.max.z : box.min.z);
    };
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            glm::dvec3 normal(0.0);
            normal[axis] = side == 0 ? -1.0 : 1.0;
            const int fixed = side << axis;
            const int u = 1 << ((axis + 1) % 3), v = 1 << ((axis + 2) % 3);
            const Corners flat{normal, normal, normal};
            // Counter-clockwise seen from outside: u × v is the axis, outward on the far side only.
            const int first = side == 1 ? u : v, second = side == 1 ? v : u;
            append(out, {corner(fixed), corner(fixed | first), corner(fixed | u | v)}, flat, surface);
            append(out, {corner(fixed), corner(fixed | u | v), corner(fixed | second)}, flat, surface);
        }
    }
}

}  // namespace

BoxShape waterHull(const WaterDesc& water) {
    return {water.basinMin, water.basinMax + glm::dvec3(0.0, water.basinMax.y - water.basinMin.y, 0.0)};
}

std::vector<float> waterHullTriangles(const Scene& scene) {
    std::vector<float> out;
    int body = 0;
    for (const ObjectDesc& object : scene.objects)
        if (object.isSharp() && object.kind == ObjectDesc::Kind::Water) appendBox(out, waterHull(object.water), body++);
    return out;
}

std::vector<float> shapeTriangles(const Scene& scene) {
    std::vector<float> out;
    int surface = 0;
    for (const ObjectDesc& object : scene.objects) {
        if (!object.isSharp()) continue;
        if (object.kind == ObjectDesc::Kind::Sphere) appendSphere(out, object.sphere, surface);
        if (object.kind == ObjectDesc::Kind::Box) appendBox(out, object.box, surface);
        ++surface;
    }
    static_assert(kSurfaceTriangleFloats == 24);
    return out;
}

}  // namespace eikon::render
