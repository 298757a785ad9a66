#include "render/stages/CausticPolygons.h"

#include "bridge/mesh/Creases.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"
#include "shaders/common/cpp_shim.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <string>

namespace eikon::render {

namespace {

constexpr auto kSheets = static_cast<std::size_t>(shader::kCausticSheets);  // refracted and reflected
constexpr std::size_t kVertexBytes = 3 * 4 * sizeof(float);
constexpr std::size_t kTriangleBytes = 3 * 4 * sizeof(float);
constexpr std::size_t kDepositBytes = 3 * 4 * sizeof(float);
constexpr unsigned kNothingToDraw[4] = {0u, 1u, 0u, 0u};     // glDrawArraysIndirect's count, instances, first, base
constexpr unsigned kNothingToDeposit[4] = {0u, 1u, 1u, 0u};  // pass 2's work groups (x, y, z), deposits

// The atlas stacks the receivers' maps: as wide as the widest, as tall as all together.
glm::ivec2 atlasSize(const ReceiverMaps& receivers) {
    glm::ivec2 size(1, 0);
    for (unsigned r = 0; r < receivers.count(); ++r) {
        const auto edge = static_cast<int>(receivers.receiver(r).map.y);
        size.x = std::max(size.x, edge);
        size.y += edge;
    }
    return {size.x, std::max(size.y, 1)};
}

// The most receivers one cell is drawn on (caustic_polygons.comp).
std::size_t receiversPerCell(const ReceiverMaps& receivers) {
    return std::clamp<std::size_t>(receivers.count(), 1, 4);
}

std::size_t cellsOf(int texels) {
    const auto edge = static_cast<std::size_t>(std::max(texels - 1, 1));
    return edge * edge * kSheets;
}

}  // namespace

CausticPolygons::CausticPolygons(int texels, const ReceiverMaps& receivers)
    : receivers_(receivers),
      vertices_(static_cast<std::size_t>(texels) * static_cast<std::size_t>(texels) * kSheets * kVertexBytes,
                gl::GpuResource{"render.caustic_map_texels", "the caustic maps' photon landings"}),
      // Two triangles per cell and sheet on each receiver its photons land on (at most four).
      triangles_(cellsOf(texels) * 2 * receiversPerCell(receivers) * kTriangleBytes,
                 gl::GpuResource{"render.caustic_map_texels", "the caustic triangles"}),
      // A splat per corner of a cell with no smooth map, or a triangle or a
      // splat in each of a smooth one's two per receiver.
      deposits_(cellsOf(texels) * std::max<std::size_t>(4, 2 * receiversPerCell(receivers)) * kDepositBytes,
                gl::GpuResource{"render.caustic_map_texels", "the caustic deposits"}),
      drawCommand_(sizeof kNothingToDraw, kNothingToDraw, GL_DYNAMIC_STORAGE_BIT),
      depositCount_(sizeof kNothingToDeposit, kNothingToDeposit, GL_DYNAMIC_STORAGE_BIT),
      cellGroups_(sizeof(glm::uvec4), {"render.caustic_map_texels", "the caustic cell pass's work groups"}),
      vertexTexels_(vertices_, GL_RGBA32F, {"render.caustic_map_texels", "the caustic maps' photon landings"}),
      atlas_(atlasSize(receivers).x, atlasSize(receivers).y,
             gl::GpuResource{"receivers", "the atlas the caustic triangles are drawn into"}),
      cellProgram_(gl::compileComputeProgram(
          "caustic_polygons.comp",
          {{"EIKON_PASS", "0"},
           {"EIKON_CELL_RECEIVERS", std::to_string(receiversPerCell(receivers))},
           receivers.countOption()})),
      gatherProgram_(
          gl::compileComputeProgram("caustic_polygons.comp", {{"EIKON_PASS", "1"}, receivers.countOption()})),
      depositProgram_(
          gl::compileComputeProgram("caustic_polygons.comp", {{"EIKON_PASS", "2"}, receivers.countOption()})),
      drawProgram_(
          gl::compileRasterProgram("caustic_polygons.vert", "caustic_polygons.frag", {receivers.countOption()})) {
    glProgramUniform1f(cellProgram_.id(), cellProgram_.uniform("crease_cosine"), static_cast<float>(creaseCosine()));
}

void CausticPolygons::clear() {
    GLint previousFramebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
    atlas_.beginDrawing(glm::vec4(0.0f));
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));
}

void CausticPolygons::bindVertices(const glm::ivec2& grid) {
    vertices_.bindStorage(layout::kCausticVertices);
    // The cell pass's work groups over the refracted sheet's cells (one fewer than texels a side).
    const glm::uvec3 cells = cellProgram_.groupsCovering(static_cast<std::size_t>(grid.x - 1),
                                                         static_cast<std::size_t>(grid.y - 1));
    const glm::uvec4 refractedSheet(cells.x, cells.y, 1u, 0u);
    cellGroups_.upload(&refractedSheet, sizeof refractedSheet);
    cellGroups_.bindStorage(layout::kCausticCellGroups);
}

void CausticPolygons::drawLight(const glm::ivec2& grid, const glm::vec3& powerUnit) {
    drawCommand_.upload(kNothingToDraw, sizeof kNothingToDraw);
    depositCount_.upload(kNothingToDeposit, sizeof kNothingToDeposit);
    receivers_.bind();
    vertexTexels_.bindSampler(layout::kCausticVertexTexture);
    triangles_.bindStorage(layout::kCausticTriangles);
    drawCommand_.bindStorage(layout::kCausticDraw);
    deposits_.bindStorage(layout::kCausticDeposits);
    depositCount_.bindStorage(layout::kCausticDepositCount);
    cellProgram_.use();
    glUniform2i(cellProgram_.uniform("layer_size"), grid.x, grid.y);
    cellProgram_.dispatchIndirect(cellGroups_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

    // The small triangles and the splats, straight into the tallies.
    depositProgram_.use();
    glUniform3fv(depositProgram_.uniform("power_unit"), 1, glm::value_ptr(powerUnit));
    depositProgram_.dispatchIndirect(depositCount_);

    // The larger triangles, into the atlas.
    GLint previousFramebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
    atlas_.continueDrawing();
    drawProgram_.use();
    glUniform2i(drawProgram_.uniform("atlas_size"), atlas_.width(), atlas_.height());
    vertexArray_.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);  // a fold of the caustic turns triangles over
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    for (GLenum plane = 0; plane < 4; ++plane) glEnable(GL_CLIP_DISTANCE0 + plane);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, drawCommand_.id());
    glDrawArraysIndirect(GL_TRIANGLES, nullptr);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    for (GLenum plane = 0; plane < 4; ++plane) glDisable(GL_CLIP_DISTANCE0 + plane);
    glDisable(GL_BLEND);
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previousFramebuffer));
    gl::checkpoint("caustic polygons");
}

void CausticPolygons::addAtlasToTallies(const glm::vec3& powerUnit) {
    receivers_.bind();
    atlas_.bindColour(layout::kCausticAtlasTexture);
    gatherProgram_.use();
    glUniform3fv(gatherProgram_.uniform("power_unit"), 1, glm::value_ptr(powerUnit));
    receivers_.dispatchOverTexels(gatherProgram_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    gl::checkpoint("caustic atlas");
}

}  // namespace eikon::render
