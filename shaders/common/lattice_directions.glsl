// The direction sets of the lattice that carries multiply scattered light
// ([Bernabei12] §III-C, eqs. 4–5): D3Q6, the six principal directions the
// paper uses, and D3Q18, which adds the twelve face diagonals of the
// original lattice-Boltzmann lighting ([Geist04]'s 18 links, here without
// the rest particle). A link moves a photon density to the
// neighbour at offset c_i in one lattice step.
//
// Weights w_i are the share of isotropically scattered power each link
// takes. D3Q6: 1/6 each. D3Q18: 1/30 per axis and 1/15 per diagonal, the
// only split of the sphere that also integrates the fourth moments
// (⟨μ⁴⟩ = 1/5, ⟨μx²μy²⟩ = 1/15) — any split of the two gives ⟨μ²⟩ = 1/3, the
// diffusion limit's moment, so both lattices diffuse alike in the bulk and
// differ where transport is not yet diffusive (thin layers, near edges).
// Shared by GLSL and C++ (cpp_shim.h).

// Direction i in [0, 6): ±x, ±y, ±z (even i positive); in [6, 18): the face
// diagonals, plane by plane (xy, yz, zx), each with the sign pairs
// (+,+), (−,+), (+,−), (−,−).
ivec3 lattice_offset(int i) {
    if (i < 6) {
        ivec3 offset = ivec3(0);
        int axis = i / 2;
        int sign_ = (i % 2 == 0) ? 1 : -1;
        if (axis == 0) offset.x = sign_;
        if (axis == 1) offset.y = sign_;
        if (axis == 2) offset.z = sign_;
        return offset;
    }
    int k = i - 6;
    int plane = k / 4;
    int first = (k % 2 == 0) ? 1 : -1;
    int second = ((k / 2) % 2 == 0) ? 1 : -1;
    if (plane == 0) return ivec3(first, second, 0);
    if (plane == 1) return ivec3(0, first, second);
    return ivec3(second, 0, first);
}

float lattice_weight(int i, int directions) {
    if (directions == 6) return 1.0f / 6.0f;
    return i < 6 ? 1.0f / 30.0f : 1.0f / 15.0f;
}

// The links' length classes: 0–2 along x, y, z; 3–5 the diagonals of the
// xy, yz and zx planes (each class one length on any box voxel).
int lattice_length_class(int i) { return i < 6 ? i / 2 : 3 + (i - 6) / 4; }

// The direction with the opposite offset.
int lattice_opposite(int i) {
    if (i < 6) return (i % 2 == 0) ? i + 1 : i - 1;
    int k = i - 6;
    return 6 + (k / 4) * 4 + (3 - k % 4);
}

// (1 − e^{−x})/x, the mean transmittance over a path of optical depth x: the
// track length a photon lays down per unit of geometric path crossed. Below
// x = 0.5 its Taylor series Σ (−x)^k/(k + 1)!, to k = 9 (error below 1e-9),
// where the quotient would lose digits to cancellation.
float mean_transmittance(float x) {
    if (x < 0.5f) {
        float sum = 1.0f / 3628800.0f;  // 1/10!
        float factorial = 3628800.0f;
        for (int k = 9; k >= 1; --k) {
            factorial /= float(k + 1);  // (k + 1)! → k!
            sum = 1.0f / factorial - x * sum;
        }
        return sum;
    }
    return (1.0f - exp(-x)) / x;
}
