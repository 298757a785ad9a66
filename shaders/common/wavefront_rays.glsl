// A wavefront ray (common/wavefront_patches.glsl): its march from the light
// to where it ends with the photons' march (common/ray_march_steps.glsl),
// following one branch of the Fresnel tree, and what it brings back (the
// Corner). A patch's corners are such rays; so is the axis of a finished
// patch's tube where the pass stores fluence, which deposits the patch's
// power along its way (common/fluence_deposits.glsl). The includer declares
// Corner, `branch`, `channel` and count_march (the march's tallies). Shared
// by GLSL and C++ (render/stages/NativeWavefrontTrace.cpp).
const uint kUnbranched = 0xFFFFFFu;  // history of a ray that ended before its branch's reflection

// A ray's ledger at sharp surfaces. A Fresnel event is a crossing whose
// reflectance is strictly between 0 and 1 (total internal reflection is not
// one: it always reflects). Each wavefront follows one branch of the ray
// tree: the main one (`branch` −1) transmits at every Fresnel event; branch
// b reflects at Fresnel event b and transmits at the others. What a branch
// does not follow is tallied as unfollowed; the power a branch starts with
// at its reflection is its source.
struct SurfaceLedger {
    uint transmissions;
    uint reflections;  // total internal reflections, and the branch's own
    uint fresnel_events;
    bool branched;     // the branch's reflection has happened (always true for the main branch)
};

#if EIKON_SHARP_SURFACES
// Where a step ended at a sharp surface: the way this wavefront's branch goes
// on, with the Fresnel transmittance or reflectance as its power factor.
void follow_branch(SurfaceCrossing crossing, INOUT(vec3) x, INOUT(vec3) x_lost, INOUT(vec3) v, INOUT(vec4) field,
                   INOUT(vec3) power, INOUT(vec3) absorbed, INOUT(vec3) source, INOUT(SurfaceLedger) ledger) {
    vec3 d = normalize(v);
    SurfaceEvent event = sharp_surface_event(crossing, x, d, inside_mask, channel_scale);
    x_lost = vec3(0.0f);
    bool fresnel_event = event.reflectance > 0.0f && event.reflectance < 1.0f;
    bool reflects = event.reflectance >= 1.0f || (fresnel_event && int(ledger.fresnel_events) == branch);
    if (fresnel_event) ++ledger.fresnel_events;
    if (reflects) {
        x = event.x_reflected;
        d = mirrored_direction(d, event.facing);
        ++ledger.reflections;
        if (event.reflectance < 1.0f) {  // this branch's reflection: its ledger starts here
            power *= event.reflectance;
            source = power;
            absorbed = vec3(0.0f);
            ledger.branched = true;
        }
    } else {
        x = event.x_transmitted;
        d = refracted_direction(d, event.facing, event.n_here, event.n_beyond);
        power *= 1.0f - event.reflectance;
        inside_mask = event.beyond_mask;
        sharp_offset = event.beyond_offset;
        ++ledger.transmissions;
    }
    field = field_at(x);
    v = field.w * d;
}
#endif

// Where a ray first crossed a receiver's plane outside its square: a
// footprint reaching past the square's edge is cut there exactly.
struct PlaneCrossing {
    int receiver;  // −1: none yet
    vec2 map_uv;
};

void note_plane_crossing(vec3 a, vec3 b, INOUT(PlaneCrossing) crossing) {
    for (uint r = 0u; r < receiver_count; ++r) {
        float da = receiver_signed_distance(a, xyz_of(receivers[r].origin), xyz_of(receivers[r].normal));
        float db = receiver_signed_distance(b, xyz_of(receivers[r].origin), xyz_of(receivers[r].normal));
        bool first = crossing.receiver < 0 && da > 0.0f && db <= 0.0f;  // lit side to back only, the first noted
        vec2 uv = receiver_map_coordinates(mix(a, b, first ? da / (da - db) : 0.0f), xyz_of(receivers[r].origin),
                                           xyz_of(receivers[r].axis_u), xyz_of(receivers[r].axis_v), receivers[r].origin.w);
        crossing.receiver = first ? int(r) : crossing.receiver;
        crossing.map_uv = first ? uv : crossing.map_uv;
    }
}

// The same for the ray x + t·d, 0 ≤ t ≤ reach, however far it goes (reach
// may be EIKON_INFINITY): the plane's crossing solved for t.
void note_ray_plane_crossing(vec3 x, vec3 d, float reach, INOUT(PlaneCrossing) crossing) {
    for (uint r = 0u; r < receiver_count; ++r) {
        float height = receiver_signed_distance(x, xyz_of(receivers[r].origin), xyz_of(receivers[r].normal));
        float approach = dot(d, xyz_of(receivers[r].normal));
        float t = approach < 0.0f ? -height / approach : 0.0f;
        bool first = crossing.receiver < 0 && height > 0.0f && approach < 0.0f && t <= reach;  // lit side to back only
        vec2 uv = receiver_map_coordinates(x + t * d, xyz_of(receivers[r].origin), xyz_of(receivers[r].axis_u),
                                           xyz_of(receivers[r].axis_v), receivers[r].origin.w);
        crossing.receiver = first ? int(r) : crossing.receiver;
        crossing.map_uv = first ? uv : crossing.map_uv;
    }
}

// Traces the ray of point u of face `face` of the emitter's domain to its
// end. A tube's axis carries tube_power (W per unit of the ray's power
// factor: the patch's power) and deposits it as fluence once its branch has
// begun; a corner (tube_power 0) deposits nothing.
Corner trace_ray(uint emitter_index, uint face, vec2 u, vec3 tube_power) {
    bool tube = any(greaterThan(tube_power, vec3(0.0f)));
    Emitter emitter = emitters[emitter_index];
    vec3 x;
    vec3 direction;
    emission_ray(emitter, face, u, x, direction);
    PlaneCrossing outside = PlaneCrossing(-1, vec2(0.0f));
    channel_scale = channel < 0 ? dispersion.x : dispersion[channel];
    vec3 power = channel_mask();  // the spot's profile is the patch's (patch_power)
    vec3 source = branch < 0 ? power : vec3(0.0f);
    vec3 absorbed = vec3(0.0f);
    SurfaceLedger ledger = SurfaceLedger(0u, 0u, 0u, branch < 0);
    vec3 x_lost = vec3(0.0f);
#if EIKON_SHARP_SURFACES
    inside_mask = 0u;
    sharp_offset = 0.0f;
    if (grid_contains(x)) enter_sharp_region(x);
#endif
    vec4 field = grid_contains(x) ? field_at(x) : vec4(0.0f, 0.0f, 0.0f, reference_index());
    vec3 v = field.w * direction;
    uint steps = 0u;
    float max_invariant_error = 0.0f;
    float invariant_error_sum = 0.0f;
    int fate = kEscaped;
    ReceiverHit landed = ReceiverHit(-1, 0.0f, false, vec2(0.0f));
    vec4 last_inside = vec4(x, grid_contains(x) ? 1.0f : 0.0f);  // xyz: the last point in the grid the march reached; w: 1 once there
    for (;;) {
        spend_loops(loops_per_pass());
        if (!loops_left()) {
            fate = kCutOff;
            break;
        }
        if (!grid_contains(x)) {
            vec3 d = normalize(v);
            StraightFlight flight = fly_straight(x, d);
            if (flight.hit.receiver >= 0) {
                landed = flight.hit;
                break;
            }
            note_ray_plane_crossing(x, d, flight.distance, outside);
            if (!flight.enters_grid) break;
            x = grid_entry_point(x, d, flight);
            x_lost = vec3(0.0f);
            if (!grid_contains(x)) continue;
#if EIKON_SHARP_SURFACES
            enter_sharp_region(x);
#endif
            field = field_at(x);
            v = field.w * d;
            last_inside = vec4(x, 1.0f);
            continue;
        }
        if (steps >= max_steps) {
            fate = kCutOff;
            break;
        }
        float ds = next_step(x, v);
#if EIKON_SHARP_SURFACES
        SurfaceCrossing crossing = nearest_surface_crossing(x, normalize(v), inside_mask, ds, 1e-4f * grid.voxel_size.x);
        ds = crossing.distance;
        if (!loops_left()) {
            fate = kCutOff;
            break;
        }
#endif
        vec3 start = x;
        integrate(x, x_lost, v, field, ds);
        ++steps;
        float invariant_error = eikonal_invariant_error(v, field.w);
        max_invariant_error = max(max_invariant_error, invariant_error);
        invariant_error_sum += invariant_error;
        ReceiverHit hit = first_receiver_crossing(start, x);
        float travelled = travelled_inside_grid(start, x, ds, hit.receiver >= 0 ? hit.fraction * ds : ds);
        vec3 medium = owned_medium_point(start, inside_mask);
        vec3 kappa = sample_extinction(medium);
        last_inside = vec4(mix(start, x, ds > 0.0f ? travelled / ds : 0.0f), 1.0f);
        if (tube && ledger.branched)
            deposit_tube_segment(start, xyz_of(last_inside), tube_power * power, kappa, sample_scattering(medium));
        vec3 transmitted = power * beer_lambert_transmittance(kappa, travelled);
        absorbed += power - transmitted;
        power = transmitted;
        if (hit.receiver >= 0) {
            landed = hit;
            break;
        }
        note_plane_crossing(start, x, outside);
#if EIKON_SHARP_SURFACES
        if (crossing.surface >= 0) follow_branch(crossing, x, x_lost, v, field, power, absorbed, source, ledger);
#endif
        if (!grid_contains(x)) v = reference_index() * normalize(v);
    }
    if (landed.receiver >= 0) fate = landed.lit_side ? kReceived : kBlocked;
    if (fate == kEscaped && outside.receiver >= 0) {  // escaped past a square: where it crossed its plane
        landed.receiver = outside.receiver;
        landed.map_uv = outside.map_uv;
    }
    count_march(steps, max_invariant_error, invariant_units(invariant_error_sum));
    Corner corner;
    corner.ends = vec4(u, landed.map_uv);
    corner.exit = last_inside;
    uint history = min(ledger.transmissions, 4095u) | (min(ledger.reflections, 4095u) << 12);
    if (!ledger.branched) {  // the ray ended before this branch's reflection: none of its power is here
        power = vec3(0.0f);
        absorbed = vec3(0.0f);
        history = kUnbranched;
        fate = kEscaped;
        landed.receiver = -1;
    }
    corner.power = vec4(power, uintBitsToFloat(history));
    corner.absorbed = vec4(absorbed, uintBitsToFloat(uint(fate) | (uint(landed.receiver + 1) << 4)));
    corner.source = vec4(source, 0.0f);
    return corner;
}
