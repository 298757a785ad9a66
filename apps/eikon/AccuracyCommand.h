// `eikon accuracy`: the tracer's error against run time on analytic cases
// with known answers, over sweeps of its knobs (verify/accuracy/).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace eikon::app {

struct AccuracyOptions {
    bool quick = false;
    std::string caseName;  // empty: all
    std::string outDir;
    std::string docPath;   // optional: regenerate the marked section of this markdown file (and images/accuracy.png beside it)
};

void addAccuracyCommand(CLI::App& app, AccuracyOptions& options);
int accuracyCommand(const AccuracyOptions& options);

}  // namespace eikon::app
