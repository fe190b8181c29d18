// The progress line: shown on a terminal, absent from logs.
#include <gtest/gtest.h>

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
    EXPECT_NE(tty.find("/240000 px"), std::string::npos) << tty;  // both passes counted
    // The line is cleared before the summary.
    EXPECT_NE(tty.find("\r\033[Kpovwall: "), std::string::npos) << tty;
    EXPECT_TRUE(std::filesystem::exists(out));
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
