// What `eikon accuracy` writes: accuracy.csv (one row per run and measure),
// accuracy.md (per case: measured orders, the floor, the cheapest setting for
// 1% and 0.1%), and the analysis both share.
#pragma once

#include "verify/accuracy/AccuracyRun.h"

#include <filesystem>
#include <string>
#include <vector>

namespace eikon::accuracy {

std::string settingsLabel(const RunRecord& record);
std::string curveLabel(const RunSettings& settings);  // integrator + step policy

// Local orders log2(e(Δs)/e(Δs/2)) of one integrator's uniform-step sweep on one case.
struct OrderEstimate {
    std::string integrator;
    std::vector<double> steps;      // voxels, descending
    std::vector<double> errors;
    std::vector<double> localOrders;
    double fittedOrder = 0.0;       // slope over points above 3× the floor; NaN when fewer than two
    bool selfConvergence = false;   // errors are stepErrorVoxels (against the finest RK4 run), not against the truth
};
// selfConvergence: by stepErrorVoxels (cases that record them); else by the error against the truth.
std::vector<OrderEstimate> estimateOrders(const std::vector<RunRecord>& records, const std::string& caseName,
                                          bool selfConvergence);

void writeCsv(const std::filesystem::path& file, const std::vector<RunRecord>& records);

struct ReportContext {
    std::string command;    // how the report was made
    std::string renderer;   // OpenGL renderer string
    double wallSeconds = 0.0;
    std::string plotPath;   // relative to the markdown file
};
void writeMarkdown(const std::filesystem::path& file, const std::vector<RunRecord>& records, const ReportContext& context);

}  // namespace eikon::accuracy
