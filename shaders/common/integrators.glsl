// Integrators of the ray equation for the state (x, v), v = n·dx/ds
// (common/ray_step.glsl). Each advances by arc length ds and leaves in
// `field` the sample at the new x, so the next step reuses it.
//
// Shared by GLSL and C++: the includer first defines
//     vec4 field_at(vec3 x)   // (∇n, n) at x
// (the photon shader samples the prepared textures; C++ tests use closed-form
// fields), then includes this file.

// Forward Euler ([Sun08] §3, eqs. 4–5): first order, one sample per step.
void integrate_euler(INOUT(vec3) x, INOUT(vec3) x_lost, INOUT(vec3) v, INOUT(vec4) field, float ds) {
    eikonal_euler_step(x, x_lost, v, field.w, xyz_of(field), ds);
    field = field_at(x);
}

// Störmer–Verlet leapfrog (kick–drift–kick) in the parameter σ, dσ = ds/n:
// with dx/dσ = v and dv/dσ = n∇n = ∇(n²/2) the ray equation is Hamiltonian,
// H = |v|²/2 − n²/2 = 0 on a ray, and leapfrog is its symplectic
// second-order integrator: |v| = n is kept to O(ds²) over long paths, at the
// cost of one field sample per step.
void integrate_leapfrog(INOUT(vec3) x, INOUT(vec3) x_lost, INOUT(vec3) v, INOUT(vec4) field, float ds) {
    float half_dsigma = 0.5f * ds / field.w;
    v = v + (half_dsigma * field.w) * xyz_of(field);
    compensated_add(x, x_lost, (2.0f * half_dsigma) * v);
    field = field_at(x);
    v = v + (half_dsigma * field.w) * xyz_of(field);
}

// Classical fourth-order Runge–Kutta on (x, v) with dx/ds = v/n, dv/ds = ∇n:
// four field samples per step.
void integrate_rk4(INOUT(vec3) x, INOUT(vec3) x_lost, INOUT(vec3) v, INOUT(vec4) field, float ds) {
    vec3 k1x = v / field.w;
    vec3 k1v = xyz_of(field);
    vec4 f2 = field_at(x + (0.5f * ds) * k1x);
    vec3 v2 = v + (0.5f * ds) * k1v;
    vec3 k2x = v2 / f2.w;
    vec3 k2v = xyz_of(f2);
    vec4 f3 = field_at(x + (0.5f * ds) * k2x);
    vec3 v3 = v + (0.5f * ds) * k2v;
    vec3 k3x = v3 / f3.w;
    vec3 k3v = xyz_of(f3);
    vec4 f4 = field_at(x + ds * k3x);
    vec3 v4 = v + ds * k3v;
    vec3 k4x = v4 / f4.w;
    vec3 k4v = xyz_of(f4);
    compensated_add(x, x_lost, (ds / 6.0f) * (k1x + 2.0f * k2x + 2.0f * k3x + k4x));
    v = v + (ds / 6.0f) * (k1v + 2.0f * k2v + 2.0f * k3v + k4v);
    field = field_at(x);
}

// Rescales v so that |v| = n at the current point (optional after each step).
vec3 renormalised_direction(vec3 v, float n) {
    return (n / length(v)) * v;
}
