// libFuzzer target: one mesh reader, chosen at build time by
// EIKON_FUZZ_MESH_EXTENSION (".obj", ".ply", ".off" or ".stl"), reading the
// input as a file of that kind, open meshes allowed (as for water) and then
// closed (as for glass). Only a mesh or an InputError may come out.
#include "bridge/core/Error.h"
#include "io/mesh/MeshReader.h"
#include "tests/fuzz/FuzzScratchFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = eikon::fuzz::writeScratchFile(std::string("mesh") + EIKON_FUZZ_MESH_EXTENSION,
                                                    eikon::fuzz::asBytes(data, size));
    for (const auto closure : {eikon::io::MeshClosure::Any, eikon::io::MeshClosure::Closed}) {
        try {
            eikon::io::readMesh(path.string(), closure);
        } catch (const eikon::InputError&) {
        }
    }
    return 0;
}
