// Where an imported volume's file lies in the scene's world: the scene's
// placement (volume.transform, offset, up_axis), and for a Blender
// (Mantaflow) cache its cells in the domain's frame (blender_domain). And
// whether the render grid holds what the file has.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/scene/VolumeDesc.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>

namespace eikon::io {

class VdbVolumeFile;

// The affine map of `file`'s world into the scene's. InputError naming the
// file and grid where a Blender cache lacks Mantaflow's metadata.
glm::dmat4 volumePlacement(const VolumeDesc& desc, const VdbVolumeFile& file);

// The box, in the scene's world, of the active voxels of every grid the
// scene reads from `file` (OpenVDB's file_bbox statistics, through the
// placement); nullopt where no grid says.
struct WorldBox {
    glm::dvec3 min{0.0}, max{0.0};
};
std::optional<WorldBox> activeVolumeBox(const VolumeDesc& desc, const VdbVolumeFile& file);

// A warning, with the figures, where the active voxels of the file of
// rendered frame 0 reach more than half a render cell past `renderGrid`
// (what lies outside is cut off); empty where they fit or no grid says
// where they are, or the volume is VTK data. InputError as volumePlacement's.
std::string describeVolumeOutsideGrid(const VolumeDesc& desc, const GridSpec& renderGrid);

}  // namespace eikon::io
