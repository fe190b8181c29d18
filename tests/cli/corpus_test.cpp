// `povwall corpus` end to end: five tiny scenes (two that match POV-Ray, one with an
// unsupported object, one with a syntax error, one that hangs the parser) give exact
// counts on stdout and a page with one row per scene, which headless Chromium loads with
// all the images of the rendered scenes.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "tests/cli/run_povwall.h"

namespace {

namespace fs = std::filesystem;
using povwall_test::RunResult;
using povwall_test::slurp;

fs::path work_dir() { return povwall_test::process_scratch("povwall-corpus-test"); }

RunResult run_shell(const std::string& command, const std::string& tag) {
    const fs::path out = work_dir() / (tag + ".out"), err = work_dir() / (tag + ".err");
    const int status =
        std::system((command + " >" + out.string() + " 2>" + err.string()).c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

bool on_path(const std::string& program) {
    return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

size_t count(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos;
         at = text.find(needle, at + 1))
        ++n;
    return n;
}

constexpr int kScenes = 5, kRendered = 2;

class Corpus : public ::testing::Test {
  protected:
    // One corpus run shared by the tests below (POV-Ray plus povwall on five scenes).
    static void SetUpTestSuite() {
        if (!on_path("povray")) return;
        fs::remove_all(work_dir());
        const fs::path scenes = work_dir() / "scenes";
        fs::create_directories(scenes / "golden");
        for (const char* name : {"csg.pov", "camera_look_at.pov"})
            fs::copy_file(fs::path(POVWALL_SOURCE_DIR) / "scenes/golden" / name,
                          scenes / "golden" / name);
        std::ofstream(scenes / "radiosity.pov")
            << "global_settings { photons { count 100 save_file \"x.ph\" } }\n"
               "camera { location <0, 1, -4> look_at 0 }\n"
               "light_source { <2, 4, -3> color rgb 1 }\n"
               "sphere { 0, 1 pigment { rgb 1 } }\n";
        std::ofstream(scenes / "syntax <error>.pov")
            << "camera { location <0, 0, -3> }\nsphere { 0, 1 pigment { colr rgb 1 } }\n";
        // Each loop stays under the parser's runaway-loop limit; together they never end.
        std::ofstream(scenes / "hang.pov")
            << "#declare I = 0;\n#while (I < 5000000)\n  #declare J = 0;\n"
               "  #while (J < 5000000) #declare J = J + 1; #end\n"
               "  #declare I = I + 1;\n#end\n";
        // Relative paths are taken from the list's folder; comments and blanks skipped.
        std::ofstream(work_dir() / "list.txt")
            << "# tiny "
               "corpus\nscenes/golden/csg.pov\n\nscenes/golden/camera_look_at.pov\n"
               "scenes/radiosity.pov\nscenes/syntax <error>.pov\nscenes/hang.pov\n";
        run_ = new RunResult(run_shell(std::string(POVWALL_BINARY) + " corpus " +
                                           (work_dir() / "list.txt").string() +
                                           " -W 32 -H 24 --timeout 4 --html " +
                                           (work_dir() / "report").string(),
                                       "corpus"));
    }
    static void TearDownTestSuite() {
        delete run_;
        run_ = nullptr;
        std::error_code ignored;  // each test binary run has its own folder
        fs::remove_all(work_dir(), ignored);
    }
    void SetUp() override {
        if (!on_path("povray"))
            GTEST_SKIP() << "povray is not on PATH: nothing to compare with";
        ASSERT_NE(run_, nullptr);
        ASSERT_EQ(run_->code, 0) << run_->out << run_->err;
    }
    static RunResult* run_;
};

RunResult* Corpus::run_ = nullptr;

TEST_F(Corpus, PrintsOneLinePerSceneAndExactCounts) {
    const std::string& out = run_->out;
    EXPECT_NE(out.find("5 scenes: 2 matched / 2 rendered / 1 unsupported / 2 failed\n"),
              std::string::npos)
        << out;
    EXPECT_TRUE(std::regex_search(out, std::regex(R"(scenes/golden/csg.pov +matched )")))
        << out;
    EXPECT_TRUE(std::regex_search(
        out, std::regex(R"(scenes/radiosity.pov +unsupported .* photons save_file\n)")))
        << out;
    // The first line of povwall's diagnostic, with the scene named as listed.
    EXPECT_TRUE(std::regex_search(
        out,
        std::regex(
            R"(scenes/syntax <error>.pov +failed .*scenes/syntax <error>.pov:2:\d+: error: )")))
        << out;
    EXPECT_TRUE(std::regex_search(
        out, std::regex(R"(scenes/hang.pov +failed .*timed out after 4.00 s while )"
                        R"(parsing scenes/hang.pov:4\n)")))
        << out;
    EXPECT_TRUE(
        std::regex_search(out, std::regex(R"(POV-Ray \d+\.\d\d s, povwall \d+\.\d\d s)")))
        << out;
}

TEST_F(Corpus, PageHasOneRowPerSceneImagesOfRenderedScenesAndEscapedNames) {
    const fs::path report = work_dir() / "report";
    const std::string page = slurp(report / "index.html");
    const size_t body = page.find("<tbody>");
    ASSERT_NE(body, std::string::npos);
    EXPECT_EQ(count(page.substr(body), "<tr"), size_t(kScenes));
    EXPECT_EQ(count(page, "<tr class=\"matched\""), 2u);
    EXPECT_EQ(count(page, "<tr class=\"failed\""), 2u);
    EXPECT_NE(page.find("syntax &lt;error&gt;.pov"), std::string::npos);
    EXPECT_EQ(page.find("syntax <error>"), std::string::npos);
    EXPECT_EQ(count(page, "<img "), size_t(3 * kRendered));
    for (const char* stem :
         {"001-scenes_golden_csg", "002-scenes_golden_camera_look_at"}) {
        for (const char* kind : {"-povray.png", "-povwall.png", "-diff.png"})
            EXPECT_TRUE(fs::exists(report / "images" / (std::string(stem) + kind)))
                << stem << kind;
    }
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(report / "images")) {
        (void)e;
        ++files;
    }
    EXPECT_EQ(files, size_t(3 * kRendered));  // nothing for the others, no temp files
    for (const auto& e : fs::directory_iterator(report))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos)
            << e.path();
}

TEST_F(Corpus, PageLoadsInHeadlessChromium) {
    if (!on_path("chromium"))
        GTEST_SKIP() << "chromium is not installed (apt-get install chromium): page not "
                        "checked in a browser";
    // --no-sandbox: Chromium refuses to run as root otherwise (CI runs as root).
    const RunResult dom = run_shell(
        "timeout 120 chromium --headless --no-sandbox --disable-gpu --dump-dom "
        "--virtual-time-budget=10000 file://" +
            (work_dir() / "report/index.html").string(),
        "chromium");
    ASSERT_EQ(dom.code, 0) << dom.err;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(dom.out, m, std::regex(R"(<body[^>]*>)"))) << dom.out;
    const std::string body = m.str();
    std::smatch rows, images;
    ASSERT_TRUE(std::regex_search(body, rows, std::regex(R"re(data-rows="(\d+)")re")))
        << body;
    ASSERT_TRUE(
        std::regex_search(body, images, std::regex(R"re(data-images-loaded="(\d+)")re")))
        << body;
    EXPECT_EQ(std::stoi(rows[1]), kScenes);
    EXPECT_EQ(std::stoi(images[1]), 3 * kRendered);
}

TEST(CorpusFolder, StricterThresholdsMismatchAndCachedReferencesKeepTheirTime) {
    if (!on_path("povray"))
        GTEST_SKIP() << "povray is not on PATH: nothing to compare with";
    // A folder this time (searched recursively), with limits nothing passes: both scenes
    // are rendered but mismatched.
    const fs::path dir = work_dir() / "folder";
    fs::remove_all(dir);
    fs::create_directories(dir / "scenes/sub");
    fs::copy_file(fs::path(POVWALL_SOURCE_DIR) / "scenes/golden/csg.pov",
                  dir / "scenes/csg.pov");
    fs::copy_file(fs::path(POVWALL_SOURCE_DIR) / "scenes/golden/camera_look_at.pov",
                  dir / "scenes/sub/look.pov");
    const std::string command =
        std::string(POVWALL_BINARY) + " corpus " + (dir / "scenes").string() +
        " -W 32 -H 24 --max-rmse -1 --max-bad-fraction -1 --html " +
        (dir / "report").string();
    RunResult r = run_shell(command, "strict");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("2 scenes: 0 matched / 2 rendered / 0 unsupported / 0 failed\n"),
              std::string::npos)
        << r.out;
    EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(sub/look.pov +mismatched )")))
        << r.out;
    EXPECT_EQ(slurp(dir / "report/index.html").find("(cached)"), std::string::npos);
    // Again: the references come from REPORT/cache, with the time POV-Ray took for them.
    r = run_shell(command, "strict-cached");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_NE(slurp(dir / "report/index.html").find("(cached)"), std::string::npos);
    EXPECT_EQ(r.out.find("without a recorded time"), std::string::npos) << r.out;
    EXPECT_FALSE(std::regex_search(r.out, std::regex(R"(POV-Ray 0\.00 s)"))) << r.out;
    fs::remove_all(dir);
}

// POV-Ray's jittered area lights are random per run: such a scene is compared by 8x8
// block means, and the report says so; other scenes stay pixel for pixel.
TEST(CorpusFolder, RandomPovRayImagesAreComparedAsBlockMeans) {
    if (!on_path("povray"))
        GTEST_SKIP() << "povray is not on PATH: nothing to compare with";
    const fs::path dir = work_dir() / "random";
    fs::remove_all(dir);
    fs::create_directories(dir / "scenes");
    fs::copy_file(fs::path(POVWALL_SOURCE_DIR) / "scenes/golden/area_light_jitter.pov",
                  dir / "scenes/jitter.pov");
    fs::copy_file(fs::path(POVWALL_SOURCE_DIR) / "scenes/golden/csg.pov",
                  dir / "scenes/csg.pov");
    RunResult r =
        run_shell(std::string(POVWALL_BINARY) + " corpus " + (dir / "scenes").string() +
                      " -W 64 -H 48 --html " + (dir / "report").string(),
                  "random");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_TRUE(std::regex_search(
        r.out,
        std::regex(R"(jitter\.pov +matched .*compared as 8x8 block means \(POV-Ray's )"
                   R"(area-light jitter, photons and rainbow jitter are random\)\n)")))
        << r.out;
    EXPECT_TRUE(
        std::regex_search(r.out, std::regex(R"(csg\.pov +matched [^\n]*[0-9] *\n)")))
        << r.out;
    fs::remove_all(dir);
}

// A scene with an .ini of its name is rendered as a user renders it: the .ini's
// animation on its first frame (frame_number 1 here: frame 0 is a negative subscript),
// under the report's size (not the .ini's Width/Height) and without its anti-aliasing.
// The files the scene writes go to REPORT/files, one folder per renderer, not to the
// folder the corpus runs in; --no-ini leaves the .ini out.
TEST(CorpusIni, SceneIniGivesTheFirstFrameAndWrittenFilesStayInTheReport) {
    if (!on_path("povray"))
        GTEST_SKIP() << "povray is not on PATH: nothing to compare with";
    const fs::path dir = work_dir() / "ini";
    fs::remove_all(dir);
    fs::create_directories(dir / "scenes");
    fs::create_directories(dir / "cwd");
    std::ofstream(dir / "scenes/anim.pov")
        << "#version 3.7;\n"
           "#declare Colours = array[2] { rgb <1, 0.5, 0>, rgb <0, 0.5, 1> }\n"
           "#fopen Out \"written.txt\" write\n"
           "#write (Out, frame_number, \"\\n\")\n"
           "#fclose Out\n"
           "camera { location <0, 0, -3> look_at 0 }\n"
           "light_source { <2, 3, -4> color rgb 1 }\n"
           "sphere { <clock, 0, 0>, 1 pigment { Colours[frame_number - 1] } }\n";
    std::ofstream(dir / "scenes/anim.ini")
        << "Input_File_Name=anim.pov\nWidth=640\nHeight=480\nAntialias=on\n"
           "Initial_Frame=1\nFinal_Frame=2\nInitial_Clock=-0.5\nFinal_Clock=0.5\n";
    const std::string command = "cd " + (dir / "cwd").string() + " && " +
                                std::string(POVWALL_BINARY) + " corpus " +
                                (dir / "scenes").string() + " -W 32 -H 24 --html " +
                                (dir / "report").string();
    RunResult r = run_shell(command, "ini");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("1 scenes: 1 matched / 1 rendered / 0 unsupported / 0 failed\n"),
              std::string::npos)
        << r.out;
    // The report's images under their own names, at the report's size: a PNG's width
    // and height are the big-endian words at bytes 16 and 20.
    for (const char* kind : {"povray", "povwall"}) {
        const std::string png =
            slurp(dir / "report/images" / (std::string("001-anim-") + kind + ".png"));
        ASSERT_GT(png.size(), 24u) << kind;
        EXPECT_EQ((unsigned char)png[19], 32) << kind;
        EXPECT_EQ((unsigned char)png[23], 24) << kind;
        const fs::path written = dir / "report/files/001-anim" / kind / "written.txt";
        EXPECT_EQ(slurp(written), "1\n") << written;
    }
    EXPECT_TRUE(fs::is_empty(dir / "cwd"));
    // Without the .ini, frame_number is 0 and the subscript negative.
    r = run_shell(command + " --no-ini", "no-ini");
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("1 scenes: 0 matched / 0 rendered / 0 unsupported / 1 failed\n"),
              std::string::npos)
        << r.out;
    fs::remove_all(dir);
}

TEST(CorpusUsage, MissingSourceOrBadOptionsExitTwo) {
    fs::create_directories(work_dir());
    RunResult r = run_shell(std::string(POVWALL_BINARY) + " corpus /nonexistent/list.txt",
                            "usage1");
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("no such scene folder or list file '/nonexistent/list.txt'"),
              std::string::npos)
        << r.err;
    r = run_shell(std::string(POVWALL_BINARY) + " corpus", "usage2");
    EXPECT_EQ(r.code, 2);
    r = run_shell(
        std::string(POVWALL_BINARY) + " corpus " + work_dir().string() + " --timeout 0",
        "usage3");
    EXPECT_EQ(r.code, 2);
}

}  // namespace
