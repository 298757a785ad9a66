// Sharp surfaces: the exact boundaries of objects inside graded media. Light
// follows the ray equation between them and refracts (Snell) or reflects
// (Fresnel, total internal reflection) where a step meets one.
// A surface is two vec4s (bridge/layout/GpuLayouts.h, GpuSharpSurface):
//   shape_a: xyz sphere centre, or box min; w kind (kSharpSphere, kSharpBox, kSharpTriangles)
//   shape_b: x sphere radius, or xyz box max; w a mesh's root node
// This file holds the analytic shapes (spheres, boxes) and the refraction
// law; mesh and water surfaces, given by their triangles, are in
// sharp_triangle_surfaces.glsl (GLSL only: it reads storage buffers).
// Shared by GLSL and C++ (cpp_shim.h).

const float EIKON_NO_CROSSING = 1e30f;

int surface_kind(vec4 shape_a) { return int(shape_a.w + 0.5f); }

bool is_box(vec4 shape_a) { return surface_kind(shape_a) == kSharpBox; }

// Whether p lies inside the box [low, high].
bool inside_box(vec3 low, vec3 high, vec3 p) { return all(greaterThan(p, low)) && all(lessThan(p, high)); }

// Parameters (t_enter, t_leave) of the line x + t·d inside the box [low,
// high] (slabs; a zero component of d becomes tiny so that 0·∞ never
// appears); t_enter > t_leave when it misses.
vec2 box_ray_interval(vec3 low, vec3 high, vec3 x, vec3 d) {
    vec3 safe = mix(d, vec3(1e-12f), lessThan(abs(d), vec3(1e-12f)));
    vec3 t1 = (low - x) / safe;
    vec3 t2 = (high - x) / safe;
    vec3 t_low = min(t1, t2);
    vec3 t_high = max(t1, t2);
    return vec2(max(t_low.x, max(t_low.y, t_low.z)), min(t_high.x, min(t_high.y, t_high.z)));
}

// Whether p lies inside the shape.
bool inside_shape(vec4 shape_a, vec4 shape_b, vec3 p) {
    if (is_box(shape_a)) return inside_box(xyz_of(shape_a), xyz_of(shape_b), p);
    vec3 offset = p - xyz_of(shape_a);
    return dot(offset, offset) < shape_b.x * shape_b.x;
}

// Distance along the unit direction d from x to the surface: where the ray
// leaves the shape when `inside`, else where it enters it beyond t_min (a
// ray just reflected off the outside starts on the surface);
// EIKON_NO_CROSSING when it does not meet it.
float surface_crossing(vec4 shape_a, vec4 shape_b, vec3 x, vec3 d, bool inside, float t_min) {
    if (is_box(shape_a)) {
        vec2 interval = box_ray_interval(xyz_of(shape_a), xyz_of(shape_b), x, d);
        float t_enter = interval.x;
        float t_leave = interval.y;
        if (inside) return t_leave > 0.0f ? t_leave : 0.0f;
        return (t_enter <= t_leave && t_enter > t_min) ? t_enter : EIKON_NO_CROSSING;
    }
    vec3 offset = x - xyz_of(shape_a);
    float b = dot(offset, d);
    float c = dot(offset, offset) - shape_b.x * shape_b.x;
    float discriminant = b * b - c;
    if (discriminant < 0.0f) return inside ? 0.0f : EIKON_NO_CROSSING;
    float root = sqrt(discriminant);
    if (inside) return max(-b + root, 0.0f);
    float near = -b - root;
    return near > t_min ? near : EIKON_NO_CROSSING;
}

// The point of the surface nearest p (p close to it), where a step that was
// cut at the crossing ends exactly.
vec3 onto_surface(vec4 shape_a, vec4 shape_b, vec3 p) {
    if (!is_box(shape_a)) {
        vec3 offset = p - xyz_of(shape_a);
        return xyz_of(shape_a) + (shape_b.x / max(length(offset), 1e-30f)) * offset;
    }
    vec3 to_low = abs(p - xyz_of(shape_a));
    vec3 to_high = abs(xyz_of(shape_b) - p);
    vec3 nearest = min(to_low, to_high);
    vec3 face = mix(xyz_of(shape_b), xyz_of(shape_a), lessThan(to_low, to_high));
    vec3 q = p;
    if (nearest.x <= nearest.y && nearest.x <= nearest.z) q.x = face.x;
    else if (nearest.y <= nearest.z) q.y = face.y;
    else q.z = face.z;
    return q;
}

// The outward unit normal at a point on the surface.
vec3 surface_normal(vec4 shape_a, vec4 shape_b, vec3 p) {
    if (!is_box(shape_a)) return normalize(p - xyz_of(shape_a));
    vec3 to_low = abs(p - xyz_of(shape_a));
    vec3 to_high = abs(xyz_of(shape_b) - p);
    vec3 nearest = min(to_low, to_high);
    vec3 sign_ = mix(vec3(1.0f), vec3(-1.0f), lessThan(to_low, to_high));
    if (nearest.x <= nearest.y && nearest.x <= nearest.z) return vec3(sign_.x, 0.0f, 0.0f);
    if (nearest.y <= nearest.z) return vec3(0.0f, sign_.y, 0.0f);
    return vec3(0.0f, 0.0f, sign_.z);
}

// p, where it lies within `margin` of the surface on the side `inside`
// says, moved along the surface's normal to `margin` off it on that side (to
// the centre of a sphere, or the middle of a box on an axis, narrower than
// that). Tracers read a sharp object's voxelised optics there (common/
// sharp_surface_crossings.glsl, owned_medium_point).
vec3 off_the_surface(vec4 shape_a, vec4 shape_b, vec3 p, bool inside, float margin) {
    if (is_box(shape_a)) {
        vec3 low = xyz_of(shape_a);
        vec3 high = xyz_of(shape_b);
        if (inside) {
            vec3 middle = 0.5f * (low + high);
            return clamp(p, min(low + margin, middle), max(high - margin, middle));
        }
        vec3 nearest = clamp(p, low, high);
        vec3 away = p - nearest;
        float gap = length(away);
        if (gap >= margin) return p;
        if (gap > 0.0f) return nearest + (margin / gap) * away;
        return p + margin * surface_normal(shape_a, shape_b, p);  // on a face
    }
    vec3 centre = xyz_of(shape_a);
    vec3 offset = p - centre;
    float r = length(offset);
    float wanted = inside ? max(shape_b.x - margin, 0.0f) : shape_b.x + margin;
    if (inside ? r <= wanted : r >= wanted) return p;
    return r > 0.0f ? centre + (wanted / r) * offset : p;
}

// Snell's law in vector form: the refracted unit direction of the unit d
// through a surface whose unit normal `facing` points back against d, from
// index n_i into n_t; cos_t² < 0 (total internal reflection) is the caller's
// to catch first.
vec3 refracted_direction(vec3 d, vec3 facing, float n_i, float n_t) {
    float eta = n_i / n_t;
    float cos_i = -dot(d, facing);
    float cos_t = sqrt(max(0.0f, 1.0f - eta * eta * (1.0f - cos_i * cos_i)));
    return normalize(eta * d + (eta * cos_i - cos_t) * facing);
}

// The mirror direction of d about the surface.
vec3 mirrored_direction(vec3 d, vec3 facing) {
    return d - 2.0f * dot(d, facing) * facing;
}
