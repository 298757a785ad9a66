// Checks of a mesh file's bytes before OpenMesh reads them (io/mesh/
// MeshReader), for what OpenMesh 9 would otherwise accept silently, allocate
// for without bound, or loop on forever. Each failure is an InputError
// naming the file and, in text files, the line.
#pragma once

#include <string>

namespace eikon::io {

// extension: ".obj", ".ply", ".off" or ".stl", lower case.
void checkMeshFileBytes(const std::string& path, const std::string& extension, const std::string& bytes);

}  // namespace eikon::io
