// The emission domain of a light for the wavefront pass
// (wavefront_trace.comp): its faces, the ray of each point of a face, and
// the exact power of a patch. Needs common/emitters.glsl and
// common/footprint_coverage.glsl; the includer declares `channel`. GLSL only.
uniform uint emission_faces;  // faces of this emitter's emission domain (WavefrontStage::emissionFaces)

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
    vec3 axis = emitter.axis.xyz;
    vec3 tangent = emitter.tangent.xyz;
    vec3 bitangent = emitter.bitangent.xyz;
    if (emission_faces == 1u) {
        float spread = sqrt(max(0.0f, 1.0f - emitter.axis.w * emitter.axis.w)) / emitter.axis.w;  // tan α
        return axis + spread * (s.x * tangent + s.y * bitangent);
    }
    float side = (face % 2u == 0u) ? 1.0f : -1.0f;
    if (face < 2u) return side * axis + s.x * tangent + s.y * bitangent;
    if (face < 4u) return side * tangent + s.x * bitangent + s.y * axis;
    return side * bitangent + s.x * axis + s.y * tangent;
}

void emission_ray(Emitter emitter, uint face, vec2 u, out vec3 x, out vec3 d) {
    if (emitter.origin.w == 0.0f) {
        x = emitter.origin.xyz;
        d = normalize(face_direction(emitter, face, u));
    } else {
        vec2 s = 2.0f * u - 1.0f;
        x = emitter.origin.xyz + emitter.axis.w * (s.x * emitter.tangent.xyz + s.y * emitter.bitangent.xyz);
        d = emitter.axis.xyz;
    }
}

vec3 channel_mask() {
    if (channel < 0) return vec3(1.0f);
    vec3 only = vec3(0.0f);
    only[channel] = 1.0f;
    return only;
}

// The power (W, RGB, where the spot profile is 1) a patch of face `face`
// with corners u0, u1, u2 receives from the emitter: the photon emitter's
// power over its cone or disk (photon power × photons) gives the intensity
// I = P/(2π(1 − cos α)) or irradiance E = P/(πR²). The solid angle is
// Van Oosterom and Strackee's, tan(Ω/2) = |a·(b×c)| / (1 + a·b + b·c + c·a),
// in double precision: a patch a ten-thousandth of a radian across would
// lose three digits in float.
vec3 patch_power(Emitter emitter, uint face, vec2 u0, vec2 u1, vec2 u2) {
    vec3 power = emitter.photon_power.rgb * float(emitter.photons.y);
    if (emitter.origin.w != 0.0f) {
        float radius = emitter.axis.w;
        return power / (3.14159265358979f * radius * radius) * (4.0f * radius * radius) *
               (0.5f * abs(twice_signed_area(u0, u1, u2)));
    }
    dvec3 a = normalize(dvec3(face_direction(emitter, face, u0)));
    dvec3 b = normalize(dvec3(face_direction(emitter, face, u1)));
    dvec3 c = normalize(dvec3(face_direction(emitter, face, u2)));
    double triple = abs(dot(a, cross(b - a, c - a)));
    double denominator = 1.0lf + dot(a, b) + dot(b, c) + dot(c, a);
    float solid_angle = 2.0f * atan(float(triple), float(denominator));
    float cone = 2.0f * 3.14159265358979f * (1.0f - emitter.axis.w);
    return power / cone * solid_angle;
}
