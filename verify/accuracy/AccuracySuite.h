// Runs the accuracy cases over their sweeps of tracer knobs (`eikon accuracy`).
#pragma once

#include "verify/accuracy/AccuracyRun.h"

#include <functional>
#include <string>
#include <vector>

namespace eikon::accuracy {

struct SuiteOptions {
    bool quick = false;
    std::string caseName;  // empty: every case
    std::function<void(const RunRecord&)> onRun;  // called after each measurement
};

std::vector<std::string> caseNames();
// Throws InputError (listing the cases) unless `name` is one.
void checkCaseName(const std::string& name);

// Traces every setting of the selected cases in the current OpenGL context.
// Throws InputError for an unknown case name.
std::vector<RunRecord> runSuite(const SuiteOptions& options);

}  // namespace eikon::accuracy
