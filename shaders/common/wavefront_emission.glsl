// The emission domain of a light for the wavefront pass
// (wavefront_trace.comp): its faces, the ray of each point of a face, and
// the exact power of a patch. Needs common/emitters.glsl and
// common/footprint_coverage.glsl; the includer declares `channel` and
// `emission_faces` (the faces of this emitter's emission domain,
// WavefrontStage::emissionFaces). Shared by GLSL and C++
// (render/stages/NativeWavefrontTrace.cpp).

// The emission domain of a light: one or six square faces, each [0, 1]², so
// that straight lines in a face stay straight where light lands on a plane
// (a patch's footprint there is the triangle of its corners) and a patch's
// power is exact:
// - a directional light: the square circumscribing its disk, positions
//   origin + R·((2u − 1)·tangent + (2v − 1)·bitangent); power E·area;
// - a point or spot light whose cone toward the traced region is at most 60°
//   wide: the gnomonic square of that cone, directions axis +
//   tan α·((2u − 1)·tangent + (2v − 1)·bitangent), normalised; power I·Ω,
//   Ω the solid angle of the spherical triangle of the corner directions
//   (great circles are the gnomonic images of straight lines);
// - a wider cone: the six faces of the cube about the light (face k: ±axis,
//   ±tangent, ±bitangent), each gnomonic.
vec3 face_direction(Emitter emitter, uint face, vec2 u) {
    vec2 s = 2.0f * u - 1.0f;
    vec3 axis = xyz_of(emitter.axis);
    vec3 tangent = xyz_of(emitter.tangent);
    vec3 bitangent = xyz_of(emitter.bitangent);
    if (emission_faces == 1u) {
        float h = emitter.axis.w;  // 1 − cos α
        float spread = sqrt(max(0.0f, h * (2.0f - h))) / (1.0f - h);  // tan α
        return axis + spread * (s.x * tangent + s.y * bitangent);
    }
    float side = (face % 2u == 0u) ? 1.0f : -1.0f;
    if (face < 2u) return side * axis + s.x * tangent + s.y * bitangent;
    if (face < 4u) return side * tangent + s.x * bitangent + s.y * axis;
    return side * bitangent + s.x * axis + s.y * tangent;
}

void emission_ray(Emitter emitter, uint face, vec2 u, OUT(vec3) x, OUT(vec3) d) {
    if (emitter.origin.w == 0.0f) {
        x = xyz_of(emitter.origin);
        d = normalize(face_direction(emitter, face, u));
    } else {
        vec2 s = 2.0f * u - 1.0f;
        x = xyz_of(emitter.origin) + emitter.axis.w * (s.x * xyz_of(emitter.tangent) + s.y * xyz_of(emitter.bitangent));
        d = xyz_of(emitter.axis);
    }
}

vec3 channel_mask() {
    if (channel < 0) return vec3(1.0f);
    vec3 only = vec3(0.0f);
    only[channel] = 1.0f;
    return only;
}

// face_direction in double precision, unit length.
dvec3 face_direction_exact(Emitter emitter, uint face, vec2 u) {
    dvec2 s = double(2.0f) * dvec2(u) - double(1.0f);
    dvec3 axis = dvec3(xyz_of(emitter.axis));
    dvec3 tangent = dvec3(xyz_of(emitter.tangent));
    dvec3 bitangent = dvec3(xyz_of(emitter.bitangent));
    dvec3 direction;
    if (emission_faces == 1u) {
        float h = emitter.axis.w;
        float spread = sqrt(max(0.0f, h * (2.0f - h))) / (1.0f - h);
        direction = axis + double(spread) * (s.x * tangent + s.y * bitangent);
    } else {
        double side = (face % 2u == 0u) ? double(1.0f) : double(-1.0f);
        if (face < 2u) direction = side * axis + s.x * tangent + s.y * bitangent;
        else if (face < 4u) direction = side * tangent + s.x * bitangent + s.y * axis;
        else direction = side * bitangent + s.x * axis + s.y * tangent;
    }
    return normalize(direction);
}

// The solid angle of the spherical triangle of unit directions a, b, c (great
// circles are the gnomonic images of straight lines): Van Oosterom and
// Strackee's tan(Ω/2) = |a·(b×c)| / (1 + a·b + b·c + c·a), in double
// precision: a patch a ten-thousandth of a radian across would lose three
// digits in float.
float solid_angle(dvec3 a, dvec3 b, dvec3 c) {
    double triple = abs(dot(a, cross(b - a, c - a)));
    double denominator = double(1.0f) + dot(a, b) + dot(b, c) + dot(c, a);
    return 2.0f * atan(float(triple), float(denominator));
}

// Versine 1 − cos θ of the angle between unit vectors: |a − b|²/2, exact
// where 1 − a·b would cancel.
double versine_between(dvec3 a, dvec3 b) {
    dvec3 apart = a - b;
    return double(0.5f) * dot(apart, apart);
}

float angle_of_versine(double h) { return 2.0f * asin(min(1.0f, sqrt(float(double(0.5f) * h)))); }

// Of a triangle on which f is linear, the share where f ≥ 0 (the spot's hard
// edge, f = vₒ − v, cut as the chord of its circle across a sub-triangle).
float share_where_positive(float f0, float f1, float f2) {
    int positive = int(f0 >= 0.0f) + int(f1 >= 0.0f) + int(f2 >= 0.0f);
    if (positive == 3) return 1.0f;
    if (positive == 0) return 0.0f;
    // The lone corner on its side, and the share of the small triangle it cuts off.
    float sign = positive == 1 ? 1.0f : -1.0f;
    float a = sign * f0, b = sign * f1, c = sign * f2;
    float lone = a >= 0.0f ? a : (b >= 0.0f ? b : c);
    float other1 = a >= 0.0f ? b : a;
    float other2 = a >= 0.0f ? c : (b >= 0.0f ? c : b);
    float cut = lone * lone / ((lone - other1) * (lone - other2));
    return positive == 1 ? cut : 1.0f - cut;
}

// The spot profile's mean over the patch with corners u0, u1, u2: 1 or 0
// where the patch lies wholly inside the inner cone or outside the outer one
// (every corner farther from each edge than the patch is wide), else the
// profile integrated over kProfileCuts² sub-triangles of the patch (exact
// partitions of its spherical triangle: the gnomonic map keeps straight
// lines), weighted by their solid angles — a hard edge cut across each
// sub-triangle by its chord, a soft one by the mean of its corners. The
// corners alone (the profile at each, a third of the patch each) put the
// power of a hard-edged spot 0.15–0.37% low.
const int kProfileCuts = 8;

float patch_profile(Emitter emitter, uint face, vec2 u0, vec2 u1, vec2 u2) {
    if (emitter.origin.w != 0.0f || emitter.spot.w < 0.0f) return 1.0f;
    dvec3 axis = normalize(dvec3(xyz_of(emitter.spot)));
    double outer = double(emitter.spot.w), inner = double(emitter.spot_edge.x);
    bool hard = inner >= outer;
    vec2 u[3];
    u[0] = u0;
    u[1] = u1;
    u[2] = u2;
    dvec3 d[3];
    for (int k = 0; k < 3; ++k) d[k] = face_direction_exact(emitter, face, u[k]);
    float width = max(angle_of_versine(versine_between(d[0], d[1])),
                      max(angle_of_versine(versine_between(d[1], d[2])), angle_of_versine(versine_between(d[2], d[0]))));
    float outer_angle = angle_of_versine(outer), inner_angle = angle_of_versine(inner);
    bool clear = true;  // no edge crosses the patch, and the profile is flat (1 or 0) over it
    float profile = 0.0f;
    for (int k = 0; k < 3; ++k) {
        double h = versine_between(d[k], axis);
        float angle = angle_of_versine(h);
        clear = clear && abs(angle - outer_angle) > 1.001f * width + 1e-7f * outer_angle &&
                (hard || (abs(angle - inner_angle) > 1.001f * width + 1e-7f * inner_angle && (h <= inner || h >= outer)));
        profile = spot_profile_at_versine(float(h), emitter.spot.w, emitter.spot_edge.x);
    }
    if (clear) return profile;
    float weighted = 0.0f, total = 0.0f;
    const float n = float(kProfileCuts);
    for (int j = 0; j < kProfileCuts; ++j)
        for (int i = 0; i + j < kProfileCuts; ++i)
            for (int up = 0; up < 2; ++up) {
                if (up == 1 && i + j + 2 > kProfileCuts) continue;
                ivec2 corner[3];
                corner[0] = ivec2(i + up, j);
                corner[1] = ivec2(i + 1, j + up);
                corner[2] = ivec2(i, j + 1);
                dvec3 c[3];
                float f[3];
                float mean = 0.0f;
                for (int k = 0; k < 3; ++k) {
                    vec2 at = u0 + (float(corner[k].x) / n) * (u1 - u0) + (float(corner[k].y) / n) * (u2 - u0);
                    c[k] = face_direction_exact(emitter, face, at);
                    double h = versine_between(c[k], axis);
                    f[k] = float(outer - h);
                    mean += spot_profile_at_versine(float(h), emitter.spot.w, emitter.spot_edge.x) / 3.0f;
                }
                float omega = solid_angle(c[0], c[1], c[2]);
                weighted += omega * (hard ? share_where_positive(f[0], f[1], f[2]) : mean);
                total += omega;
            }
    return total > 0.0f ? weighted / total : profile;
}

// The power (W, RGB) a patch of face `face` with corners u0, u1, u2 receives
// from the emitter: the photon emitter's power over its cone or disk (photon
// power × photons, where the spot profile is 1) gives the intensity
// I = P/(2π(1 − cos α)) or irradiance E = P/(πR²); a cone's patch carries
// I·Ω times the spot profile's mean over it (patch_profile).
vec3 patch_power(Emitter emitter, uint face, vec2 u0, vec2 u1, vec2 u2) {
    vec3 power = xyz_of(emitter.photon_power) * float(emitter.photons.y);
    if (emitter.origin.w != 0.0f) {
        float radius = emitter.axis.w;
        return power / (3.14159265358979f * radius * radius) * (4.0f * radius * radius) *
               (0.5f * abs(twice_signed_area(u0, u1, u2)));
    }
    float omega = solid_angle(face_direction_exact(emitter, face, u0), face_direction_exact(emitter, face, u1),
                              face_direction_exact(emitter, face, u2));
    float cone = 2.0f * 3.14159265358979f * emitter.axis.w;
    return power / cone * omega * patch_profile(emitter, face, u0, u1, u2);
}
