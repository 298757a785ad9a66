// eikon-view in a window under Xvfb (Mesa): it runs the same frame loop as
// `eikon run` — its frame is the headless render, pixel for pixel — and the
// window shows that frame with the control panel over it.
#include "io/image/ImageIo.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>

namespace {

namespace fs = std::filesystem;

// The command's exit code; what it prints goes to `output`.
int run(const std::string& command, const std::string& output = "/dev/null") {
    const int status = std::system((command + " > " + output + " 2>&1").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const std::string kSmallDefault = std::string(EIKON_SOURCE_DIR) +
                                  "/scenes/default.json --set grid.resolution=[48,40,48] --set render.photons=262144 "
                                  "--set render.width=160 --set render.height=120 --set receivers.0.resolution=96";

double luminanceSpread(const eikon::io::Rgba8Image& image, int x0, int y0, int x1, int y1) {
    double sum = 0.0, sumSquares = 0.0;
    int count = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::size_t p = 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                       static_cast<std::size_t>(x));
            const double l = 0.2126 * image.rgba[p] + 0.7152 * image.rgba[p + 1] + 0.0722 * image.rgba[p + 2];
            sum += l;
            sumSquares += l * l;
            ++count;
        }
    const double mean = sum / count;
    return std::sqrt(std::max(sumSquares / count - mean * mean, 0.0));
}

class ViewerWindow : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("eikon_viewer_window_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

// The viewer shows the headless frame pixel for pixel, beside the control
// panel: at 25 rays a pixel, the finest grid (5×5) the viewer refines to, it
// has no finer grid to add while nothing moves.
TEST_F(ViewerWindow, ShowsTheHeadlessFrameWithThePanel) {
    const fs::path frame = dir_ / "frame.png", window = dir_ / "window.png", headless = dir_ / "headless";
    const std::string scene = kSmallDefault + " --set render.samples_per_pixel=25";
    ASSERT_EQ(run(std::string(EIKON_XVFB_RUN) + " -a -s '-screen 0 800x600x24' " + EIKON_VIEW_EXECUTABLE + " " +
                  scene + " --frames 3 --width 640 --height 480 --screenshot " + frame.string() +
                  " --window-shot " + window.string()),
              0);
    ASSERT_EQ(run(std::string(EIKON_EXECUTABLE) + " run " + scene + " --quiet --out " + headless.string()), 0);
    const auto viewed = eikon::io::readImage(frame);
    const auto rendered = eikon::io::readImage(headless / "frames" / "frame_00000.png");
    ASSERT_EQ(viewed.width, rendered.width);
    ASSERT_EQ(viewed.height, rendered.height);
    EXPECT_EQ(viewed.rgba, rendered.rgba);  // the headless test checks this image's caustic

    const auto shown = eikon::io::readImage(window);
    ASSERT_EQ(shown.width, 640);
    ASSERT_EQ(shown.height, 480);
    // Not blank: the scaled frame on the right half has contrast, and the
    // panel's text at the top left has its own.
    EXPECT_GT(luminanceSpread(shown, 400, 100, 640, 480), 20.0);
    EXPECT_GT(luminanceSpread(shown, 10, 10, 300, 200), 20.0);
}

// The viewer's summary of a scripted run: previews, of them in image space,
// the largest image-space downscale, the largest pixel stride, and how many
// of them advanced a moving scene.
struct PreviewCounts {
    int previews = -1, imageSpace = -1, scale = -1, stride = -1, advanced = -1;
};

PreviewCounts previewCounts(const fs::path& log) {
    PreviewCounts counts;
    std::FILE* file = std::fopen(log.c_str(), "r");
    if (!file) return counts;
    char line[512] = {};
    bool found = false;  // the summary line, among whatever else the run printed
    while (!found && std::fgets(line, sizeof line, file)) found = std::strstr(line, "previews") != nullptr;
    std::fclose(file);
    const char* tail = found ? std::strstr(line, "photon count") : nullptr;
    if (tail)
        std::sscanf(tail,
                    "photon count %*d, %d previews (%d in image space, at up to 1/%d size; pixel stride up to %d), "
                    "%d of them advanced the scene",
                    &counts.previews, &counts.imageSpace, &counts.scale, &counts.stride, &counts.advanced);
    return counts;
}

// Orbiting shows the preview (a view-pass target of 0.1 ms makes every
// moving frame one; the viewer prints how many and of which kind): for the
// default scene, all surfaces, the image-space preview, drawn smaller once
// its first frame's view pass missed the target; for the same scene
// with smoothed (graded) glass, one camera ray per k×k pixels. Back at the
// scene's camera and at rest, the viewer refines to the headless frame,
// pixel for pixel.
TEST_F(ViewerWindow, OrbitingShowsThePreviewAndRestRefinesToTheHeadlessFrame) {
    for (const auto& [overrides, imageSpace] : {std::pair<std::string, bool>{"", true},
                                                {" --set objects.0.surface=smooth", false}}) {
        const fs::path frame = dir_ / "frame.png", headless = dir_ / "headless", log = dir_ / "viewer.txt";
        fs::remove_all(headless);
        ASSERT_EQ(run(std::string(EIKON_XVFB_RUN) + " -a -s '-screen 0 800x600x24' " + EIKON_VIEW_EXECUTABLE + " " +
                          kSmallDefault + overrides +
                          " --frames 6 --animate orbit-return --preview-ms 0.1 --width 640 --height 480" +
                          " --screenshot " + frame.string(),
                      log.string()),
                  0);
        const PreviewCounts counts = previewCounts(log);
        EXPECT_GE(counts.previews, 5) << overrides;  // every orbiting frame after the first, and the return
        if (imageSpace) {
            EXPECT_EQ(counts.imageSpace, counts.previews);
            EXPECT_GT(counts.scale, 1);
            EXPECT_EQ(counts.stride, 1);
        } else {
            EXPECT_EQ(counts.imageSpace, 0);
            EXPECT_EQ(counts.scale, 1);
            EXPECT_GT(counts.stride, 1);
        }
        ASSERT_EQ(run(std::string(EIKON_EXECUTABLE) + " run " + kSmallDefault + overrides + " --quiet --out " +
                      headless.string()),
                  0);
        const auto viewed = eikon::io::readImage(frame);
        const auto rendered = eikon::io::readImage(headless / "frames" / "frame_00000.png");
        ASSERT_EQ(viewed.width, rendered.width);
        ASSERT_EQ(viewed.height, rendered.height);
        EXPECT_EQ(viewed.rgba, rendered.rgba) << overrides;
    }
}

// A diagnostic previews too: while the camera moves, the schlieren picture
// of the live candle is drawn with one ray per k×k pixels, as the view's
// preview is (the viewer measures the diagnostic's stage, not the view it
// does not draw), and its solver, on the CPU, goes on in the background.
TEST_F(ViewerWindow, OrbitingADiagnosticShowsItsStridedPreview) {
    const std::string scene = std::string(EIKON_SOURCE_DIR) +
                              "/scenes/candle_schlieren.json --set render.width=90 --set render.height=180 "
                              "--set grid.resolution=[24,60,24] --set sim.resolution=[20,50,20]";
    const fs::path log = dir_ / "viewer.txt";
    ASSERT_EQ(run(std::string(EIKON_XVFB_RUN) + " -a -s '-screen 0 800x600x24' " + EIKON_VIEW_EXECUTABLE + " " +
                      scene + " --frames 12 --animate orbit --preview-ms 0.1 --width 640 --height 480",
                  log.string()),
              0);
    const PreviewCounts counts = previewCounts(log);
    EXPECT_GE(counts.previews, 11);  // every orbiting frame after the first
    EXPECT_EQ(counts.imageSpace, 0);
    EXPECT_GT(counts.stride, 1);
    EXPECT_GE(counts.advanced, 1) << "the simulation goes on while the camera moves";
}

// Back at the scene's camera and at rest, a diagnostic's preview refines to
// the headless picture, pixel for pixel (a still, graded sphere seen
// through the knife-edge schlieren system).
TEST_F(ViewerWindow, ADiagnosticAtRestRefinesToTheHeadlessPicture) {
    const fs::path scene = dir_ / "sphere_schlieren.json", frame = dir_ / "frame.png", headless = dir_ / "headless",
                   log = dir_ / "viewer.txt";
    std::FILE* file = std::fopen(scene.c_str(), "w");
    ASSERT_NE(file, nullptr);
    std::fputs(R"({
  "grid": {"resolution": [24, 48, 24], "bounds": {"min": [-0.06, 0.0, -0.06], "max": [0.06, 0.24, 0.06]}},
  "medium": {"index": 1.000273},
  "objects": [{"type": "sphere", "center": [0.0, 0.12, 0.0], "radius": 0.03, "index": 1.0004, "surface": "smooth"}],
  "lights": [{"type": "directional", "direction": [0.0, -1.0, 0.0], "irradiance": [1.0, 1.0, 1.0]}],
  "camera": {"position": [0.0, 0.12, 0.5], "target": [0.0, 0.12, 0.0], "up": [0, 1, 0],
             "projection": "orthographic", "width_m": 0.12},
  "render": {"width": 90, "height": 180},
  "diagnostic": {"type": "schlieren", "focal_length": 2.0, "source_height": 0.001,
                 "cutoff": "knife_edge", "knife_angle_deg": 90}
})",
               file);
    std::fclose(file);
    ASSERT_EQ(run(std::string(EIKON_XVFB_RUN) + " -a -s '-screen 0 800x600x24' " + EIKON_VIEW_EXECUTABLE + " " +
                      scene.string() + " --frames 6 --animate orbit-return --preview-ms 0.1 --width 640 --height 480" +
                      " --screenshot " + frame.string(),
                  log.string()),
              0);
    const PreviewCounts counts = previewCounts(log);
    EXPECT_GE(counts.previews, 5);  // every orbiting frame after the first, and the return
    EXPECT_GT(counts.stride, 1);
    ASSERT_EQ(run(std::string(EIKON_EXECUTABLE) + " run " + scene.string() + " --quiet --out " + headless.string()), 0);
    const auto viewed = eikon::io::readImage(frame);
    const auto rendered = eikon::io::readImage(headless / "frames" / "frame_00000.png");
    ASSERT_EQ(viewed.width, rendered.width);
    ASSERT_EQ(viewed.height, rendered.height);
    EXPECT_EQ(viewed.rgba, rendered.rgba);
    EXPECT_GT(luminanceSpread(rendered, 0, 0, rendered.width, rendered.height), 5.0) << "the sphere shows";
}

// While the camera moves (every moving frame a preview, as above), a
// deforming scene is held on the frame that draws its last advance
// (SimulationPacer): fewer frames advance it than are drawn; with no
// frame-time target every frame advances it.
TEST_F(ViewerWindow, OrbitingHoldsAMovingSceneBetweenItsFrames) {
    const std::string scene = std::string(EIKON_SOURCE_DIR) +
                              "/scenes/twisting_glass.json --set render.width=160 --set render.height=120 "
                              "--set render.photons=65536 --set grid.resolution=[40,40,40]";
    for (const auto& [target, everyFrame] : {std::pair<std::string, bool>{"", false}, {" --camera-frame-ms 0", true}}) {
        const fs::path log = dir_ / "viewer.txt";
        ASSERT_EQ(run(std::string(EIKON_XVFB_RUN) + " -a -s '-screen 0 800x600x24' " + EIKON_VIEW_EXECUTABLE + " " +
                          scene + target + " --frames 6 --animate orbit --preview-ms 0.1 --width 640 --height 480",
                      log.string()),
                  0);
        const PreviewCounts counts = previewCounts(log);
        ASSERT_GE(counts.previews, 5) << target;
        if (everyFrame) {
            EXPECT_EQ(counts.advanced, counts.previews);
        } else {
            EXPECT_GE(counts.advanced, 1);
            EXPECT_LT(counts.advanced, counts.previews);
        }
    }
}

// A hot column (T in kelvin, 200 K over ambient on its axis at x = `axis`)
// over [-0.5, 0.5] × [0, 1] × [-0.5, 0.5], as ASCII image data.
void writeColumn(const fs::path& path, double axis) {
    std::FILE* file = std::fopen(path.c_str(), "w");
    std::fputs("<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<ImageData WholeExtent=\"0 16 0 16 0 16\" Origin=\"-0.5 0 -0.5\" Spacing=\"0.0625 0.0625 0.0625\">\n"
               "<Piece Extent=\"0 16 0 16 0 16\"><PointData Scalars=\"T\">\n"
               "<DataArray type=\"Float64\" Name=\"T\" format=\"ascii\">\n",
               file);
    for (int k = 0; k <= 16; ++k)
        for (int j = 0; j <= 16; ++j)
            for (int i = 0; i <= 16; ++i) {
                const double x = -0.5 + i / 16.0 - axis, z = -0.5 + k / 16.0;
                std::fprintf(file, "%.6f\n", 293.15 + 200.0 * std::exp(-(x * x + z * z) / 0.01));
            }
    std::fputs("</DataArray></PointData></Piece></ImageData></VTKFile>\n", file);
    std::fclose(file);
}

// Following a series (`--follow`) whose middle step is damaged, the viewer
// moves on to each complete step and ends showing the last, pixel for pixel
// as `eikon run` renders that step alone, and warns of the step it skipped.
// A schlieren picture (no photons, whose count the viewer would adapt while
// the scene moves) at 25 rays a pixel, which the viewer refines to at rest.
TEST_F(ViewerWindow, FollowingASeriesEndsOnItsLastCompleteStep) {
    writeColumn(dir_ / "step_0.vti", -0.2);
    std::FILE* damaged = std::fopen((dir_ / "step_1.vti").c_str(), "w");
    std::fputs("<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\"", damaged);  // cut short
    std::fclose(damaged);
    writeColumn(dir_ / "step_2.vti", 0.2);
    std::FILE* series = std::fopen((dir_ / "run.vti.series").c_str(), "w");
    std::fputs(R"({"files": [{"name": "step_0.vti", "time": 0}, {"name": "step_1.vti", "time": 1},
                  {"name": "step_2.vti", "time": 2}]})", series);
    std::fclose(series);
    const auto sceneFor = [&](const std::string& name, const std::string& path) {
        const fs::path scene = dir_ / name;
        std::FILE* file = std::fopen(scene.c_str(), "w");
        std::fprintf(file, R"({
  "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}},
  "medium": {"index": 1.000273},
  "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1]}],
  "camera": {"position": [0, 0.5, 2], "target": [0, 0.5, 0], "up": [0, 1, 0], "projection": "orthographic", "width_m": 1},
  "render": {"width": 96, "height": 96, "samples_per_pixel": 25, "write_hdr": false},
  "diagnostic": {"type": "schlieren", "focal_length": 2.0, "source_height": 0.001, "cutoff": "knife_edge", "knife_angle_deg": 90},
  "volume": {"path": "%s", "fields": {"temperature": "T", "temperature_unit": "kelvin"}}
})",
                     path.c_str());
        std::fclose(file);
        return scene.string();
    };
    const fs::path frame = dir_ / "frame.png", log = dir_ / "viewer.log";
    ASSERT_EQ(run(std::string(EIKON_XVFB_RUN) + " -a -s '-screen 0 800x600x24' " + EIKON_VIEW_EXECUTABLE + " " +
                      sceneFor("follow.json", "run.vti.series") +
                      " --follow --follow-poll-ms 1 --frames 12 --width 320 --height 240 --screenshot " +
                      frame.string(),
                  log.string()),
              0);
    for (const char* step : {"step_0", "step_2"}) {
        const fs::path headless = dir_ / step;
        ASSERT_EQ(run(std::string(EIKON_EXECUTABLE) + " run " + sceneFor(std::string(step) + ".json", std::string(step) + ".vti") +
                      " --quiet --out " + headless.string()),
                  0);
    }
    const auto viewed = eikon::io::readImage(frame);
    const auto first = eikon::io::readImage(dir_ / "step_0" / "frames" / "frame_00000.png");
    const auto last = eikon::io::readImage(dir_ / "step_2" / "frames" / "frame_00000.png");
    ASSERT_EQ(viewed.width, last.width);
    ASSERT_EQ(viewed.height, last.height);
    EXPECT_NE(first.rgba, last.rgba);  // the steps look different
    EXPECT_EQ(viewed.rgba, last.rgba);
    std::FILE* file = std::fopen(log.c_str(), "r");
    ASSERT_NE(file, nullptr);
    std::string output;
    for (char line[1024]; std::fgets(line, sizeof line, file);) output += line;
    std::fclose(file);
    EXPECT_NE(output.find("warning: skipped step " + (dir_ / "step_1.vti").string()), std::string::npos) << output;
}

TEST_F(ViewerWindow, BadSceneIsExitCodeTwoWithoutAWindow) {
    const fs::path scene = dir_ / "bad.json";
    std::FILE* file = std::fopen(scene.c_str(), "w");
    std::fputs("{\"grid\": {\"resolution\": [0, 8, 8]}}", file);
    std::fclose(file);
    EXPECT_EQ(run(std::string(EIKON_VIEW_EXECUTABLE) + " " + scene.string()), 2);  // no DISPLAY needed to refuse
}

}  // namespace
