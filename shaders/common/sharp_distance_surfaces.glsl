// Sharp mesh and water surfaces: the zero set of a signed distance φ
// (sim/voxelize/MeshCoverage.h: OpenVDB's narrow-band unsigned distance of
// the triangles, signed by ray parity) held at cell centres, one layer per
// object stacked along z of one texture (layer L, cell (i, j, k) at texel
// (i, j, k + L·nz)). GLSL only: it samples that texture. A surface of this
// kind (shape_a.w = kSharpDistance) keeps in shape_a.xyz, shape_b.xyz the box
// outside which φ > 0 and in shape_b.w its layer.
//
// φ is read trilinearly by hand (texelFetch and float weights: hardware
// filtering keeps as few as 8 bits of the weights on some GPUs, which would
// put a ripple of h/512 into the surface). A crossing is found by sphere
// tracing along the step's chord — |φ| is a lower bound on the distance to
// the surface within the band and at its clamped edge beyond — and refined
// by regula falsi (Illinois); the normal is φ's central-difference gradient,
// which is the trilinear interpolant of the cells' own central differences,
// so it turns continuously along the surface. Position and normal errors on
// a sphere mesh against the analytic sphere: docs/accuracy.md.

layout(binding = kSurfaceDistanceTexture) uniform sampler3D surface_distance_texture;

// Probes of φ per step at most; a step that would need more ends where the
// probing stopped (no crossing yet), and the next goes on from there.
const int EIKON_DISTANCE_PROBES = 24;
// Regula falsi iterations: the bracket shrinks far below a float's
// resolution of the position long before.
const int EIKON_DISTANCE_REFINEMENTS = 20;

// φ of `layer` at x, m.
float surface_distance(int layer, vec3 x) {
    ivec3 resolution = grid.resolution.xyz;
    vec3 g = clamp((x - grid.bounds_min.xyz) / grid.voxel_size.xyz - 0.5f, vec3(0.0f), vec3(resolution - 1));
    ivec3 i0 = min(ivec3(floor(g)), resolution - 1);
    ivec3 i1 = min(i0 + 1, resolution - 1);
    vec3 f = g - vec3(i0);
    int z0 = i0.z + layer * resolution.z;
    int z1 = i1.z + layer * resolution.z;
    float c00 = mix(texelFetch(surface_distance_texture, ivec3(i0.x, i0.y, z0), 0).r,
                    texelFetch(surface_distance_texture, ivec3(i1.x, i0.y, z0), 0).r, f.x);
    float c10 = mix(texelFetch(surface_distance_texture, ivec3(i0.x, i1.y, z0), 0).r,
                    texelFetch(surface_distance_texture, ivec3(i1.x, i1.y, z0), 0).r, f.x);
    float c01 = mix(texelFetch(surface_distance_texture, ivec3(i0.x, i0.y, z1), 0).r,
                    texelFetch(surface_distance_texture, ivec3(i1.x, i0.y, z1), 0).r, f.x);
    float c11 = mix(texelFetch(surface_distance_texture, ivec3(i0.x, i1.y, z1), 0).r,
                    texelFetch(surface_distance_texture, ivec3(i1.x, i1.y, z1), 0).r, f.x);
    return mix(mix(c00, c10, f.y), mix(c01, c11, f.y), f.z);
}

int distance_layer(vec4 shape_b) { return int(shape_b.w + 0.5f); }

bool inside_distance_surface(vec4 shape_a, vec4 shape_b, vec3 x) {
    return inside_box(xyz_of(shape_a), xyz_of(shape_b), x) && surface_distance(distance_layer(shape_b), x) < 0.0f;
}

// The outward unit normal: φ's gradient by central differences one cell apart.
vec3 distance_surface_normal(vec4 shape_b, vec3 x) {
    int layer = distance_layer(shape_b);
    vec3 h = grid.voxel_size.xyz;
    vec3 gradient = vec3(surface_distance(layer, x + vec3(h.x, 0.0f, 0.0f)) - surface_distance(layer, x - vec3(h.x, 0.0f, 0.0f)),
                         surface_distance(layer, x + vec3(0.0f, h.y, 0.0f)) - surface_distance(layer, x - vec3(0.0f, h.y, 0.0f)),
                         surface_distance(layer, x + vec3(0.0f, 0.0f, h.z)) - surface_distance(layer, x - vec3(0.0f, 0.0f, h.z))) /
                    (2.0f * h);
    float length_ = length(gradient);
    return length_ > 0.0f ? gradient / length_ : vec3(0.0f, 1.0f, 0.0f);
}

// How far off a distance surface a ray goes on, on the side it continues
// on: far above the float resolution of positions (~1e-7 of the grid's
// size), far below any length the grid resolves. The crossing itself is not
// moved: φ's root is where regula falsi put it.
float distance_surface_clearance() { return 1e-4f * min(grid.voxel_size.x, min(grid.voxel_size.y, grid.voxel_size.z)); }

// Along the unit d from x, within `reach`: where φ first takes the sign of
// the other side (x.y = 1), or, when it does not, how far the chord was
// searched (x.y = 0; the whole reach unless the probes ran out). A ray is on
// the side `inside` says; the search starts t_min along, past the surface a
// ray that was just put there sits on, and a ray found on the wrong side
// there crosses at once.
vec2 distance_surface_crossing(vec4 shape_a, vec4 shape_b, vec3 x, vec3 d, bool inside, float reach, float t_min) {
    int layer = distance_layer(shape_b);
    float side = inside ? -1.0f : 1.0f;
    float t_low = t_min;
    float t_high = reach;
    if (!inside) {  // φ < 0 only inside the box
        vec2 interval = box_ray_interval(xyz_of(shape_a), xyz_of(shape_b), x, d);
        t_low = max(t_low, interval.x);
        t_high = min(t_high, interval.y);
        if (t_low >= t_high) return vec2(reach, 0.0f);
    }
    float smallest_probe = 0.05f * min(grid.voxel_size.x, min(grid.voxel_size.y, grid.voxel_size.z));
    float t_a = t_low;
    float phi_a = side * surface_distance(layer, x + t_a * d);
    if (phi_a <= 0.0f) return vec2(t_a, 1.0f);
    float t_b = t_a;
    float phi_b = phi_a;
    bool bracketed = false;
    for (int probe = 0; probe < EIKON_DISTANCE_PROBES && t_a < t_high; ++probe) {
        // |∇φ| of the trilinear φ can exceed 1 a little: 0.8 of |φ| is safe.
        t_b = min(t_a + max(0.8f * phi_a, smallest_probe), t_high);
        phi_b = side * surface_distance(layer, x + t_b * d);
        if (phi_b <= 0.0f) {
            bracketed = true;
            break;
        }
        t_a = t_b;
        phi_a = phi_b;
    }
    if (!bracketed) return vec2(min(t_a, reach), 0.0f);
    // Illinois regula falsi on φ(t_a) > 0 ≥ φ(t_b).
    int kept = 0;
    for (int i = 0; i < EIKON_DISTANCE_REFINEMENTS; ++i) {
        float t = t_a + (t_b - t_a) * phi_a / (phi_a - phi_b);
        if (!(t > t_a && t < t_b)) break;
        float phi = side * surface_distance(layer, x + t * d);
        if (phi > 0.0f) {
            t_a = t;
            phi_a = phi;
            if (kept == 1) phi_b *= 0.5f;
            kept = 1;
        } else {
            t_b = t;
            phi_b = phi;
            if (kept == -1) phi_a *= 0.5f;
            kept = -1;
        }
    }
    return vec2(t_b, 1.0f);
}
