#include "apps/common/ExportNeeds.h"

#include <algorithm>

namespace eikon::app {

ExportNeeds::ExportNeeds(const ExportDesc& exports) {
    for (const ExportSelection* selection : {static_cast<const ExportSelection*>(&exports.vtk),
                                             static_cast<const ExportSelection*>(&exports.vdb)}) {
        if (!selection->enabled) continue;
        selections_.push_back(*selection);
        all_ = all_ || selection->fields.empty();
        for (const std::string& name : selection->fields)
            if (std::find(names_.begin(), names_.end(), name) == names_.end()) names_.push_back(name);
    }
    if (all_) names_.clear();
}

bool ExportNeeds::exportsFrame(int frame) const {
    return std::any_of(selections_.begin(), selections_.end(),
                       [&](const ExportSelection& selection) { return selection.exportsFrame(frame); });
}

bool ExportNeeds::wants(const std::string& name) const {
    return any() && (all_ || std::find(names_.begin(), names_.end(), name) != names_.end());
}

}  // namespace eikon::app
