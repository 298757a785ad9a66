// `eikon run --follow` on a series that a writer (a thread of the test,
// standing in for a simulation) writes while eikon runs: files written in
// chunks with pauses, the index listing a step sometimes before its file is
// begun, one step damaged (cut short, never finished), at moments drawn from
// a seeded generator. Every complete step must be rendered once, in order,
// the damaged one skipped and reported, and the run must end by the stop
// file. The timeouts are safety nets only: nothing asserts a duration.
#include "io/vdb/VdbVolumeFile.h"
#include "tests/integration/CliRun.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using eikon::test::Outcome;
using eikon::test::readReport;

class FollowCli : public eikon::test::CliFolderTest {
protected:
    FollowCli() : CliFolderTest("eikon_follow_cli_") {}
};

// Step s's .vti: T = 300 + 10·s K over the scene's grid, [-0.5, 0.5] × [0, 1] × [-0.5, 0.5].
std::string stepBytes(int s) {
    vtkNew<vtkImageData> image;
    image->SetDimensions(5, 5, 5);
    image->SetSpacing(0.25, 0.25, 0.25);
    image->SetOrigin(-0.5, 0.0, -0.5);
    vtkNew<vtkDoubleArray> t;
    t->SetName("T");
    for (int p = 0; p < 125; ++p) t->InsertNextValue(300.0 + 10.0 * s);
    image->GetPointData()->AddArray(t);
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetInputData(image);
    writer->WriteToOutputStringOn();
    EXPECT_EQ(writer->Write(), 1);
    return writer->GetOutputString();
}

std::string stepName(int s) {
    char name[32];
    std::snprintf(name, sizeof name, "step_%03d.vti", s);
    return name;
}

TEST_F(FollowCli, EveryCompleteStepOfASeriesWrittenWhileFollowedIsRenderedOnceInOrder) {
    constexpr int kSteps = 8;
    constexpr int kDamaged = 5;  // cut short, as a writer that crashed mid-file leaves it
    std::string text = eikon::test::kSmallSphereScene;
    text.insert(text.rfind('}'), R"(, "volume": {"path": "run.vti.series",
        "fields": {"temperature": "T", "temperature_unit": "kelvin"}},
        "export": {"vdb": {"fields": ["temperature"]}})");
    const std::string scene = writeScene("follow.json", text);
    const fs::path out = dir_ / "out";
    const fs::path stop = dir_ / "done";
    std::ofstream(dir_ / "run.vti.series") << R"({"file-series-version": "1.0", "files": []})";  // no step yet
    std::future<Outcome> run = std::async(std::launch::async, [&] {
        return eikon::test::runEikonWithin(600, "run " + scene + " --out " + out.string() +
                                                    " --follow --follow-poll-ms 20 --follow-timeout 300 "
                                                    "--follow-stop " + stop.string());
    });

    std::mt19937 random(55);
    const auto pause = [&](int maxMs) {
        std::this_thread::sleep_for(
            std::chrono::milliseconds(std::uniform_int_distribution<int>(0, maxMs)(random)));
    };
    std::vector<std::string> listed;
    const auto writeIndex = [&] {  // rewritten in place, as simple writers do
        std::string files;
        for (std::size_t s = 0; s < listed.size(); ++s)
            files += (s ? ", " : "") + std::string(R"({"name": ")") + listed[s] + R"(", "time": )" +
                     std::to_string(s) + "}";
        std::ofstream(dir_ / "run.vti.series") << R"({"file-series-version": "1.0", "files": [)" << files << "]}";
    };
    pause(300);  // eikon may be waiting for the first step, or not yet looking
    for (int s = 0; s < kSteps; ++s) {
        const bool listedFirst = std::bernoulli_distribution(0.5)(random);
        if (listedFirst) {
            listed.push_back(stepName(s));
            writeIndex();
        }
        const std::string bytes = stepBytes(s);
        const std::size_t end = s == kDamaged ? bytes.size() / 2 : bytes.size();
        const int chunks = std::uniform_int_distribution<int>(2, 5)(random);
        std::ofstream file(dir_ / stepName(s), std::ios::binary);
        for (int c = 0; c < chunks; ++c) {
            const std::size_t from = end * static_cast<std::size_t>(c) / static_cast<std::size_t>(chunks);
            const std::size_t to = end * static_cast<std::size_t>(c + 1) / static_cast<std::size_t>(chunks);
            file.write(bytes.data() + from, static_cast<std::streamsize>(to - from));
            file.flush();
            pause(90);  // often longer than two looks: a half-written file then sits unchanged
        }
        file.close();
        if (!listedFirst) {
            listed.push_back(stepName(s));
            writeIndex();
        }
        pause(150);
    }
    std::ofstream(stop) << "done\n";

    const Outcome outcome = run.get();
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_NE(outcome.output.find("warning: skipped step " + (dir_ / stepName(kDamaged)).string()), std::string::npos)
        << outcome.output;
    const std::vector<nlohmann::json> lines = readReport(out / "report.jsonl");
    ASSERT_EQ(lines.size(), static_cast<std::size_t>(kSteps)) << outcome.output;  // 7 frames and the end
    std::vector<std::string> shown, skipped;
    for (std::size_t l = 0; l + 1 < lines.size(); ++l) {
        ASSERT_TRUE(lines[l].contains("follow")) << lines[l].dump();
        EXPECT_EQ(lines[l]["frame"], static_cast<int>(l));
        shown.push_back(fs::path(lines[l]["follow"]["step"].get<std::string>()).filename().string());
        for (const auto& step : lines[l]["follow"]["skipped"]) {
            skipped.push_back(fs::path(step["step"].get<std::string>()).filename().string());
            EXPECT_NE(step["reason"].get<std::string>().find(stepName(kDamaged) + ": expected"), std::string::npos)
                << step.dump();
        }
    }
    const nlohmann::json& end = lines.back()["follow_end"];
    EXPECT_EQ(end["why"], "stop file") << end.dump();
    EXPECT_EQ(end["frames"], kSteps - 1);
    EXPECT_TRUE(end["skipped"].empty()) << end.dump();
    std::vector<std::string> expected;
    for (int s = 0; s < kSteps; ++s)
        if (s != kDamaged) expected.push_back(stepName(s));
    EXPECT_EQ(shown, expected);
    EXPECT_EQ(skipped, std::vector<std::string>{stepName(kDamaged)});
    // Each frame shows its own step's data: the exported temperature is that step's T.
    const eikon::GridSpec cell{{1, 1, 1}, {0.1, 0.1, 0.1}, {0.1625, 0.1625, 0.1625}};
    for (std::size_t frame = 0; frame < expected.size(); ++frame) {
        char name[64];
        std::snprintf(name, sizeof name, "fields_%05d.vdb", static_cast<int>(frame));
        const int step = std::stoi(expected[frame].substr(5, 3));
        const eikon::io::VdbVolumeFile file(out / "vdb" / name);
        EXPECT_FLOAT_EQ(file.sample("temperature", 1, cell, {0, 0, 0})[0], 300.0f + 10.0f * float(step))
            << "frame " << frame;
        std::snprintf(name, sizeof name, "frame_%05d.png", static_cast<int>(frame));
        EXPECT_TRUE(fs::exists(out / "frames" / name)) << name;
    }
}

// --follow needs a volume a simulation adds steps to: a single file, or no
// volume, is refused (exit 2, nothing written); so is a series whose first
// step never completes before the timeout, naming why.
TEST_F(FollowCli, FollowIsRefusedWithoutATimeSeriesOrAFirstStep) {
    const std::string plain = writeScene("plain.json", eikon::test::kSmallSphereScene);
    const fs::path out = dir_ / "out";
    const Outcome noVolume = eikon::test::runEikon("run " + plain + " --out " + out.string() + " --follow --quiet");
    EXPECT_EQ(noVolume.exitCode, 2) << noVolume.output;
    EXPECT_NE(noVolume.output.find("plain.json: --follow: expected a scene whose volume.path is a VTK time series"),
              std::string::npos)
        << noVolume.output;
    EXPECT_FALSE(fs::exists(out));

    std::string text = eikon::test::kSmallSphereScene;
    text.insert(text.rfind('}'), R"(, "volume": {"path": "run.vti.series",
        "fields": {"temperature": "T", "temperature_unit": "kelvin"}})");
    const std::string scene = writeScene("follow.json", text);
    std::ofstream(dir_ / stepName(0)) << "not VTK";
    std::ofstream(dir_ / "run.vti.series") << R"({"files": [{"name": ")" << stepName(0) << R"(", "time": 0}]})";
    const Outcome none = eikon::test::runEikonWithin(
        300, "run " + scene + " --out " + out.string() + " --follow --follow-poll-ms 10 --follow-timeout 0.5");
    EXPECT_EQ(none.exitCode, 2) << none.output;
    EXPECT_NE(none.output.find("follow.json: volume.path (followed): expected a complete step of \"" +
                               (dir_ / "run.vti.series").string() + "\" before following ended, found none before "
                               "the timeout; skipped " + (dir_ / stepName(0)).string()),
              std::string::npos)
        << none.output;
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
