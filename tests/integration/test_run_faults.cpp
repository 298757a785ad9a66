// Faults of the environment during a run that exports every frame (VTK
// ImageData and PolyData, OpenVDB, PNG): `kill -9` at 20 random moments, a
// file system that fills up, a read-only one, another program saving files
// into the folder, a second run into it. Whatever happens, every file left
// under a final name loads completely and the .pvd and .series indexes list
// only such files; a fault eikon sees is exit code 1 with a message; the
// next `--force` clears exactly what the run wrote; and two runs never mix.
#include "bridge/core/Error.h"
#include "io/image/ImageIo.h"
#include "io/vdb/VdbVolumeFile.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include <sched.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

bool isTemporary(const fs::path& path) { return path.filename().string().find(".tmp") != std::string::npos; }

// A VTK XML file read back whole: no error event, and every array as long as
// the points or cells it belongs to.
template <typename Reader>
void expectWholeVtk(const fs::path& path) {
    vtkNew<Reader> reader;
    bool failed = false;
    vtkNew<vtkCallbackCommand> onError;
    onError->SetClientData(&failed);
    onError->SetCallback([](vtkObject*, unsigned long, void* failedFlag, void*) { *static_cast<bool*>(failedFlag) = true; });
    reader->AddObserver(vtkCommand::ErrorEvent, onError);
    reader->SetFileName(path.c_str());
    reader->Update();
    ASSERT_FALSE(failed) << path << " does not read back";
    vtkDataSet* data = reader->GetOutputAsDataSet();
    ASSERT_NE(data, nullptr) << path;
    for (int a = 0; a < data->GetPointData()->GetNumberOfArrays(); ++a)
        EXPECT_EQ(data->GetPointData()->GetArray(a)->GetNumberOfTuples(), data->GetNumberOfPoints()) << path;
    for (int a = 0; a < data->GetCellData()->GetNumberOfArrays(); ++a)
        EXPECT_EQ(data->GetCellData()->GetArray(a)->GetNumberOfTuples(), data->GetNumberOfCells()) << path;
}

void expectIndexListsWholeFiles(const fs::path& index, const std::vector<std::string>& listed) {
    for (const std::string& name : listed) {
        const fs::path file = index.parent_path() / name;
        EXPECT_TRUE(fs::is_regular_file(file)) << index << " lists " << name << ", which is not there";
        EXPECT_FALSE(isTemporary(file)) << index << " lists a temporary";
    }
}

// Every file of a run's output folder under a final name, checked by reading
// it as its kind; returns how many there were.
int expectWholeOutput(const fs::path& out) {
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(out)) {
        const fs::path& path = entry.path();
        if (!entry.is_regular_file() || isTemporary(path)) continue;
        ++files;
        const std::string extension = path.extension().string();
        SCOPED_TRACE(path.string());
        if (extension == ".vti") {
            expectWholeVtk<vtkXMLImageDataReader>(path);
        } else if (extension == ".vtp") {
            expectWholeVtk<vtkXMLPolyDataReader>(path);
        } else if (extension == ".vdb") {
            EXPECT_NO_THROW({
                const eikon::io::VdbVolumeFile file(path);
                EXPECT_FALSE(file.gridNames().empty());
            });
        } else if (extension == ".png") {
            EXPECT_NO_THROW(eikon::io::readImage(path));
        } else if (extension == ".pvd") {
            const std::string text = readText(path);
            std::vector<std::string> listed;
            const std::regex fileAttribute("file=\"([^\"]+)\"");
            for (auto match = std::sregex_iterator(text.begin(), text.end(), fileAttribute); match != std::sregex_iterator();
                 ++match)
                listed.push_back((*match)[1]);
            EXPECT_NE(text.find("</VTKFile>"), std::string::npos) << "a cut-off collection";
            expectIndexListsWholeFiles(path, listed);
        } else if (extension == ".series") {
            std::vector<std::string> listed;
            const nlohmann::json series = nlohmann::json::parse(readText(path));
            for (const auto& file : series.at("files")) listed.push_back(file.at("name"));
            expectIndexListsWholeFiles(path, listed);
        } else if (path.filename() == "report.jsonl") {
            std::ifstream lines(path);
            for (std::string line; std::getline(lines, line);) EXPECT_NO_THROW(nlohmann::json::parse(line)) << line;
        }
    }
    return files;
}

struct RunResult {
    int status = 0;
    std::string output;
};

// `eikon run` of the heat-shimmer scene exporting VTK and OpenVDB every
// frame, its stderr to `log`.
pid_t startExportingRun(const fs::path& out, int frames, const fs::path& log, bool force = false) {
    const std::string scene = std::string(EIKON_SOURCE_DIR) + "/scenes/hot_plate_plume.json";
    const std::string framesArgument = std::to_string(frames);
    std::vector<const char*> arguments = {EIKON_EXECUTABLE, "run", scene.c_str(), "--out", out.c_str(), "--frames",
                                          framesArgument.c_str(), "--quiet", "--vtk", "--set", "export.vdb.enabled=true",
                                          "--set", "render.width=64", "--set", "render.height=48", "--set",
                                          "render.photons=4096"};
    if (force) arguments.push_back("--force");
    arguments.push_back(nullptr);
    const pid_t child = fork();
    if (child == 0) {
        FILE* redirected = std::freopen(log.c_str(), "w", stderr);
        (void)redirected;
        execv(EIKON_EXECUTABLE, const_cast<char* const*>(arguments.data()));
        _exit(127);
    }
    return child;
}

RunResult finish(pid_t child, const fs::path& log) {
    RunResult result;
    waitpid(child, &result.status, 0);
    result.output = readText(log);
    return result;
}

class RunFaults : public ::testing::Test {
protected:
    void SetUp() override {
        const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        dir_ = fs::temp_directory_path() / ("eikon_faults_" + name);
        log_ = fs::temp_directory_path() / ("eikon_faults_" + name + ".log");  // outside any small file system
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        umount2(dir_.c_str(), MNT_DETACH);
        fs::remove_all(dir_);
        fs::remove(log_);
    }
    // A private tmpfs of `bytes` over the test's folder, gone with the test
    // process (its own mount namespace). False where the test may not mount.
    bool mountSmallFileSystem(const std::string& bytes, bool readOnly) {
        if (unshare(CLONE_NEWNS) != 0) return false;
        if (mount("none", "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) return false;
        const std::string options = "size=" + bytes;
        if (mount("tmpfs", dir_.c_str(), "tmpfs", readOnly ? MS_RDONLY : 0, options.c_str()) != 0) return false;
        return true;
    }
    fs::path dir_, log_;
};

// The frame number in an output file's name (frame_00007.png,
// fields_00007.vti), or -1.
int frameNumberOf(const fs::path& file) {
    static const std::regex numbered(R"(.*_(\d{5})\.[a-z]+)");
    std::smatch match;
    const std::string name = file.filename().string();
    return std::regex_match(name, match, numbered) ? std::stoi(match[1]) : -1;
}

// SIGKILL cannot be caught: what it leaves must still be whole wherever a
// file has its final name, since every file is written to a temporary and
// renamed; and since each is recorded in the run's journal before it is
// created and again before its rename, `--force` with fewer frames into the
// same folder then clears all of it — the frames written after the killed
// run's last report line and its temporaries included — so nothing of it
// survives beside the new run's files. 20 moments drawn uniformly over an
// uninterrupted run's duration.
TEST_F(RunFaults, KillNineAtTwentyRandomMomentsLeavesWholeFilesThatForceClears) {
    constexpr int kFrames = 10, kFewer = 3;
    // The run's duration: the faster of two whole runs (the first may pay
    // for cold caches), so that the moments fall within the later runs.
    double duration = 1e30;
    for (int run = 0; run < 2; ++run) {
        const fs::path reference = dir_ / ("whole_" + std::to_string(run));
        const auto started = std::chrono::steady_clock::now();
        const RunResult whole = finish(startExportingRun(reference, kFrames, log_), log_);
        duration = std::min(duration, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
        ASSERT_TRUE(WIFEXITED(whole.status) && WEXITSTATUS(whole.status) == 0) << whole.output;
        EXPECT_GT(expectWholeOutput(reference), 4 * kFrames);
    }

    std::mt19937 random(20261202u);
    std::uniform_real_distribution<double> moment(0.0, 0.9 * duration);
    int killedMidway = 0;
    for (int trial = 0; trial < 20; ++trial) {
        const fs::path out = dir_ / ("killed_" + std::to_string(trial));
        const pid_t child = startExportingRun(out, kFrames, log_);
        std::this_thread::sleep_for(std::chrono::duration<double>(moment(random)));
        kill(child, SIGKILL);
        const RunResult killed = finish(child, log_);
        killedMidway += WIFSIGNALED(killed.status) && fs::exists(out / "frames" / "frame_00000.png") ? 1 : 0;
        SCOPED_TRACE("trial " + std::to_string(trial));
        if (fs::exists(out)) expectWholeOutput(out);

        const RunResult forced = finish(startExportingRun(out, kFewer, log_, /*force=*/true), log_);
        ASSERT_TRUE(WIFEXITED(forced.status) && WEXITSTATUS(forced.status) == 0) << forced.output;
        int frames = 0;
        for (const auto& entry : fs::recursive_directory_iterator(out)) {
            EXPECT_FALSE(isTemporary(entry.path())) << entry.path();
            EXPECT_LT(frameNumberOf(entry.path()), kFewer) << entry.path() << " is the killed run's";
            frames += entry.path().extension() == ".png" ? 1 : 0;
        }
        EXPECT_EQ(frames, kFewer);
    }
    EXPECT_GE(killedMidway, 10) << "most kills should land after the first frame and before the run ends, or the "
                                   "test tests little";
}

// A file another program saves into the folder while the run writes there
// (a ParaView state beside the VTK files, notes) is not the run's: the next
// --force leaves it.
TEST_F(RunFaults, FilesSavedDuringARunSurviveTheNextForce) {
    constexpr int kFrames = 8;
    const fs::path out = dir_ / "run";
    const pid_t child = startExportingRun(out, kFrames, log_);
    while (!fs::exists(out / "vtk" / "fields_00000.vti") && waitpid(child, nullptr, WNOHANG) == 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_EQ(kill(child, SIGSTOP), 0);
    std::ifstream report(out / "report.jsonl");
    const auto reported = std::count(std::istreambuf_iterator<char>(report), {}, '\n');
    ASSERT_LT(reported, kFrames - 1) << "the run should have frames left to write";
    std::ofstream(out / "vtk" / "state.pvsm") << "the user's ParaView state";
    std::ofstream(out / "notes.txt") << "the user's notes";
    kill(child, SIGCONT);
    const RunResult first = finish(child, log_);
    ASSERT_TRUE(WIFEXITED(first.status) && WEXITSTATUS(first.status) == 0) << first.output;

    const RunResult forced = finish(startExportingRun(out, 1, log_, /*force=*/true), log_);
    ASSERT_TRUE(WIFEXITED(forced.status) && WEXITSTATUS(forced.status) == 0) << forced.output;
    EXPECT_EQ(readText(out / "vtk" / "state.pvsm"), "the user's ParaView state");
    EXPECT_EQ(readText(out / "notes.txt"), "the user's notes");
    EXPECT_FALSE(fs::exists(out / "frames" / "frame_00001.png"));
}

// Two runs into one folder: while the first writes, a second (with --force)
// stops at once with exit code 1 naming the first, and the first's output
// is whole, all its own.
TEST_F(RunFaults, ASecondRunIntoTheFolderIsRefusedAtOnce) {
    constexpr int kFrames = 8;
    const fs::path out = dir_ / "run", secondLog = log_.string() + ".second";
    const pid_t first = startExportingRun(out, kFrames, log_);
    // Once its first frame is out, the first run holds the folder; stopped
    // there, it stays in the middle of its run for as long as the second takes.
    while (!fs::exists(out / "frames" / "frame_00000.png") && waitpid(first, nullptr, WNOHANG) == 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_EQ(kill(first, SIGSTOP), 0);
    const RunResult second = finish(startExportingRun(out, 3, secondLog, /*force=*/true), secondLog);
    kill(first, SIGCONT);
    const RunResult firstResult = finish(first, log_);
    fs::remove(secondLog);
    ASSERT_TRUE(WIFEXITED(second.status)) << second.output;
    EXPECT_EQ(WEXITSTATUS(second.status), 1) << second.output;
    EXPECT_NE(second.output.find("another eikon run (pid " + std::to_string(first) + ") is writing into " + out.string()),
              std::string::npos)
        << second.output;
    ASSERT_TRUE(WIFEXITED(firstResult.status) && WEXITSTATUS(firstResult.status) == 0) << firstResult.output;
    std::ifstream report(out / "report.jsonl");
    int line = 0;
    for (std::string text; std::getline(report, text); ++line) EXPECT_EQ(nlohmann::json::parse(text).at("frame"), line);
    EXPECT_EQ(line, kFrames);
    int frames = 0;
    for (const auto& entry : fs::directory_iterator(out / "frames")) frames += entry.path().extension() == ".png" ? 1 : 0;
    EXPECT_EQ(frames, kFrames);
    EXPECT_GT(expectWholeOutput(out), 4 * kFrames);
}

// The file system fills up partway: eikon stops with exit code 1 (the
// environment, not the input), names what it could not write, removes its
// temporary, and what it wrote before stays whole and indexed.
TEST_F(RunFaults, FullFileSystemStopsTheRunAndKeepsWhatIsWhole) {
    if (!mountSmallFileSystem("1500k", false)) GTEST_SKIP() << "no permission to mount a tmpfs here";
    const fs::path out = dir_ / "run";
    const RunResult full = finish(startExportingRun(out, 60, log_), log_);
    ASSERT_TRUE(WIFEXITED(full.status)) << full.output;
    EXPECT_EQ(WEXITSTATUS(full.status), 1) << full.output;
    EXPECT_EQ(full.output.rfind("eikon: error: ", 0), 0u) << full.output;
    EXPECT_NE(full.output.find(out.string()), std::string::npos) << "names the file: " << full.output;
    EXPECT_GT(expectWholeOutput(out), 4);
    for (const auto& entry : fs::recursive_directory_iterator(out)) EXPECT_FALSE(isTemporary(entry.path()));
}

// A read-only file system: exit code 1 with a message naming the folder,
// and nothing written.
TEST_F(RunFaults, ReadOnlyFileSystemIsRefusedBeforeAnyFrame) {
    if (!mountSmallFileSystem("1m", true)) GTEST_SKIP() << "no permission to mount a tmpfs here";
    const fs::path out = dir_ / "run";
    const RunResult refused = finish(startExportingRun(out, 2, log_), log_);
    ASSERT_TRUE(WIFEXITED(refused.status)) << refused.output;
    EXPECT_EQ(WEXITSTATUS(refused.status), 1) << refused.output;
    EXPECT_EQ(refused.output.rfind("eikon: error: ", 0), 0u) << refused.output;
    EXPECT_NE(refused.output.find(out.string()), std::string::npos) << refused.output;
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
