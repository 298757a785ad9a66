// The water body's coverage of every render cell and the attenuation it
// paints, on the GPU (sim/gpu/GpuWaterBody.h): the arithmetic of
// sim/voxelize/HeightFieldCoverage.cpp (a box filter across the surface's
// plane, in closed form from the height field; the walls and floor as exact
// overlaps) and of Compositor.cpp's paintObjects for one object over the
// medium (m += c·(m_water − m), c rounded to float32 as the host stores
// it), in float64 as there. A sharp surface paints no index: only κ, σs
// and g, each where the scene has it.
// Variants: EIKON_HAS_EXTINCTION, EIKON_HAS_SCATTERING, EIKON_HAS_ANISOTROPY.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = kWaterHeight) readonly buffer WaterHeight { double height[]; };
#if EIKON_HAS_EXTINCTION
layout(std430, binding = kWaterBaseExtinction) readonly buffer WaterBaseExtinction { float base_extinction[]; };
layout(std430, binding = kOpticsExtinction) writeonly buffer OpticsExtinction { float extinction[]; };
uniform dvec3 water_extinction;
#endif
#if EIKON_HAS_SCATTERING
layout(std430, binding = kWaterBaseScattering) readonly buffer WaterBaseScattering { float base_scattering[]; };
layout(std430, binding = kOpticsScattering) writeonly buffer OpticsScattering { float scattering[]; };
uniform dvec3 water_scattering;
#endif
#if EIKON_HAS_ANISOTROPY
layout(std430, binding = kWaterBaseAnisotropy) readonly buffer WaterBaseAnisotropy { float base_anisotropy[]; };
layout(std430, binding = kOpticsAnisotropy) writeonly buffer OpticsAnisotropy { float anisotropy[]; };
uniform double water_anisotropy;
#endif

uniform ivec3 cells;
uniform dvec3 grid_min, voxel;
uniform dvec3 basin_min, basin_max;  // y: the floor, and the rest level
uniform ivec2 nodes;

// The fraction of [centre − width/2, centre + width/2] inside [low, high].
double overlap(double centre, double width, double low, double high) {
    double a = max(centre - 0.5lf * width, low);
    double b = min(centre + 0.5lf * width, high);
    return max(b - a, 0.0lf) / width;
}

double node_height(int i, int k) { return height[k * nodes.x + i]; }

// HeightField::sample: the surface's height and slope at (x, z), clamped into the basin.
dvec3 surface_sample(double x, double z) {
    double dx = (basin_max.x - basin_min.x) / double(nodes.x - 1);
    double dz = (basin_max.z - basin_min.z) / double(nodes.y - 1);
    double gx = clamp((x - basin_min.x) / dx, 0.0lf, double(nodes.x - 1));
    double gz = clamp((z - basin_min.z) / dz, 0.0lf, double(nodes.y - 1));
    int i = min(int(gx), nodes.x - 2);
    int k = min(int(gz), nodes.y - 2);
    precise double u = gx - double(i), v = gz - double(k);
    double h00 = node_height(i, k), h10 = node_height(i + 1, k), h01 = node_height(i, k + 1), h11 = node_height(i + 1, k + 1);
    precise dvec3 below_diagonal = dvec3(h00 + u * (h10 - h00) + v * (h11 - h10), (h10 - h00) / dx, (h11 - h10) / dz);
    precise dvec3 above_diagonal = dvec3(h00 + u * (h11 - h01) + v * (h01 - h00), (h11 - h01) / dx, (h01 - h00) / dz);
    return v >= u ? above_diagonal : below_diagonal;
}

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, cells))) return;
    uint index = uint((cell.z * cells.y + cell.y) * cells.x + cell.x);
    precise dvec3 c = grid_min + (dvec3(cell) + 0.5lf) * voxel;
    double walls = overlap(c.x, voxel.x, basin_min.x, basin_max.x) * overlap(c.z, voxel.z, basin_min.z, basin_max.z);
    precise double fraction = 0.0lf;
    if (walls > 0.0lf) {
        dvec3 s = surface_sample(c.x, c.z);
        precise double width = abs(s.y) * voxel.x + voxel.y + abs(s.z) * voxel.z;
        precise double below = clamp(0.5lf - (c.y - (basin_max.y + s.x)) / width, 0.0lf, 1.0lf);
        precise double top = c.y - 0.5lf * voxel.y + below * voxel.y;
        precise double bottom = max(c.y - 0.5lf * voxel.y, basin_min.y);
        fraction = walls * max(top - bottom, 0.0lf) / voxel.y;
    }
    double coverage = double(float(fraction));  // the host keeps coverage in float32
#if EIKON_HAS_EXTINCTION
    for (int channel = 0; channel < 3; ++channel) {
        precise double m = double(base_extinction[3u * index + uint(channel)]);
        if (coverage > 0.0lf) m += coverage * (water_extinction[channel] - m);
        extinction[3u * index + uint(channel)] = float(m);
    }
#endif
#if EIKON_HAS_SCATTERING
    for (int channel = 0; channel < 3; ++channel) {
        precise double m = double(base_scattering[3u * index + uint(channel)]);
        if (coverage > 0.0lf) m += coverage * (water_scattering[channel] - m);
        scattering[3u * index + uint(channel)] = float(m);
    }
#endif
#if EIKON_HAS_ANISOTROPY
    precise double g = double(base_anisotropy[index]);
    if (coverage > 0.0lf) g += coverage * (water_anisotropy - g);
    anisotropy[index] = float(g);
#endif
}
