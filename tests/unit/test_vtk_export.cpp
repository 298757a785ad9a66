#include "bridge/core/Error.h"
#include "io/vtk/VtkSeriesWriter.h"

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataReader.h>

#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

namespace eikon::io {
namespace {

namespace fs = std::filesystem;

class VtkExportTest : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("eikon_vtk_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root_);
    }
    void TearDown() override { fs::remove_all(root_); }
    fs::path root_;
};

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// A 4×3×2 grid with non-cubic voxels, an offset box and values that are not
// exactly representable in float32 after n_ref is added.
FieldSet makeFields(float seed) {
    FieldSet fields;
    fields.grid.resolution = {4, 3, 2};
    fields.grid.boundsMin = {-0.5, 0.25, 1.0};
    fields.grid.boundsMax = {1.5, 1.75, 2.0};
    fields.referenceIndex = 1.000293;
    const std::size_t cells = fields.grid.cellCount();
    for (std::size_t c = 0; c < cells; ++c) {
        fields.deltaIndex.push_back(seed * 1.234567e-5f * static_cast<float>(c + 1));
        for (int ch = 0; ch < 3; ++ch) {
            fields.extinction.push_back(seed * 0.1f * static_cast<float>(c) + 0.01f * static_cast<float>(ch) + 0.3f);
            fields.scattering.push_back(seed * 0.05f * static_cast<float>(c) + 0.001f * static_cast<float>(ch));
        }
    }
    return fields;
}

// Bitwise equality of a read-back Float32 array against the expected values.
void expectArray(vtkImageData& image, const char* name, int components, const std::vector<float>& expected) {
    SCOPED_TRACE(name);
    vtkDataArray* data = image.GetCellData()->GetArray(name);
    ASSERT_NE(data, nullptr);
    auto* array = vtkFloatArray::SafeDownCast(data);
    ASSERT_NE(array, nullptr) << "not Float32";
    EXPECT_EQ(array->GetNumberOfComponents(), components);
    ASSERT_EQ(static_cast<std::size_t>(array->GetNumberOfValues()), expected.size());
    EXPECT_EQ(std::memcmp(array->GetPointer(0), expected.data(), expected.size() * sizeof(float)), 0);
}

void expectRoundTrip(const fs::path& path, const FieldSet& fields, double time, const NamedArray* extra) {
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    ASSERT_NE(image, nullptr);

    int extent[6];
    image->GetExtent(extent);
    EXPECT_EQ(extent[0], 0);
    EXPECT_EQ(extent[1], 4);
    EXPECT_EQ(extent[2], 0);
    EXPECT_EQ(extent[3], 3);
    EXPECT_EQ(extent[4], 0);
    EXPECT_EQ(extent[5], 2);
    EXPECT_EQ(image->GetNumberOfCells(), 24);
    double origin[3], spacing[3];
    image->GetOrigin(origin);
    image->GetSpacing(spacing);
    EXPECT_DOUBLE_EQ(origin[0], -0.5);
    EXPECT_DOUBLE_EQ(origin[1], 0.25);
    EXPECT_DOUBLE_EQ(origin[2], 1.0);
    EXPECT_DOUBLE_EQ(spacing[0], 0.5);
    EXPECT_DOUBLE_EQ(spacing[1], 0.5);
    EXPECT_DOUBLE_EQ(spacing[2], 0.5);
    double bounds[6];
    image->GetBounds(bounds);
    EXPECT_DOUBLE_EQ(bounds[1], 1.5);
    EXPECT_DOUBLE_EQ(bounds[3], 1.75);
    EXPECT_DOUBLE_EQ(bounds[5], 2.0);
    EXPECT_EQ(image->GetPointData()->GetNumberOfArrays(), 0);

    std::vector<float> index;
    for (float dn : fields.deltaIndex) index.push_back(static_cast<float>(fields.referenceIndex + static_cast<double>(dn)));
    expectArray(*image, "index", 1, index);
    expectArray(*image, "delta_index", 1, fields.deltaIndex);
    expectArray(*image, "extinction", 3, fields.extinction);
    expectArray(*image, "scattering", 3, fields.scattering);
    EXPECT_EQ(image->GetCellData()->GetArray("anisotropy"), nullptr);
    if (extra) expectArray(*image, extra->name.c_str(), extra->components, extra->values);

    auto* timeValue = vtkDoubleArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("TimeValue"));
    ASSERT_NE(timeValue, nullptr) << "TimeValue missing or not Float64";
    ASSERT_EQ(timeValue->GetNumberOfTuples(), 1);
    EXPECT_EQ(timeValue->GetValue(0), time);
    // Each array's unit beside it, as field data NAME_unit.
    for (const auto& [name, unit] : {std::pair{"index", "1"}, {"delta_index", "1"}, {"extinction", "1/m"},
                                     {"scattering", "1/m"}}) {
        auto* units = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray((std::string(name) + "_unit").c_str()));
        ASSERT_NE(units, nullptr) << name << "_unit";
        EXPECT_EQ(units->GetValue(0), unit) << name;
    }
}

void expectIndexFiles(const VtkSeriesWriter& writer) {
    const std::string pvd = readAll(writer.collectionPath());
    EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos) << pvd;
    EXPECT_NE(pvd.find("<DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"field_00000.vti\"/>"), std::string::npos) << pvd;
    EXPECT_NE(pvd.find("<DataSet timestep=\"0.041666666666666664\" group=\"\" part=\"0\" file=\"field_00001.vti\"/>"),
              std::string::npos)
        << pvd;
    EXPECT_LT(pvd.find("field_00000.vti"), pvd.find("field_00001.vti"));

    const std::string series = readAll(writer.seriesPath());
    EXPECT_EQ(series,
              "{\n"
              "  \"file-series-version\" : \"1.0\",\n"
              "  \"files\" : [\n"
              "    { \"name\" : \"field_00000.vti\", \"time\" : 0 },\n"
              "    { \"name\" : \"field_00001.vti\", \"time\" : 0.041666666666666664 }\n"
              "  ]\n"
              "}\n");
}

void writeAndCheckTwoFrames(const fs::path& root, VtkSeriesWriter::Compression compression) {
    VtkSeriesWriter writer(root, "field", compression);
    EXPECT_EQ(writer.directory(), root / "vtk");
    EXPECT_TRUE(fs::is_directory(root / "vtk"));

    const FieldSet first = makeFields(1.0f);
    const FieldSet second = makeFields(2.0f);
    NamedArray fluence{"fluence", 3, {}};
    for (std::size_t c = 0; c < 3 * second.grid.cellCount(); ++c) fluence.values.push_back(0.1f * static_cast<float>(c) + 1e-3f);

    writer.writeFrame(0, 0.0, first);
    EXPECT_TRUE(fs::exists(writer.collectionPath()));
    EXPECT_TRUE(fs::exists(writer.seriesPath()));
    const double secondTime = 1.0 / 24.0;
    writer.writeFrame(1, secondTime, second, {fluence});

    EXPECT_EQ(writer.framePath(0), root / "vtk" / "field_00000.vti");
    EXPECT_TRUE(fs::exists(writer.framePath(1)));
    {
        SCOPED_TRACE("frame 0");
        expectRoundTrip(writer.framePath(0), first, 0.0, nullptr);
    }
    {
        SCOPED_TRACE("frame 1");
        expectRoundTrip(writer.framePath(1), second, secondTime, &fluence);
    }
    expectIndexFiles(writer);

    // Nothing but the frames and the two index files: no temporaries left.
    int files = 0;
    for (const auto& entry : fs::directory_iterator(root / "vtk")) {
        ++files;
        EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
    }
    EXPECT_EQ(files, 4);

    const std::string head = readAll(writer.framePath(1)).substr(0, 400);
    EXPECT_NE(head.find("type=\"ImageData\""), std::string::npos);
    const char* compressor = compression == VtkSeriesWriter::Compression::Zlib  ? "vtkZLibDataCompressor"
                             : compression == VtkSeriesWriter::Compression::Lz4 ? "vtkLZ4DataCompressor"
                                                                                 : nullptr;
    if (compressor) EXPECT_NE(head.find(compressor), std::string::npos) << head;
    else EXPECT_EQ(head.find("compressor="), std::string::npos) << head;
}

TEST_F(VtkExportTest, ZlibFramesRoundTripWithTimeSeriesIndex) {
    writeAndCheckTwoFrames(root_, VtkSeriesWriter::Compression::Zlib);
}

TEST_F(VtkExportTest, Lz4FramesRoundTrip) { writeAndCheckTwoFrames(root_, VtkSeriesWriter::Compression::Lz4); }

TEST_F(VtkExportTest, UncompressedFramesRoundTrip) { writeAndCheckTwoFrames(root_, VtkSeriesWriter::Compression::None); }

TEST_F(VtkExportTest, RewritingAFrameReplacesItsEntry) {
    VtkSeriesWriter writer(root_, "field");
    const FieldSet fields = makeFields(1.0f);
    writer.writeFrame(0, 0.0, fields);
    writer.writeFrame(1, 0.5, fields);
    writer.writeFrame(1, 0.75, fields);
    const std::string series = readAll(writer.seriesPath());
    EXPECT_EQ(series.find("0.5"), std::string::npos) << series;
    EXPECT_NE(series.find("\"field_00001.vti\", \"time\" : 0.75"), std::string::npos) << series;
    expectRoundTrip(writer.framePath(1), fields, 0.75, nullptr);
}

TEST_F(VtkExportTest, OptionalFieldsAreLeftOut) {
    VtkSeriesWriter writer(root_, "bare");
    FieldSet fields = makeFields(1.0f);
    fields.extinction.clear();
    fields.scattering.clear();
    writer.writeFrame(3, 1.5, fields);
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName(writer.framePath(3).c_str());
    reader->Update();
    vtkCellData* cellData = reader->GetOutput()->GetCellData();
    EXPECT_EQ(cellData->GetNumberOfArrays(), 2);
    EXPECT_NE(cellData->GetArray("index"), nullptr);
    EXPECT_NE(cellData->GetArray("delta_index"), nullptr);
}

// Arrays marked constant go once into NAME_static.vti (no TimeValue), not
// into any frame: two frames each hold only the varying arrays, the static
// file the constant one, written at the first frame, and the indexes list
// only the frames.
TEST_F(VtkExportTest, ConstantArraysAreWrittenOnceBesideTheSeries) {
    VtkSeriesWriter writer(root_, "fields");
    const FieldSet fields = makeFields(1.0f);
    NamedArray dye{"dye", 1, std::vector<float>(fields.grid.cellCount(), 0.0f), {"1", ArrayRole::Density}};
    dye.constant = true;
    writer.writeFrame(0, 0.0, fields, {dye});
    ASSERT_TRUE(fs::exists(writer.staticPath()));
    const auto staticTime = fs::last_write_time(writer.staticPath());
    writer.writeFrame(1, 0.5, makeFields(2.0f), {dye});
    EXPECT_EQ(fs::last_write_time(writer.staticPath()), staticTime) << "written once";
    for (int frame : {0, 1}) {
        vtkNew<vtkXMLImageDataReader> reader;
        reader->SetFileName(writer.framePath(frame).c_str());
        reader->Update();
        EXPECT_EQ(reader->GetOutput()->GetCellData()->GetArray("dye"), nullptr) << "frame " << frame;
        EXPECT_NE(reader->GetOutput()->GetCellData()->GetArray("extinction"), nullptr) << "frame " << frame;
    }
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName(writer.staticPath().c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    EXPECT_EQ(image->GetCellData()->GetNumberOfArrays(), 1);
    expectArray(*image, "dye", 1, dye.values);
    EXPECT_EQ(image->GetFieldData()->GetArray("TimeValue"), nullptr) << "the same at every time";
    EXPECT_EQ(image->GetNumberOfCells(), 24);
    EXPECT_EQ(readAll(writer.collectionPath()).find("static"), std::string::npos);
    EXPECT_EQ(readAll(writer.seriesPath()).find("static"), std::string::npos);

    // When nothing varies the frame stays whole: the series carries the time.
    VtkSeriesWriter still(root_, "still");
    std::vector<NamedArray> onlyConstant = ExportFrame{fields.grid, fieldArrays(viewsOf(fields))}.arrays;
    for (NamedArray& array : onlyConstant) array.constant = true;
    still.writeFrame(0, 0.0, {fields.grid, onlyConstant});
    EXPECT_FALSE(fs::exists(still.staticPath()));
    expectRoundTrip(still.framePath(0), fields, 0.0, nullptr);
}

TEST_F(VtkExportTest, RejectsUnsafeBaseNameAndMismatchedArrays) {
    EXPECT_THROW(VtkSeriesWriter(root_, "a/b"), InputError);
    EXPECT_THROW(VtkSeriesWriter(root_, "x\"y"), InputError);
    EXPECT_THROW(VtkSeriesWriter(root_, ""), InputError);
    VtkSeriesWriter writer(root_, "field");
    const FieldSet fields = makeFields(1.0f);
    EXPECT_THROW(writer.writeFrame(0, 0.0, fields, {NamedArray{"fluence", 3, std::vector<float>(5)}}), InternalError);
    EXPECT_THROW(writer.writeFrame(0, 0.0, fields, {NamedArray{"index", 1, std::vector<float>(24)}}), InternalError);
    EXPECT_THROW(writer.writeFrame(-1, 0.0, fields), InternalError);
    EXPECT_FALSE(fs::exists(writer.collectionPath()));
}

}  // namespace
}  // namespace eikon::io
