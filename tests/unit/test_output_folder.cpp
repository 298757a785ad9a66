#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"
#include "io/image/ImageIo.h"
#include "io/files/OutputFolder.h"
#include "io/files/RunJournal.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

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

// --force clears only what the earlier run recorded: files a user put beside
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
    const std::string journal = readAll(root_ / OutputFolder::kJournalName);
    EXPECT_NE(journal.find("\treport.jsonl\n"), std::string::npos) << journal;
    EXPECT_EQ(journal.find("notes.txt"), std::string::npos) << "the user's files are never recorded as eikon's";
}

// Files another program saves into the folder while a run writes there (a
// ParaView state beside the VTK files, notes) are not the run's: the next
// --force leaves them.
TEST_F(OutputFolderTest, FilesSavedDuringARunAreNotTheRuns) {
    {
        OutputFolder first(root_, false);
        writeFileAtomically(first.framePath(0), "frame 0");
        fs::create_directories(root_ / "vtk");
        writeFileAtomically(root_ / "vtk" / "fields_00000.vti", "export 0");
        std::ofstream(root_ / "vtk" / "state.pvsm") << "the user's ParaView state";
        std::ofstream(root_ / "notes.txt") << "the user's notes";
        writeFileAtomically(first.framePath(1), "frame 1");
        first.appendReport("{\"frame\":1}");
    }
    { OutputFolder second(root_, true); }
    EXPECT_FALSE(fs::exists(root_ / "frames" / "frame_00001.png"));
    EXPECT_FALSE(fs::exists(root_ / "vtk" / "fields_00000.vti"));
    EXPECT_EQ(readAll(root_ / "vtk" / "state.pvsm"), "the user's ParaView state");
    EXPECT_EQ(readAll(root_ / "notes.txt"), "the user's notes");
}

// A run that stops on a later frame's input discards what it wrote: its
// files, folders and journal go, a file a user saved there during the run
// stays, and so does the folder holding it; a folder the run made and that
// is left empty goes too.
TEST_F(OutputFolderTest, DiscardRemovesExactlyWhatTheRunWrote) {
    {
        OutputFolder run(root_, false);
        writeFileAtomically(run.framePath(0), "frame 0");
        fs::create_directories(root_ / "vtk");
        writeFileAtomically(root_ / "vtk" / "fields_00000.vti", "export 0");
        std::ofstream(root_ / "notes.txt") << "the user's notes";
        run.appendReport("{\"frame\":0}");
        run.discard();
    }
    EXPECT_EQ(readAll(root_ / "notes.txt"), "the user's notes");
    for (const char* gone : {"frames", "vtk", "report.jsonl", ".eikon-run"}) EXPECT_FALSE(fs::exists(root_ / gone)) << gone;
    fs::remove(root_ / "notes.txt");
    {
        OutputFolder run(root_, false);
        writeFileAtomically(run.framePath(0), "frame 0");
        run.discard();
    }
    EXPECT_TRUE(fs::is_directory(root_)) << "the folder was there before the run";
    EXPECT_TRUE(fs::is_empty(root_));
    fs::remove(root_);
    {
        OutputFolder run(root_, false);
        writeFileAtomically(run.framePath(0), "frame 0");
        run.discard();
    }
    EXPECT_FALSE(fs::exists(root_)) << "the run made the folder";
}

// The journal records the fingerprint of the run's scene beside its files,
// which --force still reads as entries alone.
TEST_F(OutputFolderTest, TheJournalHoldsTheScenesFingerprint) {
    {
        OutputFolder run(root_, false);
        run.recordScene("9e107d9d372bb6826bd81d3542a419d6");
        writeFileAtomically(run.framePath(0), "frame 0");
    }
    const std::string journal = readAll(root_ / OutputFolder::kJournalName);
    EXPECT_EQ(journalScene(journal), std::optional<std::string>("9e107d9d372bb6826bd81d3542a419d6"));
    EXPECT_EQ(journalScene(journalHeader(1)), std::nullopt);
    { OutputFolder second(root_, true); }
    EXPECT_FALSE(fs::exists(root_ / "frames" / "frame_00000.png"));
}

// A run killed with -9 (no handler runs) leaves the temporary it was
// writing; it was recorded before it was created, so --force clears it with
// the run, while a user's file that merely looks like one stays.
TEST_F(OutputFolderTest, ForceClearsWhatAKilledRunLeft) {
    {
        OutputFolder first(root_, false);
        writeFileAtomically(first.framePath(0), "old frame");
        first.appendReport("{\"frame\":0}");
        std::ofstream(temporaryPathFor(first.framePath(1))) << "half a frame";  // never committed
    }
    const fs::path halfFrame = root_ / "frames" / ("frame_00001.png.tmp" + std::to_string(::getpid()));
    ASSERT_TRUE(fs::exists(halfFrame));
    writeFileAtomically(root_ / "frames" / "frame_00002.png.tmp4242", "the user's");
    writeFileAtomically(root_ / "draft.tmp", "the user's too");
    EXPECT_THROW(OutputFolder(root_, false), InputError);
    { OutputFolder second(root_, true); }
    EXPECT_FALSE(fs::exists(halfFrame));
    EXPECT_FALSE(fs::exists(root_ / "frames" / "frame_00000.png"));
    EXPECT_EQ(readAll(root_ / "frames" / "frame_00002.png.tmp4242"), "the user's");
    EXPECT_EQ(readAll(root_ / "draft.tmp"), "the user's too");
}

// A file put in place of one the run wrote is not the run's: it is neither
// removed nor overwritten, and the run is refused, naming it.
TEST_F(OutputFolderTest, AReplacedFileIsRefusedNotRemoved) {
    {
        OutputFolder first(root_, false);
        writeFileAtomically(first.framePath(0), "frame 0");
        writeFileAtomically(first.framePath(1), "frame 1");
    }
    const fs::path replaced = root_ / "frames" / "frame_00000.png";
    std::ofstream(root_ / "elsewhere.png") << "another program's";
    fs::rename(root_ / "elsewhere.png", replaced);
    try {
        OutputFolder second(root_, true);
        ADD_FAILURE() << "took a folder holding a frame the earlier run did not write";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("frames/frame_00000.png: not written by the earlier run"),
                  std::string::npos)
            << error.what();
    }
    EXPECT_EQ(readAll(replaced), "another program's");
    EXPECT_EQ(readAll(root_ / "frames" / "frame_00001.png"), "frame 1") << "a refused run touches nothing";
}

// Only a journal makes an earlier run: a folder of files with eikon's names
// and no journal is not one, --force or not.
TEST_F(OutputFolderTest, AFolderWithoutAJournalIsNoEarlierRun) {
    fs::create_directories(root_ / "frames");
    writeFileAtomically(root_ / "frames" / "frame_00000.png", "old");
    writeFileAtomically(root_ / "report.jsonl", "{}\n");
    for (bool force : {false, true}) EXPECT_THROW(OutputFolder(root_, force), InputError);
    EXPECT_EQ(readAll(root_ / "frames" / "frame_00000.png"), "old");
    EXPECT_FALSE(fs::exists(root_ / OutputFolder::kJournalName)) << "a refused folder stays as it was";
}

// The list of names an older eikon kept records no identities: refused,
// nothing removed.
TEST_F(OutputFolderTest, AnOlderEikonsListIsRefused) {
    fs::create_directories(root_ / "frames");
    writeFileAtomically(root_ / "frames" / "frame_00000.png", "old");
    writeFileAtomically(root_ / OutputFolder::kJournalName,
                        "# files an eikon run wrote into this folder, one per line\nframes/frame_00000.png\n");
    try {
        OutputFolder folder(root_, true);
        ADD_FAILURE() << "cleared by names alone";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("an older eikon's list of names"), std::string::npos) << error.what();
    }
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

// A folder holding nothing but a `frames` link holds no earlier run: refused,
// naming the link, and nothing is written where it points.
TEST_F(OutputFolderTest, AFolderHoldingOnlyALinkIsNoEarlierRun) {
    const fs::path pictures = root_.string() + "_pictures";
    fs::create_directories(pictures);
    writeFileAtomically(pictures / "frame_00000.png", "the user's picture");
    fs::create_directories(root_);
    fs::create_directory_symlink(pictures, root_ / "frames");
    for (bool force : {false, true}) {
        try {
            OutputFolder folder(root_, force);
            writeFileAtomically(folder.framePath(0), "a frame");
            ADD_FAILURE() << "took a folder holding only a link for an earlier run";
        } catch (const InputError& error) {
            EXPECT_NE(std::string(error.what()).find("frames (a symbolic link)"), std::string::npos) << error.what();
        }
    }
    EXPECT_EQ(readAll(pictures / "frame_00000.png"), "the user's picture");
    EXPECT_EQ(std::distance(fs::directory_iterator(pictures), fs::directory_iterator()), 1);
    fs::remove_all(pictures);
}

// An earlier run's frames/ replaced by a link to a user's folder: --force
// refuses, naming the link, and the user's frame_00000.png stays.
TEST_F(OutputFolderTest, ALinkedFramesFolderIsRefusedAndWhereItPointsUntouched) {
    { OutputFolder first(root_, false); writeFileAtomically(first.framePath(0), "old frame"); }
    const fs::path pictures = root_.string() + "_pictures";
    fs::create_directories(pictures);
    fs::rename(root_ / "frames" / "frame_00000.png", pictures / "frame_00000.png");
    fs::remove(root_ / "frames");
    fs::create_directory_symlink(pictures, root_ / "frames");
    try {
        OutputFolder second(root_, true);
        ADD_FAILURE() << "cleared and wrote through a link";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("frames: expected a folder for eikon's files, found a symbolic link"),
                  std::string::npos)
            << error.what();
    }
    EXPECT_EQ(readAll(pictures / "frame_00000.png"), "old frame");
    fs::remove_all(pictures);
}

// A journal line that goes through a link (`link/notes.txt`, with or without
// the identity of the file there) reaches nothing outside the folder.
TEST_F(OutputFolderTest, AJournalLineThroughALinkReachesNothing) {
    { OutputFolder first(root_, false); writeFileAtomically(first.framePath(0), "old frame"); }
    const fs::path outside = root_.string() + "_outside";
    fs::create_directories(outside);
    writeFileAtomically(outside / "notes.txt", "the user's notes");
    fs::create_directory_symlink(outside, root_ / "link");
    struct stat status {};
    ASSERT_EQ(::stat((outside / "notes.txt").c_str(), &status), 0);
    std::ofstream(root_ / OutputFolder::kJournalName, std::ios::app)
        << "link/notes.txt\n"
        << "file\t" << status.st_dev << "\t" << status.st_ino << "\tlink/notes.txt\n";
    { OutputFolder second(root_, true); }
    EXPECT_EQ(readAll(outside / "notes.txt"), "the user's notes");
    EXPECT_TRUE(fs::is_symlink(root_ / "link")) << "the user's link stays too";
    EXPECT_FALSE(fs::exists(root_ / "frames" / "frame_00000.png"));
    fs::remove_all(outside);
}

// One run at a time: while a run holds the folder another is refused at
// once (std::runtime_error: exit code 1), naming the first one's pid, and
// touches nothing; once it ends, --force takes the folder.
TEST_F(OutputFolderTest, ASecondRunIntoTheFolderIsRefusedAtOnce) {
    const std::string busy = "another eikon run (pid " + std::to_string(::getpid()) + ") is writing into " + root_.string();
    {
        OutputFolder first(root_, false);
        writeFileAtomically(first.framePath(0), "first run's frame");
        for (const bool force : {false, true}) {
            try {
                OutputFolder::requireUsable(root_, force);
                OutputFolder second(root_, force);
                ADD_FAILURE() << "two runs in one folder";
            } catch (const InputError& error) {
                ADD_FAILURE() << "not an input error: " << error.what();
            } catch (const std::runtime_error& error) {
                EXPECT_NE(std::string(error.what()).find(busy), std::string::npos) << error.what();
            }
            try {
                OutputFolder second(root_, force);
                ADD_FAILURE() << "two runs in one folder";
            } catch (const std::runtime_error& error) {
                EXPECT_NE(std::string(error.what()).find(busy), std::string::npos) << error.what();
            }
        }
        EXPECT_EQ(readAll(first.framePath(0)), "first run's frame");
        writeFileAtomically(first.framePath(1), "still the first run's");
    }
    OutputFolder::requireUsable(root_, true);
    OutputFolder third(root_, true);
    EXPECT_FALSE(fs::exists(third.framePath(1)));
}

// The processes of an MPI run each record their own files, in the journal
// the first made for them: --force clears every one's.
TEST_F(OutputFolderTest, ForceClearsTheFilesOfEveryProcessOfARun) {
    {
        OutputFolder first(root_, false);
        first.shareWith(2);
        {
            OutputFolderShare rankOne(root_, 1);
            writeFileAtomically(first.framePath(1), "rank 1's frame");
        }
        writeFileAtomically(first.framePath(0), "rank 0's frame");
    }
    const fs::path shareJournal = root_ / (std::string(OutputFolder::kJournalName) + ".rank1");
    EXPECT_NE(readAll(shareJournal).find("\tframes/frame_00001.png\n"), std::string::npos);
    EXPECT_EQ(readAll(root_ / OutputFolder::kJournalName).find("frame_00001"), std::string::npos);
    { OutputFolder second(root_, true); }
    EXPECT_FALSE(fs::exists(root_ / "frames" / "frame_00000.png"));
    EXPECT_FALSE(fs::exists(root_ / "frames" / "frame_00001.png"));
    EXPECT_FALSE(fs::exists(shareJournal));
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
