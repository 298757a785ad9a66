// `eikon info`: the OpenGL implementation eikon would use, and library versions.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <utility>
#include <vector>

namespace eikon::app {

void addInfoCommand(CLI::App& app);
int infoCommand();

// (library, version) of every library eikon links.
std::vector<std::pair<std::string, std::string>> libraryVersions();

}  // namespace eikon::app
