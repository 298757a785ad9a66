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
// index, mapped to δn on the GPU, and those of κ and σs (a density, grey or
// RGB extinction and scattering), mapped or checked there. The others
// (flame, anisotropy, emission) are mapped with the scene's medium on the
// host.
inline constexpr const char* kIndexBufferFields[] = {"delta_index", "index", "temperature"};
inline constexpr const char* kCoefficientBufferFields[] = {"density", "extinction", "scattering"};

}  // namespace eikon::library
