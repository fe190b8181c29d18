// End-to-end tests of the povwall binary: exit codes, exact diagnostics, no partial
// output.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>

#include "core/image.h"
#include "output/image_io.h"
#include "tests/cli/run_povwall.h"

namespace {

namespace fs = std::filesystem;
using namespace povwall_test;

// A choice option takes only its names (cli/option_names.h: an enum's one table), never
// the enum's numbers.
TEST(Cli, ChoiceOptionsTakeOnlyTheirNames) {
    fs::path scene = write_scene("choice.pov", "sphere { 0, 1 pigment { rgb 1 } }\n");
    fs::path out = scratch() / "choice.png";
    fs::remove(out);
    RunResult r =
        run("render " + scene.string() + " -W 8 -H 6 -q --mode 1 -o " + out.string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--mode: 1 not in {auto,single,screen,space}"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(out));
    r = run("render " + scene.string() + " -W 8 -H 6 -q --plan all --queue fifo " +
            "--results parents --worker-cores off --worker-start exec -o " +
            out.string());
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(out));
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
    fs::path ok = write_scene(
        "parse_ok.pov",
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
    fs::path unsupported =
        write_scene("parse_material_map.pov",
                    "sphere { 0, 1 }\n  plane { y, 0 pigment { material_map } }\n");
    r = run("parse " + unsupported.string() + " --json");
    EXPECT_EQ(r.code, 3);
    j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["status"], "unsupported");
    EXPECT_EQ(j["message"], "unsupported: material_map");
    EXPECT_EQ(j["line"], 2);
    EXPECT_EQ(j["column"], 26);
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

// diff's exit codes are the table's (cli/exit_codes.h): 0 pass or warning, 1 differs
// (over a threshold, or another size), 2 an unreadable image.
TEST(Cli, DiffReportsMetricsAndExitCodes) {
    fs::path a = scratch() / "a.png", b = scratch() / "b.png", c = scratch() / "c.png";
    povwall::Image ia = flat(10, 10, 0.5f);
    povwall::Image ib = ia;
    // One pixel off by 51/255 = 0.2 in red: bad fraction 0.01, rmse sqrt(0.04/300).
    ib.pixel(3, 4)[0] = (128.0f + 51.0f) / 255.0f;
    save(ia, a);
    save(ib, b);
    RunResult r = run("diff " + a.string() + " " + b.string() + " --json");
    EXPECT_EQ(r.code, 1);  // bad fraction 0.01 > 0.002
    nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_DOUBLE_EQ(j["bad_pixel_fraction"].get<double>(), 0.01);
    EXPECT_NEAR(j["max_abs"].get<double>(), 0.2, 1e-6);
    EXPECT_NEAR(j["rmse"].get<double>(), std::sqrt(0.04 / 300), 1e-6);
    EXPECT_EQ(j["width"], 10);
    EXPECT_EQ(j["height"], 10);
    r = run("diff " + a.string() + " " + b.string() +
            " --max-bad-fraction 0.05 --max-rmse 0.02");
    EXPECT_EQ(r.code, 0);  // within the allowed fraction, but a pixel is over: warning
    EXPECT_NE(r.out.find("WARNING"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("max_abs: 0.200000 @ (3, 4, R) 0.501961 vs 0.701961"),
              std::string::npos)
        << r.out;
    r = run("diff " + a.string() + " " + a.string());
    EXPECT_EQ(r.code, 0);
    EXPECT_NE(r.out.find("psnr: inf"), std::string::npos);
    EXPECT_NE(r.out.find("PASS"), std::string::npos);
    save(flat(5, 10, 0.5f), c);
    EXPECT_EQ(run("diff " + a.string() + " " + c.string()).code, 1);
    EXPECT_EQ(run("diff " + a.string() + " /nonexistent.png").code, 2);
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

// POV-Ray's Unix front end reads one INI before the command line, the first that exists
// of $POVINI, ./povray.ini and ~/.povray/3.7/povray.ini (UnixOptionsProcessor::
// Process_povray_ini); the command line's switches win over it, but a name's first
// Declare is the one POV-Ray keeps; an error in it stops the render (each output below is
// POV-Ray 3.7's for the same files).
TEST(Cli, DefaultIniIsReadFirstAsPovRaysUnixFrontEndDoes) {
    const fs::path dir = scratch() / "default_ini";
    fs::create_directories(dir);
    std::ofstream(dir / "scene.pov")
        << "#debug concat(\"shade \", str(Shade, 0, 2), \" clock \", str(clock, 0, 2), "
           "\"\\n\")\nsphere { 0, 1 pigment { rgb Shade } }\n";
    std::ofstream(dir / "povray.ini") << "Declare=Shade=0.3\nClock=0.5\n";
    std::ofstream(dir / "other.ini") << "Declare=Shade=0.7\n";
    auto render = [&](const std::string& env, const std::string& args) {
        const std::string cmd = "cd " + dir.string() + " && HOME=" + dir.string() + " " +
                                env + " " + POVWALL_BINARY +
                                " render scene.pov -W 4 -H 3 " + args +
                                " -o out.png >out.txt 2>err.txt";
        const int status = std::system(cmd.c_str());
        return std::pair{WEXITSTATUS(status), slurp(dir / "err.txt")};
    };
    auto [code, err] = render("POVINI=", "");
    EXPECT_EQ(code, 0) << err;
    EXPECT_NE(err.find("shade 0.30 clock 0.50\n"), std::string::npos) << err;
    std::tie(code, err) = render("POVINI=other.ini", "");
    EXPECT_NE(err.find("shade 0.70 clock 0.00\n"), std::string::npos) << err;
    std::tie(code, err) = render("POVINI=", "Declare=Shade=0.9 +K0.25");
    EXPECT_NE(err.find("shade 0.30 clock 0.25\n"), std::string::npos) << err;
    std::tie(code, err) =
        render("POVINI=other.ini", "Declare=Shade=0.9 Declare=Shade=0.2");
    EXPECT_NE(err.find("shade 0.70 clock 0.00\n"), std::string::npos) << err;
    // ~/.povray/3.7/povray.ini when the folder has none.
    fs::create_directories(dir / ".povray" / "3.7");
    fs::rename(dir / "povray.ini", dir / ".povray" / "3.7" / "povray.ini");
    std::tie(code, err) = render("POVINI=", "");
    EXPECT_NE(err.find("shade 0.30 clock 0.50\n"), std::string::npos) << err;
    // An unknown key stops the render, as a command line's INI.
    std::ofstream(dir / "povray.ini") << "Declare=Shade=0.4\nFrobnicate=1\n";
    std::tie(code, err) = render("POVINI=", "");
    EXPECT_EQ(code, 2) << err;
    EXPECT_EQ(err.substr(0, err.find('\n')),
              "povwall: error: povray.ini:2: unknown key 'Frobnicate' in INI file");
    EXPECT_FALSE(fs::exists(dir / "out.png.tmp"));
}

TEST(Cli, IniFileSetsSceneSizeAndFormat) {
    fs::path scene = write_scene("ini_scene.pov", kGreyScene);
    fs::path out = scratch() / "from_ini";
    fs::remove(scratch() / "from_ini.tga");
    // Options before any [section] apply; a named section only when it is asked for.
    fs::path ini = write_scene(
        "opts.ini", "; POV-Ray options\nInput_File_Name=" + scene.string() +
                        "\nOutput_File_Name=" + out.string() +
                        "\nWidth=9\nHeight=4\n"
                        "Antialias=Off\nOutput_File_Type=T\nDither=on\nVerbose=on\n"
                        "[Small]\nWidth=3\n");
    RunResult r = run(ini.string() + " -GA");
    ASSERT_EQ(r.code, 0) << r.err;
    // Dither is not implemented: one warning; Verbose cannot change the image: none.
    EXPECT_EQ(r.err, "povwall: warning: " + ini.string() +
                         ":8: Dither=on is accepted but has no effect in povwall\n");
    // No extension given: POV-Ray appends the format's, and +FT means Targa.
    povwall::Image img =
        povwall::output::read_image((scratch() / "from_ini.tga").string());
    EXPECT_EQ(img.width, 9);
    EXPECT_EQ(img.height, 4);
    EXPECT_FLOAT_EQ(img.pixel(8, 3)[0] * 255.0f, 188.0f);  // sRGB(0.5)
    r = run(ini.string() + "[Small] -GA");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(povwall::output::read_image((scratch() / "from_ini.tga").string()).width,
              3);
    // `-o` wins over the INI's Output_File_Name, in any order (benchmark.ini has an
    // empty one).
    fs::path named = scratch() / "named_out.tga";
    fs::remove(named);
    r = run("render -o " + named.string() + " " + ini.string() + " -GA");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(povwall::output::read_image(named.string()).width, 9);
    // An unknown key stops, as in POV-Ray, with its file and line.
    fs::path bad = write_scene("bad.ini", "Width=9\nFrobnicate=1\n");
    r = run(bad.string());
    EXPECT_EQ(r.code, 2);
    // The whole message: the command line was right, so no usage text follows.
    EXPECT_EQ(r.err, "povwall: error: " + bad.string() +
                         ":2: unknown key 'Frobnicate' in INI file\n");
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

TEST(Cli, RadianceHdrHoldsLinearColourWithoutAlpha) {
    fs::path scene = write_scene("hdr.pov", kGreyScene);
    fs::path out = scratch() / "radiance";
    fs::remove(scratch() / "radiance.hdr");
    ASSERT_EQ(
        run("+I" + scene.string() + " +O" + out.string() + " +W3 +H2 +FH +UA -GA").code,
        0);
    fs::path hdr = scratch() / "radiance.hdr";  // POV-Ray's extension for +FH
    EXPECT_EQ(head_bytes(hdr, 10), "#?RADIANCE");
    povwall::Image img = povwall::output::read_image(hdr.string());
    EXPECT_EQ(img.pixel(2, 1)[0], 0.5f);  // exact in RGBE
    EXPECT_EQ(img.pixel(2, 1)[1], 0.0f);
    EXPECT_EQ(img.pixel(2, 1)[2], 1.0f);
    EXPECT_EQ(img.pixel(2, 1)[3], 1.0f);  // no alpha channel in the file: opaque
}

// +FJ writes a JPEG (POV-Ray's quality 85, no alpha even with +UA) named .jpg.
TEST(Cli, JpegOutput) {
    fs::path scene = write_scene("jpeg.pov", kGreyScene);
    fs::path out = scratch() / "photo";
    fs::remove(scratch() / "photo.jpg");
    ASSERT_EQ(
        run("+I" + scene.string() + " +O" + out.string() + " +W16 +H8 +FJ +UA -GA").code,
        0);
    fs::path jpg = scratch() / "photo.jpg";
    EXPECT_EQ(head_bytes(jpg, 3), "\xFF\xD8\xFF");
    povwall::Image img = povwall::output::read_image(jpg.string());
    EXPECT_EQ(img.width, 16);
    EXPECT_NEAR(img.pixel(8, 4)[0], 188.0f / 255, 0.03f);  // sRGB-encoded 0.5, lossy
    EXPECT_NEAR(img.pixel(8, 4)[2], 1.0f, 0.03f);
    EXPECT_EQ(img.pixel(8, 4)[3], 1.0f);
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
    // As POV-Ray's view.cpp: by value, a start in [0, 1) and an end in [0, 1] are
    // fractions (benchmark.ini's Start_Column=0, End_Column=1 is the whole width), the
    // end truncated: 0.75 of 10 columns ends at column 7 (index 6).
    ASSERT_EQ(run("+I" + scene.string() + " +O" + out.string() +
                  " +W10 +H10 +SR0 +ER1 +SC1.0 +EC0.75 -GA")
                  .code,
              0);
    img = povwall::output::read_image(out.string());
    for (int y = 0; y < 10; ++y) {
        for (int x = 0; x < 10; ++x) {
            EXPECT_FLOAT_EQ(img.pixel(x, y)[0] * 255.0f, x <= 6 ? 188.0f : 0.0f)
                << x << "," << y;
        }
    }
    RunResult r = run("+I" + scene.string() + " +SR-1");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err.rfind("povwall: error: bad value in switch '+SR-1'", 0), 0u) << r.err;
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
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.out.find("bad_pixel_fraction: 0.005000 (1 of 200 pixels)\nFAILURE\n"),
              std::string::npos)
        << r.out;
    povwall::Image diff = povwall::output::read_image(d.string());
    EXPECT_FLOAT_EQ(diff.pixel(19, 9)[1] * 255.0f, 51.0f);
    EXPECT_FLOAT_EQ(diff.pixel(0, 0)[1], 0.0f);
    // 1 % allowed over --fail, but the pixel is still over --warn: a warning.
    r = run("diff " + a.string() + " " + b.string() + " --failpercent 1 --max-rmse 0.1");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("WARNING"), std::string::npos);
    r = run("diff " + a.string() + " " + b.string() +
            " --failpercent 1 --warnpercent 1 --max-rmse 0.1 --json");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(nlohmann::json::parse(r.out)["status"], "pass");
    fs::path text = write_scene("notimage.png", "hello");
    r = run("diff " + a.string() + " " + text.string() + " --json");
    EXPECT_EQ(r.code, 2);
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

// POV-Ray splits a switch's value at a space unless it is quoted, and writes an image
// whose name is not ASCII under another name: compare quotes the scene, library and
// output paths and lets POV-Ray render a non-ASCII name into a scratch folder. (A scene
// path that is not ASCII POV-Ray cannot read at all.)
TEST(Cli, CompareTakesPathsWithSpacesAndNonAsciiNames) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const fs::path dir = scratch() / "scenes 2";
    fs::create_directories(dir);
    std::ofstream(dir / "my scene.pov")
        << "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
           "camera { location <0, 0, -3> look_at 0 }\n"
           "light_source { <2, 3, -4> color rgb 1 }\n"
           "sphere { 0, 1 pigment { color rgb <1, 0.5, 0.2> } }\n";
    const fs::path keep = scratch() / "keep 最終";
    fs::remove_all(keep);
    const RunResult r = run("compare '" + (dir / "my scene.pov").string() +
                            "' -W 32 -H 24 --threads 1 --keep '" + keep.string() + "'");
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("PASS"), std::string::npos) << r.out;
    for (const char* f : {"my scene-povray.png", "my scene-povwall.png"})
        EXPECT_EQ(povwall::output::read_image((keep / f).string()).width, 32) << f;
}

// A disc lying in a plane: POV-Ray's rounding picks disc or plane pixel by pixel. Every
// differing pixel is an exact tie, named as such, and --exclude-ties leaves them out.
TEST(Cli, CompareNamesExactTies) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    fs::path scene = write_scene("tie.pov",
                                 "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                                 "camera { location <0, 4, -4> look_at 0 angle 40 }\n"
                                 "light_source { <0, 5, -2> color rgb 1 }\n"
                                 "plane { y, 0 pigment { rgb 0.8 } }\n"
                                 "disc { 0, y, 1 pigment { rgb <1, 0, 0> } }\n");
    RunResult r = run("compare " + scene.string() + " -W 40 -H 30 --threads 1 --json");
    nlohmann::json j = nlohmann::json::parse(r.out);
    const long long bad = j["bad_pixels"].get<long long>();
    EXPECT_GT(bad, 20);  // the disc covers about 230 pixels
    EXPECT_EQ(j["tie_pixels"].get<long long>(), bad);
    EXPECT_EQ(j["pattern_boundary_pixels"].get<long long>(), 0);
    EXPECT_EQ(j["status"], "fail");
    EXPECT_EQ(r.code, 1);  // the images differ (cli/exit_codes.h)
    r = run("compare " + scene.string() + " -W 40 -H 30 --threads 1");
    const std::string b = std::to_string(bad);
    EXPECT_NE(r.out.find("bad pixels: " + b + " (" + b + " exact ties, 0 other)\n"),
              std::string::npos)
        << r.out;
    r = run("compare " + scene.string() + " -W 40 -H 30 --threads 1 --exclude-ties");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("left out of the decision: " + b +
                         " exact ties, 0 on a pattern boundary\nPASS\n"),
              std::string::npos)
        << r.out;
}

// Speed bars are measured with `povwall bench`: both renderers as whole processes,
// alternating, and the medians of the times it lists.
TEST(Cli, BenchAlternatesRendersAndComparesMedians) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    fs::path scene = write_scene("bench.pov",
                                 "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                                 "camera { location <0, 0, -3> look_at 0 }\n"
                                 "light_source { <2, 3, -4> color rgb 1 }\n"
                                 "sphere { 0, 1 pigment { color rgb <1, 0.5, 0.2> } }\n");
    RunResult r =
        run("bench " + scene.string() + " -W 32 -H 24 --threads 1 --runs 4 --json");
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    nlohmann::json j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["runs"], 4);
    auto pov = j["povray_seconds"].get<std::vector<double>>();
    auto ours = j["povwall_seconds"].get<std::vector<double>>();
    ASSERT_EQ(pov.size(), 4u);
    ASSERT_EQ(ours.size(), 4u);
    // The median of an even count is the lower middle time: one that was measured.
    std::sort(pov.begin(), pov.end());
    std::sort(ours.begin(), ours.end());
    EXPECT_EQ(j["povray_median_seconds"].get<double>(), pov[1]);
    EXPECT_EQ(j["povwall_median_seconds"].get<double>(), ours[1]);
    EXPECT_DOUBLE_EQ(j["speed_up"].get<double>(), pov[1] / ours[1]);
    EXPECT_GT(ours[0], 0.0);
    EXPECT_EQ(j["status"], "pass");
    EXPECT_EQ(j["width"], 32);
    EXPECT_LE(j["rmse"].get<double>(), 0.01);
    r = run("bench " + scene.string() + " --runs 0");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--runs: Value 0 not in range 1 to 1000"), std::string::npos)
        << r.err;
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
    // Its own temp directory: the scratch folder goes on this path too.
    const fs::path tmp = scratch() / "tmp";
    fs::create_directories(tmp);
    setenv("TMPDIR", tmp.c_str(), 1);
    RunResult r = run("compare " + scene.string() + " -W 8 -H 8 --threads 1");
    unsetenv("TMPDIR");
    EXPECT_EQ(r.code, 2);
    // POV-Ray's error line first, unwrapped, not its whole log.
    EXPECT_EQ(r.err, "povwall: error: povray failed (exit 1): File '" + scene.string() +
                         "' line 1: Parse Error: No matching } in 'pigment', undeclared "
                         "identifier 'colr' found instead\n");
    EXPECT_TRUE(fs::is_empty(tmp)) << fs::directory_iterator(tmp)->path();
}

// POV-Ray's statistics of the ray tree: the deepest trace level reached ("Max Level") and
// the rays refused for their weight ("Saved"). --stats gives the same numbers, in every
// mode, on nested fresnel glass where adc_bailout prunes most of the tree.
TEST(Cli, StatsMaxLevelAndAdcSavedAgreeWithPovRay) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const std::string scene =
        std::string(POVWALL_SOURCE_DIR) + "/scenes/golden/fresnel_nested_spheres.pov";
    const fs::path log = scratch() / "pov_stats.log";
    const std::string pov = "povray +I" + scene + " +O" + (scratch() / "p.png").string() +
                            " +W16 +H12 -D -A +WT1 >" + log.string() + " 2>&1";
    ASSERT_EQ(std::system(pov.c_str()), 0);
    std::smatch m;
    const std::string text = slurp(log);
    ASSERT_TRUE(std::regex_search(
        text, m, std::regex(R"(Saved:\s+(\d+)\s+Max Level:\s+(\d+)/(\d+))")))
        << text;
    const uint64_t saved = std::stoull(m[1]);
    const int level = std::stoi(m[2]);
    EXPECT_EQ(m[3], "40");
    for (const char* mode : {"", "--boxes 2x2x2", "--boxes 2x1x1 --procs 2"}) {
        SCOPED_TRACE(mode);
        const fs::path stats = scratch() / "nested_stats.json";
        RunResult r = run("render " + scene + " -W 16 -H 12 --threads 1 -q -o " +
                          (scratch() / "n.png").string() + " --stats " + stats.string() +
                          " " + mode);
        ASSERT_EQ(r.code, 0) << r.err;
        const nlohmann::json rays = nlohmann::json::parse(slurp(stats))["rays"];
        EXPECT_EQ(rays["saved_by_adc_bailout"].get<uint64_t>(), saved);
        EXPECT_EQ(rays["max_trace_level_reached"].get<int>(), level);
    }
}

// Every switch that changes the image reaches both renderers: here the version (+MV),
// the clock of an animation's frame and a Declare; an animation is compared on its first
// frame, under POV-Ray's numbered name.
TEST(Cli, CompareGivesPovRayTheSameVersionClockAndDeclares) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    fs::path scene = write_scene("cmpanim.pov", R"(
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 3, -4> color rgb 1 }
sphere { <clock * 2 - 1, 0, 0>, 0.5 + Extra pigment { rgbf <1, 0.5, 0.2, 0.5> } }
)");
    fs::path keep = scratch() / "keepanim";
    fs::remove_all(keep);
    RunResult r = run("compare " + scene.string() +
                      " -W 32 -H 24 --threads 1 --json +MV3.7 Declare=Extra=0.25 +KFI1 "
                      "+KFF4 +KI0 +KF0.75 +SF3 --keep " +
                      keep.string());
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_EQ(nlohmann::json::parse(r.out)["rmse"].get<double>(), 0.0) << r.out;
    for (const char* f : {"cmpanim-povray3.png", "cmpanim-povwall3.png"})
        EXPECT_TRUE(fs::exists(keep / f)) << f;
    EXPECT_FALSE(fs::exists(keep / "cmpanim-povray4.png"));
}

// A scene's .ini of the same name applies first, as `povray SCENE.ini` would: here its
// animation (frame_number picks the colour: frame 0 is a negative subscript), a Declare
// and its size; the command line's -W/-H win over its Width/Height, --no-ini leaves it
// out.
TEST(Cli, CompareReadsTheScenesIniFirst) {
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    const fs::path dir = scratch() / "withini";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path scene = dir / "inianim.pov";
    std::ofstream(scene) << R"(#version 3.7;
#declare Colours = array[3] { rgb <1, 0, 0>, rgb <0, 1, 0>, rgb <0, 0, 1> }
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 3, -4> color rgb 1 }
sphere { <clock, 0, 0>, Radius pigment { Colours[frame_number - 1] } }
)";
    std::ofstream(dir / "inianim.ini") << "; the scene's options\n"
                                          "Input_File_Name=elsewhere.pov\n"
                                          "Width=64\nHeight=48\n"
                                          "Initial_Frame=1\nFinal_Frame=3\n"
                                          "Initial_Clock=0.25\nFinal_Clock=1\n"
                                          "Declare=Radius=0.75\n";
    const fs::path keep = dir / "keep";
    RunResult r =
        run("compare " + scene.string() + " -H 24 --threads 1 --keep " + keep.string());
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("(64x24)"), std::string::npos) << r.out;  // Width=, then -H
    EXPECT_NE(r.err.find("options from " + (dir / "inianim.ini").string()),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.out.find("PASS"), std::string::npos) << r.out;
    for (const char* f : {"inianim-povray1.png", "inianim-povwall1.png"})
        EXPECT_TRUE(fs::exists(keep / f)) << f;
    // Without it, frame_number is 0: POV-Ray's error.
    r = run("compare " + scene.string() + " -W 16 -H 12 --threads 1 --no-ini");
    EXPECT_EQ(r.code, 2) << r.err << r.out;
    EXPECT_NE(r.err.find("povray failed"), std::string::npos) << r.err;
}

// Area-light jitter moves each sample within its cell: the penumbra changes (the
// light's grid alone would band), the lit and shadowed parts do not, and a render
// repeats exactly (the offsets depend on the point, the light and the sample only).
TEST(Cli, AreaLightJitterMovesThePenumbraAndRepeats) {
    const std::string light =
        "light_source { <-2, 5, -2> color rgb 1 area_light x * 3, z * 3, 4, 4 ";
    const std::string rest = R"(}
camera { location <0, 3, -5> look_at 0 angle 45 }
plane { y, -1 pigment { rgb 0.9 } }
sphere { 0, 1 pigment { rgb <0.8, 0.4, 0.2> } }
)";
    const fs::path fixed = write_scene("area_fixed.pov", light + rest),
                   jittered = write_scene("area_jitter.pov", light + "jitter" + rest);
    std::vector<povwall::Image> images;
    for (const fs::path& scene : {fixed, jittered, jittered}) {
        const fs::path out =
            scratch() / ("area" + std::to_string(images.size()) + ".exr");
        ASSERT_EQ(
            run("render " + scene.string() + " -W 48 -H 36 -q -o " + out.string()).code,
            0);
        images.push_back(povwall::output::read_image(out.string()));
    }
    EXPECT_EQ(images[1].rgba, images[2].rgba);
    int moved = 0;
    for (size_t i = 0; i < images[0].rgba.size(); ++i) {
        const float d = std::fabs(images[0].rgba[i] - images[1].rgba[i]);
        moved += d > 1e-4f;
        EXPECT_LT(d, 0.2f) << i;
    }
    EXPECT_GT(moved, 20);
    EXPECT_LT(moved, int(images[0].rgba.size() / 4));
}

}  // namespace

namespace povwall_cli_plan {

TEST(Cli, ExplainPrintsThePlanAndStatsShowWhatWasLeftOut) {
    fs::path scene = write_scene("plan.pov", R"(
camera { location <0, 0, -4> look_at 0 }
light_source { <2, 4, -3> color rgb 1 }
disc { 0, <0, 0.2, -1>, 1 pigment { color rgb <1, 0.6, 0.3> } }
)");
    fs::path out = scratch() / "plan.png", stats = scratch() / "plan.json";
    RunResult r = run("render " + scene.string() +
                      " -W 16 -H 12 -q --threads 2 --explain --worker-memory 1G -o " +
                      out.string() + " --stats " + stats.string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(
        r.out,
        "render plan for " + scene.string() +
            ":\n"
            "  no reflective materials: reflection rays off\n"
            "  no transparent materials: transmission and refraction rays off\n"
            "  light 1 (point light): the only object is flat and cannot shadow "
            "itself: no shadow rays\n"
            "  points a light does not reach (back faces, outside spot cones): no "
            "shadow ray\n"
            "  1 bounded primitives (< 24): no octree, a flat list\n"
            "  shading is linear: contributions go straight to the pixel, no parent "
            "table\n"
            "  scene 0.9 KB fits the 1.0 GB worker budget: one process, no walls; 2 "
            "threads take render blocks as they finish (screen subdivision, one shared "
            "scene)\n");
    // "--stats -": the same JSON on standard output.
    RunResult piped = run("render " + scene.string() + " -W 16 -H 12 -q -o " +
                          out.string() + " --stats -");
    ASSERT_EQ(piped.code, 0) << piped.err;
    EXPECT_EQ(nlohmann::json::parse(piped.out)["rays"]["shadow"], 0);
    EXPECT_FALSE(fs::exists(fs::current_path() / "-"));
    std::ifstream in(stats);
    auto j = nlohmann::json::parse(in);
    EXPECT_EQ(j["rays"]["shadow"], 0);
    EXPECT_EQ(j["rays"]["reflected"], 0);
    EXPECT_EQ(j["rays"]["refracted"], 0);
    EXPECT_EQ(j["plan"]["octree"], "flat list");
    EXPECT_EQ(j["plan"]["mode"], "single");
}

TEST(Cli, BadPlanOptionsExitTwo) {
    fs::path scene = write_scene("plan2.pov", "sphere { 0, 1 }\n");
    RunResult r = run("render " + scene.string() + " -W 8 -H 8 --worker-memory 12Q");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(
        r.err.rfind("povwall: error: bad memory size '12Q' (expected e.g. 512M or 2G)\n",
                    0),
        0u)
        << r.err;
    r = run("render " + scene.string() + " -W 8 -H 8 --boxes 4x4");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(
        r.err.rfind(
            "povwall: error: bad --boxes value '4x4' (expected NxNxN, N or auto)\n", 0),
        0u)
        << r.err;
}

}  // namespace povwall_cli_plan

namespace povwall_cli_screen {

const char* kScreenScene = R"(
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <-3, 6, -4> color rgb 1 }
plane { y, 0 pigment { checker color rgb 1 color rgb 0.2 } finish { reflection 0.2 } }
sphere { <0, 1, 0>, 1 pigment { rgbf <1, 0.9, 0.8, 0.8> } interior { ior 1.4 } }
sphere { <1.6, 0.5, 1>, 0.5 pigment { color rgb <0.2, 0.5, 1> } finish { phong 0.8 } }
)";

povwall::Image read_exr(const fs::path& p) {
    return povwall::output::read_image(p.string());
}

TEST(Cli, ScreenSubdivisionWorkersGiveTheSingleProcessImage) {
    fs::path scene = write_scene("screen.pov", kScreenScene);
    fs::path single = scratch() / "single.exr", screen = scratch() / "screen.exr";
    std::string common = "render " + scene.string() + " -W 70 -H 50 -q ";
    ASSERT_EQ(run(common + "--mode single -o " + single.string()).code, 0);
    // 3 workers, 50 tiles of 32x32 would be 6: the partial last row/column tiles too.
    RunResult r = run(common + "--mode screen --procs 3 --explain -o " + screen.string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(
        r.out.find("  --mode screen: screen subdivision, 3 worker processes each hold "
                   "the whole scene and take tiles as they finish\n"),
        std::string::npos)
        << r.out;
    povwall::Image a = read_exr(single), b = read_exr(screen);
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    EXPECT_EQ(a.rgba, b.rgba);  // bit-identical: the same code per pixel
}

TEST(Cli, DeadScreenWorkerIsNamedAndNoImageIsWritten) {
    fs::path scene = write_scene("screen2.pov", kScreenScene);
    fs::path out = scratch() / "dead.png";
    setenv("POVWALL_FAULT_WORKER_EXIT_AFTER", "1", 1);
    RunResult r =
        run("render " + scene.string() +
            " -W 70 -H 50 -q --mode screen --procs 2 --no-recover -o " + out.string());
    unsetenv("POVWALL_FAULT_WORKER_EXIT_AFTER");
    EXPECT_EQ(r.code, 3);  // a lost worker, as over TCP
    std::smatch m;
    EXPECT_TRUE(
        std::regex_match(r.err, m,
                         std::regex("povwall: error: screen worker [12] \\(pid [0-9]+\\) "
                                    "stopped answering: exit code 3 \\(no image "
                                    "written\\)\n")))
        << r.err;
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace povwall_cli_screen

namespace povwall_cli_interrupt {

TEST(Cli, InterruptedRenderSaysSoAndLeavesNoFile) {
    fs::path dir = scratch() / "interrupt";
    fs::create_directories(dir);
    fs::path out = dir / "walls.png";
    fs::path err = dir / "err";
    // The demo at 1500x1500 on one thread takes seconds: interrupt it 0.3 s after it
    // catches SIGINT (SigCgt bit 2 in /proc), as a background job starts with SIGINT
    // ignored and a loaded machine may take longer than that to reach main().
    std::string cmd = std::string(POVWALL_BINARY) + " render " + POVWALL_SOURCE_DIR +
                      "/scenes/demo/walls.pov -W 1500 -H 1500 --threads 1 -q -o " +
                      out.string() + " 2>" + err.string() +
                      " & pid=$!; for i in $(seq 200); do"
                      " m=$(sed -n \"s/^SigCgt:[[:space:]]*//p\" /proc/$pid/status);"
                      " [ $((0x${m:-0} & 2)) -ne 0 ] && break; sleep 0.05; done;"
                      " sleep 0.3; kill -INT $pid; wait $pid";
    int status = std::system(("sh -c '" + cmd + "'").c_str());
    EXPECT_EQ(WEXITSTATUS(status), 130);
    std::ifstream in(err);
    std::string text(std::istreambuf_iterator<char>(in), {});
    // Where the 0.3 s landed depends on the machine: any phase before the image, named
    // (or none yet, on a machine too busy to start the render).
    const std::string phase =
        R"((parsing .*/walls\.pov:[0-9]+|preparing the scene \([0-9,]+ objects?\)|)"
        R"(building the octree \([0-9,]+ primitives?\)|)"
        R"(tracing: [0-9,]+ of 2,250,000 pixels \([0-9.]+ %\)))";
    EXPECT_TRUE(std::regex_match(
        text, std::regex("\npovwall: interrupted(: no image written| while " + phase +
                         "; no image written)\n")))
        << text;
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.path() != err;
    EXPECT_EQ(files, 0u);  // no image, no temporary
}

}  // namespace povwall_cli_interrupt

// image_map files: a missing one is located at its name; an unreadable one too, with the
// image library's reason; exit 2 and no output file either way.
TEST(Cli, MissingOrUnreadableImageFileIsLocated) {
    fs::path scene = write_scene("img.pov",
                                 "camera { location -3*z }\nplane { z, 0\n"
                                 "  pigment { image_map { png \"no_such.png\" } } }\n");
    fs::path out = scratch() / "img.png";
    fs::remove(out);
    RunResult r = run("render " + scene.string() + " -o " + out.string() + " -W 8 -H 8");
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, scene.string() +
                         ":3:29: error: cannot find image file \"no_such.png\"\n"
                         "  pigment { image_map { png \"no_such.png\" } } }\n"
                         "                            ^~~~~~~~~~~~~\n");
    EXPECT_FALSE(fs::exists(out));

    std::ofstream(scratch() / "garbage.png") << "not an image";
    fs::path bad = write_scene("img2.pov",
                               "camera { location -3*z }\nplane { z, 0 normal {\n"
                               "  bump_map { \"garbage.png\" } } }\n");
    r = run("render " + bad.string() + " -o " + out.string() + " -W 8 -H 8");
    EXPECT_EQ(r.code, 2);
    const std::string head = bad.string() + ":3:14: error: cannot read '" +
                             (scratch() / "garbage.png").string() + "'";
    EXPECT_EQ(r.err.substr(0, head.size()), head) << r.err;
    EXPECT_FALSE(fs::exists(out));
}

namespace povwall_cli_batch {

const char* kSpin = R"(
camera { location <0, 2, -5> look_at 0 }
light_source { <3, 5, -4> color rgb 1 }
sphere { <cos(clock * 2 * pi), 0, sin(clock * 2 * pi)>, 0.5 pigment { color rgb <1, 0.5, 0.2> } }
box { -1, 1 scale <2, 0.05, 2> translate -0.6 * y pigment { checker color rgb 1 color rgb frame_number / 50 } }
)";

std::string slurp_file(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Cli, AnimationFramesAreNumberedAndClockedAsPovRay) {
    fs::path dir = scratch() / "anim";
    fs::create_directories(dir);
    fs::path scene =
        write_scene("spin_numbers.pov",
                    "#debug concat(str(frame_number, 0, 0), \":\", str(clock, 0, 4), "
                    "\":\", str(clock_delta, 0, 4), \" \")\nsphere { 0, 1 }\n");
    RunResult r =
        run("render " + scene.string() + " -W 4 -H 3 +KFI2 +KFF12 +KC +SF10 +EF12 -o " +
            (dir / "c.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    // Cyclic: 11 frames share the clock range 0..1 in 11 steps; numbers padded to 2
    // digits.
    EXPECT_NE(r.err.find("10:0.7273:0.0909 "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("12:0.9091:0.0909 "), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir / "c10.png") && fs::exists(dir / "c11.png") &&
                fs::exists(dir / "c12.png"));
    EXPECT_FALSE(fs::exists(dir / "c09.png"));
}

// POV-Ray's subset of frames: a value between 0 and 1 is a fraction of the frames
// (10 frames: 0.5 is frame 5, 0.7 frame 7), 0 is frame 0. compare renders only the first
// frame of the subset in both renderers, frame 0 included (it rendered every frame when
// an INI started the animation at 0).
TEST(Cli, SubsetFramesAreFractionsOrNumbersAsInPovRay) {
    const fs::path dir = scratch() / "subset";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path scene =
        write_scene("subset.pov", "sphere { 0, 1 pigment { rgb clock } }\n");
    RunResult r =
        run("render " + scene.string() + " -W 4 -H 3 -q +KFI1 +KFF10 +SF0.5 +EF0.7 -o " +
            (dir / "f.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    std::set<std::string> files;
    for (const auto& e : fs::directory_iterator(dir)) files.insert(e.path().filename());
    EXPECT_EQ(files, (std::set<std::string>{"f05.png", "f06.png", "f07.png"}));
    if (!povray_available()) GTEST_SKIP() << "povray is not on PATH";
    // The scene's own INI, which compare reads first.
    write_scene("subset.ini", "Initial_Frame=0\nFinal_Frame=3\n");
    const fs::path keep = dir / "keep";
    r = run("compare " + scene.string() + " -W 4 -H 3 --threads 1 --keep " +
            keep.string());
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    files.clear();
    for (const auto& e : fs::directory_iterator(keep))
        if (e.path().extension() == ".png") files.insert(e.path().filename());
    EXPECT_EQ(files, (std::set<std::string>{"subset-diff.png", "subset-povray0.png",
                                            "subset-povwall0.png"}));
}

TEST(Cli, InterruptedBatchResumesToAllFramesEachAsRenderedAlone) {
    fs::path dir = scratch() / "batch";
    fs::remove_all(dir);
    fs::create_directories(dir / "run");
    fs::create_directories(dir / "alone");
    fs::path scene = write_scene("spin.pov", kSpin);
    const std::string frames = " +KFF50 -W 160 -H 120 -q --threads 1 -o ";
    std::ofstream(dir / "jobs.txt")
        << scene.string() << frames << (dir / "run" / "f.png").string() << "\n";
    // Start the batch in its own process group, interrupt the group (as Ctrl-C does) once
    // a few frames are written, then resume.
    const std::string batch =
        std::string(POVWALL_BINARY) + " batch " + (dir / "jobs.txt").string();
    std::string cmd = "setsid " + batch + " >" + (dir / "out1").string() + " 2>" +
                      (dir / "err1").string() + " & pid=$!; while [ $(ls " +
                      (dir / "run").string() +
                      " | grep -c png) -lt 5 ]; do sleep 0.02; done; /bin/kill -s INT -- "
                      "-$pid; wait $pid";
    int status = std::system(("sh -c '" + cmd + "'").c_str());
    EXPECT_EQ(WEXITSTATUS(status), 130);
    EXPECT_NE(slurp_file(dir / "err1").find("povwall: batch interrupted"),
              std::string::npos);
    size_t before = 0;
    for (const auto& e : fs::directory_iterator(dir / "run")) {
        EXPECT_EQ(e.path().extension(), ".png") << e.path();  // no temporary left behind
        ++before;
    }
    ASSERT_GE(before, 5u);
    ASSERT_LT(before, 50u);
    const auto kept_time = fs::last_write_time(dir / "run" / "f01.png");
    RunResult r = run("batch --resume " + (dir / "jobs.txt").string());
    ASSERT_EQ(r.code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("1 jobs: 1 ok, 0 failed"), std::string::npos) << r.out;
    EXPECT_EQ(fs::last_write_time(dir / "run" / "f01.png"),
              kept_time);  // kept, not redone
    // The same 50 frames rendered in one uninterrupted run.
    r = run("render " + scene.string() + frames + (dir / "alone" / "f.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    for (int f = 1; f <= 50; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "f%02d.png", f);
        ASSERT_TRUE(fs::exists(dir / "run" / name)) << name;
        EXPECT_EQ(slurp_file(dir / "run" / name), slurp_file(dir / "alone" / name))
            << name;
    }
}

// +C (and batch --resume) keeps an image only when it is not older than the scene: an
// image made from an earlier version of the scene is rendered again.
TEST(Cli, ContinueTraceKeepsImagesNewerThanTheSceneAndRedoesStaleOnes) {
    fs::path dir = scratch() / "stale";
    fs::create_directories(dir);
    fs::path scene =
        write_scene("stale.pov", "sphere { 0, 1 pigment { color rgb 1 } }\n");
    const fs::path image = dir / "s.png";
    ASSERT_EQ(run("render " + scene.string() + " -W 8 -H 6 -q -o " + image.string()).code,
              0);
    const auto made = fs::last_write_time(image);
    fs::last_write_time(scene, made - std::chrono::seconds(10));
    RunResult r = run("render " + scene.string() + " -W 8 -H 6 +C -o " + image.string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("s.png exists, kept (+C)"), std::string::npos) << r.err;
    EXPECT_EQ(fs::last_write_time(image), made);
    fs::last_write_time(scene, made + std::chrono::seconds(10));  // edited after
    r = run("render " + scene.string() + " -W 8 -H 6 +C -o " + image.string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(
        r.err.find("s.png is older than " + scene.string() + ", rendered again (+C)"),
        std::string::npos)
        << r.err;
    EXPECT_NE(fs::last_write_time(image), made);
}

// Display, verbosity, pause, abort-test, quality and bounding switches change nothing:
// they used to fall through to +C and keep an existing image.
TEST(Cli, DisplayAndQualitySwitchesDoNotContinueATrace) {
    fs::path dir = scratch() / "noc";
    fs::create_directories(dir);
    fs::path scene = write_scene("noc.pov", "sphere { 0, 1 pigment { color rgb 1 } }\n");
    const fs::path image = dir / "n.png";
    ASSERT_EQ(run("render " + scene.string() + " -W 8 -H 6 -q -o " + image.string()).code,
              0);
    const auto made = fs::last_write_time(image) - std::chrono::seconds(10);
    fs::last_write_time(image, made);
    fs::last_write_time(scene, made - std::chrono::seconds(10));
    RunResult r = run("render " + scene.string() + " -W 8 -H 6 +D +V +P +X +Q9 +B -o " +
                      image.string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("kept (+C)"), std::string::npos) << r.err;
    EXPECT_NE(fs::last_write_time(image), made);
}

TEST(Cli, BatchKeepsGoingPastAFailingJobAndExitsOne) {
    fs::path dir = scratch() / "batch2";
    fs::create_directories(dir);
    fs::path scene = write_scene("ok.pov", "sphere { 0, 1 pigment { color rgb 1 } }\n");
    std::ofstream(dir / "jobs.txt")
        << "# two renders and a missing scene\n"
        << scene.string() << " -W 8 -H 6 -q -o " << (dir / "a.png").string() << "\n"
        << (dir / "missing.pov").string() << " -q\n"
        << scene.string() << " -W 8 -H 6 -q -o " << (dir / "b.png").string() << "\n";
    RunResult r = run("batch " + (dir / "jobs.txt").string());
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(fs::exists(dir / "a.png"));
    EXPECT_TRUE(fs::exists(dir / "b.png"));
    EXPECT_NE(r.out.find("failed(2)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("3 jobs: 2 ok, 1 failed"), std::string::npos) << r.out;
}

}  // namespace povwall_cli_batch

// POV-Ray's end-of-render isosurface messages (IsoSurface::DispatchShutdownMessages),
// located at the function: a max_gradient below the steepest slope the searches met,
// one far above it; none for a copy of a declared isosurface (POV-Ray's isCopy). The
// values are POV-Ray's for this scene ("4.858", "1.000"), in one process and in black
// boxes.
TEST(Cli, IsosurfaceMaxGradientMessagesAsPovRays) {
    const fs::path scene = write_scene(
        "iso_gradient.pov",
        "#version 3.7;\n"
        "global_settings { assumed_gamma 1 }\n"
        "camera { location <0, 2, -5> look_at 0 }\n"
        "light_source { <3, 5, -4> rgb 1 }\n"
        "isosurface { function { x*x + y*y + z*z - 1 + 0.4 * sin(8 * x) * sin(8 * y) }\n"
        "  max_gradient 1.1 contained_by { box { -2, 2 } } pigment { rgb <1, 0.8, 0.5> } "
        "translate -1.2 * x }\n"
        "#declare I = isosurface { function { sqrt(x*x + y*y + z*z) - 0.8 } max_gradient "
        "50 contained_by { sphere { 0, 1 } } pigment { rgb 1 } }\n"
        "object { I translate 1.2 * x }\n"
        "isosurface { function { sqrt(x*x + y*y + z*z) - 0.5 } max_gradient 50 "
        "contained_by { sphere { 0, 1 } } pigment { rgb 1 } translate y }\n");
    const std::string expected =
        scene.string() +
        ":5:14: warning: The maximum gradient found was 4.858, but max_gradient of the\n"
        "isosurface was set to 1.100. The isosurface may contain holes!\n"
        "Adjust max_gradient to get a proper rendering of the isosurface.\n" +
        scene.string() +
        ":9:14: warning: The maximum gradient found was 1.000, but max_gradient of\n"
        "the isosurface was set to 50.000. Adjust max_gradient to\n"
        "get a faster rendering of the isosurface.\n";
    for (const std::string mode : {"", " --boxes 2x1x1"}) {
        const RunResult r =
            run("render " + scene.string() + " -o " + (scratch() / "iso.png").string() +
                " -W 160 -H 120 --quiet" + mode);
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_EQ(r.err, expected) << mode;
    }
}
