// `eikon warm-shaders SCENE…`: renders the first frame of each scene as
// `eikon run` would, writing nothing, so that the driver's shader cache
// holds every program the scenes use before their first picture. On Mesa's
// llvmpipe a program is compiled with LLVM at its first dispatch and the
// disk cache (MESA_SHADER_CACHE_DIR, else XDG_CACHE_HOME, else ~/.cache)
// keeps it: the build runs this on scenes/default.json (cmake/WarmShaders.cmake),
// so a fresh machine's first `eikon run` starts warm and the build pays the
// compile instead. eikon writes nothing to the cache itself; the driver does.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace eikon::app {

struct WarmShadersOptions {
    std::vector<std::string> scenePaths;
};

void addWarmShadersCommand(CLI::App& app, WarmShadersOptions& options);
int warmShadersCommand(const WarmShadersOptions& options);

}  // namespace eikon::app
