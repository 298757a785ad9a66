// A caller's field handed as an OpenGL buffer (eikon::Field::buffer), the
// library's GPU path, and which fields may take it.
#pragma once

#include <string>

namespace eikon::library {

struct BufferField {
    std::string name;
    unsigned buffer = 0;
    int channels = 1;
};

// The fields the GPU path takes (apps/library/GpuFieldPass.h): those of the
// index, mapped to δn on the GPU, and the RGB coefficients, checked there.
// The others (density, flame, anisotropy, emission) are mapped with the
// scene's medium on the host.
inline constexpr const char* kIndexBufferFields[] = {"delta_index", "index", "temperature"};
inline constexpr const char* kCoefficientBufferFields[] = {"extinction", "scattering"};

}  // namespace eikon::library
