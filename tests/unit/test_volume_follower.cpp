// Following a simulation as it writes (sim/volume/VolumeFollower): each look
// is one poll(), so what a writer has done between looks is set exactly —
// a step half written, a pause, a damaged step, an OpenFOAM time directory
// that fills field by field — with no clock in the test.
#include "sim/volume/VolumeFollower.h"

#include "bridge/core/Error.h"
#include "io/scene/SceneParser.h"
#include "io/vtk/VtkVolumeSource.h"
#include "sim/SceneFields.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using eikon::GridSpec;
using eikon::InputError;
using eikon::io::VtkArrayRequest;
using eikon::io::VtkVolumeSource;
using eikon::sim::VolumeFollower;
using eikon::sim::VolumeGrids;

// A 4³-point image whose T is `kelvin` everywhere, as a .vti file's bytes.
std::string imageBytes(double kelvin) {
    vtkNew<vtkImageData> image;
    image->SetDimensions(4, 4, 4);
    image->SetSpacing(0.1, 0.1, 0.1);
    image->SetOrigin(-0.15, -0.15, -0.15);
    vtkNew<vtkDoubleArray> t;
    t->SetName("T");
    for (int p = 0; p < 64; ++p) t->InsertNextValue(kelvin);
    image->GetPointData()->AddArray(t);
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(image);
    writer->WriteToOutputStringOn();
    EXPECT_EQ(writer->Write(), 1);
    return writer->GetOutputString();
}

void writeBytes(const fs::path& path, const std::string& bytes, std::ios::openmode mode = std::ios::trunc) {
    std::ofstream(path, std::ios::binary | mode) << bytes;
}

const std::vector<VtkArrayRequest> kRequests{{"T", "volume.fields.temperature"}};

class Follower : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::path(::testing::TempDir()) /
                  ("eikon_follower_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    // A .series listing step_0 … step_{count−1}.vti, written whether or not the files exist.
    void listSteps(int count) const {
        std::string files;
        for (int s = 0; s < count; ++s)
            files += (s ? ", " : "") + std::string(R"({"name": "step_)") + std::to_string(s) +
                     R"(.vti", "time": )" + std::to_string(s) + "}";
        std::ofstream(folder_ / "run.vti.series") << R"({"file-series-version": "1.0", "files": [)" << files << "]}";
    }
    fs::path step(int s) const { return folder_ / ("step_" + std::to_string(s) + ".vti"); }

    // The step's T at the centre cell, as the follower's read gives it.
    static VolumeFollower::Read reader(const VtkVolumeSource& source) {
        return [&source](int s) {
            const GridSpec grid{{3, 3, 3}, {-0.15, -0.15, -0.15}, {0.15, 0.15, 0.15}};
            VolumeGrids samples;
            samples.temperature = source.resample(s, kRequests, grid, glm::dmat4(1.0)).arrays.at(0).values;
            return samples;
        };
    }

    fs::path folder_;
};

// A step's file half written: it is not read while it grows, is read and
// fails while the writer pauses, and is read once whole — once.
TEST_F(Follower, AHalfWrittenStepIsReadOnceWholeAndOnlyThen) {
    listSteps(1);  // listed before its file is begun: the hardest order for the follower
    VtkVolumeSource source(folder_ / "run.vti.series", true);
    VolumeFollower follower(source, kRequests, reader(source));
    EXPECT_FALSE(follower.poll());  // listed, no file yet
    const std::string bytes = imageBytes(310.0);
    writeBytes(step(0), bytes.substr(0, bytes.size() / 2));
    EXPECT_FALSE(follower.poll());  // first seen: not yet known to be complete
    EXPECT_FALSE(follower.poll());  // unchanged (the writer paused): read, and the read fails
    EXPECT_FALSE(follower.poll());  // unchanged and failed as it stands: not read again
    writeBytes(step(0), bytes.substr(bytes.size() / 2), std::ios::app);
    EXPECT_FALSE(follower.poll());  // changed since the last look
    ASSERT_TRUE(follower.poll());   // unchanged for a look, and reads
    const VolumeFollower::Step taken = follower.take();
    EXPECT_EQ(taken.index, 0);
    EXPECT_EQ(taken.name, step(0).string());
    EXPECT_TRUE(taken.skipped.empty());
    EXPECT_FLOAT_EQ(taken.samples.temperature.at(13), 310.0f);
    EXPECT_FALSE(follower.poll());  // nothing new: step 0 is not read twice
    EXPECT_TRUE(follower.finish().empty());
}

// A damaged step (never completed: the writer gave up on it) is skipped
// with the reader's reason once the step after it reads; the steps keep
// their order, and a damaged last step is reported when following ends.
TEST_F(Follower, ADamagedStepIsSkippedWithItsReasonOnceALaterStepReads) {
    const std::string bytes = imageBytes(300.0);
    writeBytes(step(0), bytes);
    writeBytes(step(1), bytes.substr(0, bytes.size() / 3));
    writeBytes(step(2), imageBytes(320.0));
    writeBytes(step(3), "not VTK at all");
    listSteps(4);
    VtkVolumeSource source(folder_ / "run.vti.series", true);
    VolumeFollower follower(source, kRequests, reader(source));
    EXPECT_FALSE(follower.poll());
    ASSERT_TRUE(follower.poll());
    EXPECT_EQ(follower.take().index, 0);
    ASSERT_TRUE(follower.poll());  // step 1 fails as it stands; step 2 reads
    const VolumeFollower::Step second = follower.take();
    EXPECT_EQ(second.index, 2);
    EXPECT_FLOAT_EQ(second.samples.temperature.at(13), 320.0f);
    ASSERT_EQ(second.skipped.size(), 1u);
    EXPECT_EQ(second.skipped[0].step, step(1).string());
    EXPECT_NE(second.skipped[0].reason.find(step(1).string() + ": expected a VTK file VTK's reader reads"),
              std::string::npos)
        << second.skipped[0].reason;
    EXPECT_FALSE(follower.poll());  // step 3 fails; nothing after it
    const std::vector<eikon::sim::SkippedStep> left = follower.finish();
    ASSERT_EQ(left.size(), 1u);
    EXPECT_EQ(left[0].step, step(3).string());
    EXPECT_NE(left[0].reason.find(step(3).string()), std::string::npos) << left[0].reason;
}

// Steps the index lists that never appear are reported as never complete;
// an index being rewritten (not JSON yet) keeps the last list.
TEST_F(Follower, AStepThatNeverAppearsIsReportedAndAHalfWrittenIndexKeepsTheList) {
    writeBytes(step(0), imageBytes(300.0));
    listSteps(2);
    VtkVolumeSource source(folder_ / "run.vti.series", true);
    VolumeFollower follower(source, kRequests, reader(source));
    EXPECT_FALSE(follower.poll());
    ASSERT_TRUE(follower.poll());
    EXPECT_EQ(follower.take().index, 0);
    std::ofstream(folder_ / "run.vti.series") << R"({"file-series-version": "1.0", "files": [{"na)";
    EXPECT_FALSE(follower.poll());
    EXPECT_EQ(source.stepCount(), 2);
    const std::vector<eikon::sim::SkippedStep> left = follower.finish();
    ASSERT_EQ(left.size(), 1u);
    EXPECT_EQ(left[0].step, step(1).string());
    EXPECT_NE(left[0].reason.find("never complete"), std::string::npos) << left[0].reason;
}

// An OpenFOAM case: a new time directory is read once every declared
// field's file is there and unchanged — not while `p` is still missing.
TEST_F(Follower, AnOpenFoamTimeDirectoryIsReadOnceItsFieldsAreAllThere) {
    const fs::path tiny = fs::path(EIKON_SOURCE_DIR) / "tests" / "data" / "openfoam_tiny";
    const fs::path foam = folder_ / "case";
    fs::copy(tiny, foam, fs::copy_options::recursive);
    fs::remove_all(foam / "0.5");
    const std::vector<VtkArrayRequest> requests{{"T", "volume.fields.temperature"}, {"p", "volume.fields.pressure"}};
    VtkVolumeSource source(foam / "case.foam", true);
    VolumeFollower follower(source, requests, [&](int s) {
        source.check(s, requests);
        return VolumeGrids{};
    });
    EXPECT_FALSE(follower.poll());
    ASSERT_TRUE(follower.poll());
    EXPECT_EQ(follower.take().name, foam.string() + " at time 0");
    fs::create_directories(foam / "0.5");
    fs::copy_file(tiny / "0.5" / "T", foam / "0.5" / "T");
    EXPECT_FALSE(follower.poll());
    EXPECT_FALSE(follower.poll());  // p still missing: not complete
    EXPECT_FALSE(follower.poll());
    fs::copy_file(tiny / "0.5" / "p", foam / "0.5" / "p");
    EXPECT_FALSE(follower.poll());
    ASSERT_TRUE(follower.poll());
    const VolumeFollower::Step later = follower.take();
    EXPECT_EQ(later.name, foam.string() + " at time 0.5");
    EXPECT_TRUE(later.skipped.empty());
    EXPECT_TRUE(follower.finish().empty());
}

// Through the scene: a step whose values the volume's optics refuse (an
// absolute temperature below 0 K) is skipped like a damaged file, naming the
// key, and the run goes on to the next step.
TEST_F(Follower, AStepWhoseValuesTheOpticsRefuseIsSkippedLikeADamagedOne) {
    writeBytes(step(0), imageBytes(300.0));
    writeBytes(step(1), imageBytes(-5.0));
    writeBytes(step(2), imageBytes(320.0));
    listSteps(3);
    nlohmann::json root = nlohmann::json::parse(
        R"({"grid": {"resolution": [3, 3, 3], "bounds": {"min": [-0.15, -0.15, -0.15], "max": [0.15, 0.15, 0.15]}},
            "lights": [{"type": "point", "position": [0, 1, 0], "power": 1}],
            "volume": {"path": "run.vti.series", "fields": {"temperature": "T", "temperature_unit": "kelvin"}}})");
    eikon::Scene scene = eikon::parseScene(root, (folder_ / "scene.json").string());
    scene.volume->follow = eikon::VolumeDesc::Follow{0.001, 60.0, ""};  // the timeout a safety net only
    eikon::sim::SceneFields fields(scene);  // waits for step 0
    eikon::sim::VolumeSequence& volume = *fields.followedVolume();
    EXPECT_EQ(volume.currentFile(), step(0).string());
    const float first = fields.fields().deltaIndex.at(13);
    ASSERT_TRUE(volume.followNext(true));
    fields.advanceFrame();
    EXPECT_EQ(volume.currentFile(), step(2).string());
    EXPECT_LT(fields.fields().deltaIndex.at(13), first);  // hotter: a lower index
    ASSERT_EQ(volume.skippedBefore().size(), 1u);
    EXPECT_EQ(volume.skippedBefore()[0].step, step(1).string());
    EXPECT_NE(volume.skippedBefore()[0].reason.find("volume.fields.temperature"), std::string::npos)
        << volume.skippedBefore()[0].reason;
}

}  // namespace
