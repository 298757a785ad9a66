// Which file of an imported volume (scene `volume`) holds a frame.
#pragma once

#include "bridge/scene/VolumeDesc.h"

#include <string>

namespace eikon {

// The file of a volume for sequence number `number` ('#' run replaced,
// zero-padded); a single file for every number when it is no sequence.
std::string volumeFramePath(const VolumeDesc& volume, int number);

}  // namespace eikon
