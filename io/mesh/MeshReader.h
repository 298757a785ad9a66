// Triangle meshes from OBJ, PLY, OFF and STL files, read with OpenMesh.
//
// Every problem throws InputError naming the file and the reason: a missing
// or unreadable file, an unknown extension, a file shorter than its header
// declares, a non-finite coordinate (with its line in text files), a face
// that refers to a vertex the file does not have, and — where a closed mesh
// is needed — the number of open and of non-manifold edges.
#pragma once

#include "bridge/mesh/TriangleMesh.h"

#include <string>

namespace eikon::io {

enum class MeshClosure { Any, Closed };

// Polygons are split into triangle fans; vertices keep the file's order.
TriangleMesh readMesh(const std::string& path, MeshClosure closure = MeshClosure::Closed);

}  // namespace eikon::io
