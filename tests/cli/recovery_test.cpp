// A worker process killed at a random moment: its work goes to the other workers and the
// image is the one an undisturbed render gives (issue 11). The coordinator itself kills
// the worker (POVWALL_FAULT_KILL_WORKER, distrib/child_process.h), so the test does not
// depend on finding worker processes from outside.
#include <gtest/gtest.h>
#include <sched.h>

#include <chrono>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/run_povwall.h"

namespace {

using namespace povwall_test;
namespace fs = std::filesystem;

class Recovery : public ::testing::TestWithParam<std::string> {};

TEST_P(Recovery, WorkerKilledAtARandomMomentGivesTheUndisturbedImage) {
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    const fs::path alone = scratch() / "alone.exr", killed = scratch() / "killed.exr";
    ASSERT_EQ(
        run("render " + scene + " -W 320 -H 240 -q --mode single -o " + alone.string())
            .code,
        0);
    std::random_device rd;
    const int worker = std::uniform_int_distribution<int>(0, 2)(rd);
    const int delay_ms = std::uniform_int_distribution<int>(0, 150)(rd);
    const std::string fault = "POVWALL_FAULT_KILL_WORKER=" + std::to_string(worker) +
                              "," + std::to_string(delay_ms);
    const std::string cmd_line = fault + " " + std::string(POVWALL_BINARY) + " render " +
                                 scene + " -W 320 -H 240 -q " + GetParam() + " -o " +
                                 killed.string();
    const fs::path err = scratch() / "killed.err";
    const int status = std::system((cmd_line + " 2>" + err.string()).c_str());
    const std::string what = "worker " + std::to_string(worker) + " killed after " +
                             std::to_string(delay_ms) + " ms: " + slurp(err);
    ASSERT_EQ(WEXITSTATUS(status), 0) << what;
    // Black boxes add forward contributions in another order: equal to float rounding.
    RunResult d =
        run("diff " + alone.string() + " " + killed.string() + " --max-rmse 1e-6");
    EXPECT_EQ(d.code, 0) << what << d.out;
    // The kill lands before the worker's last piece of work unless the render is faster
    // than the delay; then nothing was lost and nothing is said.
    const std::string said = slurp(err);
    if (!said.empty()) {
        EXPECT_NE(said.find("went to the other workers"), std::string::npos) << what;
    }
}

// A worker that hangs (SIGSTOP: alive, pipes and sockets open, silent) at a random
// moment, while parsing or tracing: it is found by its missing heartbeats within the 4 s
// timeout, killed, and its work goes to the others.
TEST_P(Recovery, WorkerHungAtARandomMomentIsFoundKilledAndGivesTheUndisturbedImage) {
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    const fs::path alone = scratch() / "alone-h.exr", hung = scratch() / "hung.exr";
    ASSERT_EQ(
        run("render " + scene + " -W 320 -H 240 -q --mode single -o " + alone.string())
            .code,
        0);
    std::random_device rd;
    const int worker = std::uniform_int_distribution<int>(0, 2)(rd);
    const int delay_ms = std::uniform_int_distribution<int>(0, 150)(rd);
    const std::string fault = "POVWALL_FAULT_STOP_WORKER=" + std::to_string(worker) +
                              "," + std::to_string(delay_ms);
    const fs::path err = scratch() / "hung.err";
    const auto t0 = std::chrono::steady_clock::now();
    const int status =
        std::system((fault + " " + std::string(POVWALL_BINARY) + " render " + scene +
                     " -W 320 -H 240 -q " + GetParam() + " -o " + hung.string() + " 2>" +
                     err.string())
                        .c_str());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::string what = "worker " + std::to_string(worker) + " stopped after " +
                             std::to_string(delay_ms) + " ms: " + slurp(err);
    ASSERT_EQ(WEXITSTATUS(status), 0) << what;
    RunResult d =
        run("diff " + alone.string() + " " + hung.string() + " --max-rmse 1e-6");
    EXPECT_EQ(d.code, 0) << what << d.out;
    const std::string said = slurp(err);
    if (!said.empty()) {
        EXPECT_TRUE(said.find("sent nothing for 4 s (hung): killed") !=
                        std::string::npos ||
                    said.find("no message for 4 s") != std::string::npos)
            << what;
        EXPECT_NE(said.find("went to the other workers"), std::string::npos) << what;
        EXPECT_EQ(said.find("coordinator lost"), std::string::npos) << what;
    }
    // Not a speed bar: a hang must not wait for a parse-sized timeout (minutes).
    EXPECT_LT(seconds, 60.0) << what;
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

namespace {

using namespace povwall_test;
namespace fs = std::filesystem;

// Forked workers are up within milliseconds: one killed right after its start may be
// found first by a peer that cannot connect to it. That is its loss too (it used to end
// the render as a job the peer refused): the frame is traced again without it.
TEST(Recovery, WorkerKilledWhileThePeersConnectIsReplaced) {
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    const fs::path alone = scratch() / "start_alone.exr",
                   killed = scratch() / "start.exr";
    ASSERT_EQ(
        run("render " + scene + " -W 160 -H 120 -q --boxes 2x2x2 -o " + alone.string())
            .code,
        0);
    for (const char* fault : {"2,0", "2,2", "2,5", "1,2", "1,5"}) {
        const fs::path err = scratch() / "start.err";
        const std::string cmd = std::string("POVWALL_FAULT_KILL_WORKER=") + fault + " " +
                                POVWALL_BINARY + " render " + scene +
                                " -W 160 -H 120 -q --boxes 2x2x2 --procs 3 -o " +
                                killed.string() + " 2>" + err.string();
        const int status = std::system(cmd.c_str());
        const std::string said = slurp(err);
        ASSERT_EQ(WEXITSTATUS(status), 0) << fault << ": " << said;
        EXPECT_EQ(
            run("diff " + alone.string() + " " + killed.string() + " --max-rmse 1e-6")
                .code,
            0)
            << fault;
        if (!said.empty()) {
            EXPECT_NE(said.find("went to the other workers"), std::string::npos) << said;
        }
    }
}

// Without recovery a lost worker ends the render with exit code 3 and no image, in screen
// mode as over TCP (README: exit codes).
TEST(Recovery, ALostWorkerWithoutRecoveryExitsThreeInEveryMode) {
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    for (const std::string mode :
         {"--mode screen --procs 2", "--boxes 2x1x1 --procs 2"}) {
        const fs::path out = scratch() / "lost.png", err = scratch() / "lost.err";
        fs::remove(out);
        const std::string cmd = "POVWALL_FAULT_KILL_WORKER=1,0 " +
                                std::string(POVWALL_BINARY) + " render " + scene +
                                " -W 160 -H 120 -q --no-recover " + mode + " -o " +
                                out.string() + " 2>" + err.string();
        const int status = std::system(cmd.c_str());
        const std::string said = slurp(err);
        EXPECT_EQ(WEXITSTATUS(status), 3) << mode << ": " << said;
        EXPECT_NE(said.find("(no image written)"), std::string::npos) << mode << said;
        EXPECT_FALSE(fs::exists(out)) << mode;
    }
}

// A worker that receives items for a box it does not host (a peer's bug or a corrupted
// stream) refuses the frame and names its sender to the coordinator, which takes the
// sender as lost: without recovery the render ends with exit code 3 naming the sender and
// writes nothing; with recovery the sender is left out and the image is the undisturbed
// one.
TEST(Recovery, ItemsForABoxTheReceiverDoesNotHostEndTheRenderNamingTheSender) {
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    const fs::path out = scratch() / "misrouted.png", err = scratch() / "misrouted.err";
    fs::remove(out);
    const std::string cmd = "POVWALL_FAULT_MISROUTE=20 " + std::string(POVWALL_BINARY) +
                            " render " + scene +
                            " -W 160 -H 120 -q --no-recover --boxes 2x1x1 --procs 2 "
                            "--worker-start exec -o " +
                            out.string() + " 2>" + err.string();
    const int status = std::system(cmd.c_str());
    const std::string said = slurp(err);
    EXPECT_EQ(WEXITSTATUS(status), 3) << said;
    EXPECT_NE(
        said.find("povwall worker 1: worker 0 sent worker 1 a malformed item frame, "
                  "or items for a box not hosted here\n"),
        std::string::npos)
        << said;
    EXPECT_NE(said.find("povwall: error: worker 0 ("), std::string::npos) << said;
    EXPECT_NE(said.find("): sent worker 1 a malformed item frame, or items for a box not "
                        "hosted here"),
              std::string::npos)
        << said;
    EXPECT_FALSE(fs::exists(out));
}

TEST(Recovery, ASenderOfItemsForABoxTheReceiverDoesNotHostIsLeftOut) {
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    const fs::path alone = scratch() / "misrouted_alone.exr",
                   out = scratch() / "misrouted_recovered.exr",
                   err = scratch() / "misrouted_recovered.err";
    ASSERT_EQ(
        run("render " + scene + " -W 160 -H 120 -q --mode single -o " + alone.string())
            .code,
        0);
    const std::string cmd = "POVWALL_FAULT_MISROUTE=20 " + std::string(POVWALL_BINARY) +
                            " render " + scene +
                            " -W 160 -H 120 -q --boxes 2x1x1 --procs 2 "
                            "--worker-start exec -o " +
                            out.string() + " 2>" + err.string();
    const int status = std::system(cmd.c_str());
    const std::string said = slurp(err);
    ASSERT_EQ(WEXITSTATUS(status), 0) << said;
    EXPECT_NE(said.find("povwall: worker 0 ("), std::string::npos) << said;
    EXPECT_NE(
        said.find("its boxes went to the other workers; the frame is traced again on "
                  "1 worker process\n"),
        std::string::npos)
        << said;
    RunResult d = run("diff " + alone.string() + " " + out.string() + " --max-rmse 1e-6");
    EXPECT_EQ(d.code, 0) << said << d.out;
}

// Ctrl-C reaches the whole process group: the worker processes end quietly and the
// coordinator alone says what was kept; no worker is left behind. The render with --procs
// restarts itself (huge-page heap) first: a Ctrl-C during that exec must not end it
// silently (Interrupt.ArrivingDuringTheRestartIsStillReported).
TEST(Interrupt, WorkersEndQuietlyAndOnlyTheCoordinatorSpeaks) {
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    for (const std::string mode :
         {"--boxes 2x1x1 --procs 2", "--mode screen --procs 2"}) {
        const fs::path err = scratch() / "interrupt.err",
                       pid = scratch() / "interrupt.pid";
        const fs::path out = scratch() / "interrupt.png";
        const std::string start = "setsid " + std::string(POVWALL_BINARY) + " render " +
                                  scene + " +KFF200 -W 320 -H 240 -q " + mode + " -o " +
                                  out.string() + " 2>" + err.string() + " & echo $! >" +
                                  pid.string() + "; wait";
        // Ctrl-C once the workers run (a fixed wait was too short for two starts under
        // ASan on a busy machine), and some frames into the render.
        fs::remove(pid);
        const std::string p = pid.string();
        const std::string cmd =
            "sh -c '(" + start + ") & i=0; until [ -s " + p + " ] && pgrep -P $(cat " +
            p + ") >/dev/null || [ $i -ge 600 ]; do sleep 0.05; i=$((i+1)); done; " +
            "sleep 0.5; /bin/kill -s INT -- -$(cat " + p + "); sleep 1.5'";
        ASSERT_EQ(std::system(cmd.c_str()), 0) << mode;
        const std::string said = slurp(err);
        // One line, the coordinator's, naming the frame and the phase it was in (it may
        // have been between frames, or writing or just written a frame's image).
        const std::string phase =
            R"((parsing .*/walls\.pov:[0-9]+|preparing the scene \([0-9,]+ objects?\)|)"
            R"(building the octree \([0-9,]+ primitives?\)|)"
            R"(tracing: [0-9,]+ of 76,800 pixels \([0-9.]+ %\)))";
        const std::string image = R"(.*/interrupt[0-9]+\.png)";
        EXPECT_TRUE(std::regex_match(
            said, std::regex("\npovwall: (interrupted: no image written|frame [0-9]+: "
                             "interrupted (while " +
                             phase + "; no image written|while writing " + image +
                             "(: the partly written image was removed)?; no image "
                             "written|after writing " +
                             image + ", which is complete))\n")))
            << mode << ": " << said;
        // Nothing of this render still runs (the bracket keeps pgrep's own shell, whose
        // command line holds the pattern, from matching it).
        const std::string left =
            "pgrep -f -- '" + scratch().string() + "/interrupt[.]png' >/dev/null";
        EXPECT_NE(std::system(left.c_str()), 0) << mode;
    }
}

// Local worker processes share the cores: they run as batch tasks (policy 3 in
// /proc/PID/stat), so a worker that sends rays is not preempted by the one it wakes.
TEST(Procs, LocalWorkersRunAsBatchTasks) {
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    for (const std::string start_mode : {"", " --worker-start exec"}) {
        const fs::path pid = scratch() / "batch.pid", policies = scratch() / "batch.txt";
        fs::remove(pid);
        fs::remove(policies);
        const std::string start =
            "setsid " + std::string(POVWALL_BINARY) + " render " + scene +
            " +KFF100 -W 320 -H 240 -q --boxes 2x1x1 --procs 2" + start_mode + " -o " +
            (scratch() / "batch.png").string() + " 2>/dev/null & echo $! >" +
            pid.string() + "; wait";
        const std::string p = pid.string();
        const std::string cmd =
            "sh -c '(" + start + ") & i=0; until [ -s " + p +
            " ] && [ $(pgrep -P $(cat " + p +
            ") | wc -l) -ge 2 ] || [ $i -ge 600 ]; do sleep 0.05; i=$((i+1)); done; " +
            "sleep 0.3; for c in $(pgrep -P $(cat " + p +
            ")); do cut -d\\  -f41 /proc/$c/stat; done >" + policies.string() +
            "; /bin/kill -s INT -- -$(cat " + p + "); wait'";
        ASSERT_EQ(std::system(cmd.c_str()), 0) << start_mode;
        EXPECT_EQ(slurp(policies), "3\n3\n") << start_mode;
    }
}

// Local workers that outnumber the cores are each kept on one core, both cores in use;
// with --worker-cores off, or a core each, the system places them.
TEST(Procs, CrowdedLocalWorkersAreKeptOnCores) {
    cpu_set_t allowed;
    ASSERT_EQ(sched_getaffinity(0, sizeof allowed, &allowed), 0);
    const int cores = CPU_COUNT(&allowed);
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    for (const std::string extra : {"", " --worker-start exec", " --worker-cores off"}) {
        const fs::path pid = scratch() / "cores.pid", lists = scratch() / "cores.txt";
        fs::remove(pid);
        fs::remove(lists);
        const std::string start = "setsid " + std::string(POVWALL_BINARY) + " render " +
                                  scene +
                                  " +KFF100 -W 320 -H 240 -q --boxes 2x2x1 --procs 4" +
                                  extra + " -o " + (scratch() / "cores.png").string() +
                                  " 2>/dev/null & echo $! >" + pid.string() + "; wait";
        const bool pinned =
            cores >= 2 && cores < 4 && extra.find("off") == std::string::npos;
        const std::string p = pid.string();
        // The workers are kept on cores once a quarter of the first frame is out: read
        // until every list is one CPU (or 10 s, under a sanitizer), then once more.
        const std::string read_lists = "for c in $(pgrep -P $(cat " + p +
                                       ")); do grep Cpus_allowed_list /proc/$c/status | "
                                       "cut -f2; done >" +
                                       lists.string();
        const std::string cmd =
            "sh -c '(" + start + ") & i=0; until [ -s " + p +
            " ] && [ $(pgrep -P $(cat " + p +
            ") | wc -l) -ge 4 ] || [ $i -ge 600 ]; do sleep 0.05; i=$((i+1)); done; " +
            "sleep 0.3; i=0; " + read_lists + "; " +
            (pinned ? "until ! grep -q \"[^0-9]\" " + lists.string() +
                          " || [ $i -ge 100 ]; do sleep 0.1; i=$((i+1)); " + read_lists +
                          "; done; "
                    : std::string()) +
            "/bin/kill -s INT -- -$(cat " + p + "); wait'";
        ASSERT_EQ(std::system(cmd.c_str()), 0) << extra;
        std::istringstream in(slurp(lists));
        std::vector<std::string> each;
        for (std::string line; std::getline(in, line);) each.push_back(line);
        ASSERT_EQ(each.size(), 4u) << extra;
        std::set<std::string> used(each.begin(), each.end());
        if (pinned) {
            for (const std::string& l : each) {
                EXPECT_EQ(l.find_first_not_of("0123456789"), std::string::npos)
                    << extra << ": " << l;  // one CPU
            }
            EXPECT_EQ(int(used.size()), cores) << extra;
        } else {
            EXPECT_EQ(used.size(), 1u) << extra;  // all alike: the render's own set
            EXPECT_EQ(int(used.size()) == 1 && cores > 1,
                      each[0].find_first_not_of("0123456789") != std::string::npos)
                << extra << ": " << each[0];
        }
    }
}

// A render that forks its workers first executes itself again with the huge-page heap.
// Between that exec and main() setting the handler, a Ctrl-C used to find the default
// disposition and end the render without a word; now it waits, blocked, and is reported.
TEST(Interrupt, ArrivingDuringTheRestartIsStillReported) {
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    const fs::path err = scratch() / "restart_interrupt.err",
                   out = scratch() / "restart_interrupt.png";
    fs::remove(out);
    const std::string cmd = std::string("POVWALL_FAULT_INTERRUPT_AT_RESTART=1 ") +
                            POVWALL_BINARY + " render " + scene +
                            " -W 16 -H 16 -q --boxes 2x1x1 --procs 2 -o " + out.string() +
                            " 2>" + err.string();
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << "ended by a signal, silently";
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
    EXPECT_EQ(slurp(err), "\npovwall: interrupted: no image written\n");
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
