// `eikon accuracy`'s image-space rows (render.method "image_space") on the
// glass-sphere cases: present, with finite errors against the exact sharp
// sphere within loose bounds that a black caustic map (an error of 100%), a
// view without exit directions (no finite error) or one whose rays do not
// bend would fail — the caustic within 25% at every map size (2–10%
// measured), the view within 0.1% (1e-5 measured); and carried into the
// CSV, the Markdown report and the plot. No timing is asserted.
#include "tests/integration/GlTestContext.h"
#include "verify/accuracy/AccuracyCase.h"
#include "verify/accuracy/AccuracyReport.h"
#include "verify/accuracy/ErrorPlot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace eikon {
namespace {

using accuracy::RunRecord;
using accuracy::RunSettings;

// The image-space runs of case `name`'s quick sweep.
std::vector<RunRecord> imageSpaceRows(const std::string& name) {
    std::vector<RunRecord> records;
    for (const auto& c : accuracy::allCases()) {
        if (c->name() != name) continue;
        for (const RunSettings& settings : c->sweep(true))
            if (settings.method == RenderDesc::Method::ImageSpace)
                for (RunRecord& record : c->run(settings, true)) records.push_back(std::move(record));
    }
    return records;
}

void expectRows(const std::vector<RunRecord>& rows, const std::string& measure, int minimumSamples, double bound) {
    ASSERT_GE(rows.size(), 2u);
    for (const RunRecord& r : rows) {
        const std::string label = accuracy::settingsLabel(r);
        test::reportFigure((measure + " " + label).c_str(), r.measurement.error);
        EXPECT_EQ(r.measurement.caseName, measure) << label;
        EXPECT_TRUE(std::isfinite(r.measurement.error)) << label;
        EXPECT_LT(r.measurement.error, bound) << label;
        EXPECT_GE(r.measurement.samples, minimumSamples) << label;
        EXPECT_GT(r.runtimeSeconds, 0.0) << label;
    }
}

TEST(AccuracyImageSpace, GlassSphereMapHasCausticMapRows) {
    test::glContext();
    expectRows(imageSpaceRows("glass_sphere_map"), "glass_sphere_map", 64 * 64, 0.25);
}

TEST(AccuracyImageSpace, GlassSphereHasViewRows) {
    test::glContext();
    expectRows(imageSpaceRows("glass_sphere"), "glass_sphere_reference", 5000, 1e-3);
}

// One eikonal and one image-space record through every output: the CSV
// (the tracer's cells empty for image space), the report's image-space
// table, and the plot.
TEST(AccuracyImageSpace, ReportsCarryTheImageSpaceRows) {
    RunRecord eikonal;
    eikonal.measurement = {"glass_sphere_map", "relative L1 against the smoothed sphere", 0.02, -1.0, 4096};
    eikonal.runtimeSeconds = 0.5;
    eikonal.grid = "64x64x64";
    RunRecord imageSpace;
    imageSpace.settings.method = RenderDesc::Method::ImageSpace;
    imageSpace.settings.causticMapTexels = 256;
    imageSpace.settings.sweep = "caustic_map";
    imageSpace.measurement = {"glass_sphere_map", "image space: relative L1 against the sharp sphere", 0.03, -1.0, 4096};
    imageSpace.runtimeSeconds = 0.05;
    const std::vector<RunRecord> records = {eikonal, imageSpace};
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "eikon_accuracy_image_space";
    std::filesystem::create_directories(dir);
    accuracy::writeCsv(dir / "accuracy.csv", records);
    accuracy::writeMarkdown(dir / "accuracy.md", records, {"test", "renderer", 1.0, "accuracy.png"});
    accuracy::writeErrorPlot(dir / "accuracy.png", records);
    const auto read = [](const std::filesystem::path& file) {
        std::ifstream in(file);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    };
    const std::string csv = read(dir / "accuracy.csv");
    EXPECT_NE(csv.find(",method,caustic_map_texels,image_pixels\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find("glass_sphere_map,,,caustic_map,,,,,,"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",image_space,256,0\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",eikonal,0,0\n"), std::string::npos) << csv;
    const std::string md = read(dir / "accuracy.md");
    EXPECT_NE(md.find("### Image space beside the eikonal tracer"), std::string::npos) << md;
    EXPECT_NE(md.find("| glass_sphere_map | image_space caustic map 256² | 0.05 | 3% | "), std::string::npos) << md;
    EXPECT_NE(md.find("- glass_sphere_map: image space: relative L1 against the sharp sphere."), std::string::npos) << md;
    // Measured against another truth, the image-space run is kept off the tracer's tables and fronts.
    EXPECT_EQ(md.find("image_space caustic map 256²"), md.rfind("image_space caustic map 256²")) << md;
    EXPECT_GT(std::filesystem::file_size(dir / "accuracy.png"), 10000u);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace eikon
