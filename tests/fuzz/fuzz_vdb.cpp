// libFuzzer target: an OpenVDB file through the structural checker and then
// VdbVolumeFile, whose every grid is sampled onto a small render grid as a
// volume sequence would be. Only samples or an InputError may come out.
#include "bridge/core/Error.h"
#include "io/vdb/VdbFileCheck.h"
#include "io/vdb/VdbVolumeFile.h"
#include "tests/fuzz/FuzzScratchFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes = eikon::fuzz::asBytes(data, size);
    try {
        for (const eikon::io::VdbGridEntry& grid : eikon::io::checkVdbHeader(bytes, "fuzz.vdb").grids)
            if (!grid.instance && (grid.valueType == "float" || grid.valueType == "vec3s"))
                eikon::io::checkVdbGrid(bytes, grid, "fuzz.vdb");
    } catch (const eikon::InputError&) {
    }
    try {
        const eikon::io::VdbVolumeFile file(eikon::fuzz::writeScratchFile("fuzz.vdb", bytes));
        const eikon::GridSpec grid{glm::ivec3(4), glm::dvec3(-1.0), glm::dvec3(1.0)};
        for (const std::string& name : file.gridNames())
            for (const int components : {1, 3}) {
                try {
                    file.sample(name, components, grid, glm::dvec3(0.0));
                } catch (const eikon::InputError&) {  // the other type: try the next
                }
            }
    } catch (const eikon::InputError&) {
    }
    return 0;
}
