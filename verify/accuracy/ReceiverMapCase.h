// An accuracy case measured on a receiver map (the "_map" cases): one scene
// and one sampled analytic field, swept over the two light estimators —
// photon counts and the wavefront's split size — and scored by the relative
// L1 of its receiver map against a ground truth computed once, on first use.
#pragma once

#include "verify/accuracy/AccuracyCase.h"
#include "verify/reference/IndexField.h"

#include <functional>
#include <string>
#include <vector>

namespace eikon::accuracy {

struct ReceiverMapCaseDefinition {
    std::string name;
    std::string metric;  // what the error is, in words
    std::function<Scene()> scene;
    std::function<const reference::IndexField&()> field;
    double referenceIndex = 1.0;
    // The ground truth, and the map's error against it.
    std::function<std::vector<double>()> truth;
    std::function<double(const std::vector<float>& map, const std::vector<double>& truth)> error;
};

std::unique_ptr<AccuracyCase> makeReceiverMapCase(ReceiverMapCaseDefinition definition);

}  // namespace eikon::accuracy
