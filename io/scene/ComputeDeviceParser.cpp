#include "io/scene/ComputeDeviceParser.h"

#include <string>

namespace eikon {

ComputeDevice readComputeDevice(const JsonReader& node) {
    const std::string name = node.oneOf({"auto", "cpu", "gpu"});
    return name == "cpu" ? ComputeDevice::Cpu : name == "gpu" ? ComputeDevice::Gpu : ComputeDevice::Auto;
}

}  // namespace eikon
