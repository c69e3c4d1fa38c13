// Outputs are written through temporary files: a signal mid-write removes them, and a set of files
// is replaced whole or not at all.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "error.h"
#include "gltf_test_helpers.h"
#include "io/image_io.h"
#include "io/temporary_files.h"

namespace vct {
namespace {

namespace fs = std::filesystem;
using test::TempFolder;

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(TemporaryFiles, SignalWhileWritingRemovesTheTemporaryFileAndEndsTheProcess) {
    // The child writes 1 MiB into OUT.tmp.PID, which the test made a FIFO that it reads only a
    // little of: the child is then blocked inside the write, with the temporary file in place,
    // when the signal comes.
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
        TempFolder folder;
        const fs::path out = folder.path / "out.pfm";
        std::ofstream(out) << "the earlier image";
        int go[2];
        ASSERT_EQ(pipe(go), 0);
        const pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            installTemporaryFileCleanup();
            char start = 0;
            if (read(go[0], &start, 1) != 1) _exit(3);
            try {
                writeFileAtomically(out.string(), std::string(1 << 20, 'x'));
            } catch (...) {
                _exit(4);
            }
            _exit(0);
        }
        const fs::path temporary = out.string() + ".tmp." + std::to_string(child);
        ASSERT_EQ(mkfifo(temporary.c_str(), 0600), 0);
        const int reader = open(temporary.c_str(), O_RDONLY | O_NONBLOCK);
        ASSERT_GE(reader, 0);
        ASSERT_EQ(write(go[1], "g", 1), 1);
        pollfd readable{reader, POLLIN, 0};
        ASSERT_EQ(poll(&readable, 1, 30000), 1) << "the child never wrote";
        char some[256];
        ASSERT_GT(read(reader, some, sizeof some), 0);
        ASSERT_EQ(kill(child, signal), 0);
        int status = 0;
        ASSERT_EQ(waitpid(child, &status, 0), child);
        close(reader);
        close(go[0]);
        close(go[1]);
        EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "status " << status;
        EXPECT_FALSE(fs::exists(fs::symlink_status(temporary))) << "the temporary file was left behind";
        EXPECT_EQ(readText(out), "the earlier image");
    }
}

TEST(TemporaryFiles, ASetIsReplacedWholeOrNotAtAll) {
    TempFolder folder;
    const fs::path first = folder.path / "bench.csv", second = folder.path / "no-such-folder" / "bench.json";
    std::ofstream(first) << "old";
    EXPECT_THROW(writeFilesAtomically({{first.string(), "new"}, {second.string(), "new"}}), Error);
    EXPECT_EQ(readText(first), "old");
    EXPECT_EQ(std::distance(fs::directory_iterator(folder.path), fs::directory_iterator()), 1)
        << "a temporary file was left behind";
    EXPECT_TRUE(registeredTemporaryFiles().empty());

    const fs::path third = folder.path / "bench.svg";
    writeFilesAtomically({{first.string(), "new csv"}, {third.string(), "new svg"}});
    EXPECT_EQ(readText(first), "new csv");
    EXPECT_EQ(readText(third), "new svg");
    EXPECT_TRUE(registeredTemporaryFiles().empty());
}

}  // namespace
}  // namespace vct
