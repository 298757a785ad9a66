// Ground truth for the photon tracer: the ray equation d/ds(n dx/ds) = ∇n as
// the system dx/ds = v/n, dv/ds = ∇n (v = n·dx/ds; [Sun08] §3),
// integrated in double precision by the embedded Dormand–Prince 5(4) pair
// ([Dormand80]) with step-size control to a tight tolerance, on
// closed-form fields (IndexField). For accuracy reports and tests only: it is
// never on the rendering path.
#pragma once

#include "verify/reference/IndexField.h"

#include <glm/vec3.hpp>

#include <functional>

namespace eikon::reference {

struct RayState {
    glm::dvec3 x{0.0};  // m
    glm::dvec3 v{0.0};  // n·dx/ds, |v| = n(x) on an exact ray
};

struct ReferenceOptions {
    double tolerance = 1e-11;     // per step, on x (m) and on v, absolute plus relative to the state
    double initialStep = 1e-4;    // m of arc length
    double maxStep = 1e-2;        // m: keeps steps from leaping over thin features
    long long maxSteps = 10'000'000;
};

struct ReferenceResult {
    RayState state;               // at the event, or where the trace stopped
    double arcLength = 0.0;       // m travelled
    bool eventHit = false;        // the event function changed sign (state is on it)
    long long acceptedSteps = 0, rejectedSteps = 0;
    double maxInvariantError = 0.0;  // max | |v| − n | / n over accepted steps
};

// Returns a quantity whose change of sign marks the event (a plane crossed,
// a box left, v·ŷ turning positive).
using RayEvent = std::function<double(const RayState&)>;

class ReferenceTracer {
public:
    explicit ReferenceTracer(const IndexField& field, ReferenceOptions options = {});

    // The state starting at x along the unit direction d: v = n(x)·d.
    RayState start(const glm::dvec3& x, const glm::dvec3& direction) const;

    // Integrates until `event` changes sign (located to ~1e-13 m by bisecting
    // the last step) or `maxArcLength` is travelled.
    ReferenceResult trace(RayState state, double maxArcLength, const RayEvent& event = {}) const;

private:
    struct Derivative {
        glm::dvec3 dx, dv;
    };
    Derivative derivative(const RayState& state) const;
    // One Dormand–Prince step of size h from `state` with k1 = f(state);
    // returns the fifth-order solution and the error estimate norm (≤ 1: accept).
    RayState step(const RayState& state, const Derivative& k1, double h, double& errorNorm) const;

    const IndexField& field_;
    ReferenceOptions options_;
};

}  // namespace eikon::reference
