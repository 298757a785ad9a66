#include "apps/eikon/InfoCommand.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <CLI/Version.hpp>
#include <glm/detail/setup.hpp>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <openvdb/version.h>
#include <tbb/version.h>
#include <vtkVersion.h>

namespace eikon::app {

std::vector<std::pair<std::string, std::string>> libraryVersions() {
    auto dotted = [](int major, int minor, int patch) {
        return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
    };
    char mpi[MPI_MAX_LIBRARY_VERSION_STRING] = {};
    int length = 0;
    MPI_Get_library_version(mpi, &length);  // may be called before MPI_Init
    std::string mpiVersion(mpi, static_cast<std::size_t>(length));
    mpiVersion = mpiVersion.substr(0, mpiVersion.find(','));  // "Open MPI v4.1.4"
    return {
        {"OpenVDB", openvdb::getLibraryAbiVersionString()},
        {"VTK", vtkVersion::GetVTKVersion()},
        {"oneTBB", TBB_runtime_version()},
        {"GLFW", glfwGetVersionString()},
        {"GLM", dotted(GLM_VERSION_MAJOR, GLM_VERSION_MINOR, GLM_VERSION_PATCH)},
        {"nlohmann_json", dotted(NLOHMANN_JSON_VERSION_MAJOR, NLOHMANN_JSON_VERSION_MINOR, NLOHMANN_JSON_VERSION_PATCH)},
        {"CLI11", CLI11_VERSION},
        {"MPI", mpiVersion},
    };
}

}  // namespace eikon::app
