#include "verify/accuracy/ReceiverMapCase.h"

#include <mutex>

namespace eikon::accuracy {

namespace {

class ReceiverMapCase final : public AccuracyCase {
public:
    explicit ReceiverMapCase(ReceiverMapCaseDefinition definition) : definition_(std::move(definition)) {}

    std::string name() const override { return definition_.name; }

    std::vector<RunSettings> sweep(bool quick) const override {
        // The step's error is the path cases' to measure: here the estimators.
        return standardSweep(quick, {.steps = false, .integrators = false, .octree = false, .grid = false,
                                     .photons = true, .wavefront = true});
    }

    std::vector<RunRecord> run(const RunSettings& settings, bool) const override {
        std::call_once(truthOnce_, [&] { truth_ = definition_.truth(); });
        Scene scene = definition_.scene();
        applySettings(scene, settings, scene.grid.resolution);
        const GpuTrace trace =
            traceOnGpu(scene, sampleIndexField(definition_.field(), scene.grid.spec(), definition_.referenceIndex));
        Measurement m{name(), definition_.metric, definition_.error(trace.receiverMap, truth_), -1.0,
                      static_cast<int>(truth_.size())};
        return {makeRecord(scene, settings, trace, m)};
    }

private:
    ReceiverMapCaseDefinition definition_;
    mutable std::once_flag truthOnce_;
    mutable std::vector<double> truth_;
};

}  // namespace

std::unique_ptr<AccuracyCase> makeReceiverMapCase(ReceiverMapCaseDefinition definition) {
    return std::make_unique<ReceiverMapCase>(std::move(definition));
}

}  // namespace eikon::accuracy
