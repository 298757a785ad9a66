// A flow brought in as VTK data (scene `volume` with `fields`): a 64³
// temperature plume written with VTK's own writers as image data (.vti) and
// as tetrahedra (.vtu) is resampled by VTK's probe filter onto the render
// grid and must give the δn the built-in optics give the same temperatures
// (sim/optics/OpticalMapping.h, Gladstone–Dale), in each temperature unit;
// an OpenFOAM case (tests/data/openfoam_tiny, written by
// tests/data/make_openfoam_tiny.py) must give Gladstone–Dale of its T and p
// as VTK's probe filter samples them, and its cells' values as written; a
// missing array, surface data and a short time series are refused by name.
#include "bridge/core/Error.h"
#include "io/scene/SceneParser.h"
#include "sim/SceneFields.h"
#include "sim/optics/AirOptics.h"
#include "sim/optics/OpticalMapping.h"
#include "sim/volume/VolumeSequence.h"
#include "tests/unit/OpenFoamProbe.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace eikon::sim {
namespace {

namespace fs = std::filesystem;

constexpr int kN = 64;             // plume points per axis
constexpr double kH = 0.01;        // m between points
constexpr double kAmbient = 293.15;  // K
// The plume's points sit on the render cells' centres: 64 cells of 1 cm over [−0.32, 0.32] m.
constexpr double kLow = -0.5 * kN * kH;

// A rising plume in absolute kelvin: 450 K hotter on its axis, a Gaussian of
// 8 cm radius about x = z = 0 that widens and cools with height.
double plumeTemperature(double x, double y, double z) {
    const double width = 0.08 * (1.0 + 0.5 * (y - kLow) / (kN * kH));
    return kAmbient + 450.0 / (width / 0.08) * std::exp(-(x * x + z * z) / (width * width));
}

glm::dvec3 plumePoint(int i, int j, int k) { return glm::dvec3(kLow + (i + 0.5) * kH, kLow + (j + 0.5) * kH, kLow + (k + 0.5) * kH); }

// T (K), T_C (°C) and dT (K above ambient) at each point, float32 as solvers write them.
void addPlumeArrays(vtkPointData& data) {
    vtkNew<vtkFloatArray> kelvin, celsius, above;
    kelvin->SetName("T");
    celsius->SetName("T_C");
    above->SetName("dT");
    for (int k = 0; k < kN; ++k)
        for (int j = 0; j < kN; ++j)
            for (int i = 0; i < kN; ++i) {
                const glm::dvec3 p = plumePoint(i, j, k);
                const double t = plumeTemperature(p.x, p.y, p.z);
                kelvin->InsertNextValue(static_cast<float>(t));
                celsius->InsertNextValue(static_cast<float>(t - 273.15));
                above->InsertNextValue(static_cast<float>(t - kAmbient));
            }
    data.AddArray(kelvin);
    data.AddArray(celsius);
    data.AddArray(above);
}

void writeImagePlume(const fs::path& path) {
    vtkNew<vtkImageData> image;
    image->SetDimensions(kN, kN, kN);
    image->SetSpacing(kH, kH, kH);
    const glm::dvec3 origin = plumePoint(0, 0, 0);
    image->SetOrigin(origin.x, origin.y, origin.z);
    addPlumeArrays(*image->GetPointData());
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(image);
    ASSERT_EQ(writer->Write(), 1);
}

// The same points, each cube of 8 split into the 6 tetrahedra about its
// main diagonal (Kuhn's), which meet conformingly across cubes.
void writeTetrahedralPlume(const fs::path& path) {
    vtkNew<vtkUnstructuredGrid> mesh;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (int k = 0; k < kN; ++k)
        for (int j = 0; j < kN; ++j)
            for (int i = 0; i < kN; ++i) {
                const glm::dvec3 p = plumePoint(i, j, k);
                points->InsertNextPoint(p.x, p.y, p.z);
            }
    mesh->SetPoints(points);
    const auto id = [](int i, int j, int k) { return static_cast<vtkIdType>(i + kN * (j + kN * k)); };
    const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    mesh->Allocate(static_cast<vtkIdType>(6) * (kN - 1) * (kN - 1) * (kN - 1));
    for (int k = 0; k + 1 < kN; ++k)
        for (int j = 0; j + 1 < kN; ++j)
            for (int i = 0; i + 1 < kN; ++i)
                for (const auto& order : axes) {
                    glm::ivec3 corner(i, j, k);
                    vtkIdType tet[4];
                    tet[0] = id(corner.x, corner.y, corner.z);
                    for (int s = 0; s < 3; ++s) {
                        corner[order[s]] += 1;
                        tet[s + 1] = id(corner.x, corner.y, corner.z);
                    }
                    mesh->InsertNextCell(VTK_TETRA, 4, tet);
                }
    addPlumeArrays(*mesh->GetPointData());
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(mesh);
    writer->SetCompressorTypeToNone();
    ASSERT_EQ(writer->Write(), 1);
}

class VtkVolume : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::path(::testing::TempDir()) /
                  ("eikon_vtk_volume_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    // A scene over the plume's cells whose medium is still air at the
    // ambient temperature, so that δn is the built-in optics' n_air(T) − 1.
    Scene scene(const std::string& volumeJson, const std::string& grid = "") const {
        nlohmann::json root = nlohmann::json::parse(
            grid.empty() ? R"({"grid": {"resolution": [64, 64, 64], "bounds": {"min": [-0.32, -0.32, -0.32],
                                                                                "max": [0.32, 0.32, 0.32]}}})"
                         : grid);
        root["medium"] = {{"index", builtIn_.index(kAmbient, 0.0)}};
        root["lights"] = nlohmann::json::parse(R"([{"type": "point", "position": [0, 1, 0], "power": 1}])");
        root["volume"] = nlohmann::json::parse(volumeJson);
        return parseScene(root, (folder_ / "scene.json").string());
    }

    // The largest |δn − the built-in optics' δn| over the render cells,
    // relative to the largest change the plume makes to δn.
    double plumeError(const FieldSet& set) const {
        double error = 0.0, signal = 0.0;
        const double ambientDelta = builtIn_.index(kAmbient, 0.0) - set.referenceIndex;
        for (int k = 0; k < kN; ++k)
            for (int j = 0; j < kN; ++j)
                for (int i = 0; i < kN; ++i) {
                    const glm::dvec3 x = set.grid.cellCentre(i, j, k);
                    const double expected = builtIn_.index(plumeTemperature(x.x, x.y, x.z), 0.0) - set.referenceIndex;
                    error = std::max(error, std::abs(set.deltaIndex[set.grid.linearIndex(i, j, k)] - expected));
                    signal = std::max(signal, std::abs(expected - ambientDelta));
                }
        EXPECT_GT(signal, 5e-5);  // the plume shows: 450 K over ambient lowers n − 1 by about 1.7e-4
        return error / signal;
    }

    fs::path folder_;
    OpticalModel builtIn_{SimDesc{}};  // air by Gladstone–Dale, the solver's own optics
};

// The plume as image data, read as absolute kelvin, as Celsius and as kelvin
// above ambient: each the built-in optics' δn to 1e-4 of the plume's change.
TEST_F(VtkVolume, ImageDataPlumeGivesTheBuiltInOpticsInEachUnit) {
    writeImagePlume(folder_ / "plume.vti");
    for (const auto& [array, unit] : {std::pair{"T", "kelvin"}, {"T_C", "celsius"}, {"dT", "kelvin_above_ambient"}}) {
        SCOPED_TRACE(unit);
        SceneFields fields(scene(std::string(R"({"path": "plume.vti", "fields": {"temperature": ")") + array +
                                 R"(", "temperature_unit": ")" + unit + R"("}})"));
        const double error = plumeError(fields.fields());
        EXPECT_LT(error, 1e-4);
        std::printf("[ measured ] .vti, %s: largest |δn error| / largest plume δn change = %.3g\n", unit, error);
    }
}

TEST_F(VtkVolume, TetrahedralPlumeGivesTheBuiltInOptics) {
    writeTetrahedralPlume(folder_ / "plume.vtu");
    SceneFields fields(scene(R"({"path": "plume.vtu", "fields": {"temperature": "T", "temperature_unit": "kelvin"}})"));
    const double error = plumeError(fields.fields());
    EXPECT_LT(error, 1e-4);
    std::printf("[ measured ] .vtu tetrahedra, kelvin: relative δn error %.3g\n", error);
}

// Render cells the data do not reach are the ambient medium: a plume file
// covering x < 0 only leaves the other half at the medium's δn exactly.
TEST_F(VtkVolume, CellsOutsideTheDataAreTheAmbientMedium) {
    writeImagePlume(folder_ / "plume.vti");
    const Scene s = scene(R"({"path": "plume.vti", "fields": {"temperature": "T", "temperature_unit": "kelvin"},
                              "transform": {"translate": [-0.32, 0, 0]}})");
    SceneFields fields(s);
    const FieldSet& set = fields.fields();
    const auto medium = static_cast<float>(s.medium.index - set.referenceIndex);
    int hot = 0;
    for (int i = 0; i < kN; ++i) {
        const float delta = set.deltaIndex[set.grid.linearIndex(i, kN / 2, kN / 2)];
        const double x = set.grid.cellCentre(i, 0, 0).x;
        if (x > 0.0) {
            EXPECT_EQ(delta, medium) << "cell " << i;
        } else {
            const glm::dvec3 p = set.grid.cellCentre(i, kN / 2, kN / 2) + glm::dvec3(0.32, 0, 0);
            EXPECT_NEAR(delta, builtIn_.index(plumeTemperature(p.x, p.y, p.z), 0.0) - set.referenceIndex, 1e-9);
            hot += delta < medium - 1e-6f;
        }
    }
    EXPECT_GT(hot, 5);  // the plume's axis, now at x = −0.32, is inside
}

TEST_F(VtkVolume, AMissingArrayIsRefusedNamingTheFileAndItsArrays) {
    writeImagePlume(folder_ / "plume.vti");
    try {
        SceneFields fields(scene(R"({"path": "plume.vti", "fields": {"temperature": "Temp", "temperature_unit": "kelvin"}})"));
        FAIL() << "no error";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("scene.json: volume.path: " + (folder_ / "plume.vti").string() +
                               ": expected a point or cell array \"Temp\" (volume.fields.temperature), found the "
                               "arrays \"T\", \"T_C\", \"dT\""),
                  std::string::npos)
            << message;
    }
}

TEST_F(VtkVolume, SurfaceDataAndUndeclaredArraysAreRefused) {
    vtkNew<vtkPolyData> surface;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    surface->SetPoints(points);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName((folder_ / "surface.vtp").c_str());
    writer->SetInputData(surface);
    ASSERT_EQ(writer->Write(), 1);
    try {
        SceneFields fields(scene(R"({"path": "surface.vtp", "fields": {"temperature": "T", "temperature_unit": "kelvin"}})"));
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("surface.vtp: expected volume data"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("found polygonal data: a surface"), std::string::npos) << error.what();
    }
    writeImagePlume(folder_ / "plume.vti");
    const auto refused = [&](const std::string& volume, const std::string& expected) {
        try {
            scene(volume);
            ADD_FAILURE() << "accepted " << volume;
        } catch (const InputError& error) {
            EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
        }
    };
    refused(R"({"path": "plume.vti"})", "volume.fields: expected an object declaring what the VTK file's arrays mean");
    refused(R"({"path": "plume.vti", "fields": {"temperature": "T"}})", "volume.fields.temperature_unit");
    refused(R"({"path": "plume.vti", "fields": {"pressure": "p"}})",
            "volume.fields.pressure: expected a temperature array beside the pressure");
    refused(R"({"path": "plume.vti", "fields": {"temperature": "T", "temperature_unit": "kelvin"}, "temperature_scale": 2})",
            "volume.temperature_scale: expected no temperature_scale with an absolute temperature_unit");
    refused(R"({"path": "plume.vti", "grids": {"temperature": "T"}, "fields": {"temperature": "T", "temperature_unit": "kelvin"}})",
            "volume.grids: expected no `grids` beside `fields`");
}

// A .pvd and a .series of two image-data steps: rendered frame k shows step
// k (listed out of order, sorted by time), and a third frame, or a damaged
// second step, is refused before anything runs.
TEST_F(VtkVolume, TimeSeriesShowStepKAtFrameK) {
    for (int step = 0; step < 2; ++step) {
        vtkNew<vtkImageData> image;
        image->SetDimensions(4, 4, 4);
        image->SetSpacing(0.1, 0.1, 0.1);
        image->SetOrigin(-0.15, -0.15, -0.15);
        vtkNew<vtkDoubleArray> t;
        t->SetName("T");
        for (int p = 0; p < 64; ++p) t->InsertNextValue(300.0 + 100.0 * step);
        image->GetPointData()->AddArray(t);
        vtkNew<vtkXMLImageDataWriter> writer;
        writer->SetFileName((folder_ / ("step_" + std::to_string(step) + ".vti")).c_str());
        writer->SetInputData(image);
        ASSERT_EQ(writer->Write(), 1);
    }
    std::ofstream(folder_ / "plume.pvd") << R"(<?xml version="1.0"?>
<VTKFile type="Collection" version="0.1"><Collection>
  <DataSet timestep="0.5" file="step_1.vti"/>
  <DataSet timestep="0" file="step_0.vti"/>
</Collection></VTKFile>)";
    std::ofstream(folder_ / "plume.vti.series")
        << R"({"file-series-version": "1.0", "files": [{"name": "step_1.vti", "time": 0.5}, {"name": "step_0.vti", "time": 0}]})";
    const std::string grid = R"({"grid": {"resolution": [3, 3, 3], "bounds": {"min": [-0.15, -0.15, -0.15], "max": [0.15, 0.15, 0.15]}}})";
    for (const char* index : {"plume.pvd", "plume.vti.series"}) {
        SCOPED_TRACE(index);
        const Scene s = scene(std::string(R"({"path": ")") + index +
                                  R"(", "fields": {"temperature": "T", "temperature_unit": "kelvin"}})",
                              grid);
        EXPECT_NO_THROW(checkVolumeFrames(*s.volume, s.grid.spec(), 2, s.sourcePath));
        EXPECT_THROW(checkVolumeFrames(*s.volume, s.grid.spec(), 3, s.sourcePath), InputError);
        SceneFields fields(s);
        EXPECT_TRUE(fields.changesOverTime());
        for (int frame = 0; frame < 2; ++frame) {
            if (frame > 0) fields.advanceFrame();
            const FieldSet& set = fields.fields();
            const double expected = builtIn_.index(300.0 + 100.0 * frame, 0.0) - set.referenceIndex;
            EXPECT_NEAR(set.deltaIndex[13], expected, 1e-10) << "frame " << frame;
        }
        EXPECT_THROW(fields.advanceFrame(), InputError);
    }
    // A damaged later step is found before frame 0: a file that is not VTK,
    // then a valid one without the declared array.
    const Scene s = scene(R"({"path": "plume.pvd", "fields": {"temperature": "T", "temperature_unit": "kelvin"}})", grid);
    for (const bool xml : {false, true}) {
        if (xml) {
            vtkNew<vtkImageData> image;
            image->SetDimensions(2, 2, 2);
            vtkNew<vtkXMLImageDataWriter> writer;
            writer->SetFileName((folder_ / "step_1.vti").c_str());
            writer->SetInputData(image);
            ASSERT_EQ(writer->Write(), 1);
        } else {
            std::ofstream(folder_ / "step_1.vti") << "not VTK";
        }
        try {
            checkVolumeFrames(*s.volume, s.grid.spec(), 2, s.sourcePath);
            ADD_FAILURE() << "no error";
        } catch (const InputError& error) {
            EXPECT_NE(std::string(error.what()).find("volume.path: " + (folder_ / "step_1.vti").string() + ": expected "),
                      std::string::npos)
                << error.what();
            if (xml) {
                EXPECT_NE(std::string(error.what()).find("found no arrays"), std::string::npos) << error.what();
            }
        }
    }
}

// The OpenFOAM case's T (K) and p (Pa): δn is Gladstone–Dale of them as
// VTK's probe filter samples the case at the render cell centres, to 1e-6
// of the case's δn change, in both time steps; and those samples are the
// values the case's cells were written with.
TEST_F(VtkVolume, OpenFoamCaseGivesGladstoneDaleOfItsTemperatureAndPressure) {
    const fs::path foam = fs::path(EIKON_SOURCE_DIR) / "tests/data/openfoam_tiny/case.foam";
    const std::string grid = R"({"grid": {"resolution": [6, 4, 4], "bounds": {"min": [0, 0, 0], "max": [0.3, 0.2, 0.2]}}})";
    const Scene s = scene(R"({"path": ")" + foam.string() +
                              R"(", "fields": {"temperature": "T", "temperature_unit": "kelvin", "pressure": "p"}})",
                          grid);
    SceneFields fields(s);
    const GridSpec spec = s.grid.spec();

    test::OpenFoamProbe probe(foam, spec);  // the independent sampling

    const GladstoneDale air;  // the volume's defaults
    const double ambient = air.refractivityAt(kAmbient, 101325.0);
    for (int step = 0; step < 2; ++step) {
        SCOPED_TRACE("step " + std::to_string(step));
        if (step > 0) fields.advanceFrame();
        const vtkSmartPointer<vtkDataSet> sampled = probe.at(0.5 * step);
        vtkDataArray* t = sampled->GetPointData()->GetArray("T");
        vtkDataArray* p = sampled->GetPointData()->GetArray("p");
        ASSERT_TRUE(t && p);
        const FieldSet& set = fields.fields();
        const double medium = s.medium.index - set.referenceIndex;
        double error = 0.0, signal = 0.0;
        for (int k = 0; k < 4; ++k)
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 6; ++i) {
                    const std::size_t c = spec.linearIndex(i, j, k);
                    const double tc = t->GetComponent(static_cast<vtkIdType>(c), 0);
                    const double pc = p->GetComponent(static_cast<vtkIdType>(c), 0);
                    // The case's cell (i/2, j/2, k/2) as make_openfoam_tiny.py wrote it, to
                    // float32 rounding (vtkOpenFOAMReader's arrays are float).
                    const int cell = i / 2 + 3 * (j / 2 + 2 * (k / 2));
                    const double writtenT = 293.15 + (40.0 + 30.0 * step) * (1 + cell % 3) / 3.0 + 2.0 * (cell / 6);
                    const double writtenP = 101325.0 - 1.2 * 9.81 * 0.1 * (0.5 + (cell / 3) % 2) + 50.0 * step;
                    EXPECT_NEAR(tc, writtenT, 1.2e-7 * writtenT);
                    EXPECT_NEAR(pc, writtenP, 1.2e-7 * writtenP);
                    const double expected = medium + air.refractivityAt(tc, pc) - ambient;
                    error = std::max(error, std::abs(set.deltaIndex[c] - expected));
                    signal = std::max(signal, std::abs(expected - medium));
                }
        EXPECT_LT(error / signal, 1e-6);
        std::printf("[ measured ] OpenFOAM step %d: largest |δn error| / largest δn change = %.3g\n", step, error / signal);
    }
}

// A temperature grid in absolute kelvin read by the OpenVDB default (kelvin
// above ambient, Blender's convention) would count the ambient twice: it is
// refused with its smallest value; declared as kelvin it gives the optics.
TEST_F(VtkVolume, AnAbsoluteTemperatureVdbGridIsRefusedUnlessDeclared) {
    test::writeVdbFile(folder_ / "plume.vdb",
                       {{"temperature", 1, [](double x, double, double, int) { return float(300.0 + 100.0 * x); }}}, 0.05,
                       -0.3, 0.3);
    const std::string grid = R"({"grid": {"resolution": [8, 4, 4], "bounds": {"min": [-0.2, -0.1, -0.1], "max": [0.2, 0.1, 0.1]}}})";
    try {
        SceneFields fields(scene(R"({"path": "plume.vdb", "grids": {"density": ""}})", grid));
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("volume.grids.temperature (grid \"temperature\" in "), std::string::npos)
            << error.what();
        EXPECT_NE(std::string(error.what()).find("found every nonzero sample at least 28"), std::string::npos)
            << error.what();
    }
    SceneFields fields(scene(R"({"path": "plume.vdb", "fields": {"temperature": "temperature", "temperature_unit": "kelvin"}})", grid));
    const FieldSet& set = fields.fields();
    const glm::dvec3 x = set.grid.cellCentre(7, 2, 2);
    EXPECT_NEAR(set.deltaIndex[set.grid.linearIndex(7, 2, 2)],
                builtIn_.index(300.0 + 100.0 * x.x, 0.0) - set.referenceIndex, 1e-9);
}

}  // namespace
}  // namespace eikon::sim
