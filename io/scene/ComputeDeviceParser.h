// "device": "auto" | "cpu" | "gpu" — where a simulation runs (sim.device,
// a water object's device; bridge/scene/ComputeDevice.h).
#pragma once

#include "bridge/scene/ComputeDevice.h"
#include "io/scene/JsonReader.h"

namespace eikon {

ComputeDevice readComputeDevice(const JsonReader& node);

}  // namespace eikon
