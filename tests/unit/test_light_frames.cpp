// A light's frame over the refractors (render/stages/LightFrames.h): it
// holds every refractor, fits their outline to within a texel, and keeps
// the texels' size that render.caustic_map_texels across the refractors'
// bounding sphere gives, checked against closed forms.
#include "render/stages/LightFrames.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace eikon::render {
namespace {

constexpr int kMapTexels = 256;

// Where x lands in the frame's view, in normalized device coordinates.
glm::dvec2 ndcOf(const LightFrame& frame, const glm::dvec3& x) {
    const glm::dvec4 clip = glm::dmat4(frame.view.viewProjection) * glm::dvec4(x, 1.0);
    return glm::dvec2(clip) / clip.w;
}

TEST(LightFrames, ASphereUnderAPointLightFillsItsFrame) {
    LightDesc light;
    light.position = glm::dvec3(0.0, 1.8, 0.0);
    const double r = 0.25, distance = 1.25;
    const LightFrame frame = lightFrameOver(light, {RefractorExtent::ofSphere({0.0, 0.55, 0.0}, r)}, kMapTexels);
    // The bounding sphere of the sphere's box sets the texels' size; the
    // sphere's own cone (1% margin) how many are used.
    const double bounding = std::tan(std::asin((std::sqrt(3.0) * r * 1.01 * (1.0 + 1e-6)) / distance));
    const double cone = std::tan(std::asin(1.01 * r / distance));
    EXPECT_EQ(frame.texels, static_cast<int>(std::ceil(kMapTexels * cone / bounding)));
    EXPECT_NEAR(2.0 * frame.halfExtent / frame.texels, 2.0 * bounding / kMapTexels, 1e-12);
    EXPECT_GE(frame.halfExtent, cone);
    EXPECT_LT(frame.halfExtent - cone, 2.0 * frame.halfExtent / frame.texels);
    EXPECT_LT(frame.texels, 150);  // a third of the texels the bounding sphere spent
    // The sphere's silhouette, seen from the light, lies inside the frame.
    const double tangentAngle = std::asin(r / distance);
    for (int k = 0; k < 16; ++k) {
        const double around = 2.0 * 3.14159265358979 * k / 16.0;
        const glm::dvec3 toward(std::sin(tangentAngle) * std::cos(around), -std::cos(tangentAngle),
                                std::sin(tangentAngle) * std::sin(around));
        const glm::dvec2 ndc = ndcOf(frame, light.position + toward);
        EXPECT_LE(std::max(std::abs(ndc.x), std::abs(ndc.y)), 1.0);
    }
}

TEST(LightFrames, TwoSpheresBesideTheAxisStayInsideTheFrame) {
    // The axis aims between them, so each sphere's cone lies off it.
    LightDesc light;
    light.position = glm::dvec3(0.2, 2.0, -0.1);
    const std::vector<RefractorExtent> spheres = {RefractorExtent::ofSphere({-0.6, 0.4, 0.2}, 0.2),
                                                  RefractorExtent::ofSphere({0.5, 0.3, -0.3}, 0.1)};
    const LightFrame frame = lightFrameOver(light, spheres, kMapTexels);
    EXPECT_LT(frame.texels, kMapTexels);
    for (const RefractorExtent& sphere : spheres) {
        // Points of the sphere's outline seen from the light: on its tangent cone.
        const glm::dvec3 toward = sphere.centre - light.position;
        const double distance = glm::length(toward);
        const glm::dvec3 axis = toward / distance;
        const glm::dvec3 side = glm::normalize(glm::cross(axis, glm::dvec3(0.0, 0.0, 1.0)));
        const glm::dvec3 other = glm::cross(axis, side);
        const double tangent = std::sqrt(distance * distance - sphere.radius * sphere.radius);
        const double angle = std::asin(sphere.radius / distance);
        for (int k = 0; k < 32; ++k) {
            const double around = 2.0 * 3.14159265358979 * k / 32.0;
            const glm::dvec3 ray = std::cos(angle) * axis +
                                   std::sin(angle) * (std::cos(around) * side + std::sin(around) * other);
            const glm::dvec2 ndc = ndcOf(frame, light.position + tangent * ray);
            EXPECT_LE(std::max(std::abs(ndc.x), std::abs(ndc.y)), 1.0) << "sphere at x " << sphere.centre.x;
        }
    }
}

TEST(LightFrames, AFlatBoxUnderTheSunFitsItsOutline) {
    LightDesc sun;
    sun.kind = LightDesc::Kind::Directional;
    sun.direction = glm::normalize(glm::dvec3(-0.15, -1.0, -0.1));
    const RefractorExtent pool = RefractorExtent::ofBox({-0.52, -0.02, -0.52}, {0.52, 0.3, 0.52});
    const LightFrame frame = lightFrameOver(sun, {pool}, kMapTexels);
    const double bounding = 0.5 * glm::length(pool.high - pool.low) * 1.01 * (1.0 + 1e-6);
    EXPECT_NEAR(2.0 * frame.halfExtent / frame.texels, 2.0 * bounding / kMapTexels, 1e-12);
    EXPECT_LT(frame.texels, 200);
    // Every corner inside; the outermost within a texel and the margin of the edge.
    double outermost = 0.0;
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 corner(k & 1 ? pool.high.x : pool.low.x, k & 2 ? pool.high.y : pool.low.y,
                                k & 4 ? pool.high.z : pool.low.z);
        const glm::dvec2 ndc = ndcOf(frame, corner);
        outermost = std::max(outermost, std::max(std::abs(ndc.x), std::abs(ndc.y)));
    }
    EXPECT_LE(outermost, 1.0);
    EXPECT_GT(outermost, 1.0 / 1.01 - 2.0 / frame.texels);
}

TEST(LightFrames, ALightAmongTheRefractorsUsesEveryTexel) {
    LightDesc light;
    light.position = glm::dvec3(0.0, 0.1, 0.0);
    const RefractorExtent box = RefractorExtent::ofBox({-1.0, -1.0, -1.0}, {1.0, 0.5, 1.0});
    const LightFrame frame = lightFrameOver(light, {box}, kMapTexels);
    EXPECT_EQ(frame.texels, kMapTexels);
}

}  // namespace
}  // namespace eikon::render
