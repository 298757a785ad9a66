#include "apps/eikon/InfoCommand.h"

#include "apps/eikon/Ranks.h"
#include "gl/GlContext.h"

#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

namespace eikon::app {

void addInfoCommand(CLI::App& app) {
    app.add_subcommand("info", "Print the OpenGL vendor, renderer and version eikon uses, and library versions");
}

namespace {

// Under mpirun: which machine and OpenGL device each rank renders with.
void listRanks(const Ranks& ranks, const std::string& device) {
    char host[256] = {};
    ::gethostname(host, sizeof host - 1);
    const std::string line = "rank " + std::to_string(ranks.rank()) + " (" + host + ", local rank " +
                             std::to_string(ranks.localRank()) + " of " + std::to_string(ranks.localSize()) +
                             "): " + device;
    const std::vector<std::string> lines = ranks.gatherToFirst(line);
    if (!ranks.first()) return;
    std::cout << "MPI ranks:       " << ranks.size() << "\n";
    for (const std::string& rankLine : lines) std::cout << "  " << rankLine << "\n";
}

}  // namespace

int infoCommand() {
    Ranks& ranks = Ranks::world();
    std::string device = "OpenGL unavailable";
    if (!ranks.first()) {  // only rank 0 prints; the others say which device they took
        try {
            const auto context = gl::createHeadlessContext(static_cast<unsigned>(ranks.localRank()));
            device = context->info().platform + ", " + context->info().renderer;
        } catch (const std::exception&) {
        }
        listRanks(ranks, device);
        return 0;
    }
    std::cout << "eikon " << EIKON_VERSION << "\n";
    try {
        const auto context = gl::createHeadlessContext(static_cast<unsigned>(ranks.localRank()));
        device = context->info().platform + ", " + context->info().renderer;
        const gl::GlInfo& info = context->info();
        std::cout << "OpenGL platform: " << info.platform << "\n"
                  << "OpenGL vendor:   " << info.vendor << "\n"
                  << "OpenGL renderer: " << info.renderer << "\n"
                  << "OpenGL version:  " << info.version << "\n"
                  << "GLSL version:    " << info.glslVersion << "\n"
                  << "OpenGL limits:   storage buffers " << info.maxStorageBlockBytes << " bytes, textures "
                  << info.maxTextureSize << " (2D) and " << info.max3dTextureSize << " (3D) texels a side, loop budget "
                  << (info.loopBudget > 0 ? std::to_string(info.loopBudget) + " iterations an invocation"
                                          : std::string("none")) << "\n";
    } catch (const std::exception& error) {
        std::cout << "OpenGL: unavailable: " << error.what() << "\n";
    }
    for (const auto& [library, version] : libraryVersions()) std::cout << library << ": " << version << "\n";
    if (ranks.distributed()) listRanks(ranks, device);
    return 0;
}

}  // namespace eikon::app
