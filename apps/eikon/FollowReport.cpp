#include "apps/eikon/FollowReport.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace eikon::app {

namespace {

nlohmann::json skippedJson(const std::vector<sim::SkippedStep>& skipped) {
    nlohmann::json steps = nlohmann::json::array();
    for (const sim::SkippedStep& step : skipped) steps.push_back({{"step", step.step}, {"reason", step.reason}});
    return steps;
}

}  // namespace

std::string withFollowedStep(const std::string& reportLine, const std::string& step,
                             const std::vector<sim::SkippedStep>& skipped) {
    nlohmann::json line = nlohmann::json::parse(reportLine);
    line["follow"] = {{"step", step}, {"skipped", skippedJson(skipped)}};
    return line.dump();
}

std::string followEndLine(const std::string& why, int frames, const std::vector<sim::SkippedStep>& skipped) {
    return nlohmann::json{{"follow_end", {{"why", why}, {"frames", frames}, {"skipped", skippedJson(skipped)}}}}.dump();
}

void warnSkipped(const std::vector<sim::SkippedStep>& skipped) {
    for (const sim::SkippedStep& step : skipped)
        std::cerr << "eikon: warning: skipped step " << step.step << ": " << step.reason << "\n";
}

}  // namespace eikon::app
