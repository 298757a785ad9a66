// The ray equation of geometric optics, d/ds (n dx/ds) = ∇n, written for the
// state (x, v) with v = n·dx/ds ([Sun08] §3; [Ihrke07] §4.1, eqs. 9–10):
//   dx/ds = v / n,   dv/ds = ∇n.
// The invariant |v| = n(x) holds along the exact path; its drift is the free
// error signal of every step.

// x += increment with Kahan compensation: `lost` carries the low-order bits
// each float32 addition drops. Without it, hundreds of equal increments round
// the same way and a straight ray drifts by ~1e-6 of the grid size.
void compensated_add(INOUT(vec3) x, INOUT(vec3) lost, vec3 increment) {
    precise vec3 corrected = increment - lost;
    precise vec3 sum = x + corrected;
    lost = (sum - x) - corrected;
    x = sum;
}

// Forward Euler step ([Sun08] §3, eqs. 4–5):
//   x_{i+1} = x_i + (Δs / n(x_i)) · v_i,   v_{i+1} = v_i + Δs · ∇n(x_i),
// with the position sum compensated (x_lost: see compensated_add).
void eikonal_euler_step(INOUT(vec3) x, INOUT(vec3) x_lost, INOUT(vec3) v, float n, vec3 grad_n, float ds) {
    compensated_add(x, x_lost, (ds / n) * v);
    v = v + ds * grad_n;
}

// Relative violation of |v| = n at the current point.
float eikonal_invariant_error(vec3 v, float n) {
    return abs(length(v) - n) / n;
}
