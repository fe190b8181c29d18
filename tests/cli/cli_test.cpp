// End-to-end tests of the povwall binary: exit codes, exact diagnostics, no partial
// output.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
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
    fs::path d =
        fs::temp_directory_path() / ("povwall-cli-test-" + std::to_string(getpid()));
    fs::create_directories(d);
    return d;
}

RunResult run(const std::string& args) {
    fs::path d = scratch();
    std::string cmd = std::string(POVWALL_BINARY) + " " + args + " >" +
                      (d / "out").string() + " 2>" + (d / "err").string();
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
    fs::path scene = write_scene("bad.pov",
                                 "camera { location <0, 0, -3> }\nsphere { 0, 1\n"
                                 "  pigment { colour rgb <1, 0, 0> }\n  finsh { }\n}\n");
    fs::path out = scratch() / "bad.png";
    fs::remove(out);
    RunResult r =
        run("render " + scene.string() + " -o " + out.string() + " -W 16 -H 16");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err,
              scene.string() +
                  ":4:3: error: expected an object modifier or '}' but found 'finsh'\n"
                  "  finsh { }\n"
                  "  ^~~~~\n");
    EXPECT_FALSE(fs::exists(out));
    for (const auto& e : fs::directory_iterator(scratch())) {
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos)
            << e.path();
    }
}

TEST(Cli, UnknownIdentifierAndMissingIncludeAreLocated) {
    fs::path scene = write_scene("undef.pov", "sphere { 0, Radius }\n");
    RunResult r =
        run("+I" + scene.string() + " +O" + (scratch() / "u.png").string() + " +W8 +H8");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, scene.string() +
                         ":1:13: error: undeclared identifier 'Radius'\n"
                         "sphere { 0, Radius }\n"
                         "            ^~~~~~\n");
    fs::path inc = write_scene("inc.pov", "#include \"missing.inc\"\n");
    r = run("render " + inc.string() + " -o " + (scratch() / "i.png").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, inc.string() +
                         ":1:10: error: cannot find include file \"missing.inc\"\n"
                         "#include \"missing.inc\"\n"
                         "         ^~~~~~~~~~~~~\n");
    EXPECT_FALSE(fs::exists(scratch() / "i.png"));
}

TEST(Cli, ParseReportsContentsUnsupportedAndErrors) {
    fs::path ok = write_scene("parse_ok.pov",
                              "#version 3.7;\n#declare I = 0;\n#while (I < 3) sphere { x * I, 0.5 }"
                              " #declare I = I + 1; #end\nunion { box { 0, 1 } cone { 0, 1, y, 0 } }\n"
                              "light_source { <1, 2, 3> color rgb 1 }\n");
    RunResult r = run("parse " + ok.string() + " --json");
    ASSERT_EQ(r.code, 0) << r.err;
    nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["status"], "ok");
    EXPECT_EQ(j["objects"], 4);
    EXPECT_EQ(j["shapes"]["sphere"], 3);
    EXPECT_EQ(j["shapes"]["union"], 1);
    EXPECT_EQ(j["shapes"]["cone"], 1);
    EXPECT_EQ(j["lights"], 1);
    EXPECT_DOUBLE_EQ(j["language_version"].get<double>(), 3.7);
    fs::path unsupported = write_scene("parse_text.pov", "sphere { 0, 1 }\n  text { ttf \"a.ttf\" \"x\" 1, 0 }\n");
    r = run("parse " + unsupported.string() + " --json");
    EXPECT_EQ(r.code, 3);
    j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["status"], "unsupported");
    EXPECT_EQ(j["message"], "unsupported: text");
    EXPECT_EQ(j["line"], 2);
    EXPECT_EQ(j["column"], 3);
    fs::path bad = write_scene("parse_bad.pov", "sphere { 0, 1 ");
    r = run("parse " + bad.string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find(bad.string() + ":1:"), std::string::npos) << r.err;
}

TEST(Cli, MissingSceneFile) {
    RunResult r =
        run("render /nonexistent/scene.pov -o " + (scratch() / "m.png").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, "povwall: error: cannot open scene file '/nonexistent/scene.pov'\n");
    EXPECT_FALSE(fs::exists(scratch() / "m.png"));
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
    r = run("diff " + a.string() + " " + b.string() +
            " --max-bad-fraction 0.05 --max-rmse 0.02");
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

namespace {

std::string head_bytes(const fs::path& p, size_t n) {
    std::ifstream in(p, std::ios::binary);
    std::string s(n, '\0');
    in.read(s.data(), std::streamsize(n));
    s.resize(size_t(in.gcount()));
    return s;
}

bool povray_available() { return std::system("command -v povray >/dev/null 2>&1") == 0; }

const char* kGreyScene =
    "#version 3.7;\nglobal_settings { assumed_gamma 1 }\nbackground { color rgb <0.5, 0, "
    "1> }\n";

TEST(Cli, IniFileSetsSceneSizeAndFormat) {
    fs::path scene = write_scene("ini_scene.pov", kGreyScene);
    fs::path out = scratch() / "from_ini";
    fs::remove(scratch() / "from_ini.tga");
    fs::path ini = write_scene(
        "opts.ini", "; POV-Ray options\n[default]\nInput_File_Name=" + scene.string() +
                        "\nOutput_File_Name=" + out.string() +
                        "\nWidth=9\nHeight=4\n"
                        "Antialias=Off\nOutput_File_Type=T\n");
    RunResult r = run(ini.string() + " -GA");
    ASSERT_EQ(r.code, 0) << r.err;
    // No extension given: POV-Ray appends the format's, and +FT means Targa.
    povwall::Image img =
        povwall::output::read_image((scratch() / "from_ini.tga").string());
    EXPECT_EQ(img.width, 9);
    EXPECT_EQ(img.height, 4);
    EXPECT_FLOAT_EQ(img.pixel(8, 3)[0] * 255.0f, 188.0f);  // sRGB(0.5)
    fs::path bad = write_scene("bad.ini", "Width=9\nFrobnicate=1\n");
    r = run(bad.string());
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("povwall: error: " + bad.string() +
                              ":2: option 'Frobnicate' is not supported by povwall\n",
                          0),
              0u)
        << r.err;
}

TEST(Cli, FormatSwitchWinsOverExtensionAndSixteenBits) {
    fs::path scene = write_scene("fmt.pov", kGreyScene);
    fs::path ppm = scratch() / "really_ppm.png", p16 = scratch() / "deep.png";
    ASSERT_EQ(
        run("render " + scene.string() + " -o " + ppm.string() + " -W 3 -H 2 +FP -q")
            .code,
        0);
    EXPECT_EQ(head_bytes(ppm, 2), "P6");
    ASSERT_EQ(
        run("+I" + scene.string() + " +O" + p16.string() + " +W3 +H2 +FN16 -GA").code, 0);
    EXPECT_NEAR(povwall::output::read_image(p16.string()).pixel(0, 0)[0] * 65535.0f,
                48192.0f, 0.01);
    RunResult r = run("+I" + scene.string() + " +FX");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("povwall: error: unsupported output format in '+FX'", 0), 0u)
        << r.err;
}

TEST(Cli, PartialRenderByRowNumbersAndFractions) {
    fs::path scene = write_scene("part.pov", kGreyScene);
    fs::path out = scratch() / "part.png";
    // Rows from half the height (fraction), columns 3..4 (1-based numbers): 5 x 2 pixels.
    ASSERT_EQ(run("+I" + scene.string() + " +O" + out.string() +
                  " +W10 +H10 +SR0.5 +SC3 +EC4 -GA")
                  .code,
              0);
    povwall::Image img = povwall::output::read_image(out.string());
    int rendered = 0;
    for (int y = 0; y < 10; ++y) {
        for (int x = 0; x < 10; ++x) {
            bool inside = y >= 5 && x >= 2 && x <= 3;
            EXPECT_FLOAT_EQ(img.pixel(x, y)[0] * 255.0f, inside ? 188.0f : 0.0f)
                << x << "," << y;
            rendered += inside;
        }
    }
    EXPECT_EQ(rendered, 10);
    EXPECT_EQ(run("+I" + scene.string() + " +SR0").code, 2);
}

TEST(Cli, UsageErrorsExitTwo) {
    RunResult r = run("frobnicate");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("povwall: error: unknown command 'frobnicate'\n", 0), 0u)
        << r.err;
    r = run("render -W 10");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("povwall: error: no scene file given", 0), 0u) << r.err;
    r = run("+Ifoo.pov +Wabc");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("povwall: error: bad value in switch '+Wabc'", 0), 0u) << r.err;
}

TEST(Cli, DiffWritesDifferenceImageAndTakesIdiffPercentages) {
    fs::path a = scratch() / "da.png", b = scratch() / "db.png", d = scratch() / "dd.png";
    povwall::Image ia = flat(20, 10, 0.5f);
    povwall::Image ib = ia;
    ib.pixel(19, 9)[1] = (128.0f + 51.0f) / 255.0f;  // one bad pixel of 200: 0.5 %
    save(ia, a);
    save(ib, b);
    fs::remove(d);
    RunResult r = run("diff " + a.string() + " " + b.string() + " -o " + d.string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.out.find("bad_pixel_fraction: 0.005000 (1 of 200 pixels)\nFAILURE\n"),
              std::string::npos)
        << r.out;
    povwall::Image diff = povwall::output::read_image(d.string());
    EXPECT_FLOAT_EQ(diff.pixel(19, 9)[1] * 255.0f, 51.0f);
    EXPECT_FLOAT_EQ(diff.pixel(0, 0)[1], 0.0f);
    // 1 % allowed over --fail, but the pixel is still over --warn: a warning.
    r = run("diff " + a.string() + " " + b.string() + " --failpercent 1 --max-rmse 0.1");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("WARNING"), std::string::npos);
    r = run("diff " + a.string() + " " + b.string() +
            " --failpercent 1 --warnpercent 1 --max-rmse 0.1 --json");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(nlohmann::json::parse(r.out)["status"], "pass");
    fs::path text = write_scene("notimage.png", "hello");
    r = run("diff " + a.string() + " " + text.string() + " --json");
    EXPECT_EQ(r.code, 4);
    EXPECT_EQ(nlohmann::json::parse(r.out)["status"], "unreadable");
}

TEST(Cli, CompareReportsBothRendersAsJson) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    fs::path scene = write_scene("cmp.pov",
                                 "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                                 "camera { location <0, 0, -3> look_at 0 }\n"
                                 "light_source { <2, 3, -4> color rgb 1 }\n"
                                 "sphere { 0, 1 pigment { color rgb <1, 0.5, 0.2> } }\n");
    fs::path keep = scratch() / "keep";
    fs::remove_all(keep);
    RunResult r = run("compare " + scene.string() +
                      " -W 32 -H 24 --threads 1 --json --keep " + keep.string());
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    nlohmann::json j = nlohmann::json::parse(r.out);
    for (const char* key : {"rmse", "psnr", "max_abs", "bad_pixel_fraction", "width",
                            "height", "povwall_seconds", "povray_seconds", "scene"}) {
        EXPECT_TRUE(j.contains(key)) << key;
    }
    EXPECT_EQ(j["width"], 32);
    EXPECT_EQ(j["height"], 24);
    EXPECT_EQ(j["scene"], scene.string());
    EXPECT_GT(j["povray_seconds"].get<double>(), 0.0);
    EXPECT_LE(j["rmse"].get<double>(), 0.01);
    for (const char* f : {"cmp-povray.png", "cmp-povwall.png", "cmp-diff.png"}) {
        EXPECT_EQ(povwall::output::read_image((keep / f).string()).width, 32) << f;
    }
}

TEST(Cli, CompareWithoutPovRaySaysWhyAndExitsWithCTestSkipCode) {
    fs::path scene = write_scene("nopov.pov", kGreyScene);
    fs::path d = scratch();
    std::string cmd = "PATH=/nonexistent " + std::string(POVWALL_BINARY) + " compare " +
                      scene.string() + " -W 8 -H 8 2>" + (d / "nopov.err").string();
    int status = std::system(cmd.c_str());
    EXPECT_EQ(WEXITSTATUS(status), 77);  // golden tests declare SKIP_RETURN_CODE 77
    std::ifstream in(d / "nopov.err");
    std::string err(std::istreambuf_iterator<char>(in), {});
    EXPECT_EQ(
        err,
        "povwall: povray is not installed or not on PATH: nothing to compare with\n");
}

TEST(Cli, CompareReportsPovRayFailure) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    fs::path scene =
        write_scene("cmpbad.pov", "sphere { 0, 1 pigment { colr rgb 1 } }\n");
    RunResult r = run("compare " + scene.string() + " -W 8 -H 8 --threads 1");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("povwall: error: povray failed (exit ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("Parse Error"), std::string::npos)
        << r.err;  // povray's own text
}

}  // namespace
