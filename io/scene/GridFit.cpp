#include "io/scene/GridFit.h"

#include "bridge/core/Error.h"
#include "io/vdb/VdbVolumeFile.h"
#include "io/vdb/VolumeFramePath.h"
#include "io/vdb/VolumePlacement.h"

#include <optional>

namespace eikon {

bool readGridFit(const JsonObjectReader& grid) {
    const std::optional<JsonReader> fit = grid.optional("fit");
    if (!fit || fit->oneOf({"none", "volume"}) == "none") return false;
    if (grid.optional("bounds")) grid.member("bounds").fail("no bounds beside fit \"volume\" (it sets them)", "bounds");
    return true;
}

void fitGridToVolume(const JsonReader& fit, Scene& scene) {
    if (!scene.volume) fit.fail("a `volume` section to fit the grid to", "\"volume\" without one");
    if (scene.volume->format != VolumeDesc::Format::OpenVdb)
        fit.fail("an OpenVDB volume (its active voxels' box is what the grid fits)", "VTK data (give grid.bounds)");
    std::optional<io::WorldBox> box;
    try {
        box = io::activeVolumeBox(*scene.volume,
                                  io::VdbVolumeFile(volumeFramePath(*scene.volume, scene.volume->frameStart)));
    } catch (const InputError& error) {
        throw InputError(scene.sourcePath + ": " + fit.path() + ": " + error.what());
    }
    if (!box)
        fit.fail("a volume file whose grids say where their active voxels are (OpenVDB's file_bbox_min and "
                 "file_bbox_max metadata)",
                 "grids without them, or with no active voxel");
    scene.grid.boundsMin = box->min;
    scene.grid.boundsMax = box->max;
}

}  // namespace eikon
