#include "render/stages/LightFrames.h"

#include "render/stages/ImageSpaceView.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace eikon::render {

namespace {

// A point or spot light's frustum holds the refractors' bounding sphere,
// but opens no wider than this (a light inside or close to the sphere sees
// the part of it within 80° of the axis).
constexpr double kWidestHalfAngleDeg = 80.0;
// The margin around the refractors, of their size (1%).
constexpr double kMargin = 1.01;

std::array<glm::dvec3, 8> cornersOf(const RefractorExtent& box) {
    std::array<glm::dvec3, 8> corners;
    for (int k = 0; k < 8; ++k)
        corners[static_cast<std::size_t>(k)] =
            glm::dvec3(k & 1 ? box.high.x : box.low.x, k & 2 ? box.high.y : box.low.y, k & 4 ? box.high.z : box.low.z);
    return corners;
}

// Half the width of the square about the axis through `eye` that holds
// every refractor seen along `axis` (orthographic), and the offset of its
// centre from that axis along right and up.
double orthographicFit(const std::vector<RefractorExtent>& refractors, const glm::dvec3& right, const glm::dvec3& up,
                       glm::dvec2& offset) {
    glm::dvec2 low(1e300), high(-1e300);
    for (const RefractorExtent& refractor : refractors) {
        if (refractor.sphere) {
            const glm::dvec2 at(glm::dot(refractor.centre, right), glm::dot(refractor.centre, up));
            low = glm::min(low, at - refractor.radius);
            high = glm::max(high, at + refractor.radius);
            continue;
        }
        for (const glm::dvec3& corner : cornersOf(refractor)) {
            const glm::dvec2 at(glm::dot(corner, right), glm::dot(corner, up));
            low = glm::min(low, at);
            high = glm::max(high, at);
        }
    }
    offset = 0.5 * (low + high);
    return 0.5 * std::max(high.x - low.x, high.y - low.y) * kMargin;
}

// The tangent of the half-angle of the square frustum from `eye` along
// `axis` that holds every refractor, or `widest` where one reaches beside
// or behind the light.
double perspectiveFit(const std::vector<RefractorExtent>& refractors, const glm::dvec3& eye, const glm::dvec3& axis,
                      const glm::dvec3& right, const glm::dvec3& up, double widest) {
    const double widestAngle = std::atan(widest);
    double fit = 0.0;
    for (const RefractorExtent& refractor : refractors) {
        if (refractor.sphere) {
            // Its cone about the direction to its centre, within the angle from the axis to the cone's far edge.
            const glm::dvec3 toward = refractor.centre - eye;
            const double distance = glm::length(toward);
            if (distance <= refractor.radius * kMargin) return widest;
            const double off = std::acos(std::clamp(glm::dot(toward, axis) / distance, -1.0, 1.0));
            const double angle = off + std::asin(refractor.radius * kMargin / distance);
            if (angle >= widestAngle) return widest;
            fit = std::max(fit, std::tan(angle));
            continue;
        }
        for (const glm::dvec3& corner : cornersOf(refractor)) {
            const glm::dvec3 p = corner - eye;
            const double depth = glm::dot(p, axis);
            if (depth <= 0.0) return widest;
            fit = std::max(fit, std::max(std::abs(glm::dot(p, right)), std::abs(glm::dot(p, up))) / depth * kMargin);
        }
    }
    return std::min(fit, widest);
}

}  // namespace

LightFrame lightFrameOver(const LightDesc& light, const std::vector<RefractorExtent>& refractors, int mapTexels) {
    // The refractors' bounding sphere (of their boxes), which sets the texels' size.
    glm::dvec3 low(1e300), high(-1e300);
    for (const RefractorExtent& refractor : refractors) {
        low = glm::min(low, refractor.sphere ? refractor.centre - refractor.radius : refractor.low);
        high = glm::max(high, refractor.sphere ? refractor.centre + refractor.radius : refractor.high);
    }
    const bool anyRefractor = !refractors.empty();
    const glm::dvec3 centre = anyRefractor ? 0.5 * (low + high) : glm::dvec3(0.0);
    // Not below 1e-30 m: any refractor's size is the scale, however small. A
    // millionth more than the bound, at any scale (as the former absolute
    // 1e-6 m was in a metre-sized scene): a frame whose texels align exactly
    // with a mesh's round coordinates drew a crease's beam 3.4% off in one
    // floor texel (CausticPolygons.KeepTheGapUnderACreaseDark).
    const double radius =
        anyRefractor ? std::max(0.5 * glm::length(high - low) * kMargin * (1.0 + 1e-6), 1e-30) : 1e-6;

    LightFrame frame;
    const bool directional = light.kind == LightDesc::Kind::Directional;
    const glm::dvec3 axis = directional ? glm::normalize(light.direction)
                            : glm::length(centre - light.position) > 0.0 ? glm::normalize(centre - light.position)
                                                                          : glm::dvec3(0, -1, 0);
    const glm::dvec3 hint = std::abs(axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 right = glm::normalize(glm::cross(axis, hint));
    const glm::dvec3 up = glm::cross(right, axis);
    glm::dvec3 eye;
    double bounding = 0.0, fit = 0.0;  // half-extents: over the bounding sphere, over the refractors
    if (directional) {
        glm::dvec2 offset(0.0);
        bounding = radius;
        fit = anyRefractor ? orthographicFit(refractors, right, up, offset) : bounding;
        // On the square's axis, before all the refractors.
        const glm::dvec3 across = centre - glm::dot(centre, right) * right - glm::dot(centre, up) * up;
        eye = across + offset.x * right + offset.y * up - axis * (2.0 * radius);
    } else {
        eye = light.position;
        const double distance = glm::length(centre - eye);
        const double widest = std::tan(glm::radians(kWidestHalfAngleDeg));
        bounding = distance > radius ? std::min(std::tan(std::asin(radius / distance)), widest) : widest;
        fit = anyRefractor ? perspectiveFit(refractors, eye, axis, right, up, widest) : bounding;
    }
    // As many texels as the fit needs, each as large as across the bounding sphere.
    frame.texels = std::clamp(static_cast<int>(std::ceil(mapTexels * std::min(fit / bounding, 1.0))), 2, mapTexels);
    frame.halfExtent = bounding * frame.texels / mapTexels;
    const double h = frame.halfExtent;
    const glm::dmat4 view = glm::lookAt(eye, eye + axis, up);
    const glm::dvec2 planes = rasterPlanes(eye, centre, radius);
    const glm::dmat4 projection = directional
                                      ? glm::ortho(-h, h, -h, h, 0.0, planes.y)
                                      : glm::perspective(2.0 * std::atan(h), 1.0, planes.x, planes.y);
    frame.view.viewProjection = glm::mat4(projection * view);
    frame.view.eye = glm::vec3(eye);
    frame.view.axis = glm::vec3(axis);
    frame.view.orthographic = directional;
    frame.right = glm::vec3(right);
    frame.up = glm::vec3(up);
    return frame;
}

}  // namespace eikon::render
