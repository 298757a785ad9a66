#include "verify/accuracy/AccuracySuite.h"

#include "bridge/core/Error.h"
#include "verify/accuracy/AccuracyCase.h"

#include <algorithm>

namespace eikon::accuracy {

std::vector<std::string> caseNames() {
    std::vector<std::string> names;
    for (const auto& c : allCases()) names.push_back(c->name());
    return names;
}

void checkCaseName(const std::string& name) {
    const auto names = caseNames();
    if (std::find(names.begin(), names.end(), name) != names.end()) return;
    std::string list;
    for (const auto& known : names) list += (list.empty() ? "" : ", ") + known;
    throw InputError("--case", "one of " + list, "'" + name + "'");
}

std::vector<RunRecord> runSuite(const SuiteOptions& options) {
    if (!options.caseName.empty()) checkCaseName(options.caseName);
    const auto cases = allCases();
    std::vector<RunRecord> records;
    for (const auto& c : cases) {
        if (!options.caseName.empty() && c->name() != options.caseName) continue;
        for (const RunSettings& settings : c->sweep(options.quick))
            for (RunRecord& record : c->run(settings, options.quick)) {
                if (options.onRun) options.onRun(record);
                records.push_back(std::move(record));
            }
    }
    measureStepErrors(records);
    return records;
}

}  // namespace eikon::accuracy
