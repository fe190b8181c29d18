// The progress line: shown on a terminal, absent from logs.
#include <gtest/gtest.h>

#include <regex>

#include "tests/cli/run_povwall.h"

namespace {

using namespace povwall_test;

// A render of a second or more at one thread (anti-aliasing on every pixel).
std::string long_render(const std::string& out) {
    return std::string("render ") + POVWALL_SOURCE_DIR +
           "/scenes/demo/walls.pov -W 400 -H 300 +A0.0 +R3 --threads 1 -o " + out;
}

TEST(Progress, TerminalShowsShareRaysPerSecondAndTimeLeft) {
    if (std::system("command -v script >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "script(1) is not installed: no pseudo-terminal to test with";
    const auto out = scratch() / "progress.png";
    const auto log = scratch() / "tty.log";
    // script(1) runs povwall on a pseudo-terminal and copies what it printed.
    const std::string cmd = "script -qec \"" + std::string(POVWALL_BINARY) + " " +
                            long_render(out.string()) + "\" /dev/null >" + log.string();
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const std::string tty = slurp(log);
    EXPECT_NE(tty.find("% ["), std::string::npos) << tty;
    EXPECT_NE(tty.find(" M rays/s  ETA "), std::string::npos) << tty;
    // The image's pixels once: a render block counts when done, anti-aliasing included.
    EXPECT_NE(tty.find("/120000 px"), std::string::npos) << tty;
    EXPECT_EQ(tty.find("/240000 px"), std::string::npos) << tty;
    // The line is cleared before the summary.
    EXPECT_NE(tty.find("\r\033[Kpovwall: "), std::string::npos) << tty;
    EXPECT_TRUE(std::filesystem::exists(out));
}

// Black boxes, in one process and over TCP: the share is the pixels sent scaled by the
// items finished, and reaches the whole image. (800x600: the line first shows after half
// a second, and 400x300 in one process took less.)
TEST(Progress, BlackBoxesShowTheLineInProcessAndOverTcp) {
    if (std::system("command -v script >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "script(1) is not installed: no pseudo-terminal to test with";
    for (const std::string mode : {"--threads 1", "--procs 2"}) {
        const auto out = scratch() / "progress-boxes.png";
        const auto log = scratch() / "tty-boxes.log";
        const std::string cmd =
            "script -qec \"" + std::string(POVWALL_BINARY) + " render " +
            POVWALL_SOURCE_DIR + "/scenes/demo/walls.pov -W 800 -H 600 --boxes 2x2x2 " +
            mode + " -o " + out.string() + "\" /dev/null >" + log.string();
        ASSERT_EQ(std::system(cmd.c_str()), 0) << mode;
        const std::string tty = slurp(log);
        EXPECT_NE(tty.find("/480000 px"), std::string::npos) << mode << tty;
        EXPECT_NE(tty.find(" M rays/s  ETA "), std::string::npos) << mode << tty;
        // Every sample within the image, never going back.
        std::regex sample("([0-9]+)/480000 px");
        long last = 0;
        int samples = 0;
        for (auto it = std::sregex_iterator(tty.begin(), tty.end(), sample);
             it != std::sregex_iterator(); ++it, ++samples) {
            const long n = std::stol((*it)[1].str());
            EXPECT_LE(n, 480000) << mode;
            EXPECT_GE(n, last) << mode;
            last = n;
        }
        EXPECT_GE(samples, 1) << mode;
    }
}

TEST(Progress, LogsAndPipesStayQuiet) {
    const auto out = scratch() / "quiet.png";
    RunResult r = run(long_render(out.string()));
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("rays/s"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.rfind("povwall: ", 0), 0u) << r.err;  // only the summary line
}

}  // namespace
