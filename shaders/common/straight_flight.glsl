// Outside the field grid the medium is uniform (n = n_ref, no extinction),
// so photons and camera rays fly straight until they meet a receiver, enter
// the grid, or leave for good. Shared by GLSL and C++; needs
// common/grid_box.glsl and common/receiver_hits.glsl.
struct StraightFlight {
    ReceiverHit hit;   // the receiver met first (hit.receiver < 0: none)
    bool enters_grid;  // no receiver first, and the grid lies ahead
    float distance;    // to the receiver hit, the grid entry, or EIKON_INFINITY
};

// No distance ends the flight: receivers are met analytically however far
// they are, so a scene of any size (io/scene accepts positions to 1e9 m)
// keeps its light.
StraightFlight fly_straight(vec3 x, vec3 d) {
    vec2 span = grid_ray_interval(x, d);
    float t_grid = (span.x <= span.y && span.y > 0.0f) ? max(span.x, 0.0f) : EIKON_INFINITY;
    StraightFlight flight;
    flight.hit = first_receiver_on_ray(x, d, t_grid, flight.distance);
    flight.enters_grid = flight.hit.receiver < 0 && t_grid != EIKON_INFINITY;
    return flight;
}

// A point just inside the grid on a flight that enters it.
vec3 grid_entry_point(vec3 x, vec3 d, StraightFlight flight) {
    return x + (flight.distance + 1e-4f * grid.voxel_size.x) * d;
}

// Where a photon that stepped out of the grid at x, going d, crossed the
// grid's boundary: its straight flight outside traced back onto the box
// (a step overshoots the boundary by up to its length).
vec3 grid_exit_point(vec3 x, vec3 d) {
    vec2 behind = grid_ray_interval(x, -d);
    return behind.x <= behind.y && behind.x >= 0.0f ? x - behind.x * d : x;
}
