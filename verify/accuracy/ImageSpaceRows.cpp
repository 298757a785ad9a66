#include "verify/accuracy/ImageSpaceRows.h"

#include <utility>

namespace eikon::accuracy {

namespace {

class WithImageSpaceRows final : public AccuracyCase {
public:
    WithImageSpaceRows(std::unique_ptr<AccuracyCase> eikonal, std::unique_ptr<AccuracyCase> imageSpace)
        : eikonal_(std::move(eikonal)), imageSpace_(std::move(imageSpace)) {}

    std::string name() const override { return eikonal_->name(); }

    std::vector<RunSettings> sweep(bool quick) const override {
        std::vector<RunSettings> runs = eikonal_->sweep(quick);
        for (const RunSettings& run : imageSpace_->sweep(quick)) runs.push_back(run);
        return runs;
    }

    std::vector<RunRecord> run(const RunSettings& settings, bool quick) const override {
        return (settings.method == RenderDesc::Method::ImageSpace ? imageSpace_ : eikonal_)->run(settings, quick);
    }

private:
    std::unique_ptr<AccuracyCase> eikonal_, imageSpace_;
};

}  // namespace

std::unique_ptr<AccuracyCase> withImageSpaceRows(std::unique_ptr<AccuracyCase> eikonal,
                                                 std::unique_ptr<AccuracyCase> imageSpace) {
    return std::make_unique<WithImageSpaceRows>(std::move(eikonal), std::move(imageSpace));
}

}  // namespace eikon::accuracy
