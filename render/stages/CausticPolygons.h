// Caustic polygons for the image-space caustic maps (shaders/caustic_polygons.*;
// [Wyman06] §3.2.1, Fig. 5 and Eq. 1): a light's photons, one per texel of
// its surface layers, sample a map from the light's texel grid onto the
// receivers. Rather than splatting each photon's power at one point, which
// shows the photons' regular grid as moiré wherever fewer than a few land
// per receiver texel, the power between four neighbouring photons is spread
// over the quadrilateral between their landings: its two triangles are met
// with every receiver one of the photons lands on, clipped to each
// receiver's square, at the irradiance of their power over their landing
// area. Triangles smaller than a quarter of a receiver texel are splatted
// at their middle. Cells with no smooth map are splatted corner by corner:
// those whose photons left through different surfaces, and those whose
// photons met or left one on facets more than a crease apart (an edge of a
// bar; the paper culls such polygons or draws them), unless they land
// within a few texels. Drawn, a creased cell spreads its power across the
// gap under the edge (4% of the light there, CausticPolygons.
// KeepTheGapUnderACreaseDark), and twisting_glass's cost 5.4 million
// texels of triangles a frame. A cell on a silhouette keeps the triangle of
// its three corners on the surface. A splat shares its power bilinearly
// among the four texels around it.
//
// A triangle adds its irradiance to the texels whose centres it covers.
// The larger ones are drawn by the raster pipeline, with additive
// blending, into an atlas that stacks the receivers' maps a texel per
// pixel, which is then added into the receivers' fixed-point tallies. A
// CPU rasterizer's cost is per primitive, though, and most triangles are
// small (pool_caustics: 45 000 of 56 000 within 2 × 2 texel centres; their
// draw took 9 ms of a 43 ms frame on two cores): those whose box holds at
// most 3 texel centres along each axis, and the splats, are deposited by
// a compute pass instead, which tests those few centres exactly as the
// raster pipeline samples them (corners snapped to 1/256 texel, a centre
// on a shared edge counted once) and adds straight into the tallies. So
// every photon's power is counted (up to where a triangle's edge falls
// between texel centres).
#pragma once

#include "gl/GlObjects.h"
#include "gl/RasterTarget.h"
#include "render/stages/ReceiverMaps.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace eikon::render {

class CausticPolygons {
public:
    // texels: the light layers' edge (render.caustic_map_texels).
    CausticPolygons(int texels, const ReceiverMaps& receivers);

    // Clears the atlas: the start of a frame's lights.
    void clear();
    // Where the photon pass over a layers' grid of `grid` texels writes its
    // landings (kCausticVertices), and the cell pass's work groups
    // (kCausticCellGroups): the refracted sheet's, and the reflected sheet's
    // too once a reflected photon lands (a pool reflects the light to the
    // sky: its reflected cells would cost half the cell pass for nothing).
    void bindVertices(const glm::ivec2& grid);
    // After a light's photon pass over a layers' grid of `grid` texels, and
    // a barrier for texel fetches and commands: lists its cells' triangles
    // and splats, deposits the small ones into the tallies in units of
    // powerUnit (W per tally unit, a channel each), and draws the larger
    // triangles into the atlas. The cell pass reads the landings as a buffer
    // texture, which a CPU rasterizer fetches for all lanes at once (its
    // storage-buffer loads at lane-dependent offsets go a lane and a float
    // at a time: 2–3 ms more of a 256² cell pass on two cores).
    void drawLight(const glm::ivec2& grid, const glm::vec3& powerUnit);
    // Adds the atlas, all lights drawn, into the receivers' tallies.
    void addAtlasToTallies(const glm::vec3& powerUnit);

private:
    const ReceiverMaps& receivers_;
    gl::Buffer vertices_, triangles_, deposits_, drawCommand_, depositCount_, cellGroups_;
    gl::BufferTexture vertexTexels_;  // vertices_, read by the cell pass
    gl::RasterTarget atlas_;
    gl::Program cellProgram_, gatherProgram_, depositProgram_, drawProgram_;
    gl::EmptyVertexArray vertexArray_;
};

}  // namespace eikon::render
