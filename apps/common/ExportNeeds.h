// What a run exports, frame by frame (the scene's `export` section): which
// frames, and which arrays — so that the live loop reads back from the GPU
// only what goes out, when it goes out (LiveFrames.h).
#pragma once

#include "bridge/scene/ExportDesc.h"

#include <string>
#include <vector>

namespace eikon::app {

class ExportNeeds {
public:
    ExportNeeds() = default;  // nothing
    explicit ExportNeeds(const ExportDesc& exports);

    bool any() const { return !selections_.empty(); }
    bool exportsFrame(int frame) const;
    bool wants(const std::string& name) const;
    // The names to hand SceneFields::exportArrays (empty: all).
    const std::vector<std::string>& names() const { return names_; }

private:
    std::vector<ExportSelection> selections_;  // the enabled ones
    std::vector<std::string> names_;
    bool all_ = false;
};

}  // namespace eikon::app
