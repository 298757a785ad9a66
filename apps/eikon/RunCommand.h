// `eikon run SCENE`: render a scene headless into an output folder.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace eikon::app {

struct RunOptions {
    std::string scenePath;
    std::string outDir;  // default: out/<scene file stem>
    int frames = 1;
    std::vector<std::string> overrides;
    bool quiet = false;
    bool force = false;
    bool vtk = false;                  // turn export.vtk on (the scene's and --set's settings apply)
    std::string pipelining = "auto";  // on, off, or auto: on unless OpenGL renders on the CPU
    std::string distribute = "auto";  // under mpirun: photons, frames, or auto (FrameLoop.h, Distribution)
    bool framesGiven = false;         // --frames on the command line (following: else without a count)
    bool follow = false;              // follow the volume as a simulation writes it (VolumeFollower.h)
    double followPollMs = 250.0;
    double followTimeoutS = 60.0;
    std::string followStop;
};

void addRunCommand(CLI::App& app, RunOptions& options);
int runCommand(const RunOptions& options);

}  // namespace eikon::app
