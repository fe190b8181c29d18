// The distributed back end must give the single-process image: same scene, many wall
// layouts, both ways of returning colours.
#include "distrib/space_render.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "distrib/box_host.h"
#include "distrib/shared_pixel_sums.h"
#include "distrib/tcp.h"
#include "parser/parser.h"
#include "trace/render.h"

namespace povwall::distrib {
namespace {

const char* kScene = R"(
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0.3, 2.5, -9> look_at <0, 0.8, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.4 }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.6> } finish { reflection 0.2 } }
#declare S = seed(7);
#declare I = 0;
#while (I < 60)
  sphere { <rand(S) * 8 - 4, rand(S) * 3, rand(S) * 6 - 2>, 0.2 + 0.4 * rand(S)
    pigment { color rgb <rand(S), rand(S), rand(S)> }
    finish { phong 0.5 reflection 0.3 } }
  #declare I = I + 1;
#end
// On the walls of a 2x2x2 and 4x4x4 cut, and straddling them:
sphere { <0, 1, 0>, 0.7 pigment { rgbf <1, 1, 1, 0.8> } interior { ior 1.4 } }
box { <-0.5, 0, 2>, <0.5, 2, 2.5> pigment { rgbt <0.2, 0.9, 0.3, 0.5> } }
difference { box { -0.6, 0.6 } sphere { 0, 0.75 } translate <2, 0.6, -1>
             pigment { color rgb <1, 0.4, 0.1> } }
)";

double rmse(const Image& a, const Image& b) {
    double s = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        double d = a.rgba[i] - b.rgba[i];
        s += d * d;
    }
    return std::sqrt(s / double(a.width * a.height * 3));
}

class SpaceRender : public ::testing::Test {
  protected:
    void SetUp() override {
        scene_ = parser::parse_scene_text(kScene, "space.pov", {});
        settings_.width = 96;
        settings_.height = 72;
        settings_.threads = 2;
        reference_ = trace::render_scene(scene_, settings_);
    }
    Image render(std::array<int, 3> boxes, SpaceOptions::Results results, bool balanced,
                 SpaceStats* stats = nullptr) {
        SpaceOptions o;
        o.boxes = boxes;
        o.results = results;
        o.balanced = balanced;
        return render_space(scene_, settings_, o, stats);
    }
    Scene scene_;
    trace::RenderSettings settings_;
    Image reference_;
};

TEST_F(SpaceRender, EveryLayoutAndModeGivesTheSingleProcessImage) {
    using R = SpaceOptions::Results;
    for (auto boxes : {std::array<int, 3>{1, 1, 1}, {2, 2, 2}, {4, 4, 4}, {3, 1, 5}}) {
        for (R mode : {R::Forward, R::Parents}) {
            for (bool balanced : {false, true}) {
                Image img = render(boxes, mode, balanced);
                EXPECT_LE(rmse(img, reference_), 1e-6)
                    << boxes[0] << "x" << boxes[1] << "x" << boxes[2] << " mode "
                    << int(mode) << " balanced " << balanced;
            }
        }
    }
}

// A thread processes items for boxes nobody holds itself, skipping inbox and queue. The
// rays still cross the same walls in the same number of messages, and the image is the
// one the queues give; only the queues stay shorter.
TEST_F(SpaceRender, DirectHandOverGivesTheQueuedImageAndTheSameMessages) {
    auto run = [&](bool direct, SpaceOptions::Results results, SpaceStats& stats) {
        SpaceOptions o;
        o.boxes = {4, 4, 4};
        o.results = results;
        o.direct_handoff = direct;
        return render_space(scene_, settings_, o, &stats);
    };
    for (auto results :
         {SpaceOptions::Results::Forward, SpaceOptions::Results::Parents}) {
        SpaceStats queued, direct;
        const Image a = run(false, results, queued);
        const Image b = run(true, results, direct);
        EXPECT_LE(rmse(a, reference_), 1e-6);
        EXPECT_LE(rmse(b, reference_), 1e-6);
        uint64_t sent[2] = {0, 0}, rays[2] = {0, 0};
        size_t peak[2] = {0, 0};
        for (int k = 0; k < 2; ++k) {
            for (const auto& box : (k == 0 ? queued : direct).boxes) {
                sent[k] += box.messages_sent;
                rays[k] += box.rays.rays();
                peak[k] += box.peak_queue;
            }
        }
        EXPECT_EQ(sent[1], sent[0]);
        EXPECT_EQ(rays[1], rays[0]);
        EXPECT_LT(peak[1], peak[0]);
    }
}

// Forked workers add into one mapping the coordinator reads (SharedPixelSums): what
// another process adds shows here, and a host adding there leaves its own sums empty
// and the image whole, in either way of returning colours.
TEST_F(SpaceRender, SharedSumsTakeEveryContributionFromAnyProcess) {
    const size_t count = size_t(settings_.width) * size_t(settings_.height) * 3;
    SharedPixelSums sums(count);
    ASSERT_EQ(sums.size(), count);
    const pid_t pid = fork();
    if (pid == 0) {
        sums.data()[count - 1] = 0.25;
        _exit(0);
    }
    ASSERT_GT(pid, 0);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_EQ(sums.data()[count - 1], 0.25);
    for (auto results :
         {SpaceOptions::Results::Forward, SpaceOptions::Results::Parents}) {
        std::fill(sums.values().begin(), sums.values().end(), 0.0);
        SpaceOptions o;
        o.boxes = {2, 2, 2};
        o.results = results;
        BoxHost host(scene_, settings_, o);
        host.place_walls();
        host.build_boxes({0, 1, 2, 3, 4, 5, 6, 7});
        host.use_shared_sums(sums.data(), sums.stripe_locks());
        host.run(2, true);
        int visited = 0;
        host.for_each_pixel_sum([&](size_t, const double*) { ++visited; });
        EXPECT_EQ(visited, 0);
        const Image image =
            image_from_sums(sums.values(), settings_.width, settings_.height, false);
        EXPECT_LE(rmse(image, reference_), 1e-6) << int(results);
    }
}

// A stripe whose lock another process holds keeps its contributions logged: the host
// adds them once the lock is free, and the run ends only after that.
TEST_F(SpaceRender, SharedSumsWaitForAStripeAnotherProcessHolds) {
    const size_t count = size_t(settings_.width) * size_t(settings_.height) * 3;
    SharedPixelSums sums(count);
    uint32_t* locks = sums.stripe_locks();
    for (size_t s = 0; s < SharedPixelSums::kStripes; ++s)
        ASSERT_EQ(locks[s * SharedPixelSums::kLockStride], 0u);
    // The first and the last stripe: the top rows (sky and far spheres) and the floor.
    const size_t held[] = {0, SharedPixelSums::kStripes - 1};
    for (size_t s : held) locks[s * SharedPixelSums::kLockStride] = 1;
    SpaceOptions o;
    o.boxes = {2, 2, 2};
    BoxHost host(scene_, settings_, o);
    host.place_walls();
    host.build_boxes({0, 1, 2, 3, 4, 5, 6, 7});
    host.use_shared_sums(sums.data(), locks);
    std::atomic<bool> released{false};
    std::thread holder([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        released = true;
        for (size_t s : held)
            std::atomic_ref<uint32_t>(locks[s * SharedPixelSums::kLockStride])
                .store(0, std::memory_order_release);
    });
    host.run(2, true);
    EXPECT_TRUE(released.load());
    holder.join();
    for (size_t s = 0; s < SharedPixelSums::kStripes; ++s)
        EXPECT_EQ(locks[s * SharedPixelSums::kLockStride], 0u) << s;
    const Image image =
        image_from_sums(sums.values(), settings_.width, settings_.height, false);
    EXPECT_LE(rmse(image, reference_), 1e-6);
}

// Worker processes of this process that have not exited (zombies count as gone).
int live_children() {
    int live = 0;
    for (const auto& e : std::filesystem::directory_iterator("/proc")) {
        const std::string name = e.path().filename().string();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        std::ifstream in(e.path() / "stat");
        std::string text((std::istreambuf_iterator<char>(in)), {});
        const size_t close = text.rfind(')');
        if (close == std::string::npos) continue;
        char state = 0;
        int ppid = 0;
        if (std::sscanf(text.c_str() + close + 1, " %c %d", &state, &ppid) != 2) continue;
        if (ppid == getpid() && state != 'Z') ++live;
    }
    return live;
}

// After the last frame a session lets its workers go without waiting for them (the
// image is written meanwhile): they exit on their own, and a later frame starts new
// ones and gives the same image.
TEST_F(SpaceRender, ReleasedWorkersExitAndTheNextFrameStartsNewOnes) {
    SceneSource source;
    source.parse.scene = kScene;
    source.parse.name = "space.pov";
    TcpOptions tcp;
    tcp.procs = 2;
    tcp.fork_workers = true;
    SpaceOptions o;
    o.boxes = {2, 1, 1};
    TcpSession session(tcp);
    const Image first = session.render(scene_, source, settings_, o);
    EXPECT_EQ(session.processes_started(), 2);
    EXPECT_EQ(live_children(), 2);
    session.release_workers();
    for (int i = 0; i < 500 && live_children() > 0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_EQ(live_children(), 0);
    const Image second = session.render(scene_, source, settings_, o);
    EXPECT_EQ(session.processes_started(), 4);
    EXPECT_EQ(rmse(first, second), 0.0);
    EXPECT_LE(rmse(first, reference_), 1e-6);
}

TEST_F(SpaceRender, StatsShowLocalScenesAndTraffic) {
    SpaceStats stats;
    render({2, 2, 2}, SpaceOptions::Results::Forward, false, &stats);
    ASSERT_EQ(stats.boxes.size(), 8u);
    EXPECT_FALSE(stats.parent_tracking);
    size_t max_objects = 0;
    uint64_t camera = 0, sent = 0;
    for (const auto& b : stats.boxes) {
        max_objects = std::max(max_objects, b.objects);
        camera += b.rays.camera;
        sent += b.messages_sent;
        EXPECT_EQ(b.peak_parents, 0u);  // forward contributions park nothing
    }
    EXPECT_LT(max_objects, scene_.objects.size());  // each box holds part of the scene
    EXPECT_EQ(camera, uint64_t(96 * 72));
    EXPECT_GT(sent, 0u);
    // Every message a box sends, another receives, besides the camera rays the emitter
    // hands in; in process a message is one Item. Busy plus idle is the render's wall
    // time, the same for every box.
    uint64_t received = 0, bytes_sent = 0, bytes_received = 0;
    double lo = 1e300, hi = -1;
    for (const auto& b : stats.boxes) {
        received += b.messages_received;
        bytes_sent += b.bytes_sent;
        bytes_received += b.bytes_received;
        EXPECT_GE(b.idle_seconds, 0.0);
        lo = std::min(lo, b.busy_seconds + b.idle_seconds);
        hi = std::max(hi, b.busy_seconds + b.idle_seconds);
    }
    EXPECT_EQ(received, sent + uint64_t(96 * 72));
    EXPECT_EQ(bytes_sent, sent * sizeof(Item));
    EXPECT_EQ(bytes_received, received * sizeof(Item));
    EXPECT_GT(lo, 0.0);
    EXPECT_LE(hi - lo, 1e-3 * hi);
    render({2, 2, 2}, SpaceOptions::Results::Parents, false, &stats);
    EXPECT_TRUE(stats.parent_tracking);
    size_t parents = 0;
    for (const auto& b : stats.boxes) parents = std::max(parents, b.peak_parents);
    EXPECT_GT(parents, 0u);
}

TEST(SpaceRenderPlan, ReflectionExponentNeedsParents) {
    Scene linear = parser::parse_scene_text("sphere { 0, 1 finish { reflection 0.5 } }",
                                            "a.pov", {});
    Scene exponent = parser::parse_scene_text(
        "sphere { 0, 1 finish { reflection { 0.5 exponent 2 } } }", "b.pov", {});
    EXPECT_TRUE(shading_is_linear(linear));
    EXPECT_FALSE(shading_is_linear(exponent));
}

}  // namespace
}  // namespace povwall::distrib
