// End-to-end tests of the povwall binary: exit codes, exact diagnostics, no partial output.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/image.h"
#include "output/image_io.h"

namespace {

namespace fs = std::filesystem;

struct RunResult {
    int code;
    std::string out, err;
};

fs::path scratch() {
    fs::path d = fs::temp_directory_path() / ("povwall-cli-test-" + std::to_string(getpid()));
    fs::create_directories(d);
    return d;
}

RunResult run(const std::string& args) {
    fs::path d = scratch();
    std::string cmd = std::string(POVWALL_BINARY) + " " + args + " >" + (d / "out").string() +
                      " 2>" + (d / "err").string();
    int status = std::system(cmd.c_str());
    auto slurp = [](const fs::path& p) {
        std::ifstream in(p);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    return {WEXITSTATUS(status), slurp(d / "out"), slurp(d / "err")};
}

fs::path write_scene(const std::string& name, const std::string& text) {
    fs::path p = scratch() / name;
    std::ofstream(p) << text;
    return p;
}

TEST(Cli, SyntaxErrorIsLocatedExitsTwoAndWritesNothing) {
    fs::path scene = write_scene("bad.pov", "camera { location <0, 0, -3> }\nsphere { 0, 1\n"
                                            "  pigment { colour rgb <1, 0, 0> }\n  finsh { }\n}\n");
    fs::path out = scratch() / "bad.png";
    fs::remove(out);
    RunResult r = run("render " + scene.string() + " -o " + out.string() + " -W 16 -H 16");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, scene.string() +
                         ":4:3: error: expected an object modifier or '}' but found 'finsh'\n"
                         "  finsh { }\n"
                         "  ^~~~~\n");
    EXPECT_FALSE(fs::exists(out));
    for (const auto& e : fs::directory_iterator(scratch())) {
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
    }
}

TEST(Cli, UnknownIdentifierAndMissingIncludeAreLocated) {
    fs::path scene = write_scene("undef.pov", "sphere { 0, Radius }\n");
    RunResult r = run("+I" + scene.string() + " +O" + (scratch() / "u.png").string() + " +W8 +H8");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, scene.string() + ":1:13: error: undeclared identifier 'Radius'\n"
                                      "sphere { 0, Radius }\n"
                                      "            ^~~~~~\n");
    fs::path inc = write_scene("inc.pov", "#include \"missing.inc\"\n");
    r = run("render " + inc.string() + " -o " + (scratch() / "i.png").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, inc.string() + ":1:10: error: cannot find include file \"missing.inc\"\n"
                                    "#include \"missing.inc\"\n"
                                    "         ^~~~~~~~~~~~~\n");
    EXPECT_FALSE(fs::exists(scratch() / "i.png"));
}

TEST(Cli, MissingSceneFile) {
    RunResult r = run("render /nonexistent/scene.pov -o " + (scratch() / "m.png").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, "povwall: error: cannot open scene file '/nonexistent/scene.pov'\n");
}

TEST(Cli, RenderWritesImageOfRequestedSizeWithPovSwitches) {
    fs::path scene = write_scene("ok.pov", "background { color rgb <1, 0.5, 0> }\n");
    fs::path out = scratch() / "ok.png";
    RunResult r = run("+I" + scene.string() + " +O" + out.string() + " +W7 +H5 -D -GA");
    ASSERT_EQ(r.code, 0) << r.err;
    povwall::Image img = povwall::output::read_image(out.string());
    EXPECT_EQ(img.width, 7);
    EXPECT_EQ(img.height, 5);
    // Legacy scene (no #version): written raw, 0.5 -> 128/255.
    EXPECT_FLOAT_EQ(img.pixel(3, 2)[1], 128.0f / 255.0f);
}

povwall::Image flat(int w, int h, float v) {
    povwall::Image img(w, h);
    for (float& c : img.rgba) c = v;
    return img;
}

void save(const povwall::Image& img, const fs::path& p) {
    povwall::OutputEncoding raw;
    raw.gamma_handling = false;
    povwall::output::write_image(img, p.string(), raw);
}

TEST(Cli, DiffReportsMetricsAndIdiffExitCodes) {
    fs::path a = scratch() / "a.png", b = scratch() / "b.png", c = scratch() / "c.png";
    povwall::Image ia = flat(10, 10, 0.5f);
    povwall::Image ib = ia;
    // One pixel off by 51/255 = 0.2 in red: bad fraction 0.01, rmse sqrt(0.04/300).
    ib.pixel(3, 4)[0] = (128.0f + 51.0f) / 255.0f;
    save(ia, a);
    save(ib, b);
    RunResult r = run("diff " + a.string() + " " + b.string() + " --json");
    EXPECT_EQ(r.code, 2);  // bad fraction 0.01 > 0.002
    nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_DOUBLE_EQ(j["bad_pixel_fraction"].get<double>(), 0.01);
    EXPECT_NEAR(j["max_abs"].get<double>(), 0.2, 1e-6);
    EXPECT_NEAR(j["rmse"].get<double>(), std::sqrt(0.04 / 300), 1e-6);
    EXPECT_EQ(j["width"], 10);
    EXPECT_EQ(j["height"], 10);
    r = run("diff " + a.string() + " " + b.string() + " --max-bad-fraction 0.05 --max-rmse 0.02");
    EXPECT_EQ(r.code, 1);  // within the allowed fraction, but a pixel is over: warning
    EXPECT_NE(r.out.find("max_abs: 0.200000 @ (3, 4, R) 0.501961 vs 0.701961"),
              std::string::npos)
        << r.out;
    r = run("diff " + a.string() + " " + a.string());
    EXPECT_EQ(r.code, 0);
    EXPECT_NE(r.out.find("psnr: inf"), std::string::npos);
    EXPECT_NE(r.out.find("PASS"), std::string::npos);
    save(flat(5, 10, 0.5f), c);
    EXPECT_EQ(run("diff " + a.string() + " " + c.string()).code, 3);
    EXPECT_EQ(run("diff " + a.string() + " /nonexistent.png").code, 4);
}

}  // namespace
