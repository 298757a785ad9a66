#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"
#include "io/image/ImageIo.h"
#include "io/files/OutputFolder.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace eikon::io {
namespace {

namespace fs = std::filesystem;

class OutputFolderTest : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("eikon_output_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(root_);
    }
    void TearDown() override { fs::remove_all(root_); }
    fs::path root_;
};

std::string readAll(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST_F(OutputFolderTest, CreatesFramesFolderAndNamesFrames) {
    OutputFolder folder(root_, false);
    EXPECT_TRUE(fs::is_directory(root_ / "frames"));
    EXPECT_EQ(folder.framePath(7).filename(), "frame_00007.png");
}

TEST_F(OutputFolderTest, RefusesEarlierRunWithoutForce) {
    { OutputFolder first(root_, false); first.appendReport("{\"frame\":0}"); }
    EXPECT_THROW(OutputFolder(root_, false), InputError);
    EXPECT_TRUE(fs::exists(root_ / "report.jsonl")) << "a refused run must not touch the earlier one";
}

TEST_F(OutputFolderTest, ForceClearsEarlierRun) {
    { OutputFolder first(root_, false); writeFileAtomically(first.framePath(3), "old"); }
    OutputFolder second(root_, true);
    EXPECT_FALSE(fs::exists(second.framePath(3)));
}

// --force clears only what the earlier run listed: files a user put beside
// it stay, and a folder eikon never wrote is refused even with --force.
TEST_F(OutputFolderTest, ForceRemovesOnlyWhatEikonWrote) {
    {
        OutputFolder first(root_, false);
        writeFileAtomically(first.framePath(0), "old frame");
        fs::create_directories(root_ / "vtk");
        writeFileAtomically(root_ / "vtk" / "fields_00000.vti", "old export");
        first.appendReport("{\"frame\":0}");
    }
    writeFileAtomically(root_ / "notes.txt", "the user's");
    writeFileAtomically(root_ / "frames" / "mine.jpg", "the user's too");
    OutputFolder second(root_, true);
    EXPECT_FALSE(fs::exists(root_ / "frames" / "frame_00000.png"));
    EXPECT_FALSE(fs::exists(root_ / "vtk")) << "emptied folders of the earlier run go too";
    EXPECT_FALSE(fs::exists(root_ / "report.jsonl"));
    EXPECT_EQ(readAll(root_ / "notes.txt"), "the user's");
    EXPECT_EQ(readAll(root_ / "frames" / "mine.jpg"), "the user's too");
    second.appendReport("{\"frame\":0}");
    const std::string list = readAll(root_ / OutputFolder::kManifestName);
    EXPECT_NE(list.find("report.jsonl"), std::string::npos);
    EXPECT_EQ(list.find("notes.txt"), std::string::npos) << "the user's files are never listed as eikon's";
}

// A run killed with -9 (no handler runs) leaves the temporaries it was
// writing, NAME.tmpPID of its own file names: --force clears them with the
// run they belong to, and a user's file that merely ends in ".tmp" stays.
TEST_F(OutputFolderTest, ForceClearsTheTemporariesOfAKilledRun) {
    {
        OutputFolder first(root_, false);
        writeFileAtomically(first.framePath(0), "old frame");
        first.appendReport("{\"frame\":0}");
    }
    writeFileAtomically(root_ / "frames" / "frame_00001.png.tmp4242", "half a frame");
    writeFileAtomically(root_ / "report.jsonl.tmp4242", "half a report");
    writeFileAtomically(root_ / "draft.tmp", "the user's");
    EXPECT_THROW(OutputFolder(root_, false), InputError);
    { OutputFolder second(root_, true); }
    EXPECT_FALSE(fs::exists(root_ / "frames" / "frame_00001.png.tmp4242"));
    EXPECT_FALSE(fs::exists(root_ / "report.jsonl.tmp4242"));
    EXPECT_EQ(readAll(root_ / "draft.tmp"), "the user's");
}

// A run from before the list existed: every file has an eikon output name,
// so it is an earlier run (refused, cleared with --force); one foreign file
// makes it a folder eikon did not write.
TEST_F(OutputFolderTest, UnlistedEarlierRunIsRecognisedByItsNames) {
    fs::create_directories(root_ / "frames");
    fs::create_directories(root_ / "vtk");
    writeFileAtomically(root_ / "frames" / "frame_00000.png", "old");
    writeFileAtomically(root_ / "report.jsonl", "{}\n");
    writeFileAtomically(root_ / "vtk" / "fields_00000.vti", "old");
    writeFileAtomically(root_ / "vtk" / "fields.pvd", "old");
    EXPECT_THROW(OutputFolder(root_, false), InputError);
    { OutputFolder cleared(root_, true); }
    EXPECT_FALSE(fs::exists(root_ / "vtk"));
    EXPECT_FALSE(fs::exists(root_ / "report.jsonl"));

    fs::remove_all(root_);
    fs::create_directories(root_ / "frames");
    writeFileAtomically(root_ / "frames" / "frame_00000.png", "old");
    writeFileAtomically(root_ / "frames" / "holiday.png", "the user's");
    EXPECT_THROW(OutputFolder(root_, true), InputError);
    EXPECT_TRUE(fs::exists(root_ / "frames" / "frame_00000.png"));
}

TEST_F(OutputFolderTest, RefusesAFolderEikonDidNotWriteEvenWithForce) {
    fs::create_directories(root_ / "photos");
    writeFileAtomically(root_ / "notes.txt", "keep");
    writeFileAtomically(root_ / "photos" / "a.jpg", "keep");
    for (bool force : {false, true}) {
        try {
            OutputFolder folder(root_, force);
            ADD_FAILURE() << "accepted a folder eikon did not write";
        } catch (const InputError& error) {
            EXPECT_NE(std::string(error.what()).find("eikon did not write"), std::string::npos) << error.what();
        }
    }
    EXPECT_EQ(readAll(root_ / "notes.txt"), "keep");
    EXPECT_EQ(readAll(root_ / "photos" / "a.jpg"), "keep");
}

TEST_F(OutputFolderTest, ReportAccumulatesWholeLines) {
    OutputFolder folder(root_, false);
    folder.appendReport("{\"frame\":0}");
    folder.appendReport("{\"frame\":1}");
    EXPECT_EQ(readAll(root_ / "report.jsonl"), "{\"frame\":0}\n{\"frame\":1}\n");
    for (const auto& entry : fs::directory_iterator(root_))
        EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << "temporary left behind";
}

TEST_F(OutputFolderTest, PngRoundTrip) {
    OutputFolder folder(root_, false);
    const std::vector<std::uint8_t> pixels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 10, 20, 30, 255};
    writePng(folder.framePath(0), 2, 2, pixels);
    const Rgba8Image image = readImage(folder.framePath(0));
    EXPECT_EQ(image.width, 2);
    EXPECT_EQ(image.height, 2);
    EXPECT_EQ(image.rgba, pixels);
}

TEST_F(OutputFolderTest, UnreadableImageIsInputError) {
    fs::create_directories(root_);
    writeFileAtomically(root_ / "broken.png", "not a png");
    EXPECT_THROW(readImage(root_ / "broken.png"), InputError);
}

}  // namespace
}  // namespace eikon::io
