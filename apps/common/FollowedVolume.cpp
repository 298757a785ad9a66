#include "apps/common/FollowedVolume.h"

#include "bridge/core/Error.h"
#include "io/vtk/VtkVolumeSource.h"

namespace eikon::app {

void followVolume(Scene& scene, const VolumeDesc::Follow& follow) {
    if (!scene.volume || scene.volume->format != VolumeDesc::Format::Vtk ||
        !io::isVtkTimeSeriesPath(scene.volume->path))
        throw InputError(scene.sourcePath + ": --follow",
                         "a scene whose volume.path is a VTK time series (.pvd, .series) or an OpenFOAM case, to "
                         "which a simulation adds steps",
                         scene.volume ? "volume.path \"" + scene.volume->path + "\"" : "no volume section");
    scene.volume->follow = follow;
}

}  // namespace eikon::app
