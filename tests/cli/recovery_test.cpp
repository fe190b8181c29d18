// A worker process killed at a random moment: its work goes to the other workers and the
// image is the one an undisturbed render gives (issue 11).
#include <gtest/gtest.h>

#include <random>

#include "tests/cli/run_povwall.h"

namespace {

using namespace povwall_test;
namespace fs = std::filesystem;

struct KilledRun {
    int code;
    std::string err;
    bool killed;  // a worker was found and killed before the render ended
};

// Starts `povwall ARGS` in the background, waits until it has started worker processes,
// sleeps `delay_ms`, kills one worker with SIGKILL and waits for the render.
KilledRun render_and_kill_a_worker(const std::string& args, int delay_ms) {
    const fs::path err = scratch() / "killed.err", mark = scratch() / "killed.mark";
    fs::remove(mark);
    const std::string script = std::string(POVWALL_BINARY) + " " + args + " 2>" +
                               err.string() +
                               " & R=$!; n=0; "
                               "until W=$(pgrep -P $R | head -1); [ -n \"$W\" ]; do "
                               "n=$((n+1)); [ $n -gt 500 ] && break; sleep 0.01; done; "
                               "sleep " +
                               std::to_string(delay_ms / 1000.0) + "; " +
                               "[ -n \"$W\" ] && kill -9 $W 2>/dev/null && touch " +
                               mark.string() + "; " + "wait $R";
    const int status = std::system(("sh -c '" + script + "'").c_str());
    return {WEXITSTATUS(status), slurp(err), fs::exists(mark)};
}

int random_delay_ms() {
    std::random_device rd;
    return std::uniform_int_distribution<int>(0, 150)(rd);
}

class Recovery : public ::testing::TestWithParam<std::string> {};

TEST_P(Recovery, WorkerKilledAtARandomMomentGivesTheUndisturbedImage) {
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    const fs::path alone = scratch() / "alone.exr", killed = scratch() / "killed.exr";
    ASSERT_EQ(
        run("render " + scene + " -W 320 -H 240 -q --mode single -o " + alone.string())
            .code,
        0);
    const int delay = random_delay_ms();
    const KilledRun r = render_and_kill_a_worker(
        "render " + scene + " -W 320 -H 240 -q " + GetParam() + " -o " + killed.string(),
        delay);
    ASSERT_TRUE(r.killed) << "no worker to kill";
    ASSERT_EQ(r.code, 0) << "killed after " << delay << " ms: " << r.err;
    // Black boxes add forward contributions in another order: equal to float rounding.
    RunResult d = run("diff " + alone.string() + " " + killed.string() + " --max-rmse 1e-6");
    EXPECT_EQ(d.code, 0) << "killed after " << delay << " ms: " << d.out;
    // Said on stderr when the kill landed before the worker's last piece of work.
    if (!r.err.empty()) {
        EXPECT_NE(r.err.find("went to the other workers"), std::string::npos) << r.err;
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, Recovery,
                         ::testing::Values("--mode screen --procs 3",
                                           "--boxes 2x2x2 --procs 3"),
                         [](const auto& param_info) {
                             return param_info.param.find("screen") != std::string::npos
                                        ? std::string("ScreenTiles")
                                        : std::string("BoxesOverTcp");
                         });

}  // namespace
