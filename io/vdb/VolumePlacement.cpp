#include "io/vdb/VolumePlacement.h"

#include "bridge/core/Error.h"
#include "bridge/core/NumberFormat.h"
#include "io/vdb/VdbVolumeFile.h"
#include "io/vdb/VolumeFramePath.h"

#include <glm/common.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace eikon::io {

namespace {

std::string cellCounts(const glm::dvec3& cells) {
    return formatRounded(cells.x) + " × " + formatRounded(cells.y) + " × " + formatRounded(cells.z);
}

// Blender sizes its domain's grid from the domain: dx = the longest
// dimension / resolution_max, and res = dimensions / dx rounded per axis,
// at least 4 (the cells then stretch to fill the domain). The file's voxel (its dx)
// and file_base_resolution must be what the dimensions the scene gives
// make, to within that rounding: a cache of an adaptive domain (its grid
// covers the part of the domain with smoke, at an offset the file does not
// hold) or dimensions copied from another domain are refused.
void requireDomainOfTheCache(const VdbVolumeFile& file, const std::string& grid, const glm::dvec3& dimensions,
                             const glm::ivec3& resolution, double dx) {
    const glm::dvec3 cells = dimensions / dx;
    const glm::dvec3 error = glm::abs(glm::max(cells, glm::dvec3(4.0)) - glm::dvec3(resolution));
    if (glm::all(glm::lessThanEqual(error, glm::dvec3(0.5 + 1e-6) + 1e-6 * cells))) return;
    throw InputError(file.path().string() + ": grid \"" + grid + "\"",
                     "file_base_resolution = volume.blender_domain.dimensions / the file's voxel of " +
                         formatRounded(dx) + " m, each rounded (" + cellCounts(cells) + ")",
                     cellCounts(glm::dvec3(resolution)) +
                         ": dimensions of another domain, or a cache of an adaptive domain, whose grid covers only "
                         "the part of the domain with smoke at an offset the file does not hold (bake with Adaptive "
                         "Domain off)");
}

// A Blender (Mantaflow) cache's index frame in its domain's, centred: voxel
// (i,j,k) at (i,j,k)·dx in the file is the cell covering
// [i, i+1]·D/res from the domain's corner (VolumeDesc::blenderDomainDimensions).
glm::dmat4 blenderCellFrame(const VdbVolumeFile& file, const std::string& grid, const glm::dvec3& dimensions) {
    const VdbVolumeFile::GridFrame frame = file.gridFrame(grid);
    if (!frame.baseResolution || glm::any(glm::lessThan(*frame.baseResolution, glm::ivec3(1))))
        throw InputError(file.path().string() + ": grid \"" + grid + "\"",
                         "Mantaflow's file_base_resolution metadata (volume.preset \"blender\" reads a Blender cache)",
                         frame.baseResolution ? "a resolution below 1" : "none");
    const double dx = frame.voxelSize.x;
    requireDomainOfTheCache(file, grid, dimensions, *frame.baseResolution, dx);
    const glm::dvec3 cell = dimensions / glm::dvec3(*frame.baseResolution);
    return glm::translate(glm::dmat4(1.0), -0.5 * dimensions) * glm::scale(glm::dmat4(1.0), cell / dx) *
           glm::translate(glm::dmat4(1.0), glm::dvec3(0.5 * dx));
}

// The names of every grid the scene reads.
std::vector<std::string> gridsRead(const VolumeDesc& desc) {
    std::vector<std::string> names;
    for (const std::string* name : {&desc.densityGrid, &desc.temperatureGrid, &desc.flameGrid, &desc.velocityGrid,
                                    &desc.indexGrid, &desc.deltaIndexGrid, &desc.extinctionGrid, &desc.scatteringGrid,
                                    &desc.anisotropyGrid, &desc.emissionGrid})
        if (!name->empty()) names.push_back(*name);
    return names;
}

std::string span(const glm::dvec3& min, const glm::dvec3& max) {
    const char* axes = "xyz";
    std::string text;
    for (int a = 0; a < 3; ++a)
        text += (a ? ", " : "") + std::string(1, axes[a]) + " " + formatRounded(min[a]) + " … " + formatRounded(max[a]);
    return text + " m";
}

// The first grid the scene reads (the one whose metadata places a Blender cache).
std::string firstGrid(const VolumeDesc& desc) {
    const std::vector<std::string> names = gridsRead(desc);
    return names.empty() ? std::string() : names.front();
}

}  // namespace

glm::dmat4 volumePlacement(const VolumeDesc& desc, const VdbVolumeFile& file) {
    return desc.blenderDomainDimensions
               ? desc.placement * blenderCellFrame(file, firstGrid(desc), *desc.blenderDomainDimensions)
               : desc.placement;
}

std::optional<WorldBox> activeVolumeBox(const VolumeDesc& desc, const VdbVolumeFile& file) {
    const glm::dmat4 placement = volumePlacement(desc, file);
    std::optional<WorldBox> box;
    for (const std::string& grid : gridsRead(desc)) {
        const std::optional<std::vector<glm::dvec3>> corners = file.activeBoxCorners(grid);
        if (!corners) continue;
        for (const glm::dvec3& corner : *corners) {
            const glm::dvec3 x(placement * glm::dvec4(corner, 1.0));
            if (!box) box = WorldBox{x, x};
            box->min = glm::min(box->min, x);
            box->max = glm::max(box->max, x);
        }
    }
    return box;
}

std::string describeVolumeOutsideGrid(const VolumeDesc& desc, const GridSpec& renderGrid) {
    // VTK data are probed at the grid's cells, and cells they do not cover
    // keep the ambient medium (io/vtk/VtkVolumeSource): only an OpenVDB
    // volume's box is compared here.
    if (desc.format != VolumeDesc::Format::OpenVdb) return {};
    const VdbVolumeFile file(volumeFramePath(desc, desc.frameStart));
    const std::optional<WorldBox> box = activeVolumeBox(desc, file);
    if (!box) return {};
    const glm::dvec3 halfCell = 0.5 * renderGrid.voxelSize();
    if (glm::all(glm::greaterThanEqual(box->min, renderGrid.boundsMin - halfCell)) &&
        glm::all(glm::lessThanEqual(box->max, renderGrid.boundsMax + halfCell)))
        return {};
    const glm::dvec3 size = box->max - box->min;
    const glm::dvec3 inside =
        glm::max(glm::min(box->max, renderGrid.boundsMax) - glm::max(box->min, renderGrid.boundsMin), glm::dvec3(0.0));
    const double volume = size.x * size.y * size.z;
    const double outside = volume > 0.0 ? 100.0 * (1.0 - inside.x * inside.y * inside.z / volume) : 100.0;
    return "volume: the active voxels of " + file.path().string() + " span " + span(box->min, box->max) +
           " in the scene's world, past the render grid's " + span(renderGrid.boundsMin, renderGrid.boundsMax) +
           ": " + formatRounded(std::round(outside * 10.0) / 10.0) +
           "% of their box lies outside and is cut off (grid.fit \"volume\" sizes the grid to that box)";
}

}  // namespace eikon::io
