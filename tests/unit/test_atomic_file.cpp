// Atomic writes say why they failed in the OS's own words: a rename over a
// folder that holds files reports "Is a directory", not the outcome of the
// cleanup that followed ("Success"), and leaves no temporary behind.
#include "io/files/AtomicFile.h"
#include "io/files/OutputFolder.h"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace eikon::io {
namespace {

namespace fs = std::filesystem;

class AtomicFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() /
                ("eikon_atomic_test_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(root_);
        fs::create_directories(root_);
    }
    void TearDown() override { fs::remove_all(root_); }

    // `write` fails; its message names `target` and the OS's reason for a
    // rename over a folder, and no temporary is left beside it.
    template <typename Write>
    void expectRenameOverAFolderFails(const fs::path& target, Write&& write) {
        fs::create_directories(target / "inside");
        try {
            write();
            ADD_FAILURE() << "renamed over a folder that holds files";
        } catch (const std::runtime_error& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find(target.string() + ": cannot rename into place"), std::string::npos) << message;
            EXPECT_NE(message.find(std::strerror(EISDIR)), std::string::npos) << message;
            EXPECT_EQ(message.find("Success"), std::string::npos) << message;
        }
        for (const auto& entry : fs::directory_iterator(target.parent_path()))
            EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
    }
    fs::path root_;
};

TEST_F(AtomicFileTest, AFailedRenameSaysWhyByPath) {
    const fs::path target = root_ / "report.jsonl";
    expectRenameOverAFolderFails(target, [&] { writeFileAtomically(target, "{}\n"); });
}

TEST_F(AtomicFileTest, AFailedRenameSaysWhyInAnOutputFolder) {
    OutputFolder folder(root_ / "out", false);
    const fs::path target = root_ / "out" / "report.jsonl";
    expectRenameOverAFolderFails(target, [&] { folder.appendReport("{}"); });
    const fs::path streamed = root_ / "out" / "streamed.vti";
    expectRenameOverAFolderFails(streamed, [&] {
        const fs::path temporary = temporaryPathFor(streamed);
        std::ofstream(temporary) << "a streamed file";
        commitTemporary(temporary, streamed, true);
    });
}

}  // namespace
}  // namespace eikon::io
