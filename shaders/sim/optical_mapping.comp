// The optical mapping of sim/optics/OpticalMapping.h on the GPU: the
// solver's temperature, concentration and dye, resampled trilinearly onto
// the render grid (clamped to the solver's lattice like sampleTrilinear;
// render cells outside the solver box see the ambient fluid), to δn, κ and
// σs. Air: Gladstone–Dale, n − 1 = (n0 − 1)(p/p0)(T0/T) (AirOptics.h);
// liquid: linear or Lorentz–Lorenz mixing of the two liquids
// (LiquidOptics.h); dye: κ = κ_dye·dye, σs = σ_dye·dye. The index is formed
// in float64 and only δn = n − n_ref rounded to float32, as on the CPU.
// Variants: EIKON_LIQUID, EIKON_LORENTZ_LORENZ, EIKON_HAS_EXTINCTION, EIKON_HAS_SCATTERING.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = kOpticsTemperature) readonly buffer OpticsTemperature { float theta[]; };
layout(std430, binding = kOpticsConcentration) readonly buffer OpticsConcentration { float concentration[]; };
layout(std430, binding = kOpticsDye) readonly buffer OpticsDye { float dye[]; };
layout(std430, binding = kOpticsDeltaIndex) writeonly buffer OpticsDeltaIndex { float delta_index[]; };
#if EIKON_HAS_EXTINCTION
layout(std430, binding = kOpticsExtinction) writeonly buffer OpticsExtinction { float extinction[]; };
uniform dvec3 dye_extinction;  // κ per unit dye, 1/m
#endif
#if EIKON_HAS_SCATTERING
layout(std430, binding = kOpticsScattering) writeonly buffer OpticsScattering { float scattering[]; };
uniform dvec3 dye_scattering;  // σs per unit dye, 1/m
#endif

uniform ivec3 render_cells;
uniform dvec3 render_min, render_voxel;
uniform ivec3 solver_cells;
uniform dvec3 solver_min, solver_max, solver_voxel;
uniform double reference_index;  // n_ref
#if EIKON_LIQUID
uniform double index_a, index_b;  // concentration 0 and 1
#else
uniform double ambient_temperature;  // K; theta is T minus it
uniform double air_scale;            // (n0 − 1)·(p/p0)·T0, so that n − 1 = air_scale / T
#endif

// sampleTrilinear (sim/field/GridField.h) along one axis: the lower sample,
// the step to the next (0 on a one-sample axis) and the fraction.
void locate(double g, int n, out int lower, out int step, out double t) {
    if (n == 1) {
        lower = 0;
        step = 0;
        t = 0.0lf;
        return;
    }
    double clamped = clamp(g, 0.0lf, double(n - 1));
    lower = min(int(clamped), n - 2);
    step = 1;
    t = clamped - double(lower);
}

// The three scalars at solver lattice coordinate g: x theta, y concentration, z dye.
dvec3 sampleScalars(dvec3 g) {
    int lx, sx, ly, sy, lz, sz;
    double tx, ty, tz;
    locate(g.x, solver_cells.x, lx, sx, tx);
    locate(g.y, solver_cells.y, ly, sy, ty);
    locate(g.z, solver_cells.z, lz, sz, tz);
    dvec3 corners[8];
    for (int c = 0; c < 8; ++c) {
        int i = lx + ((c & 1) != 0 ? sx : 0);
        int j = ly + ((c & 2) != 0 ? sy : 0);
        int k = lz + ((c & 4) != 0 ? sz : 0);
        int s = i + solver_cells.x * (j + solver_cells.y * k);
        corners[c] = dvec3(theta[s], concentration[s], dye[s]);
    }
    dvec3 x00 = corners[0] + tx * (corners[1] - corners[0]);
    dvec3 x10 = corners[2] + tx * (corners[3] - corners[2]);
    dvec3 x01 = corners[4] + tx * (corners[5] - corners[4]);
    dvec3 x11 = corners[6] + tx * (corners[7] - corners[6]);
    dvec3 y0 = x00 + ty * (x10 - x00);
    dvec3 y1 = x01 + ty * (x11 - x01);
    return y0 + tz * (y1 - y0);
}

#if EIKON_LORENTZ_LORENZ
double lorentzLorenzRefraction(double n) { return (n * n - 1.0lf) / (n * n + 2.0lf); }
#endif

double indexOf(double excess, double c) {
#if EIKON_LIQUID
    c = clamp(c, 0.0lf, 1.0lf);
#if EIKON_LORENTZ_LORENZ
    double r = (1.0lf - c) * lorentzLorenzRefraction(index_a) + c * lorentzLorenzRefraction(index_b);
    return sqrt((1.0lf + 2.0lf * r) / (1.0lf - r));
#else
    return (1.0lf - c) * index_a + c * index_b;
#endif
#else
    return 1.0lf + air_scale / (ambient_temperature + excess);
#endif
}

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, render_cells))) return;
    dvec3 x = render_min + (dvec3(cell) + 0.5lf) * render_voxel;
    dvec3 scalars = dvec3(0.0lf);  // the ambient fluid: T_amb, no concentration, no dye
    if (all(greaterThanEqual(x, solver_min)) && all(lessThanEqual(x, solver_max)))
        scalars = sampleScalars((x - solver_min) / solver_voxel - 0.5lf);
    uint c = uint(cell.x + render_cells.x * (cell.y + render_cells.y * cell.z));
    delta_index[c] = float(indexOf(scalars.x, scalars.y) - reference_index);
#if EIKON_HAS_EXTINCTION
    for (int channel = 0; channel < 3; ++channel) extinction[3u * c + uint(channel)] = float(dye_extinction[channel] * scalars.z);
#endif
#if EIKON_HAS_SCATTERING
    for (int channel = 0; channel < 3; ++channel) scattering[3u * c + uint(channel)] = float(dye_scattering[channel] * scalars.z);
#endif
}
