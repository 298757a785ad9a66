// Checks of a mesh file's bytes before OpenMesh reads them (io/mesh/
// MeshReader), for what OpenMesh 9 would otherwise accept silently, allocate
// for without bound, or loop on forever. Each failure is an InputError
// naming the file and, in text files, the line.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace eikon::io {

// extension: ".obj", ".ply", ".off" or ".stl", lower case.
void checkMeshFileBytes(const std::string& path, const std::string& extension, const std::string& bytes);

// Lines of a text OFF or ASCII PLY file after its header, blank lines and
// '#' comments left out; nullopt for other files. OpenMesh's text readers
// repeat the last values they read when a file ends early, so truncation
// shows only here: a header declaring V vertices and F faces needs V + F lines.
std::optional<std::size_t> dataLines(const std::string& extension, const std::string& bytes);

}  // namespace eikon::io
