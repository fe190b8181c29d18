// POV-Ray .ini files read as POV-Ray 3.7 reads them (notes/parser-rules.md §4): every key
// of its table accepted, warnings only for keys that could change the image, POV-Ray's
// booleans, value lists, bare words, sections and errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/options.h"
#include "tests/scratch_folder.h"

namespace {

namespace fs = std::filesystem;
using povwall::cli::RenderOptions;
using povwall::cli::UsageError;

struct Read {
    RenderOptions o;
    std::string warnings;
};

Read read_ini(const std::string& text) {
    Read r;
    std::istringstream in(text);
    std::ostringstream warnings;
    povwall::cli::apply_ini_stream(in, "t.ini", r.o, &warnings);
    r.warnings = warnings.str();
    return r;
}

std::string error_of(const std::string& text) {
    try {
        read_ini(text);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "(no error)";
}

fs::path scratch_dir() { return povwall_test::process_scratch("povwall-ini-test"); }

fs::path write(const std::string& name, const std::string& text) {
    fs::path p = scratch_dir() / name;
    std::ofstream(p) << text;
    return p;
}

// Every key of POV-Ray 3.7's RenderOptions_INI_Table at its default: accepted, and no
// warning (none of them changes the image).
TEST(Ini, EveryPovRayKeyIsAcceptedAndDefaultsAreQuiet) {
    const char* keys =
        "All_Console=on\nAll_File=\nAntialias_Depth=3\nAntialias=off\n"
        "Antialias_Threshold=0.3\nAntialias_Gamma=2.5\nAppend_File=off\n"
        "Bits_Per_Color=8\nBits_Per_Colour=8\nBounding=on\nBounding_Method=1\n"
        "Bounding_Threshold=3\nBSP_BaseAccessCost=1\nBSP_ChildAccessCost=1.5\n"
        "BSP_ISectCost=150\nBSP_MaxDepth=0\nBSP_MissChance=0.2\nClock=0\n"
        "Clockless_Animation=off\nCompression=0\nContinue_Trace=off\nCreate_Ini=x.ini\n"
        "Cyclic_Animation=off\nDebug_Console=on\nDebug_File=d.log\nDeclare=Q=1\n"
        "Display=off\nDisplay_Gamma=sRGB\nDither=off\nDither_Method=B2\n"
        "Draw_Vistas=off\nEnd_Column=1\nEnd_Row=1\nFatal_Console=on\n"
        "Fatal_Error_Command=echo \"failed\" ; a comment\nFatal_Error_Return=I\n"
        "Fatal_File=f.log\nField_Render=off\nFile_Gamma=srgb\nFinal_Clock=1\n"
        "Final_Frame=1\nFrame_Step=1\nGrayscale_Output=off\nHeight=240\n"
        "High_Reproducibility=off\nInitial_Clock=0\nInitial_Frame=1\n"
        "Input_File_Name=scene.pov\nInclude_Header=\nJitter_Amount=1.0\nJitter=on\n"
        "Library_Path=inc\nLight_Buffer=on\nMax_Image_Buffer_Memory=128\nOdd_Field=off\n"
        "Output_Alpha=off\nOutput_File_Name=out.png\nOutput_File_Type=N\n"
        "Output_To_File=on\nPalette=3\nPause_When_Done=off\nPost_Frame_Command=\n"
        "Post_Frame_Return=I\nPost_Scene_Command=\nPost_Scene_Return=I\n"
        "Preview_End_Size=1\nPreview_Start_Size=1\nPre_Frame_Command=\n"
        "Pre_Frame_Return=I\nPre_Scene_Command=\nPre_Scene_Return=I\nQuality=9\n"
        "Radiosity_File_Name=\nRadiosity_From_File=off\nRadiosity_To_File=off\n"
        "Radiosity_Vain_Pretrace=on\nReal_Time_Raytracing=off\nRemove_Bounds=on\n"
        "Render_Block_Size=32\nRender_Block_Step=0\nRender_Console=on\n"
        "Render_File=r.log\nRender_Pattern=0\nSampling_Method=1\nSplit_Unions=off\n"
        "Start_Column=0\nStart_Row=0\nStatistic_Console=on\nStatistic_File=s.log\n"
        "Subset_End_Frame=1\nSubset_Start_Frame=1\nTest_Abort_Count=0\nTest_Abort=off\n"
        "User_Abort_Command=\nUser_Abort_Return=I\nVerbose=off\nVersion=3.7\n"
        "Video_Mode=0\nVista_Buffer=on\nWarning_Console=on\nWarning_File=w.log\n"
        "Warning_Level=5\nWidth=320\nWork_Threads=2\n";
    Read r = read_ini(keys);
    EXPECT_EQ(r.warnings, "");
    EXPECT_EQ(r.o.scene, "scene.pov");
    EXPECT_EQ(r.o.output, "out.png");
    EXPECT_EQ(r.o.width, 320);
    EXPECT_EQ(r.o.height, 240);
    EXPECT_EQ(r.o.library_paths, std::vector<std::string>{"inc"});
    EXPECT_FALSE(r.o.render.antialias);
    EXPECT_EQ(r.o.render.aa_threshold, 0.3);
    EXPECT_EQ(r.o.render.aa_depth, 3);
    EXPECT_TRUE(r.o.render.aa_jitter);
    EXPECT_EQ(r.o.render.aa_jitter_amount, 1.0);
    EXPECT_EQ(r.o.render.threads, 2);
    EXPECT_EQ(r.o.declares.at("Q"), 1.0);
    EXPECT_EQ(r.o.language_version, 370);
    // Start 0 and end 1 are fractions: the whole image.
    povwall::cli::resolve_partial_render(r.o);
    EXPECT_EQ(r.o.render.first_col, 0);
    EXPECT_EQ(r.o.render.last_col, 319);
    EXPECT_EQ(r.o.render.first_row, 0);
    EXPECT_EQ(r.o.render.last_row, 239);
}

// The anti-aliasing gamma and the render block size act (blocks decide the
// anti-aliasing); POV-Ray refuses blocks under 4 pixels.
TEST(Ini, AntialiasGammaAndRenderBlockSize) {
    Read r = read_ini("Antialias_Gamma=1.8\nRender_Block_Size=16\n");
    EXPECT_EQ(r.warnings, "");
    EXPECT_EQ(r.o.render.aa_gamma, 1.8);
    EXPECT_EQ(r.o.render.block_size, 16);
}

TEST(Ini, FileGammaAsPovRayReadsIt) {
    // A number above 0 is a power law (1: neutral), else only sRGB (any case).
    EXPECT_EQ(read_ini("File_Gamma=1.0").o.file_gamma, 1.0f);
    EXPECT_EQ(read_ini("File_Gamma=1.8").o.file_gamma, 1.8f);
    EXPECT_EQ(read_ini("File_Gamma=2.2abc").o.file_gamma, 2.2f);
    EXPECT_EQ(read_ini("File_Gamma=1.8\nFile_Gamma=SRGB").o.file_gamma, std::nullopt);
    EXPECT_EQ(read_ini("File_Gamma=srgb").warnings, "");
    EXPECT_EQ(error_of("File_Gamma=0"), "t.ini:1: Unrecognized gamma setting '0'.");
    EXPECT_EQ(error_of("File_Gamma=-2.2"), "t.ini:1: Unrecognized gamma setting '-2.2'.");
    EXPECT_EQ(error_of("File_Gamma=bt709"),
              "t.ini:1: Unrecognized gamma setting 'bt709'.");
    // Display_Gamma is the preview window's: checked the same way, the file keeps sRGB.
    Read d = read_ini("Display_Gamma=1.8");
    EXPECT_EQ(d.o.file_gamma, std::nullopt);
    EXPECT_EQ(d.warnings, "");
    EXPECT_EQ(error_of("Display_Gamma=x"), "t.ini:1: Unrecognized gamma setting 'x'.");
}

TEST(Ini, OptionsOnTheCommandLineAsPovRayTakesThem) {
    RenderOptions o;
    EXPECT_TRUE(povwall::cli::looks_like_pov_switch("File_Gamma=1.0"));
    EXPECT_TRUE(povwall::cli::looks_like_pov_switch("width=64"));
    EXPECT_FALSE(povwall::cli::looks_like_pov_switch("Not_A_Key=1"));
    EXPECT_FALSE(povwall::cli::looks_like_pov_switch("scene.pov"));
    EXPECT_TRUE(povwall::cli::apply_pov_switch("File_Gamma=1.0", o));
    EXPECT_TRUE(povwall::cli::apply_pov_switch("width=64", o));
    EXPECT_EQ(o.file_gamma, 1.0f);
    EXPECT_EQ(o.width, 64);
    try {
        povwall::cli::apply_pov_switch("File_Gamma=0", o);
        ADD_FAILURE() << "no error";
    } catch (const UsageError& e) {
        EXPECT_STREQ(e.what(), "command line:1: Unrecognized gamma setting '0'.");
    }
}

TEST(Ini, KeysThatCouldChangeTheImageWarnOnceEachDisplayKeysStaySilent) {
    Read r = read_ini(
        "Quality=4\nVerbose=on\nTest_Abort_Count=100\nPause_When_Done=on\n"
        "Antialias_Gamma=1.0\nFile_Gamma=2.2\nDisplay_Gamma=1.8\nGrayscale_Output=on\n"
        "Dither=on\nDither_Method=FS\nField_Render=on\nOdd_Field=on\nSplit_Unions=on\n"
        "Remove_Bounds=off\nHigh_Reproducibility=on\nRadiosity_From_File=on\n"
        "Radiosity_File_Name=r.rad\nInclude_Header=head.inc\nFrame_Step=2\n"
        "Output_To_File=off\nQuality=11\nPre_Scene_Command=make textures\n"
        "Buffer_Output=on\nHistogram_Type=C\n");
    EXPECT_EQ(
        r.warnings,
        "povwall: warning: t.ini:8: Grayscale_Output=on is accepted but has no "
        "effect in povwall\n"
        "povwall: warning: t.ini:9: Dither=on is accepted but has no effect in "
        "povwall\n"
        "povwall: warning: t.ini:10: Dither_Method=FS is accepted but has no effect "
        "in povwall\n"
        "povwall: warning: t.ini:11: Field_Render=on is accepted but has no effect "
        "in povwall\n"
        "povwall: warning: t.ini:12: Odd_Field=on is accepted but has no effect in "
        "povwall\n"
        "povwall: warning: t.ini:13: Split_Unions=on is accepted but has no effect "
        "in povwall\n"
        "povwall: warning: t.ini:14: Remove_Bounds=off is accepted but has no effect "
        "in povwall\n"
        "povwall: warning: t.ini:15: High_Reproducibility=on is accepted but has no "
        "effect in povwall\n"
        "povwall: warning: t.ini:16: Radiosity_From_File=on is accepted but has no "
        "effect in povwall\n"
        "povwall: warning: t.ini:17: Radiosity_File_Name=r.rad is accepted but has "
        "no effect in povwall\n"
        "povwall: warning: t.ini:18: Include_Header=head.inc is accepted but has no "
        "effect in povwall\n"
        "povwall: warning: t.ini:19: Frame_Step=2 is accepted but has no effect in "
        "povwall\n"
        "povwall: warning: t.ini:20: Output_To_File=off is accepted but has no "
        "effect in povwall\n"
        "povwall: warning: t.ini:23: INI option 'Buffer_Output' is no longer used "
        "and will result in an error in future versions of POV-Ray\n"
        "povwall: warning: t.ini:24: INI option 'Histogram_Type' is no longer used "
        "and will result in an error in future versions of POV-Ray\n");
    // Quality acts (+Q): the last one given, 11 clamped to 9.
    EXPECT_EQ(r.o.render.quality, 9);
    EXPECT_EQ(read_ini("Quality=4").o.render.quality, 4);
    // Quiet options: nothing printed.
    std::istringstream in("Dither=on\n");
    std::ostringstream warnings;
    RenderOptions quiet;
    quiet.quiet = true;
    povwall::cli::apply_ini_stream(in, "q.ini", quiet, &warnings);
    EXPECT_EQ(warnings.str(), "");
}

TEST(Ini, BooleansAsPovRay) {
    // True when the value and on/true/yes/1 agree over the shorter of the two.
    for (const char* v : {"on", "On", "TRUE", "y", "yes", "1", "10", "o", ""}) {
        EXPECT_TRUE(read_ini(std::string("Antialias=") + v).o.render.antialias) << v;
    }
    for (const char* v : {"off", "false", "no", "0", "nope", "2"}) {
        Read r = read_ini(std::string("Antialias=on\nAntialias=") + v);
        EXPECT_FALSE(r.o.render.antialias) << v;
    }
    // The threshold and the jitter amount do not turn anything on (raddem.ini has
    // Antialias=Off then Antialias_Threshold=0.2).
    Read r = read_ini(
        "Antialias=Off\nAntialias_Threshold=0.2\nJitter=off\nJitter_Amount=0.5\n");
    EXPECT_FALSE(r.o.render.antialias);
    EXPECT_EQ(r.o.render.aa_threshold, 0.2);
    EXPECT_FALSE(r.o.render.aa_jitter);
    EXPECT_EQ(r.o.render.aa_jitter_amount, 0.5);
}

TEST(Ini, ValuesListsSwitchesAndComments) {
    Read r = read_ini(
        "Library_Path = inc1, \"with space\" ,'q' ; a comment\n"
        "Width=100, 200\n"
        "  +H50 -A +WT3 ; switches, several on a line\n"
        "Input_File_Name=my scene.pov ; unquoted path with a space\n"
        "Output_File_Name=out.png Width=5\n"
        "# a comment\n"
        "Version = 3.5\n"
        "Initial_Frame=2.9\n");
    EXPECT_EQ(r.o.library_paths, (std::vector<std::string>{"inc1", "with space", "q"}));
    EXPECT_EQ(r.o.width, 200);  // once per value; `Width=5` after a value is ignored
    EXPECT_EQ(r.o.height, 50);
    EXPECT_FALSE(r.o.render.antialias);
    EXPECT_EQ(r.o.render.threads, 3);
    EXPECT_EQ(r.o.scene, "my scene.pov");
    EXPECT_EQ(r.o.output, "out.png");
    EXPECT_EQ(r.o.language_version, 350);
    EXPECT_EQ(r.o.animation.initial_frame, 2);  // %d reads the integer part
}

// Found by fuzz_ini: a carriage return mid-file made no progress and the reader looped
// forever, as did a comma before an item. White space of any kind and commas separate
// items; other control characters are errors.
TEST(Ini, StrayControlCharacters) {
    Read r = read_ini("\rWidth=64\n\fHeight=32\n\v+A0.2\n, ,+W48\n");
    EXPECT_EQ(r.o.width, 48);
    EXPECT_EQ(r.o.height, 32);
    EXPECT_TRUE(r.o.render.antialias);
    EXPECT_EQ(error_of(std::string("Width=64\n\r\0Height=32\n", 22)),
              "t.ini:2: unexpected control character 0x00");
}

TEST(Ini, BareWordsSectionsAndIncludes) {
    const fs::path inner = write("inner.ini", "Height=77\n");
    const fs::path sections = write(
        "sections.ini", "Width=10\n[Big]\nWidth=800\n[Small]\nWidth=20\nHeight=5\n");
    // A .pov name is the scene, a name ending in '/' a library path, anything else an
    // INI file to read (found with .ini added too).
    Read r = read_ini("scene.pov\nlib/\n" + (scratch_dir() / "inner").string() + "\n");
    EXPECT_EQ(r.o.scene, "scene.pov");
    EXPECT_EQ(r.o.library_paths, std::vector<std::string>{"lib/"});
    EXPECT_EQ(r.o.height, 77);
    r = read_ini("Include_Ini=" + inner.string() + "\n");
    EXPECT_EQ(r.o.height, 77);
    // Named sections are read only when asked for (case-insensitively), and only that
    // one; what comes before the first section always applies.
    RenderOptions o;
    povwall::cli::apply_ini_file(sections.string(), o, nullptr);
    EXPECT_EQ(o.width, 10);
    EXPECT_EQ(o.height, 240);
    RenderOptions small;
    povwall::cli::apply_ini_file(sections.string() + "[small]", small, nullptr);
    EXPECT_EQ(small.width, 20);
    EXPECT_EQ(small.height, 5);
    EXPECT_TRUE(povwall::cli::looks_like_ini_file(sections.string() + "[Big]"));
    RenderOptions big;
    povwall::cli::apply_ini_file(sections.string() + "[Big]", big, nullptr);
    EXPECT_EQ(big.width, 800);
    EXPECT_EQ(big.height, 240);
    // An INI file that includes itself stops with a located error.
    const fs::path loop = write("loop.ini", "loop.ini\n");
    const fs::path cwd = fs::current_path();
    fs::current_path(scratch_dir());
    RenderOptions l;
    std::string message;
    try {
        povwall::cli::apply_ini_file("loop.ini", l, nullptr);
    } catch (const UsageError& e) {
        message = e.what();
    }
    fs::current_path(cwd);
    EXPECT_EQ(message, "loop.ini:1: INI files included too deeply (limit 16)");
}

TEST(Ini, UnknownKeysAndBadValuesAreLocatedErrors) {
    EXPECT_EQ(error_of("Width=9\nFrobnicate=1\n"),
              "t.ini:2: unknown key 'Frobnicate' in INI file");
    EXPECT_EQ(error_of("Width=abc\n"),
              "t.ini:1: integer parameter expected for option 'Width', found 'abc'");
    EXPECT_EQ(error_of("Final_Frame=\n"),
              "t.ini:1: integer parameter expected for option 'Final_Frame', found ''");
    EXPECT_EQ(error_of("Jitter_Amount=x\n"),
              "t.ini:1: floating-point parameter expected for option 'Jitter_Amount', "
              "found 'x'");
    EXPECT_EQ(error_of("Test_Abort_Count=many\n"),
              "t.ini:1: integer parameter expected for option 'Test_Abort_Count', found "
              "'many'");
    EXPECT_EQ(error_of("\n+ZZ9\n"), "t.ini:2: unknown switch '+ZZ9'");
    EXPECT_EQ(error_of("Input_File_Name=a.pov\nmissing_options\n"),
              "t.ini:2: cannot open option file 'missing_options'");
}

// The INI files of POV-Ray's examples are accepted, except __empty.ini, which POV-Ray
// refuses too (`Final_Frame=` has no value).
TEST(Ini, PovRayExampleFilesAreAccepted) {
    const fs::path examples = "/usr/share/doc/povray/examples";
    if (!fs::is_directory(examples)) GTEST_SKIP() << "no " << examples;
    int files = 0;
    for (const auto& e : fs::recursive_directory_iterator(examples)) {
        if (e.path().extension() != ".ini") continue;
        RenderOptions o;
        std::ostringstream warnings;
        if (e.path().filename() == "__empty.ini") {
            EXPECT_THROW(povwall::cli::apply_ini_file(e.path().string(), o, &warnings),
                         UsageError);
            continue;
        }
        EXPECT_NO_THROW(povwall::cli::apply_ini_file(e.path().string(), o, &warnings))
            << e.path();
        EXPECT_FALSE(o.scene.empty()) << e.path();
        ++files;
        if (e.path().filename() == "benchmark.ini") {
            const std::string at = e.path().string() + ":";
            EXPECT_EQ(warnings.str(),
                      "povwall: warning: " + at +
                          "41: Output_To_File=Off is accepted but has no effect in "
                          "povwall\n");
            EXPECT_EQ(o.width, 512);
            EXPECT_TRUE(o.render.antialias);
            EXPECT_EQ(o.language_version, 370);
        } else {
            EXPECT_EQ(warnings.str(), "") << e.path();
        }
    }
    EXPECT_EQ(files, 40);
}

}  // namespace
