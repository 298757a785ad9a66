#include "apps/eikon/InfoCommand.h"

#include "render/gl/GlContext.h"

#include <iostream>
#include <string>

namespace eikon::app {

void addInfoCommand(CLI::App& app) {
    app.add_subcommand("info", "Print the OpenGL vendor, renderer and version eikon uses, and library versions");
}

int infoCommand() {
    std::cout << "eikon " << EIKON_VERSION << "\n";
    try {
        const auto context = gl::createHeadlessContext();
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
    return 0;
}

}  // namespace eikon::app
