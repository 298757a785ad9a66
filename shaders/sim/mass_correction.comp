// Restores the total of an advected scalar in a closed domain, as
// restoreTotal in sim/fluid/MassCorrection.cpp: the drift of Σφ that the
// MacCormack limiter causes ([Selle08] §3.1) is put back at the fronts, in
// proportion to w_c = (φ_c − low)(high − φ_c)/(high − low) with φ_c clamped
// to [low, high], by scale = clamp((total − Σφ)/Σw, −1, 1), which keeps every
// value in [low, high] (a global mass-fixing step, cf. [Rasch90]; [Kim05] §4).
// Sums, minimum and maximum in float64 over a fixed partition, as
// shaders/sim/reduce.comp, so a run repeats bit for bit. Budget `field` owns
// results[4·field + 0..3]: total, low, high (before advection) and scale.
//   STAGE_RECORD  PASS 0: work group g folds Σφ, min φ, max φ of elements
//                         g·256 + t, stepping by groups·256, into partials[3g..3g+2];
//                 PASS 1: one work group folds them into total, low, high.
//   STAGE_MEASURE PASS 0: the same for Σw and Σφ after advection;
//                 PASS 1: folds them into scale (0 where the CPU returns early:
//                         high ≤ low or Σw ≤ 0).
//   STAGE_RESTORE:        φ_c += scale · w_c, one invocation per sample.
layout(local_size_x = 256) in;

#include "sim/entry_index.glsl"

const int STAGE_RECORD = 0;
const int STAGE_MEASURE = 1;
const int STAGE_RESTORE = 2;

layout(std430, binding = kSolverField) buffer Field { float values[]; };
layout(std430, binding = kSolverPartials) buffer Partials { double partials[]; };  // 3 per work group
layout(std430, binding = kSolverResults) buffer Results { double results[]; };

uniform uint count;  // PASS 0 and STAGE_RESTORE: samples; PASS 1: work groups of PASS 0
uniform uint field;  // the budget (unused by STAGE_RECORD PASS 0)

shared double folded[3][256];

double low() { return results[4u * field + 1u]; }
double high() { return results[4u * field + 2u]; }

// restoreTotal's front weight of a value (NaN where high = low: see scale).
double frontWeight(double value) {
    double v = clamp(value, low(), high());
    return (v - low()) * (high() - v) / (high() - low());
}

// Folds b into a: sums, then (STAGE_RECORD) the minimum and maximum.
void combine(inout double a[3], double b[3]) {
    a[0] += b[0];
    if (STAGE == STAGE_RECORD) {
        a[1] = min(a[1], b[1]);
        a[2] = max(a[2], b[2]);
    } else {
        a[1] += b[1];
    }
}

void restore() {
    uint i = entryIndex();
    double scale = results[4u * field + 3u];
    // scale is 0 where restoreTotal returns early, and where nothing is owed.
    if (i >= count || scale == 0.0lf) return;
    values[i] = float(double(values[i]) + scale * frontWeight(double(values[i])));
}

void main() {
    if (STAGE == STAGE_RESTORE) {
        restore();
        return;
    }
    uint t = gl_LocalInvocationID.x;
    // Sums start at 0; the minimum and maximum at a value of the field, so
    // that invocations without samples leave them as they are.
    double first = PASS == 0 ? double(values[0]) : partials[1];
    double totals[3] = STAGE == STAGE_RECORD ? double[3](0.0lf, first, first) : double[3](0.0lf, 0.0lf, 0.0lf);
    if (PASS == 0) {
        uint stride = gl_NumWorkGroups.x * 256u;
        for (uint i = gl_WorkGroupID.x * 256u + t; i < count; i += stride) {
            double value = double(values[i]);
            double term[3] = STAGE == STAGE_RECORD ? double[3](value, value, value)
                                                   : double[3](frontWeight(value), value, 0.0lf);
            combine(totals, term);
        }
    } else {
        for (uint i = t; i < count; i += 256u)
            combine(totals, double[3](partials[3u * i], partials[3u * i + 1u], partials[3u * i + 2u]));
    }
    for (int k = 0; k < 3; ++k) folded[k][t] = totals[k];
    barrier();
    for (uint width = 128u; width > 0u; width >>= 1) {
        if (t < width) {
            double mine[3] = double[3](folded[0][t], folded[1][t], folded[2][t]);
            combine(mine, double[3](folded[0][t + width], folded[1][t + width], folded[2][t + width]));
            for (int k = 0; k < 3; ++k) folded[k][t] = mine[k];
        }
        barrier();
    }
    if (t != 0u) return;
    if (PASS == 0) {
        for (int k = 0; k < 3; ++k) partials[3u * gl_WorkGroupID.x + uint(k)] = folded[k][0];
    } else if (STAGE == STAGE_RECORD) {
        for (int k = 0; k < 3; ++k) results[4u * field + uint(k)] = folded[k][0];
    } else {
        double total = results[4u * field], weights = folded[0][0], sum = folded[1][0];
        bool restorable = high() > low() && weights > 0.0lf;
        results[4u * field + 3u] = restorable ? clamp((total - sum) / weights, -1.0lf, 1.0lf) : 0.0lf;
    }
}
