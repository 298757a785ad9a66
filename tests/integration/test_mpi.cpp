// `mpirun -n 2 eikon run`, against the same run in one process (no
// mpirun): sharing the photons gives the default scene's frame and report
// figures bit for bit; sharing the frames of a volume sequence gives the
// same files, with series indexes that list every frame once; a bad scene,
// or a damaged later file of a volume sequence, is reported once before
// anything is written; a bad option one rank alone sees ends the job; ranks
// given different arguments, scenes or files are refused before any
// output; a rank that fails on its own, or is killed, ends the run with a
// message and leaves neither processes nor temporaries behind.
#include "io/vdb/VdbVolumeFile.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Outcome {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

Outcome runCommand(const std::string& command) {
    Outcome outcome;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) outcome.output += buffer;
    const int status = pclose(pipe);
    outcome.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return outcome;
}

// mpirun as the tests' user may start it (CI runs as root), on a machine
// with fewer cores than ranks too.
std::string mpirun(int ranks) {
    return std::string(EIKON_MPIEXEC) + (geteuid() == 0 ? " --allow-run-as-root" : "") + " --oversubscribe -n " +
           std::to_string(ranks) + " ";
}

std::string eikon() { return std::string(EIKON_EXECUTABLE) + " "; }

// An mpirun whose job is stopped after two minutes, so that a job that hangs
// fails its test (timeout's exit 124) instead of holding ctest.
std::string boundedMpirun() { return "timeout --kill-after=10 120 " + mpirun(1); }

std::string fileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<nlohmann::json> readReport(const fs::path& path) {
    std::vector<nlohmann::json> lines;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

// A report line without what a second run may change: wall times, and how
// the run was shared. A rank that renders every other frame uploads frame 0
// and its own first frame: its copied bytes are its own.
nlohmann::json withoutTimings(nlohmann::json line, bool framesShared = false) {
    line.erase("loop");
    if (framesShared) {  // a rank that starts mid-run uploads what the run before it had uploaded
        line.erase("host_bytes_copied");
        line.erase("bus_bytes");
    }
    line.erase("distribution");
    line["photons"]["resumed"].erase("dispatches");  // each share resumes its own batches
    for (auto& stage : line["stages"]) stage.erase("ms");
    if (line.contains("error_estimate")) line["error_estimate"].erase("ms");
    if (line.contains("simulation"))
        for (auto& phase : line["simulation"]) phase.erase("ms");
    return line;
}

// The output files below `root`; not the run's journals (.eikon-run, and
// one per other rank where ranks share the frames), which name each file's
// inode.
std::set<std::string> filesBelow(const fs::path& root) {
    std::set<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(root))
        if (entry.is_regular_file() && entry.path().filename().string().rfind(".eikon-run", 0) != 0)
            files.insert(fs::relative(entry.path(), root).string());
    return files;
}

// Processes whose command line mentions `marker` (the run's output folder).
std::vector<pid_t> processesMentioning(const std::string& marker) {
    std::vector<pid_t> pids;
    for (const auto& entry : fs::directory_iterator("/proc")) {
        const std::string name = entry.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::string cmdline = fileBytes(entry.path() / "cmdline");
        for (char& c : cmdline)
            if (c == '\0') c = ' ';
        if (cmdline.find(marker) != std::string::npos && cmdline.find(EIKON_EXECUTABLE) == 0)
            pids.push_back(static_cast<pid_t>(std::stol(name)));
    }
    return pids;
}

// The rank of an eikon process started by mpirun, from its environment.
int rankOf(pid_t pid) {
    const std::string environment = fileBytes("/proc/" + std::to_string(pid) + "/environ");
    const std::string key = std::string("OMPI_COMM_WORLD_RANK=");
    std::size_t at = environment.find(key);
    if (at == std::string::npos) return -1;
    return std::stoi(environment.substr(at + key.size()));
}

class Mpi : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("eikon_mpi_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // One process and two ranks, the same arguments otherwise.
    void runBoth(const std::string& arguments, const std::string& distribute, const fs::path& alone,
                 const fs::path& shared) {
        const Outcome one = runCommand(eikon() + arguments + " --quiet --out " + alone.string());
        ASSERT_EQ(one.exitCode, 0) << one.output;
        const Outcome two = runCommand(mpirun(2) + eikon() + arguments + " --quiet --distribute " + distribute +
                                       " --out " + shared.string());
        ASSERT_EQ(two.exitCode, 0) << two.output;
    }

    fs::path dir_;
};

TEST_F(Mpi, TwoRanksSharingPhotonsGiveTheDefaultFrameBitForBit) {
    const std::string scene = std::string(EIKON_SOURCE_DIR) + "/scenes/default.json";
    for (const std::string estimator : {"wavefront", "photons"}) {
        SCOPED_TRACE(estimator);
        const fs::path alone = dir_ / ("alone_" + estimator), shared = dir_ / ("shared_" + estimator);
        runBoth("run " + scene + " --set 'tracer.estimator=\"" + estimator + "\"' --set render.photons=262144",
                "photons", alone, shared);
        EXPECT_EQ(fileBytes(alone / "frames/frame_00000.png"), fileBytes(shared / "frames/frame_00000.png"));
        EXPECT_EQ(fileBytes(alone / "frames/frame_00000.hdr"), fileBytes(shared / "frames/frame_00000.hdr"));
        auto one = readReport(alone / "report.jsonl"), two = readReport(shared / "report.jsonl");
        ASSERT_EQ(one.size(), 1u);
        ASSERT_EQ(two.size(), 1u);
        EXPECT_EQ(two[0]["distribution"], (nlohmann::json{{"mode", "photons"}, {"ranks", 2}}));
        // A shared pass has no halves to estimate its noise by (docs/accuracy.md);
        // every other figure is the one process's.
        EXPECT_FALSE(two[0]["error_estimate"]["noise"].contains("receivers"));
        one[0]["error_estimate"].erase("noise");
        two[0]["error_estimate"].erase("noise");
        EXPECT_EQ(withoutTimings(one[0]), withoutTimings(two[0]));
        EXPECT_GT(one[0]["photons"]["power_w"]["received"][1].get<double>(), 1.0) << "the floor is lit";
        EXPECT_EQ(filesBelow(alone), filesBelow(shared));
    }
}

// `frames` files of a Blender-style sequence whose temperature rises frame
// by frame, and a scene that imports it, exported to ParaView and OpenVDB.
std::string writeVolumeScene(const fs::path& dir, int frames) {
    for (int f = 1; f <= frames; ++f) {
        char name[64];
        std::snprintf(name, sizeof name, "fluid_data_%04d.vdb", f);
        eikon::test::writeVdbFile(
            dir / name,
            {{"density", 1, [](double, double, double, int) { return 0.5f; }},
             {"temperature", 1, [f](double x, double y, double, int) { return float(f) * float(1.0 + x + y); }}},
            0.05, -0.6, 0.6);
    }
    std::ofstream(dir / "volume.json") << R"({
  "grid": {"resolution": [24, 24, 24], "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}},
  "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.2, "index": 1.5}],
  "lights": [{"type": "point", "position": [0, 1.5, 0], "power": [10, 10, 10]}],
  "receivers": [{"type": "plane", "point": [0, 0.05, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": 32}],
  "camera": {"position": [0, 1, 2], "target": [0, 0.3, 0], "up": [0, 1, 0], "fov_deg": 45},
  "render": {"photons": 16384, "width": 64, "height": 48, "seed": 3},
  "tracer": {"estimator": "photons"},
  "volume": {"path": "fluid_data_####.vdb", "temperature_scale": 30, "density_extinction": 0.5},
  "export": {"vtk": {"fields": ["index", "extinction", "temperature"]}, "vdb": {"fields": ["temperature", "index"]}}
})";
    return (dir / "volume.json").string();
}

TEST_F(Mpi, TwoRanksSharingFramesWriteTheFilesOfOneProcess) {
    constexpr int kFrames = 6;
    const std::string scene = writeVolumeScene(dir_, kFrames);
    const fs::path alone = dir_ / "alone", shared = dir_ / "shared";
    runBoth("run " + scene + " --frames " + std::to_string(kFrames), "frames", alone, shared);
    ASSERT_EQ(filesBelow(alone), filesBelow(shared));
    for (const std::string& file : filesBelow(alone)) {
        if (fs::path(file).extension() == ".vdb") continue;  // OpenVDB writes a new UUID into each file
        if (file == "report.jsonl") continue;
        EXPECT_EQ(fileBytes(alone / file), fileBytes(shared / file)) << file;
    }
    const eikon::GridSpec cell{{1, 1, 1}, {0.1, 0.1, 0.1}, {0.1625, 0.3625, 0.1625}};
    for (int frame = 0; frame < kFrames; ++frame) {
        char name[64];
        std::snprintf(name, sizeof name, "vdb/fields_%05d.vdb", frame);
        const eikon::io::VdbVolumeFile one(alone / name), two(shared / name);
        EXPECT_EQ(one.sample("temperature", 1, cell, {0, 0, 0}), two.sample("temperature", 1, cell, {0, 0, 0}));
        EXPECT_EQ(one.sample("index", 1, cell, {0, 0, 0}), two.sample("index", 1, cell, {0, 0, 0}));
    }
    const auto one = readReport(alone / "report.jsonl"), two = readReport(shared / "report.jsonl");
    ASSERT_EQ(one.size(), std::size_t{kFrames});
    ASSERT_EQ(two.size(), std::size_t{kFrames});
    for (int frame = 0; frame < kFrames; ++frame) {
        EXPECT_EQ(two[frame]["frame"], frame) << "in frame order";
        EXPECT_EQ(two[frame]["distribution"]["mode"], "frames");
        EXPECT_EQ(withoutTimings(one[frame], true), withoutTimings(two[frame], true)) << "frame " << frame;
    }
    EXPECT_NE(one[0]["photons"]["power_w"]["absorbed"], one[kFrames - 1]["photons"]["power_w"]["absorbed"])
        << "the frames differ";
    // Every frame once in each index, in order.
    const nlohmann::json series = nlohmann::json::parse(fileBytes(shared / "vtk/fields.vti.series"));
    ASSERT_EQ(series["files"].size(), std::size_t{kFrames});
    for (int frame = 0; frame < kFrames; ++frame) {
        char name[64];
        std::snprintf(name, sizeof name, "fields_%05d.vti", frame);
        EXPECT_EQ(series["files"][frame]["name"], name);
    }
    const std::string pvd = fileBytes(shared / "vtk/fields.pvd");
    for (int frame = 0; frame < kFrames; ++frame) {
        char name[64];
        std::snprintf(name, sizeof name, "file=\"fields_%05d.vti\"", frame);
        EXPECT_EQ(pvd.find(name), pvd.rfind(name)) << name << " once";
        EXPECT_NE(pvd.find(name), std::string::npos) << name;
    }
    // Each rank recorded the files it wrote: --force clears rank 1's too.
    const Outcome forced = runCommand(eikon() + "run " + scene + " --frames 1 --quiet --force --out " + shared.string());
    ASSERT_EQ(forced.exitCode, 0) << forced.output;
    EXPECT_FALSE(fs::exists(shared / "frames/frame_00001.png"));
    EXPECT_FALSE(fs::exists(shared / "vdb/fields_00003.vdb"));
    EXPECT_FALSE(fs::exists(shared / ".eikon-run.rank1"));
}

// Frame 3's file holds a NaN temperature: its structure passes the check
// before frame 0, and rank 1 meets the value alone, after the inputs were
// agreed on, and ends the job with its rank, the file and exit 2 — no rank is
// left waiting.
TEST_F(Mpi, AFailureOfOneRankEndsTheJobWithItsRankAndMessage) {
    const std::string scene = writeVolumeScene(dir_, 4);
    const fs::path damaged = dir_ / "fluid_data_0004.vdb";
    eikon::test::writeVdbFile(damaged,
                              {{"density", 1, [](double, double, double, int) { return 0.5f; }},
                               {"temperature", 1, [](double, double, double, int) { return std::nanf(""); }}},
                              0.05, -0.6, 0.6);
    const fs::path out = dir_ / "out";
    const Outcome outcome = runCommand(mpirun(2) + eikon() + "run " + scene +
                                       " --frames 4 --quiet --distribute frames --out " + out.string());
    EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
    EXPECT_NE(outcome.output.find("eikon: error (rank 1 of 2): " + scene + ": volume.path: " + damaged.string()),
              std::string::npos)
        << outcome.output;
    EXPECT_TRUE(processesMentioning(out.string()).empty());
}

// The last file of a three-file sequence cut short, or overwritten with
// text: every rank checks every file before frame 0, so the job ends at once
// with exit 2, the file named once, and nothing written — though rank 0's
// frames (0 and 2) would not read it.
TEST_F(Mpi, ADamagedLaterFileOfASequenceStopsTheJobBeforeFrameZero) {
    const std::string scene = writeVolumeScene(dir_, 3);
    const fs::path last = dir_ / "fluid_data_0003.vdb", out = dir_ / "out";
    const std::string whole = fileBytes(last);
    for (const auto& [label, bytes] : {std::pair<std::string, std::string>{"truncated", whole.substr(0, whole.size() / 2)},
                                       {"garbage", std::string(whole.size(), 'x')}}) {
        SCOPED_TRACE(label);
        std::ofstream(last, std::ios::binary | std::ios::trunc) << bytes;
        const Outcome outcome = runCommand(mpirun(2) + eikon() + "run " + scene +
                                           " --frames 3 --quiet --distribute frames --out " + out.string());
        EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
        const std::string named = "eikon: error: " + scene + ": volume.path: " + last.string() + ": ";
        const std::size_t first = outcome.output.find(named);
        EXPECT_NE(first, std::string::npos) << outcome.output;
        EXPECT_EQ(outcome.output.find("eikon: error", first + 1), std::string::npos) << "once: " << outcome.output;
        EXPECT_FALSE(fs::exists(out));
        EXPECT_TRUE(processesMentioning(out.string()).empty());
    }
}

TEST_F(Mpi, ABadSceneIsReportedOnceWithExitTwoAndNothingWritten) {
    std::ofstream(dir_ / "bad.json") << R"({"grid": {"resolution": [16, 16, -1]}})";
    const fs::path out = dir_ / "out";
    const Outcome outcome =
        runCommand(mpirun(2) + eikon() + "run " + (dir_ / "bad.json").string() + " --quiet --out " + out.string());
    EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
    const std::size_t first = outcome.output.find("eikon: error: ");
    ASSERT_NE(first, std::string::npos) << outcome.output;
    EXPECT_EQ(outcome.output.find("eikon: error: ", first + 1), std::string::npos) << "once: " << outcome.output;
    EXPECT_NE(outcome.output.find("grid.resolution"), std::string::npos) << outcome.output;
    EXPECT_FALSE(fs::exists(out));
}

// A small scene, cheap to check: the refusals below come before any frame.
void writeSmallScene(const fs::path& path, long long photons, const std::string& mesh = "") {
    fs::create_directories(path.parent_path());
    const std::string object =
        mesh.empty() ? R"({"type": "sphere", "center": [0, 0.5, 0], "radius": 0.2, "index": 1.5})"
                     : R"({"type": "mesh", "mesh": {"path": ")" + mesh + R"("}, "index": 1.5})";
    std::ofstream(path) << R"({
  "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}},
  "objects": [)" << object << R"(],
  "lights": [{"type": "point", "position": [0, 1.5, 0], "power": [10, 10, 10]}],
  "camera": {"position": [0, 1, 2], "target": [0, 0.3, 0], "up": [0, 1, 0], "fov_deg": 45},
  "render": {"photons": )" << photons << R"(, "width": 32, "height": 24}
})";
}

// The launcher's MPMD form gives each rank its own command line: a bad
// option that rank 1 alone sees (or rank 0 alone) is refused by that rank,
// and the job ends at once with exit 2 — before, rank 0 waited for rank 1
// for ever.
TEST_F(Mpi, ABadOptionOnlyOneRankSeesEndsTheJobWithExitTwo) {
    const fs::path scene = dir_ / "scene.json", out = dir_ / "out";
    writeSmallScene(scene, 4096);
    const std::string good = eikon() + "run " + scene.string() + " --quiet --out " + out.string();
    const std::vector<std::pair<std::string, std::string>> cases = {
        {good + " : -n 1 " + good + " --frames 0", "eikon: error (rank 1 of 2): --frames: Value 0 not in range"},
        {good + " : -n 1 " + good + " --distribute bogus", "eikon: error (rank 1 of 2): --distribute: bogus not in"},
        {good + " --frames 0 : -n 1 " + good, "eikon: error: --frames: Value 0 not in range"}};
    for (const auto& [job, message] : cases) {
        const Outcome outcome = runCommand(boundedMpirun() + job);
        EXPECT_EQ(outcome.exitCode, 2) << job << "\n" << outcome.output;
        EXPECT_NE(outcome.output.find(message), std::string::npos) << outcome.output;
        EXPECT_FALSE(fs::exists(out)) << job;
    }
}

TEST_F(Mpi, RanksGivenDifferentFramesAreRefused) {
    const fs::path scene = dir_ / "scene.json", out = dir_ / "out";
    writeSmallScene(scene, 4096);
    const std::string run = eikon() + "run " + scene.string() + " --quiet --out " + out.string();
    const Outcome outcome = runCommand(boundedMpirun() + run + " --frames 4 : -n 1 " + run + " --frames 2");
    EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
    EXPECT_NE(outcome.output.find("eikon: error: ranks disagree: rank 1's --frames is 2, rank 0's is 4"),
              std::string::npos)
        << outcome.output;
    EXPECT_FALSE(fs::exists(out));
}

// The same relative scene path in two working folders: two machines whose
// copies of a scene differ.
TEST_F(Mpi, RanksReadingDifferentScenesAreRefused) {
    writeSmallScene(dir_ / "a" / "scene.json", 4096);
    writeSmallScene(dir_ / "b" / "scene.json", 8192);
    const fs::path out = dir_ / "out";
    const std::string run = eikon() + "run scene.json --quiet --out " + out.string();
    const Outcome outcome = runCommand(boundedMpirun() + "-wdir " + (dir_ / "a").string() + " " + run +
                                       " : -n 1 -wdir " + (dir_ / "b").string() + " " + run);
    EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
    EXPECT_NE(outcome.output.find("rank 1's scene differs from rank 0's at render.photons (8192, rank 0's 4096)"),
              std::string::npos)
        << outcome.output;
    EXPECT_FALSE(fs::exists(out));
}

// The same scene over meshes of the same size whose bytes differ.
TEST_F(Mpi, RanksReadingDifferentCopiesOfAMeshAreRefused) {
    const std::string mesh = fileBytes(fs::path(EIKON_SOURCE_DIR) / "scenes/meshes/glass_bar.obj");
    std::string changed = mesh;
    changed.replace(changed.find("v -0.06 "), 8, "v -0.05 ");  // one vertex moved
    for (const auto& [folder, bytes] : {std::pair{"a", mesh}, std::pair{"b", changed}}) {
        writeSmallScene(dir_ / folder / "scene.json", 4096, "bar.obj");
        std::ofstream(dir_ / folder / "bar.obj", std::ios::binary) << bytes;
    }
    const fs::path out = dir_ / "out";
    const std::string run = eikon() + "run scene.json --quiet --out " + out.string();
    const Outcome outcome = runCommand(boundedMpirun() + "-wdir " + (dir_ / "a").string() + " " + run +
                                       " : -n 1 -wdir " + (dir_ / "b").string() + " " + run);
    EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
    EXPECT_NE(outcome.output.find("rank 1's file for objects[0].mesh.path differs from rank 0's in its bytes"),
              std::string::npos)
        << outcome.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Mpi, SharingTheFramesOfALiveSimulationIsRefused) {
    const fs::path out = dir_ / "out";
    const Outcome outcome = runCommand(mpirun(2) + eikon() + "run " + EIKON_SOURCE_DIR +
                                       "/scenes/hot_plate_plume.json --quiet --distribute frames --out " + out.string());
    EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
    EXPECT_NE(outcome.output.find("--distribute: expected photons for a scene whose frames depend on each other"),
              std::string::npos)
        << outcome.output;
    EXPECT_FALSE(fs::exists(out));
}

// The same binary started without mpirun makes no MPI call: one process,
// whatever --distribute says, and no distribution in the report.
TEST_F(Mpi, WithoutMpirunTheRunIsOneProcess) {
    const fs::path out = dir_ / "out";
    const Outcome outcome = runCommand(eikon() + "run " + EIKON_SOURCE_DIR +
                                       "/scenes/hot_plate_plume.json --frames 2 --quiet --distribute frames "
                                       "--set render.photons=4096 --out " + out.string());
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    for (const auto& line : readReport(out / "report.jsonl")) EXPECT_FALSE(line.contains("distribution"));
}

TEST_F(Mpi, InfoListsEveryRanksDevice) {
    const Outcome outcome = runCommand(mpirun(2) + eikon() + "info");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_NE(outcome.output.find("MPI ranks:       2"), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("rank 0 ("), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("rank 1 ("), std::string::npos) << outcome.output;
}

// A live scene sharing its photons, exporting every frame; rank 1 is sent
// `signal` once frames are being written.
struct KilledRun {
    Outcome outcome;
    std::vector<pid_t> left;  // eikon processes of the run still alive afterwards
    std::vector<std::string> temporaries;
};

KilledRun killRankOne(const fs::path& out, int signal) {
    KilledRun run;
    const std::string command = mpirun(2) + eikon() + "run " + EIKON_SOURCE_DIR +
                                "/scenes/hot_plate_plume.json --frames 500 --quiet --vtk --set export.vdb.enabled=true "
                                "--set render.width=64 --set render.height=48 --set render.photons=4096 --out " +
                                out.string();
    std::thread killer([&] {
        for (int wait = 0; wait < 600 && !fs::exists(out / "vtk" / "fields_00002.vti"); ++wait)
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        std::this_thread::sleep_for(std::chrono::milliseconds(150));
        for (const pid_t pid : processesMentioning(out.string()))
            if (rankOf(pid) == 1) kill(pid, signal);
    });
    run.outcome = runCommand(command);
    killer.join();
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    run.left = processesMentioning(out.string());
    for (const auto& entry : fs::recursive_directory_iterator(out))
        if (entry.path().filename().string().find(".tmp") != std::string::npos)
            run.temporaries.push_back(entry.path().string());
    return run;
}

TEST_F(Mpi, ARankStoppedBySigtermEndsTheRunWithExitOneAndAMessage) {
    const KilledRun run = killRankOne(dir_ / "run", SIGTERM);
    EXPECT_EQ(run.outcome.exitCode, 1) << run.outcome.output;
    EXPECT_NE(run.outcome.output.find("eikon: error (rank 1 of 2): stopped by a signal"), std::string::npos)
        << run.outcome.output;
    EXPECT_TRUE(run.left.empty()) << run.left.size() << " eikon processes left";
    EXPECT_TRUE(run.temporaries.empty()) << run.temporaries.front();
    EXPECT_TRUE(fs::exists(dir_ / "run" / "report.jsonl"));
}

// SIGKILL cannot be caught: mpirun reports the rank's death and stops the
// other, which removes its own temporaries.
TEST_F(Mpi, ARankKilledOutrightEndsTheRunWithMpirunsMessage) {
    const KilledRun run = killRankOne(dir_ / "run", SIGKILL);
    EXPECT_NE(run.outcome.exitCode, 0) << run.outcome.output;
    EXPECT_NE(run.outcome.output.find("exited on signal 9"), std::string::npos) << run.outcome.output;
    EXPECT_TRUE(run.left.empty()) << run.left.size() << " eikon processes left";
    EXPECT_TRUE(run.temporaries.empty()) << run.temporaries.front();
}

}  // namespace
