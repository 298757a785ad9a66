// verify/plot: a log–log figure comes out as a PNG whose curves, markers,
// axes and labels are drawn (not a blank page) and an SVG beside it with
// the same text, both written atomically (no temporary left), and a folder
// it cannot write into is an error naming the file.
#include "io/image/ImageIo.h"
#include "verify/plot/LogLogFigure.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace eikon {
namespace {

namespace fs = std::filesystem;

plot::Figure twoPanels() {
    plot::Figure figure;
    figure.columns = 2;
    figure.xLabel = "run time (s)";
    figure.yLabel = "relative error";
    figure.panels = {{"first knob",
                      {{{0.01, 0.1, 1.0}, {0.5, 0.05, 0.005}, {214, 39, 40}, plot::Marker::Square, false, 2.0}},
                      {0.01}},
                     {"second knob",
                      {{{0.02, 0.2}, {0.3, 0.03}, {31, 119, 180}, plot::Marker::Triangle, true, 1.0}},
                      {}}};
    figure.legendRows = {{{"photons", {214, 39, 40}}, {"step", {31, 119, 180}, plot::Marker::Triangle, true, true}}};
    figure.caption = "error against run time";
    return figure;
}

int pixelsNear(const io::Rgba8Image& image, int r, int g, int b) {
    int count = 0;
    for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
        if (std::abs(image.rgba[i] - r) < 40 && std::abs(image.rgba[i + 1] - g) < 40 && std::abs(image.rgba[i + 2] - b) < 40)
            ++count;
    return count;
}

class Plot : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("eikon_plot_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(Plot, WritesPngAndSvgWithCurvesAxesAndLabels) {
    plot::writeFigure(dir_ / "figure.png", twoPanels());
    const io::Rgba8Image image = io::readImage(dir_ / "figure.png");
    EXPECT_EQ(image.width, 2 * 420);
    EXPECT_GT(image.height, 320);
    EXPECT_GT(pixelsNear(image, 214, 39, 40), 200) << "the red curve, its markers and its legend line";
    EXPECT_GT(pixelsNear(image, 31, 119, 180), 100) << "the blue curve";
    EXPECT_GT(pixelsNear(image, 20, 20, 20), 500) << "axes, tick labels and text";
    EXPECT_GT(pixelsNear(image, 255, 255, 255), image.width * image.height / 2) << "a white page";

    std::stringstream svg;
    svg << std::ifstream(dir_ / "figure.svg").rdbuf();
    EXPECT_NE(svg.str().find("<svg"), std::string::npos);
    EXPECT_GT(svg.str().size(), 10000u) << "paths and glyphs, not an empty page";
    int entries = 0;
    for (const auto& entry : fs::directory_iterator(dir_)) {
        ++entries;
        EXPECT_TRUE(entry.path().extension() == ".png" || entry.path().extension() == ".svg") << entry.path();
    }
    EXPECT_EQ(entries, 2) << "no temporaries left";
}

TEST_F(Plot, AFolderThatCannotBeWrittenIsAnErrorNamingTheFile) {
    const fs::path missing = dir_ / "no_such_folder" / "figure.png";
    try {
        plot::writeFigure(missing, twoPanels());
        FAIL() << "wrote into a missing folder";
    } catch (const std::exception& error) {
        EXPECT_NE(std::string(error.what()).find("figure.png"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace eikon
