// The framer (issue 8): an animation on black boxes over TCP keeps its worker processes
// from frame to frame and sends them only the new animation values; every frame must
// still be the frame rendered alone.
#include <gtest/gtest.h>

#include <random>
#include <regex>

#include "tests/cli/run_povwall.h"

namespace {

using namespace povwall_test;
namespace fs = std::filesystem;

// Moves with the clock and changes colour with the frame number, so a worker that kept
// the previous frame's scene gives a wrong image.
const char* kOrbit = R"(
camera { location <0, 2, -5> look_at 0 }
light_source { <3, 5, -4> color rgb 1 }
sphere { <cos(clock * 2 * pi), 0, sin(clock * 2 * pi)>, 0.5
  pigment { color rgb <1, frame_number / 6, 0.2> } finish { reflection 0.3 } }
box { -1, 1 scale <2, 0.05, 2> translate -0.6 * y pigment { checker color rgb 1 color rgb 0.2 } }
)";

std::string frame_file(const fs::path& dir, const std::string& stem, int f) {
    return (dir / (stem + std::to_string(f) + ".exr")).string();
}

// Black boxes add forward contributions in another order: equal to float rounding.
bool same_image(const std::string& a, const std::string& b, std::string* out) {
    RunResult d = run("diff " + a + " " + b + " --max-rmse 1e-6");
    *out = d.out;
    return d.code == 0;
}

TEST(Framer, AnimationKeepsItsTcpWorkersAndEachFrameEqualsItsRenderAlone) {
    const fs::path dir = scratch() / "framer";
    fs::create_directories(dir);
    const fs::path scene = write_scene("orbit.pov", kOrbit);
    const std::string frames = " +KFI1 +KFF5 -W 48 -H 36 -q ";
    const fs::path stats = dir / "stats.json";
    RunResult r =
        run("render " + scene.string() + frames + "--boxes 2x1x1 --procs 2 --stats " +
            stats.string() + " -o " + (dir / "tcp.exr").string());
    ASSERT_EQ(r.code, 0) << r.err;
    // The last frame's statistics: five frames on the two processes started for the
    // first.
    const std::string s = slurp(stats);
    EXPECT_NE(s.find("\"frames_on_these_workers\": 5"), std::string::npos) << s;
    EXPECT_NE(s.find("\"processes_started\": 2"), std::string::npos) << s;
    // Each worker's peak resident memory: a live process, not a placeholder.
    std::smatch peaks;
    ASSERT_TRUE(std::regex_search(
        s, peaks,
        std::regex("\"peak_resident_bytes\": \\[\\s*([0-9]+),\\s*([0-9]+)\\s*\\]")))
        << s;
    for (int k = 1; k <= 2; ++k) {
        EXPECT_GT(std::stod(peaks[k].str()), 1e6) << s;
        EXPECT_LT(std::stod(peaks[k].str()), 4e9) << s;
    }
    r = run("render " + scene.string() + frames + "--mode single -o " +
            (dir / "alone.exr").string());
    ASSERT_EQ(r.code, 0) << r.err;
    std::string why;
    for (int f = 1; f <= 5; ++f) {
        EXPECT_TRUE(
            same_image(frame_file(dir, "tcp", f), frame_file(dir, "alone", f), &why))
            << "frame " << f << ": " << why;
    }
    // The frames differ from each other, so the comparison above can fail.
    EXPECT_FALSE(same_image(frame_file(dir, "tcp", 2), frame_file(dir, "tcp", 3), &why));
}

TEST(Framer, WorkerKilledDuringASequenceIsReplacedAndEveryFrameIsWhole) {
    const fs::path dir = scratch() / "framer-kill";
    fs::create_directories(dir);
    const fs::path scene = write_scene("orbit-kill.pov", kOrbit);
    const std::string frames = " +KFI1 +KFF6 -W 48 -H 36 -q ";
    std::random_device rd;
    const int worker = std::uniform_int_distribution<int>(0, 2)(rd);
    const int delay_ms = std::uniform_int_distribution<int>(0, 300)(rd);
    const fs::path err = dir / "err";
    const std::string cmd = "POVWALL_FAULT_KILL_WORKER=" + std::to_string(worker) + "," +
                            std::to_string(delay_ms) + " " + POVWALL_BINARY + " render " +
                            scene.string() + frames + "--boxes 3x1x1 --procs 3 -o " +
                            (dir / "tcp.exr").string() + " 2>" + err.string();
    const int status = std::system(cmd.c_str());
    const std::string what = "worker " + std::to_string(worker) + " killed after " +
                             std::to_string(delay_ms) + " ms: " + slurp(err);
    ASSERT_EQ(WEXITSTATUS(status), 0) << what;
    RunResult r = run("render " + scene.string() + frames + "--mode single -o " +
                      (dir / "alone.exr").string());
    ASSERT_EQ(r.code, 0) << r.err;
    std::string why;
    for (int f = 1; f <= 6; ++f) {
        EXPECT_TRUE(
            same_image(frame_file(dir, "tcp", f), frame_file(dir, "alone", f), &why))
            << what << "frame " << f << ": " << why;
    }
    const std::string said = slurp(err);
    if (!said.empty()) {
        EXPECT_NE(said.find("went to the other workers"), std::string::npos) << what;
    }
}

// A caustic that moves with the clock, and a frame without photons between: each frame's
// photon map goes to the kept workers, and none is left from the frame before.
const char* kMovingCaustic = R"(#version 3.7;
#if (frame_number != 2)
global_settings { max_trace_level 10 photons { spacing 0.03 } }
#end
camera { location <0, 4, -4> look_at <0, 0.3, 0> angle 40 }
light_source { <1, 7, 1> color rgb 1.2 }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.6 } }
sphere { <clock - 0.5, 1, 0>, 0.8
  pigment { rgbf <0.95, 1, 0.95, 0.95> } interior { ior 1.5 }
  photons { target refraction on reflection on } }
)";

TEST(Framer, EachFramesPhotonMapReachesTheKeptWorkers) {
    const fs::path dir = scratch() / "framer-photons";
    fs::create_directories(dir);
    const fs::path scene = write_scene("caustic.pov", kMovingCaustic);
    const std::string frames = " +KFI1 +KFF3 -W 40 -H 30 -q ";
    RunResult r = run("render " + scene.string() + frames +
                      "--boxes 2x1x1 --procs 2 -o " + (dir / "tcp.exr").string());
    ASSERT_EQ(r.code, 0) << r.err;
    r = run("render " + scene.string() + frames + "--mode single -o " +
            (dir / "alone.exr").string());
    ASSERT_EQ(r.code, 0) << r.err;
    std::string why;
    for (int f = 1; f <= 3; ++f) {
        EXPECT_TRUE(
            same_image(frame_file(dir, "tcp", f), frame_file(dir, "alone", f), &why))
            << "frame " << f << ": " << why;
    }
}

}  // namespace
