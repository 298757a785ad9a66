// `eikon converge`: error against run time for the user's own scene — a
// self-convergence study over its knobs within a time budget
// (verify/converge/): converge.csv, converge.png and .svg, converge.md.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace eikon::app {

struct ConvergeOptions {
    std::string scenePath;
    std::string outDir;
    double budgetSeconds = 300.0;
    int frame = 0;
    std::string outputs;    // comma-separated; empty: every output the scene has
    std::string reference;  // "photons=16,step=4,grid=1.5"; empty: chosen to fit the budget
    std::vector<std::string> overrides;
    bool force = false;
};

void addConvergeCommand(CLI::App& app, ConvergeOptions& options);
int convergeCommand(const ConvergeOptions& options);

}  // namespace eikon::app
