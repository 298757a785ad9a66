// Seeded, stateless random numbers: the PCG hash ([Jarzynski20]) turns
// (seed, photon, dimension) into a uniform float, so the same seed gives the
// same frame on any device.
uint pcg_hash(uint value) {
    uint state = value * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Uniform in [0, 1), with 24 random bits.
float random_uniform(uint seed, uint index, uint dimension) {
    uint bits = pcg_hash(seed ^ pcg_hash(index ^ pcg_hash(dimension)));
    return float(bits >> 8u) * (1.0f / 16777216.0f);
}
