// What `eikon converge` writes: converge.csv (every rung: knob, setting,
// run time, each output's error with its metric), converge.png and .svg
// (error against run time, log–log, a panel per output and a curve per
// knob) and converge.md (the cheapest setting for 10%, 1% and 0.1% where a
// rung reached it, the reference's own error extrapolated where the order
// is known, and what was left out).
#pragma once

#include "verify/converge/ConvergeStudy.h"

#include <filesystem>
#include <optional>
#include <string>

namespace eikon::converge {

// The cheapest rung whose every compared output is within `target`.
std::optional<Measured> cheapestWithin(const Study& study, double target);

// The reference's own error, extrapolated from the finest rung of a knob
// whose order is known, per output; with the method stated.
struct OwnError {
    std::string knob, method;
    std::optional<double> receivers, image, fluence;
};
std::vector<OwnError> referenceOwnError(const Study& study);

std::string csvText(const Study& study);
std::string markdownText(const Study& study, const std::string& command, const std::string& renderer);
// converge.png and converge.svg into `folder`.
void writePlot(const Study& study, const std::filesystem::path& folder);

}  // namespace eikon::converge
