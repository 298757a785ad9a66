// `--follow` of `eikon run` and `eikon-view`: the scene's volume is followed
// as a simulation writes it (sim/volume/VolumeFollower.h), step after step.
#pragma once

#include "bridge/scene/Scene.h"

namespace eikon::app {

// Sets scene.volume's follow settings. InputError, naming the scene file and
// `--follow`, where the scene has no volume, or one that is not a VTK time
// series (.pvd, .series) or an OpenFOAM case, to which steps are added.
void followVolume(Scene& scene, const VolumeDesc::Follow& follow);

}  // namespace eikon::app
