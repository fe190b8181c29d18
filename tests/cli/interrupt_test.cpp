// An interrupted render says in which phase it stopped: the message itself for every
// phase (cli/interrupt.h), and the povwall binary stopped while parsing and while
// tracing.
#include "cli/interrupt.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/cli/run_povwall.h"
#include "trace/pixel_sampler.h"

namespace {

namespace fs = std::filesystem;
using namespace povwall_test;
using povwall::cli::RenderPhase;
using povwall::cli::RenderRecord;
using Stage = povwall::trace::RenderProgress::Stage;

std::string message(const RenderRecord& r, bool removed = false) {
    char out[4096];
    const size_t n = povwall::cli::interrupt_message(r, removed, out, sizeof out);
    EXPECT_EQ(n, std::string(out).size());
    return std::string(out, n);
}

TEST(InterruptMessage, NamesEachPhase) {
    RenderRecord r;
    EXPECT_EQ(message(r), "\npovwall: interrupted: no image written\n");
    EXPECT_EQ(message(r, true),
              "\npovwall: interrupted: the partly written image was removed; no image "
              "written\n");
    r.phase = RenderPhase::Parsing;
    r.parse.set("scenes/big.pov", 0);  // still reading the file
    EXPECT_EQ(message(r),
              "\npovwall: interrupted while parsing scenes/big.pov; no image written\n");
    r.parse.set_line(123);
    EXPECT_EQ(message(r),
              "\npovwall: interrupted while parsing scenes/big.pov:123; no "
              "image written\n");
    r.phase = RenderPhase::Rendering;
    r.progress.objects = 41200;
    EXPECT_EQ(message(r),
              "\npovwall: interrupted while preparing the scene (41,200 "
              "objects); no image written\n");
    r.progress.objects = 1234567;
    r.progress.stage = Stage::BuildingOctree;
    EXPECT_EQ(message(r),
              "\npovwall: interrupted while building the octree (1,234,567 "
              "primitives); no image written\n");
    r.progress.stage = Stage::ShootingPhotons;
    EXPECT_EQ(message(r),
              "\npovwall: interrupted while shooting photons; no image written\n");
    r.progress.stage = Stage::Pretracing;
    EXPECT_EQ(message(r),
              "\npovwall: interrupted in radiosity's pretrace; no image written\n");
    r.progress.start_pass(19200);
    r.progress.pixels_done = 1234;
    EXPECT_EQ(message(r),
              "\npovwall: interrupted while tracing: 1,234 of 19,200 pixels "
              "(6.4 %); no image written\n");
    r.progress.pixels_done = 19199;  // rounded down: not done yet
    EXPECT_EQ(message(r),
              "\npovwall: interrupted while tracing: 19,199 of 19,200 pixels "
              "(99.9 %); no image written\n");
    r.phase = RenderPhase::Writing;
    r.output.set("out/walls.png", 0);
    EXPECT_EQ(message(r),
              "\npovwall: interrupted while writing out/walls.png; no image "
              "written\n");
    EXPECT_EQ(message(r, true),
              "\npovwall: interrupted while writing out/walls.png: the partly written "
              "image was removed; no image written\n");
    r.phase = RenderPhase::Written;
    EXPECT_EQ(message(r),
              "\npovwall: interrupted after writing out/walls.png, which is complete\n");
    r.phase = RenderPhase::Parsing;
    r.frame = 12;
    EXPECT_EQ(message(r),
              "\npovwall: frame 12: interrupted while parsing "
              "scenes/big.pov:123; no image written\n");
}

TEST(InterruptMessage, IsCutToTheBuffer) {
    RenderRecord r;
    r.phase = RenderPhase::Parsing;
    r.parse.set(std::string(5000, 'a'), 7);  // cut to the record's capacity
    std::string whole = message(r);
    EXPECT_EQ(whole, "\npovwall: interrupted while parsing " +
                         std::string(povwall::PublishedPlace::kCapacity - 1, 'a') +
                         ":7; no image written\n");
    char small[16];
    EXPECT_EQ(povwall::cli::interrupt_message(r, false, small, sizeof small), 15u);
    EXPECT_EQ(std::string(small), whole.substr(0, 15));
}

// A reader never sees a name of one write with the line of another.
TEST(InterruptMessage, PlaceIsReadWhole) {
    povwall::PublishedPlace place;
    std::atomic<bool> stop{false};
    std::thread writer([&] {
        for (uint32_t i = 0; !stop; ++i) {
            if (i % 2)
                place.set("odd.pov", 1);
            else
                place.set("even/longer/name.pov", 2);
        }
    });
    int read = 0;
    for (int i = 0; i < 200000; ++i) {
        char name[64];
        uint32_t line = 0;
        if (!place.get(name, sizeof name, line)) continue;
        ++read;
        const std::string n(name);
        ASSERT_TRUE((n == "odd.pov" && line == 1) ||
                    (n == "even/longer/name.pov" && line == 2) ||
                    (n.empty() && line == 0))
            << n << ":" << line;
    }
    stop = true;
    writer.join();
    EXPECT_GT(read, 0);
}

// Processor time used by `pid` (user and system), in seconds; -1 when it is gone.
double cpu_seconds(pid_t pid) {
    std::string stat = slurp("/proc/" + std::to_string(pid) + "/stat");
    const size_t close = stat.rfind(')');
    if (close == std::string::npos) return -1;
    std::istringstream in(stat.substr(close + 2));
    std::string field;
    long long utime = 0, stime = 0;
    for (int i = 0; i < 13 && in >> field; ++i) {  // from the state (field 3) on
        if (i == 11) utime = std::stoll(field);
        if (i == 12) stime = std::stoll(field);
    }
    return double(utime + stime) / double(sysconf(_SC_CLK_TCK));
}

// Runs povwall with `args` (stderr to `err`) and sends it `sig` once its stderr holds
// `said` and it has used `cpu` seconds of processor time since: progress a loaded machine
// can delay but not fake, so the render is known to be in the phase under test. Returns
// its exit code, or -1 if that never came within two minutes (it is then killed).
int interrupt_when(const std::vector<std::string>& args, const fs::path& err,
                   const std::string& said, double cpu, int sig) {
    std::vector<std::string> all{POVWALL_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        const int fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = open("/dev/null", O_WRONLY);
        if (fd < 0 || null < 0) _exit(127);
        dup2(fd, 2);
        dup2(null, 1);
        execv(argv[0], argv.data());
        _exit(127);
    }
    if (pid < 0) return -1;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    int status = 0;
    double cpu_when_said = -1;
    for (;;) {
        if (waitpid(pid, &status, WNOHANG) == pid) return -1;  // ended on its own
        if (std::chrono::steady_clock::now() > give_up) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            return -1;
        }
        if (cpu_when_said < 0 && slurp(err).find(said) != std::string::npos)
            cpu_when_said = cpu_seconds(pid);
        if (cpu_when_said >= 0 && cpu_seconds(pid) >= cpu_when_said + cpu) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    kill(pid, sig);
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Nothing but the scene in `dir`: no image, no temporary.
void expect_only(const fs::path& dir, const fs::path& scene) {
    for (const auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path(), scene) << "left behind";
}

// A parse that never ends (each loop stays under the runaway-loop limit) is named at the
// loop's line, in a still and in a frame of an animation.
TEST(Interrupt, WhileParsingNamesTheFileAndLine) {
    const fs::path dir = scratch() / "interrupt_parse";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path scene = dir / "loop.pov", err = dir / "err";
    std::ofstream(scene) << "#declare I = 0;\n#debug \"looping\\n\"\n"
                            "#while (I < 5000000) #declare J = 0; #while (J < 5000000) "
                            "#declare J = J + 1; #end #declare I = I + 1; #end\n";
    // Not quiet: the #debug line says the loop is next.
    EXPECT_EQ(
        interrupt_when({"render", scene.string(), "-o", (dir / "loop.png").string()}, err,
                       "looping\n", 0.3, SIGINT),
        128 + SIGINT);
    EXPECT_EQ(slurp(err), "looping\n\npovwall: interrupted while parsing " +
                              scene.string() + ":3; no image written\n");
    fs::remove(err);
    expect_only(dir, scene);
    // POV-Ray's form, an animation, SIGTERM.
    EXPECT_EQ(interrupt_when({"+I" + scene.string(), "+O" + (dir / "f.png").string(),
                              "+KFI1", "+KFF2"},
                             err, "looping\n", 0.3, SIGTERM),
              128 + SIGTERM);
    EXPECT_EQ(slurp(err), "looping\n\npovwall: frame 1: interrupted while parsing " +
                              scene.string() + ":3; no image written\n");
    fs::remove(err);
    expect_only(dir, scene);
}

// A render stopped while tracing says how many pixels were done of how many.
TEST(Interrupt, WhileTracingCountsThePixels) {
    const fs::path dir = scratch() / "interrupt_trace";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path scene = dir / "slow.pov", err = dir / "err";
    // Parsed and prepared in a millisecond, traced in a minute or more: 1,089 shadow rays
    // for each point in view.
    std::ofstream(scene)
        << "camera { location <0, 5, -5> look_at 0 }\n"
           "light_source { <3, 6, -4> color rgb 1\n"
           "  area_light <4, 0, 0>, <0, 0, 4>, 33, 33 circular orient }\n"
           "#declare I = 0;\n"
           "#while (I < 20) sphere { <mod(I, 5) - 2, 0, div(I, 5) - 2>, 0.4 pigment { "
           "color rgb <1, 0.5, 0.2> } } #declare I = I + 1; #end\n"
           "plane { y, -1 pigment { checker color rgb 1 color rgb 0.2 } }\n";
    // Nothing on stderr tells that tracing has begun, so the signal comes after some
    // processor time; a sanitizer build on a loaded machine can spend a second before
    // tracing (loading alone takes half of one), so an earlier phase is tried again with
    // twice the time.
    const std::regex tracing(
        "\npovwall: interrupted while tracing: ([0-9,]+) of 1,200,000 pixels "
        "\\(([0-9.]+) %\\); no image written\n");
    const std::regex earlier(
        "\npovwall: interrupted(: | while preparing | while building the octree ).*no "
        "image written\n");
    std::string said;
    std::smatch m;
    for (double cpu = 1.0; cpu <= 16.0; cpu *= 2) {
        EXPECT_EQ(
            interrupt_when({"render", scene.string(), "-W", "1200", "-H", "1000",
                            "--threads", "1", "-q", "-o", (dir / "slow.png").string()},
                           err, "", cpu, SIGINT),
            128 + SIGINT);
        said = slurp(err);
        if (!std::regex_match(said, earlier)) break;
    }
    ASSERT_TRUE(std::regex_match(said, m, tracing)) << said;
    const uint64_t done =
        std::stoull(std::regex_replace(m[1].str(), std::regex(","), ""));
    EXPECT_LT(done, 1200000u);
    // Whole render blocks, done in POV-Ray's order by the one thread.
    uint64_t blocks_done = 0;
    bool whole_blocks = done == 0;
    for (const auto& b : povwall::trace::render_blocks({0, 0, 1200, 1000}, 32)) {
        blocks_done += uint64_t(b.pixels());
        whole_blocks = whole_blocks || blocks_done == done;
    }
    EXPECT_TRUE(whole_blocks) << done;
    char share[16];
    std::snprintf(share, sizeof share, "%.1f", double(done * 1000 / 1200000) / 10);
    EXPECT_EQ(m[2].str(), share);
    fs::remove(err);
    expect_only(dir, scene);
}

}  // namespace
