// The glass-sphere cases' image-space rows (render.method "image_space"):
// the caustic on glass_sphere_map's receiver from caustic maps ([Wyman06]
// §3) over their size, and glass_sphere's exit rays from the camera's view
// ([Hu07] §2) over its resolution, each against the exact sharp sphere.
#include "verify/accuracy/Cases.h"

#include "verify/accuracy/GlassSphereMap.h"
#include "verify/accuracy/GlassSphereView.h"
#include "verify/accuracy/ReceiverCaseScene.h"

#include <mutex>

namespace eikon::accuracy {

namespace {

RunSettings imageSpaceRun(const char* sweep) {
    RunSettings run;
    run.method = RenderDesc::Method::ImageSpace;
    run.sweep = sweep;
    return run;
}

class GlassSphereCausticRows final : public AccuracyCase {
public:
    std::string name() const override { return "glass_sphere_map"; }

    std::vector<RunSettings> sweep(bool quick) const override {
        std::vector<RunSettings> runs;
        for (int texels : quick ? std::vector<int>{128, 256, 512} : std::vector<int>{128, 256, 512, 1024}) {
            RunSettings run = imageSpaceRun("caustic_map");
            run.causticMapTexels = texels;
            runs.push_back(run);
        }
        return runs;
    }

    std::vector<RunRecord> run(const RunSettings& settings, bool) const override {
        std::call_once(truthOnce_, [&] { truth_ = sharpGlassSphereReferenceMap(); });
        const ImageSpaceFrame frame = renderImageSpace(sharpGlassSphereMapScene(settings.causticMapTexels));
        Measurement m{"glass_sphere_map",
                      "image space: relative L1 over the receiver against the exact sharp sphere's rings (Fresnel)",
                      texelMapError(frame.receiverMap, truth_), -1.0, static_cast<int>(truth_.size())};
        return {makeImageSpaceRecord(settings, frame.runtimeSeconds, m)};
    }

private:
    mutable std::once_flag truthOnce_;
    mutable std::vector<double> truth_;
};

class GlassSphereViewRows final : public AccuracyCase {
public:
    std::string name() const override { return "glass_sphere"; }

    std::vector<RunSettings> sweep(bool quick) const override {
        std::vector<RunSettings> runs;
        for (int pixels : quick ? std::vector<int>{160, 320} : std::vector<int>{160, 320, 640}) {
            RunSettings run = imageSpaceRun("view");
            run.imagePixels = pixels;
            runs.push_back(run);
        }
        return runs;
    }

    std::vector<RunRecord> run(const RunSettings& settings, bool) const override {
        const Scene scene = glassSphereViewScene(settings.imagePixels);
        const ImageSpaceFrame frame = renderImageSpace(scene);
        return {makeImageSpaceRecord(settings, frame.runtimeSeconds, glassSphereViewError(scene, frame.exits))};
    }
};

}  // namespace

std::unique_ptr<AccuracyCase> makeGlassSphereCausticRows() { return std::make_unique<GlassSphereCausticRows>(); }
std::unique_ptr<AccuracyCase> makeGlassSphereViewRows() { return std::make_unique<GlassSphereViewRows>(); }

}  // namespace eikon::accuracy
