// `eikon run` with a `diagnostic`: the instrument's picture goes where the
// view's would (frames/frame_NNNNN.png, report stage "diagnostic"), and the
// VTK export holds its measurements — vtk/diagnostic_NNNNN.vti with
// `deflection` (rad) and `optical_path_difference` (m) on the image plane,
// upright, each with its unit — listed in diagnostic.pvd, its .series and
// the ParaView state (valid Python, the orthographic camera's scale). The
// index is a Gaussian bump off the axis, imported as a delta_index grid;
// `--set` switches the instrument.
#include "io/image/ImageIo.h"
#include "tests/integration/CliRun.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataReader.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using eikon::test::runEikon;

constexpr double kSigma = 0.1, kAmplitude = 1e-4, kCentreX = 0.1, kCentreY = 0.15;

std::string text(const fs::path& path) {
    std::ifstream file(path);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// A BOS scene over the Gaussian bump (bump.vdb) seen by a perspective
// camera: `sections` adds its render, diagnostic and export sections.
std::string bosScene(const std::string& sections) {
    return R"({
  "grid": {"resolution": [40, 40, 40], "bounds": {"min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]},
           "smoothing_sigma_voxels": 0},
  "volume": {"path": "bump.vdb", "grids": {"density": "", "temperature": "", "delta_index": "dn"},
             "offset": [0.0125, 0.0125, 0.0125]},
  "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 1}],
  "camera": {"position": [0, 0, 2], "target": [0, 0, 0], "fov_deg": 25},
)" + sections + "\n}";
}

// Frame 0's diagnostic export, read by VTK's own reader.
vtkSmartPointer<vtkImageData> readDiagnosticExport(const fs::path& out) {
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName((out / "vtk" / "diagnostic_00000.vti").string().c_str());
    reader->Update();
    return reader->GetOutput();
}

// The unit the export stores beside an array (its field `<array>_unit`), or
// "(none)".
std::string unitOf(vtkImageData* image, const std::string& array) {
    auto* units = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray((array + "_unit").c_str()));
    return units ? units->GetValue(0) : "(none)";
}

class DiagnosticCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("eikon_diagnostic_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        // 40 cells over [−0.5, 0.5]: the file's voxels, half a voxel on, are the cells' centres.
        const double h = 1.0 / 40;
        eikon::test::writeVdbFile(dir_ / "bump.vdb",
                                  {{"dn", 1,
                                    [&](double x, double y, double z, int) {
                                        const double dx = x + 0.5 * h - kCentreX, dy = y + 0.5 * h - kCentreY,
                                                     dz = z + 0.5 * h;
                                        return static_cast<float>(
                                            kAmplitude * std::exp(-(dx * dx + dy * dy + dz * dz) / (kSigma * kSigma)));
                                    }}},
                                  h, -0.55, 0.55);
        std::ofstream(dir_ / "scene.json") << R"({
  "grid": {"resolution": [40, 40, 40], "bounds": {"min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]},
           "smoothing_sigma_voxels": 0},
  "volume": {"path": "bump.vdb", "grids": {"density": "", "temperature": "", "delta_index": "dn"},
             "offset": [0.0125, 0.0125, 0.0125]},
  "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 1}],
  "camera": {"position": [0, 0, 2], "target": [0, 0, 0], "projection": "orthographic", "width_m": 0.8},
  "render": {"width": 40, "height": 30},
  "diagnostic": {"type": "interferometry"},
  "export": {"vtk": {"fields": ["delta_index"]}}
})";
    }
    void TearDown() override { fs::remove_all(dir_); }

    eikon::test::Outcome run(const std::string& arguments = "", int frames = 1) {
        return runEikon("run " + (dir_ / "scene.json").string() + " --out " + (dir_ / "out").string() +
                            " --frames " + std::to_string(frames) + " --quiet " + arguments,
                        "LP_NUM_THREADS=2");
    }
    fs::path dir_;
};

TEST_F(DiagnosticCli, WritesThePictureAndTheMeasurementsForParaView) {
    const auto outcome = run();
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    const fs::path out = dir_ / "out";
    EXPECT_TRUE(fs::exists(out / "frames" / "frame_00000.png"));
    EXPECT_NE(text(out / "report.jsonl").find("\"name\":\"diagnostic\",\"ran\":true"), std::string::npos);
    EXPECT_EQ(text(out / "report.jsonl").find("\"name\":\"view\""), std::string::npos);
    for (const char* index : {"diagnostic.pvd", "diagnostic.vti.series"})
        EXPECT_NE(text(out / "vtk" / index).find("diagnostic_00000.vti"), std::string::npos) << index;
    const fs::path script = out / "vtk" / "open_in_paraview.py";
    EXPECT_NE(text(script).find("collection('diagnostic')"), std::string::npos);
    std::smatch scale;
    const std::string state = text(script);
    ASSERT_TRUE(std::regex_search(state, scale, std::regex(R"(camera_parallel_scale = (\S+))")));
    EXPECT_NEAR(std::stod(scale[1]), 0.3, 1e-12) << "half the height of a view 0.8 m wide, 40 × 30 pixels";
    const std::string parse = "python3 -c \"import ast, sys; ast.parse(open(sys.argv[1]).read())\" " + script.string();
    EXPECT_EQ(std::system(parse.c_str()), 0) << text(script);

    const vtkSmartPointer<vtkImageData> image = readDiagnosticExport(out);
    int cells[3];
    image->GetDimensions(cells);
    EXPECT_EQ(cells[0], 41);  // points: one more than the pixels
    EXPECT_EQ(cells[1], 31);
    vtkDataArray* deflection = image->GetCellData()->GetArray("deflection");
    vtkDataArray* opd = image->GetCellData()->GetArray("optical_path_difference");
    ASSERT_TRUE(deflection && opd);
    EXPECT_EQ(deflection->GetNumberOfComponents(), 2);
    EXPECT_EQ(unitOf(image, "deflection"), "rad");
    EXPECT_EQ(unitOf(image, "optical_path_difference"), "m");
    // The pixel over the bump's centre (2 cm pixels; x right, y up from the
    // axis) holds the peak: the image is upright, not mirrored. (On 4 voxels
    // a σ, to 3%: accuracy is test_diagnostics' business.)
    double origin[3], spacing[3];
    image->GetOrigin(origin);
    image->GetSpacing(spacing);
    const int i = static_cast<int>(std::floor((kCentreX - origin[0]) / spacing[0]));
    const int j = static_cast<int>(std::floor((kCentreY - origin[1]) / spacing[1]));
    const double peak = kAmplitude * kSigma * std::sqrt(std::numbers::pi);
    const double centreX = origin[0] + (i + 0.5) * spacing[0] - kCentreX, centreY = origin[1] + (j + 0.5) * spacing[1] - kCentreY;
    const double expected = peak * std::exp(-(centreX * centreX + centreY * centreY) / (kSigma * kSigma));
    EXPECT_NEAR(opd->GetComponent(j * 40 + i, 0), expected, 0.03 * peak);
    EXPECT_LT(opd->GetComponent((29 - j) * 40 + i, 0), 0.1 * peak) << "the mirror image of the peak's pixel is dark";
}

// The per-frame error estimate covers the diagnostic's outputs: each
// frame's report line holds the picture's, the deflection's and the optical
// path difference's discretisation estimates (relative L1, finite, and small
// on this bump at one-voxel steps), no noise, and its cost.
TEST_F(DiagnosticCli, TheReportEstimatesTheErrorOfEveryMeasurement) {
    const auto outcome = run("", 2);
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    const std::vector<nlohmann::json> report = eikon::test::readReport(dir_ / "out" / "report.jsonl");
    ASSERT_EQ(report.size(), 2u);
    for (const nlohmann::json& frame : report) {
        ASSERT_TRUE(frame.contains("error_estimate")) << frame.dump();
        const nlohmann::json& discretisation = frame["error_estimate"]["discretisation"];
        for (const char* output : {"image", "deflection", "optical_path_difference"}) {
            ASSERT_TRUE(discretisation.contains(output)) << output << ": " << discretisation.dump();
            EXPECT_GE(discretisation[output].get<double>(), 0.0) << output;
            EXPECT_LT(discretisation[output].get<double>(), 0.01) << output;
        }
        EXPECT_FALSE(discretisation.contains("displacement"));
        EXPECT_FALSE(frame["error_estimate"]["noise"].contains("image"));
        EXPECT_GT(frame["error_estimate"]["ms"].get<double>(), 0.0);
    }
}

TEST_F(DiagnosticCli, SetSwitchesTheInstrumentAndRefusesABadValueAtItsKey) {
    const auto schlieren = run("--set diagnostic.type=schlieren --set diagnostic.cutoff=colour");
    EXPECT_EQ(schlieren.exitCode, 0) << schlieren.output;
    EXPECT_NE(text(dir_ / "out" / "vtk" / "open_in_paraview.py").find("diagnostic_array = 'deflection'"),
              std::string::npos);
    const auto refused = run("--force --set diagnostic.type=schlieren --set diagnostic.cutoff=razor");
    EXPECT_EQ(refused.exitCode, 2) << refused.output;
    EXPECT_NE(refused.output.find("scene.json: diagnostic.cutoff: expected one of"), std::string::npos)
        << refused.output;
}

// The shadowgraph by `--set`: the screen's I/I₀ as `relative_irradiance`
// (RGB, unit 1), the export's only array, coloured in the ParaView state.
TEST_F(DiagnosticCli, ShadowgraphExportsTheScreensRelativeIrradiance) {
    const auto outcome = run("--set diagnostic.type=shadowgraph --set diagnostic.screen_distance=2");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    const fs::path out = dir_ / "out";
    EXPECT_TRUE(fs::exists(out / "frames" / "frame_00000.png"));
    EXPECT_NE(text(out / "vtk" / "open_in_paraview.py").find("diagnostic_array = 'relative_irradiance'"),
              std::string::npos);
    const vtkSmartPointer<vtkImageData> image = readDiagnosticExport(out);
    vtkDataArray* irradiance = image->GetCellData()->GetArray("relative_irradiance");
    ASSERT_NE(irradiance, nullptr);
    EXPECT_EQ(irradiance->GetNumberOfComponents(), 3);
    EXPECT_EQ(image->GetCellData()->GetArray("deflection"), nullptr);
    EXPECT_EQ(unitOf(image, "relative_irradiance"), "1");
    // The bump (a converging lens) brightens the screen over its centre, 2.5 m beyond it.
    double range[2];
    irradiance->GetRange(range, 0);
    EXPECT_GT(range[1], 1.0);
    EXPECT_LT(range[0], 1.0);
}

// BOS through a perspective camera: the picture with the medium and the
// reference without it, frame by frame, and the displacement in pixels
// (2 components, unit px) in the export.
TEST_F(DiagnosticCli, BosWritesTheReferencePictureAndTheDisplacement) {
    std::ofstream(dir_ / "scene.json") << bosScene(R"(
  "render": {"width": 40, "height": 30},
  "diagnostic": {"type": "bos", "background_distance": 1.5, "seed": 3},
  "export": {"vtk": {"fields": ["delta_index"]}})");
    const auto outcome = run("", 2);
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    const fs::path out = dir_ / "out";
    for (const char* name : {"frame_00000.png", "reference_00000.png", "frame_00001.png", "reference_00001.png"})
        EXPECT_TRUE(fs::exists(out / "frames" / name)) << name;
    EXPECT_NE(text(out / "vtk" / "open_in_paraview.py").find("diagnostic_array = 'displacement'"), std::string::npos);
    const vtkSmartPointer<vtkImageData> image = readDiagnosticExport(out);
    vtkDataArray* displacement = image->GetCellData()->GetArray("displacement");
    ASSERT_NE(displacement, nullptr);
    EXPECT_EQ(displacement->GetNumberOfComponents(), 2);
    EXPECT_EQ(unitOf(image, "displacement"), "px");
    double range[2];
    displacement->GetRange(range, 0);
    EXPECT_GT(range[1] - range[0], 1e-3) << "the bump moves the background";
    EXPECT_TRUE(eikon::test::readReport(out / "report.jsonl")[0]["error_estimate"]["discretisation"].contains(
        "displacement"));
    const auto refused = run("--force --set camera.projection=orthographic --set camera.width_m=1");
    EXPECT_EQ(refused.exitCode, 2) << refused.output;
    EXPECT_NE(refused.output.find("scene.json: camera.projection: expected \"perspective\" with a bos diagnostic"),
              std::string::npos)
        << refused.output;
}

// A dense flint ball (n = 1.9, R = 0.3 m) in the interferometer: rays that
// meet it beyond ρ/R = sin θᵢ with θᵢ − θₜ = 45° leave turned by 90° or
// more and are lost. The report counts the pixels with a lost ray — here
// those with one of their 2 × 2 sample points in that rim — and a scene
// without sharp surfaces counts none (no "diagnostic" entry).
TEST_F(DiagnosticCli, TheReportCountsThePixelsWhoseRaysAGlassBallTurnsBack) {
    constexpr double kRadius = 0.3, kIndex = 1.9;
    std::ofstream(dir_ / "scene.json") << R"({
  "grid": {"resolution": [40, 40, 40], "bounds": {"min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]}},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.3, "index": 1.9}],
  "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 1}],
  "camera": {"position": [0, 0, 2], "target": [0, 0, 0], "projection": "orthographic", "width_m": 0.8},
  "render": {"width": 40, "height": 30},
  "diagnostic": {"type": "interferometry"}
})";
    const auto outcome = run();
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    // sin θᵢ = n·sin(θᵢ − 45°): tan θᵢ = (n/√2) / (n/√2 − 1).
    const double ratio = kIndex / std::numbers::sqrt2, tangent = ratio / (ratio - 1.0);
    const double rim = kRadius * tangent / std::sqrt(1.0 + tangent * tangent);
    int expected = 0;
    for (int j = 0; j < 30; ++j)
        for (int i = 0; i < 40; ++i) {
            bool lost = false;
            for (const double dx : {0.25, 0.75})
                for (const double dy : {0.25, 0.75}) {
                    const double rho = std::hypot((i + dx - 20) * 0.02, (15 - j - dy) * 0.02);
                    lost = lost || (rho > rim && rho < kRadius);
                }
            expected += lost;
        }
    const std::vector<nlohmann::json> report = eikon::test::readReport(dir_ / "out" / "report.jsonl");
    ASSERT_EQ(report.size(), 1u);
    ASSERT_TRUE(report[0].contains("diagnostic")) << report[0].dump();
    EXPECT_GT(expected, 50);
    EXPECT_EQ(report[0]["diagnostic"]["lost"].get<int>(), expected);
    ASSERT_EQ(run("--force --set objects.0.surface=smooth").exitCode, 0);
    EXPECT_FALSE(eikon::test::readReport(dir_ / "out" / "report.jsonl")[0].contains("diagnostic"));
}

// BOS over a background image (`pattern` names a PNG beside the scene):
// the reference picture is the image where it fills the view at the
// picture's own pixel count; a file that is no image, or none, is refused
// with exit code 2 naming the key and the file, before anything is written.
TEST_F(DiagnosticCli, BosReadsItsBackgroundFromAnImageFile) {
    std::ofstream(dir_ / "scene.json") << bosScene(R"(
  "render": {"width": 40, "height": 30, "samples_per_pixel": 1},
  "diagnostic": {"type": "bos", "background_distance": 1.5, "pattern": "pattern.png"})");
    // Stripes four pixels wide, sRGB 40 and 220, and a white top row.
    std::vector<std::uint8_t> pattern(40 * 30 * 4, 255);
    for (int j = 1; j < 30; ++j)
        for (int i = 0; i < 40; ++i)
            for (int c = 0; c < 3; ++c) pattern[4 * (j * 40 + i) + c] = (i / 4) % 2 ? 220 : 40;
    eikon::io::writePng(dir_ / "pattern.png", 40, 30, pattern);
    const auto outcome = run();
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    const eikon::io::Rgba8Image reference = eikon::io::readImage(dir_ / "out" / "frames" / "reference_00000.png");
    ASSERT_EQ(reference.rgba.size(), pattern.size());
    int worst = 0;
    for (std::size_t i = 0; i < pattern.size(); ++i)
        if (i % 4 != 3) worst = std::max(worst, std::abs(int(reference.rgba[i]) - int(pattern[i])));
    EXPECT_LE(worst, 1) << "the reference is the image, texel for pixel";

    std::ofstream(dir_ / "notes.png") << "not an image";
    for (const char* file : {"notes.png", "missing.png"}) {
        const auto refused = runEikon("run " + (dir_ / "scene.json").string() + " --out " +
                                          (dir_ / "refused").string() + " --quiet --set diagnostic.pattern=" + file,
                                      "LP_NUM_THREADS=2");
        EXPECT_EQ(refused.exitCode, 2) << refused.output;
        EXPECT_NE(refused.output.find("scene.json: diagnostic.pattern: expected \"dots\" or an existing PNG"),
                  std::string::npos) << refused.output;
        EXPECT_NE(refused.output.find((dir_ / file).string()), std::string::npos) << refused.output;
        EXPECT_FALSE(fs::exists(dir_ / "refused")) << "nothing written";
    }
}

}  // namespace
