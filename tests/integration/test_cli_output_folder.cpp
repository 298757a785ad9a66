// The output folder as a user (or another program) can leave it before a
// run, through `eikon run` as a user runs it: nothing outside the folder is
// ever removed or written, whatever links the folder holds or the run's
// journal names, and a folder holding only a link is no earlier run.
#include "tests/integration/CliRun.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <sys/stat.h>

namespace {

namespace fs = std::filesystem;
using eikon::test::Outcome;
using eikon::test::runEikon;

class FolderCli : public eikon::test::CliFolderTest {
protected:
    FolderCli() : CliFolderTest("eikon_folder_cli_") {}
    void SetUp() override {
        CliFolderTest::SetUp();
        fs::create_directories(dir_ / "pictures");
        std::ofstream(dir_ / "scene.json") << eikon::test::kSmallSphereScene;
        std::ofstream(pictures() / "frame_00000.png") << "the user's picture";
    }

    Outcome run(const std::string& options) {
        return runEikon("run " + (dir_ / "scene.json").string() + " --out " + out().string() + " --quiet " + options);
    }
    fs::path out() const { return dir_ / "out"; }
    // A user's folder outside the output folder, holding frame_00000.png.
    fs::path pictures() const { return dir_ / "pictures"; }
    void expectPicturesUntouched() {
        EXPECT_EQ(std::distance(fs::directory_iterator(pictures()), fs::directory_iterator()), 1);
        std::ifstream picture(pictures() / "frame_00000.png");
        EXPECT_EQ(std::string(std::istreambuf_iterator<char>(picture), {}), "the user's picture");
    }
};

// An earlier run's frames/ replaced by a link to a user's folder that holds a
// frame_00000.png: --force removed it and wrote the new frames there.
TEST_F(FolderCli, ALinkedFramesFolderIsRefusedAndWhereItPointsUntouched) {
    ASSERT_EQ(run("--frames 2").exitCode, 0);
    fs::remove_all(out() / "frames");
    fs::create_directory_symlink(pictures(), out() / "frames");
    const Outcome refused = run("--force");
    EXPECT_EQ(refused.exitCode, 2) << refused.output;
    EXPECT_NE(refused.output.find((out() / "frames").string() + ": expected a folder for eikon's files, found a symbolic link"),
              std::string::npos)
        << refused.output;
    expectPicturesUntouched();
}

// A folder holding nothing but a `frames` or `vtk` link is no earlier run:
// --force wrote its frames, or seven VTK files, into the user's folder.
TEST_F(FolderCli, AFolderHoldingOnlyALinkIsNoEarlierRun) {
    for (const char* link : {"frames", "vtk"}) {
        SCOPED_TRACE(link);
        fs::remove_all(out());
        fs::create_directories(out());
        fs::create_directory_symlink(pictures(), out() / link);
        for (const char* force : {"", "--force"}) {
            const Outcome refused = run(std::string("--vtk ") + force);
            EXPECT_EQ(refused.exitCode, 2) << refused.output;
            EXPECT_NE(refused.output.find("holds files eikon did not write (" + std::string(link) + " (a symbolic link))"),
                      std::string::npos)
                << refused.output;
        }
        expectPicturesUntouched();
    }
}

// A line of the run's journal that goes through a link (`link/notes.txt`,
// with or without the identity of the file there): --force removed the
// file outside.
TEST_F(FolderCli, AJournalLineThroughALinkRemovesNothingOutside) {
    ASSERT_EQ(run("").exitCode, 0);
    fs::create_directory_symlink(pictures(), out() / "link");
    struct stat status {};
    ASSERT_EQ(::stat((pictures() / "frame_00000.png").c_str(), &status), 0);
    std::ofstream(out() / ".eikon-run", std::ios::app)
        << "link/frame_00000.png\n"
        << "file\t" << status.st_dev << "\t" << status.st_ino << "\tlink/frame_00000.png\n";
    const Outcome forced = run("--force");
    EXPECT_EQ(forced.exitCode, 0) << forced.output;
    expectPicturesUntouched();
    EXPECT_TRUE(fs::is_symlink(out() / "link")) << "the user's link stays";
}

}  // namespace
