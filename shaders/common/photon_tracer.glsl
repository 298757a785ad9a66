// The photon pass's tracer ([Sun08] §4.3–4.4 and §5.3; the program and
// its options: photon_trace.comp): a photon's emission, its flight and
// march, its crossings of sharp surfaces, its landings on receivers and its
// tallies. Shared by GLSL and C++: the includer declares the pass's
// uniforms, buffers and per-photon state and its tallies —
//   add_group_power(index, units)   power units into [3·tally + channel]
//   add_wide_receiver(word, units)  units into a receiver texel's 64-bit sum
//   count_surface_event(kind)       0 reflected, 1 transmitted at a sharp surface
//   count_photon(fate)              a photon ended (fate: layout::PowerTally)
//   count_march(steps, max error, deposits, invariant units)
// — and record_vertex and record_end (GLSL: photon_trace.comp, as atomics
// on the work group's shared tallies; C++: render/stages/NativePhotonTrace.cpp,
// as sums in a thread's own integer tallies: the same integers either way).
// The resumable parts (EIKON_RESUMABLE: the driver caps loops) are GLSL
// only; the native pass runs without a loop budget.

const uint MAX_BOUNCES = 16u;
// Random dimensions of the roulette draws, apart from those of emission (0,
// 1), receiver bounces (2, 3, …), sharp surfaces (64, 65, …) and a glow
// photon's cell and point (kGlowDimensions).
const uint kRouletteDimensions = 0x80000000u;

// A power in fixed-point tally units (power_unit W each), per channel.
uvec3 power_units(vec3 power) {
    return uvec3(power / power_unit + 0.5f);
}

// Into the pass's energy balance, tally `tally` (layout::PowerTally).
void add_power(int tally, vec3 power) {
    uvec3 units = power_units(power);
    for (int channel = 0; channel < 3; ++channel)
        if (units[channel] != 0u) add_group_power(3 * tally + channel, units[channel]);
}

// The photon's power, in fixed point, into the receiver texel it lands in
// (exact and order-independent: the same seed gives bit-identical maps); the
// kernel filter runs afterwards (receiver_filter.comp).
void deposit_on_receiver(ReceiverHit hit, vec3 power) {
    uint resolution = receivers[hit.receiver].map.y;
    uvec2 texel = min(uvec2(hit.map_uv * float(resolution)), uvec2(resolution - 1u));
    uint base = 6u * (receivers[hit.receiver].map.x + texel.y * resolution + texel.x);
    uvec3 units = power_units(power);
    for (int channel = 0; channel < 3; ++channel)
        if (units[channel] != 0u) add_wide_receiver(base + uint(2 * channel), units[channel]);
}

uint emitter_of(uint photon) {
    spend_loops(emitter_count);
    uint e = 0u;
    while (e + 1u < emitter_count && photon >= emitters[e + 1u].photons.x) ++e;
    return e;
}

// Stratified (u1, u2): the first strata.x·strata.y photons of an emitter each
// take one jittered cell of the unit square; any remainder is uniform.
vec2 emission_sample(Emitter emitter, uint photon) {
    uint local = photon - emitter.photons.x;
    vec2 jitter = vec2(random_uniform(seed, photon, 0u), random_uniform(seed, photon, 1u));
    uvec2 strata = uvec2(emitter.photons.z, emitter.photons.w);
    if (local >= strata.x * strata.y) return jitter;
    return (vec2(local % strata.x, local / strata.x) + jitter) / vec2(strata);
}

// A photon meets a receiver at x: the lit side records it and, if the
// receiver bounces, sends power × albedo back out in a cosine-distributed
// direction (returns true: the photon goes on); otherwise it stops there
// as received, or as blocked on the back.
bool land_on_receiver(ReceiverHit hit, uint photon, INOUT(uint) bounces, INOUT(vec3) x, INOUT(vec3) x_lost,
                      INOUT(vec3) v, INOUT(vec4) field, INOUT(vec3) power, INOUT(vec3) reflected, INOUT(int) fate) {
    if (!hit.lit_side) {
        fate = kBlocked;
        return false;
    }
    deposit_on_receiver(hit, power);
#if EIKON_BOUNCE
    Receiver receiver = receivers[hit.receiver];
    if (receiver.map.z == 0u || bounces >= MAX_BOUNCES) {
        fate = kReceived;
        return false;
    }
    // The arriving power is received; what the albedo sends back is a new source.
    add_power(kReceived, power);
    power *= xyz_of(receiver.albedo);
    reflected += power;
    vec3 direction = sample_cosine_hemisphere(xyz_of(receiver.normal), xyz_of(receiver.axis_u), xyz_of(receiver.axis_v),
                                              random_uniform(seed, photon, 2u + 2u * bounces),
                                              random_uniform(seed, photon, 3u + 2u * bounces));
    ++bounces;
    x = x + 1e-4f * grid.voxel_size.x * xyz_of(receiver.normal);
    x_lost = vec3(0.0f);
    field = grid_contains(x) ? field_at(x) : vec4(0.0f, 0.0f, 0.0f, reference_index());
    v = field.w * direction;
    return true;
#else
    fate = kReceived;
    return false;
#endif
}

#if EIKON_SHARP_SURFACES
// Where a step ended at a sharp surface (`crossing`): Snell refraction into the index on
// the other side, or reflection with the unpolarised Fresnel probability
// (Russian roulette: the photon keeps its power either way, so the split is
// unbiased) and always under total internal reflection. The indices on
// either side are the graded field at the surface plus each side's offset.
void cross_sharp_surface(SurfaceCrossing crossing, uint photon, INOUT(vec3) x, INOUT(vec3) x_lost, INOUT(vec3) v,
                         INOUT(vec4) field) {
    vec3 d = normalize(v);
    SurfaceEvent event = sharp_surface_event(crossing, x, d, inside_mask, channel_scale);
    x_lost = vec3(0.0f);
    bool reflects = event.reflectance >= 1.0f ||
                    (event.reflectance > 0.0f && random_uniform(seed, photon, 64u + surface_events) < event.reflectance);
    ++surface_events;
    x = reflects ? event.x_reflected : event.x_transmitted;
    if (reflects) {
        d = mirrored_direction(d, event.facing);
        count_surface_event(0);
    } else {
        d = refracted_direction(d, event.facing, event.n_here, event.n_beyond);
        inside_mask = event.beyond_mask;
        sharp_offset = event.beyond_offset;
        count_surface_event(1);
    }
    field = field_at(x);
    v = field.w * d;
}
#endif

// The RGB channel a dispersive photon carries, and its scale of δn.
void take_channel(uint photon) {
#if EIKON_DISPERSION
    channel_scale = dispersion[photon % 3u];
#else
    channel_scale = dispersion.x;
#endif
}

// The photon that index `photon` of a stride-2 half of the pass traces: an
// emitter's photon i takes stratum (i mod s, i / s), so with s even the even
// indices alone would be the even columns, a half whose mean differs from
// the other's at first order in the strata; swapping the pairs (2k, 2k + 1)
// of odd rows gives each half a checkerboard, whose diagonal pairs of strata
// share their centre. With s odd, index parity is the checkerboard already.
// A bijection on each emitter's photons, so the two halves are the pass.
uint checkerboard_photon(uint photon) {
    Emitter emitter = emitters[emitter_of(photon)];
    uint local = photon - emitter.photons.x;
    uvec2 strata = uvec2(emitter.photons.z, emitter.photons.w);
    if (strata.x % 2u != 0u || local >= strata.x * strata.y || ((local / strata.x) & 1u) == 0u) return photon;
    return emitter.photons.x + (local ^ 1u);
}

// Where photon `photon` starts, its direction and the power it carries,
// sampled from its emitter (stratified; a dispersive photon carries one
// channel, at three times its power, so each channel keeps its total).
void emit_photon(uint photon, OUT(vec3) x, OUT(vec3) direction, OUT(vec3) emitted) {
    Emitter emitter = emitters[emitter_of(photon)];
    vec2 u = emission_sample(emitter, photon);
    if (emitter.origin.w == 0.0f) {
        x = xyz_of(emitter.origin);
        // Sampled in the cone's own frame; a spot sampled over its own cone
        // (the usual case) takes its profile from the sampled versine itself.
        float h = u.x * emitter.axis.w;
        direction = cone_direction(xyz_of(emitter.axis), xyz_of(emitter.tangent), xyz_of(emitter.bitangent), h, u.y);
        float profile = all(equal(xyz_of(emitter.spot), xyz_of(emitter.axis)))
                            ? spot_profile_at_versine(h, emitter.spot.w, emitter.spot_edge.x)
                            : spot_profile(emitter, direction);
        emitted = xyz_of(emitter.photon_power) * profile;
    } else if (emitter.origin.w == 1.0f) {
        vec2 disk = emitter.axis.w * sample_disk_concentric(u.x, u.y);
        x = xyz_of(emitter.origin) + disk.x * xyz_of(emitter.tangent) + disk.y * xyz_of(emitter.bitangent);
        direction = xyz_of(emitter.axis);
        emitted = xyz_of(emitter.photon_power);
    } else {
#if EIKON_VOLUME_GLOW
        emit_glow_photon(photon, u, xyz_of(emitter.photon_power), x, direction, emitted);
#else
        x = vec3(0.0f);
        direction = vec3(0.0f, 0.0f, 1.0f);
        emitted = vec3(0.0f);  // not built without the option (PhotonStage)
#endif
    }
    take_channel(photon);
#if EIKON_DISPERSION
    int channel = int(photon % 3u);
    vec3 only = vec3(0.0f);
    only[channel] = 3.0f * emitted[channel];
    emitted = only;
#endif
}

// Traces photon `photon_offset + id · photon_stride`, or resumes suspended photon `id`.
void trace_photon(uint id) {
    uint photon;
    vec3 x;
    vec3 x_lost = vec3(0.0f);  // Kahan compensation of x
    vec3 v;
    vec4 field;
    vec3 power;
    vec3 emitted = vec3(0.0f);
    float cutoff;
    uint bounces = 0u;
    uint roulettes = 0u;
    uint steps = 0u;
    uint vertex = 0u;
#if EIKON_RESUMABLE
    if (resuming != 0u) {
        SuspendedPhoton suspended = suspended_in[id];
        photon = suspended.counters.x;
        take_channel(photon);
        x = suspended.x.xyz;
        cutoff = suspended.x.w;
        x_lost = suspended.x_lost.xyz;
        v = suspended.v.xyz;
        power = suspended.power.rgb;
        bounces = suspended.counters.y;
        roulettes = suspended.counters.z;
        steps = suspended.counters.w;
        vertex = suspended.surfaces.x;
#if EIKON_SHARP_SURFACES
        surface_events = suspended.surfaces.y;
        inside_mask = suspended.surfaces.z;
        sharp_offset = uintBitsToFloat(suspended.surfaces.w);
#endif
        field = grid_contains(x) ? field_at(x) : vec4(0.0f, 0.0f, 0.0f, reference_index());
    } else
#endif
    {
        photon = photon_offset + id * photon_stride;
        if (checkerboard != 0u) photon = checkerboard_photon(photon);
        vec3 direction;
        emit_photon(photon, x, direction, emitted);
        power = emitted;
        cutoff = power_cutoff * max(power.r, max(power.g, power.b));
#if EIKON_SHARP_SURFACES
        if (grid_contains(x)) enter_sharp_region(x);
#endif
        field = grid_contains(x) ? field_at(x) : vec4(0.0f, 0.0f, 0.0f, reference_index());
        v = field.w * direction;  // |v| = n where the photon starts, inside the grid or out
        record_vertex(photon, vertex++, x, power);
    }
    vec3 absorbed = vec3(0.0f);
    vec3 reflected = vec3(0.0f);
    vec3 roulette_gain = vec3(0.0f);
    const uint first_step = steps;
    float max_invariant_error = 0.0f;
    float invariant_error_sum = 0.0f;
    int fate = kEscaped;
    int end_receiver = -1;  // the receiver it last landed on
    bool marched = false;  // the last move was a step of the march (not a flight, bounce or emission)

    for (uint passes = 1u;; ++passes) {
        spend_loops(loops_per_pass());
        if (!loops_left()) {  // only where the driver caps loops: suspended or cut off, and counted
            fate = out_of_loops(passes);
            break;
        }
        if (!grid_contains(x)) {
            vec3 d = normalize(v);
            bool stepped_out = marched;
            marched = false;
            StraightFlight flight = fly_straight(x, d);
#if !EIKON_BARE_MARCH
            if (flight.hit.receiver >= 0) {
                x = x + flight.distance * d;
                record_vertex(photon, vertex++, x, power);
                end_receiver = flight.hit.receiver;
                if (land_on_receiver(flight.hit, photon, bounces, x, x_lost, v, field, power, reflected, fate)) continue;
                break;
            }
#endif
            if (!flight.enters_grid) {
                // A recorded path ends where the photon left the grid — its
                // last vertex, one step past the boundary, moved back onto
                // it — or where it last was (a light or receiver outside
                // the grid); never far away.
                if (stepped_out) x = grid_exit_point(x, d);
                if (stepped_out && vertex > 0u) record_vertex(photon, vertex - 1u, x, power);
                fate = kEscaped;
                break;
            }
            x = grid_entry_point(x, d, flight);
            x_lost = vec3(0.0f);
            if (!grid_contains(x)) continue;
#if EIKON_SHARP_SURFACES
            enter_sharp_region(x);
#endif
            // Keep |v| = n at entry so the invariant starts exact.
            field = field_at(x);
            v = field.w * d;
            record_vertex(photon, vertex++, x, power);
            continue;
        }
        if (steps >= max_steps) {
            fate = kCutOff;
            break;
        }
        float ds = next_step(x, v);
#if EIKON_SHARP_SURFACES
        // A step never crosses a sharp surface: it ends there, and the
        // crossing is resolved before the next one.
        SurfaceCrossing crossing = nearest_surface_crossing(x, normalize(v), inside_mask, ds, 1e-4f * grid.voxel_size.x);
        ds = crossing.distance;
        if (!loops_left()) {  // the search stopped short; the photon is still where the step began
            fate = out_of_loops(passes);
            break;
        }
#endif
        vec3 start = x;
        integrate(x, x_lost, v, field, ds);
        marched = true;
        ++steps;
        float invariant_error = eikonal_invariant_error(v, field.w);
        max_invariant_error = max(max_invariant_error, invariant_error);
        invariant_error_sum += invariant_error;
#if EIKON_RENORMALIZE
        v = renormalised_direction(v, field.w);
#endif

#if !EIKON_BARE_MARCH
        ReceiverHit hit = first_receiver_crossing(start, x);
        float travelled = travelled_inside_grid(start, x, ds, hit.receiver >= 0 ? hit.fraction * ds : ds);
        vec3 medium = owned_medium_point(start, inside_mask);
        vec3 kappa = sample_extinction(medium);
        deposit_segment(start, hit.receiver >= 0 ? mix(start, x, hit.fraction) : x, power, kappa,
                        sample_scattering(medium));
        vec3 transmitted = power * beer_lambert_transmittance(kappa, travelled);
        absorbed += power - transmitted;
        power = transmitted;
        if (hit.receiver >= 0) {
            x = mix(start, x, hit.fraction);
            marched = false;  // it is on the receiver, not past the grid's boundary
            record_vertex(photon, vertex++, x, power);
            end_receiver = hit.receiver;
            if (land_on_receiver(hit, photon, bounces, x, x_lost, v, field, power, reflected, fate)) continue;
            break;
        }
#endif
#if EIKON_SHARP_SURFACES
        if (crossing.surface >= 0) cross_sharp_surface(crossing, photon, x, x_lost, v, field);
#endif
        record_vertex(photon, vertex++, x, power);
        float brightest = max(power.r, max(power.g, power.b));
        if (brightest < cutoff) {
            // Russian roulette: go on with probability brightest/cutoff and
            // power divided by it, else stop; unbiased, and the tallies stay
            // exact with the gain counted as a source.
            float survival = brightest / cutoff;
            if (!(random_uniform(seed, photon, kRouletteDimensions + roulettes) < survival)) {
                fate = kCutOff;
                break;
            }
            vec3 boosted = power / survival;
            roulette_gain += boosted - power;
            power = boosted;
            ++roulettes;
        }
        if (!grid_contains(x)) v = reference_index() * normalize(v);
    }

    // What this dispatch did with the photon is tallied now; a suspended
    // photon's power and fate wait for the dispatch that ends it.
    add_power(kEmitted, emitted);
    add_power(kReflected, reflected);
    add_power(kRouletteGain, roulette_gain);
    add_power(kAbsorbed, absorbed);
#if EIKON_RESUMABLE
    if (fate == kSuspended) {
        uint slot = atomicAdd(suspended_count, 1u);
        if (slot < suspended_capacity) {
            uint sharp_state[3] = uint[3](0u, 0u, 0u);
#if EIKON_SHARP_SURFACES
            sharp_state = uint[3](surface_events, inside_mask, floatBitsToUint(sharp_offset));
#endif
            suspended_out[slot] = SuspendedPhoton(vec4(x, cutoff), vec4(x_lost, 0.0f), vec4(v, 0.0f), vec4(power, 0.0f),
                                                  uvec4(photon, bounces, roulettes, steps),
                                                  uvec4(vertex, sharp_state[0], sharp_state[1], sharp_state[2]));
        } else {
            fate = kCutOff;  // no room left to suspend it in
        }
    }
    if (fate != kSuspended) {
        add_power(fate, power);
        count_photon(fate);
        record_end(photon, x, fate, fate == kReceived ? end_receiver : -1, power);
    }
#else
    add_power(fate, power);
    count_photon(fate);
    record_end(photon, x, fate, fate == kReceived ? end_receiver : -1, power);
#endif
    count_march(steps - first_step, max_invariant_error, deposits, invariant_units(invariant_error_sum));
}

