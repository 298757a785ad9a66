// Deformers that are closed-form maps of space, keyed over time:
//  - rigid: a keyed pose (scale, rotation, translation) about the centre of
//    the rest mesh's bounds;
//  - twist: rotation about an axis by an angle proportional to the distance
//    along it, θ = τ(t)·s (τ in degrees per metre);
//  - bend: the axis curved into a circular arc of curvature κ(t) (degrees
//    per metre) toward a direction ⟂ axis, cross-sections kept
//    perpendicular to the arc ([Barr84]).
#pragma once

#include "sim/deform/Deformer.h"

namespace eikon::sim {

class RigidDeformer : public Deformer {
public:
    RigidDeformer(const DeformerDesc& desc, const TriangleMesh& rest);
    void deform(double time, std::vector<glm::dvec3>& deformed) override;

private:
    std::vector<PoseKey> keys_;
    std::vector<glm::dvec3> rest_;
    glm::dvec3 centre_;
};

class TwistDeformer : public Deformer {
public:
    TwistDeformer(const DeformerDesc& desc, const TriangleMesh& rest);
    void deform(double time, std::vector<glm::dvec3>& deformed) override;

private:
    DeformerDesc desc_;
    std::vector<glm::dvec3> rest_;
};

class BendDeformer : public Deformer {
public:
    BendDeformer(const DeformerDesc& desc, const TriangleMesh& rest);
    void deform(double time, std::vector<glm::dvec3>& deformed) override;

private:
    DeformerDesc desc_;
    std::vector<glm::dvec3> rest_;
};

}  // namespace eikon::sim
