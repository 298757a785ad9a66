#include "render/accuracy/AccuracySuite.h"

#include "bridge/core/Error.h"
#include "render/accuracy/AccuracyCase.h"
#include "render/accuracy/AccuracyCase.h"

namespace eikon::accuracy {

std::vector<std::string> caseNames() {
    std::vector<std::string> names;
    for (const auto& c : allCases()) names.push_back(c->name());
    return names;
}

std::vector<RunRecord> runSuite(const SuiteOptions& options) {
    const auto cases = allCases();
    if (!options.caseName.empty()) {
        bool known = false;
        for (const auto& c : cases) known = known || c->name() == options.caseName;
        if (!known) {
            std::string list;
            for (const auto& c : cases) list += (list.empty() ? "" : ", ") + c->name();
            throw InputError("--case", "one of " + list, "'" + options.caseName + "'");
        }
    }
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
