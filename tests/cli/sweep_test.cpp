// `povwall sweep` (error against run time) and render options it relies on.
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <vector>

#include "tests/cli/run_povwall.h"

namespace {

using namespace povwall_test;
namespace fs = std::filesystem;

struct CsvRow {
    std::string renderer;
    double seconds, rmse;
    bool pareto;
};

// setting -> row; quoted fields hold no commas in sweep's output except the arguments.
std::map<std::string, CsvRow> read_sweep_csv(const fs::path& p) {
    std::map<std::string, CsvRow> rows;
    std::ifstream in(p);
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::string cur;
        bool quoted = false;
        for (char c : line) {
            if (c == '"')
                quoted = !quoted;
            else if (c == ',' && !quoted)
                f.push_back(cur), cur.clear();
            else
                cur += c;
        }
        f.push_back(cur);
        if (f.size() != 10) continue;
        rows[f[0]] = {f[1], std::stod(f[4]), std::stod(f[5]), f[9] == "1"};
    }
    return rows;
}

TEST(Sweep, LadderOfSettingsAgainstThePovRayReferenceWithPlot) {
    const fs::path csv = scratch() / "sweep.csv", svg = scratch() / "sweep.svg";
    RunResult r = run(std::string("sweep ") + POVWALL_SOURCE_DIR +
                      "/scenes/demo/walls.pov -W 48 -H 36 --repeat 1 --threads 1 --csv " +
                      csv.string() + " --plot " + svg.string());
    if (r.code == 77) GTEST_SKIP() << "povray not installed: " << r.err;
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    const auto rows = read_sweep_csv(csv);
    int ours = 0, theirs = 0;
    for (const auto& [name, row] : rows) (row.renderer == "povwall" ? ours : theirs)++;
    EXPECT_GE(ours, 8);
    EXPECT_EQ(theirs, 2);
    auto rmse = [&](const std::string& k) {
        EXPECT_TRUE(rows.count(k)) << k;
        return rows.count(k) ? rows.at(k).rmse : -1.0;
    };
    // The reflective seed scene: fewer bounces, looser bailout, or coarser anti-aliasing
    // cost accuracy; the reference's own settings reproduce it.
    EXPECT_GT(rmse("max_trace_level 1"), rmse("max_trace_level 2"));
    EXPECT_GE(rmse("max_trace_level 2"), rmse("no AA"));
    EXPECT_GE(rmse("adc_bailout 0.1"), rmse("no AA"));
    EXPECT_GT(rmse("no AA"), rmse("AA 0.3 depth 3"));
    EXPECT_GE(rmse("AA 0.3 depth 3"), rmse("AA 0.1 depth 3"));
    EXPECT_GE(rmse("AA 0.1 depth 3"), rmse("AA 0.0 depth 3"));
    EXPECT_LE(rmse("AA 0.0 depth 3"), 0.01);
    // Distribution changes time, never the image; POV-Ray at the same settings agrees.
    EXPECT_EQ(rmse("no AA, 8 boxes"), rmse("no AA"));
    EXPECT_EQ(rmse("no AA, screen tiles"), rmse("no AA"));
    EXPECT_NEAR(rmse("POV-Ray no AA"), rmse("no AA"), 0.01);
    EXPECT_NEAR(rmse("POV-Ray AA 0.3"), rmse("AA 0.3 depth 3"), 0.01);
    // The most accurate setting is on the Pareto front.
    EXPECT_TRUE(rows.at("AA 0.0 depth 3").pareto);
    // The plot: POV-Ray's two points, povwall's ten, the front.
    const std::string plot = slurp(svg);
    auto count = [&](const std::string& needle) {
        size_t n = 0;
        for (size_t at = plot.find(needle); at != std::string::npos;
             at = plot.find(needle, at + 1))
            ++n;
        return n;
    };
    EXPECT_EQ(count("<rect class=\"povray\""), 2u);
    EXPECT_EQ(count("<circle class=\"povwall"), size_t(ours));
    EXPECT_EQ(count("<polyline class=\"pareto\""), 1u);
    EXPECT_NE(r.out.find("median of 1 run"), std::string::npos) << r.out;
}

TEST(Sweep, OverridesOfMaxTraceLevelAndAdcBailoutChangeTheImage) {
    const std::string scene = std::string(POVWALL_SOURCE_DIR) + "/scenes/demo/walls.pov";
    const fs::path a = scratch() / "mtl1.png", b = scratch() / "mtl5.png";
    ASSERT_EQ(
        run("render " + scene + " -W 32 -H 24 -q --max-trace-level 1 -o " + a.string())
            .code,
        0);
    ASSERT_EQ(run("render " + scene + " -W 32 -H 24 -q -o " + b.string()).code, 0);
    EXPECT_EQ(run("diff " + a.string() + " " + b.string()).code,
              1);  // reflections gone: they differ
    RunResult bad = run("render " + scene + " --max-trace-level 0");
    EXPECT_EQ(bad.code, 2);
    EXPECT_NE(bad.err.find("--max-trace-level"), std::string::npos) << bad.err;
}

TEST(Sweep, ScreenWorkersRenderEachAnimationFrameWithItsOwnClock) {
    const fs::path scene = write_scene(
        "moving.pov",
        "camera { location <0,0,-4> look_at 0 }\n"
        "light_source { <5,5,-5> rgb 1 }\n"
        "sphere { <clock*2-1, frame_number*0.1-0.2, 0>, 0.5 pigment { rgb 1 } }\n");
    const fs::path screen = scratch() / "screen.png", single = scratch() / "single.png";
    ASSERT_EQ(run("render " + scene.string() + " -W 40 -H 30 +KFI1 +KFF3 --mode screen " +
                  "--procs 2 -q -o " + screen.string())
                  .code,
              0);
    ASSERT_EQ(run("render " + scene.string() +
                  " -W 40 -H 30 +KFI1 +KFF3 --mode single -q -o " + single.string())
                  .code,
              0);
    for (int f = 1; f <= 3; ++f) {
        const std::string n = std::to_string(f);
        RunResult d =
            run("diff " + (scratch() / ("screen" + n + ".png")).string() + " " +
                (scratch() / ("single" + n + ".png")).string() + " --max-rmse 0");
        EXPECT_EQ(d.code, 0) << "frame " << f << ": " << d.out;
    }
}

}  // namespace
