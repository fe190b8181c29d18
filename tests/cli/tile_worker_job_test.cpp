// The screen workers' settings travel as one typed job (cli/tile_worker_job.h): what the
// coordinator writes on a worker's command line reads back to the same job, bit for bit.
#include "cli/tile_worker_job.h"

#include <gtest/gtest.h>

#include <limits>

namespace {

using povwall::cli::RenderOptions;
using povwall::cli::TileWorkerJob;
using povwall::cli::UsageError;

// Every field away from its default, doubles that need all 17 digits.
TileWorkerJob populated() {
    TileWorkerJob j;
    j.name = "dir with space/a=b.pov";
    j.width = 641;
    j.height = 479;
    j.plan = povwall::cli::PlanChoice::All;
    j.library_paths = {"/inc", "rel/dir", "x=y"};
    j.declares = {{"Angle", 0.1}, {"N", -3}, {"Tiny", 1e-300}};
    j.language_version = 362;
    j.output_file_type = 'E';
    j.alpha = true;
    j.quality = 5;
    j.antialias = true;
    j.aa_threshold = 1.0 / 3;
    j.aa_method = 2;
    j.aa_depth = 4;
    j.aa_jitter = false;
    j.aa_jitter_amount = 0.7;
    j.aa_gamma = -1;
    j.max_trace_level = 12;
    j.adc_bailout = 0.1 + 0.2;
    j.max_loop_iterations = std::numeric_limits<uint64_t>::max();
    j.frame = RenderOptions::FrameValues{7, 0.7000000000000001, 1.0 / 9};
    j.initial_frame = 3;
    j.final_frame = 19;
    j.initial_clock = -0.25;
    j.final_clock = 2.0 / 3;
    j.clock = 0.123456789012345678;
    return j;
}

TEST(TileWorkerJob, CommandLineReadsBackToTheSameJob) {
    const TileWorkerJob job = populated();
    const std::vector<std::string> argv = job.to_argv();
    ASSERT_FALSE(argv.empty());
    EXPECT_EQ(argv[0], TileWorkerJob::kFlag);
    EXPECT_EQ(TileWorkerJob::from_argv(argv), job);
    // Defaults (no frame, no overrides, empty lists) too.
    EXPECT_EQ(TileWorkerJob::from_argv(TileWorkerJob{}.to_argv()), TileWorkerJob{});
}

TEST(TileWorkerJob, MadeFromRenderOptionsAndAppliedBack) {
    RenderOptions o;
    o.scene = "s.pov";
    o.width = 50;
    o.render.antialias = true;
    o.render.aa_threshold = 0.2;
    o.adc_bailout = 0.01;
    o.frame = RenderOptions::FrameValues{2, 0.5, 0.25};
    o.animation.final_frame = 5;
    o.declares["K"] = 2.5;
    const TileWorkerJob job = TileWorkerJob::of(o);
    EXPECT_EQ(job.aa_threshold, 0.2);
    RenderOptions w;
    TileWorkerJob::from_argv(job.to_argv()).apply_to(w);
    EXPECT_EQ(TileWorkerJob::of(w), job);
    EXPECT_TRUE(w.tile_worker);
    EXPECT_TRUE(w.quiet);
    EXPECT_EQ(w.render.threads, 1);
}

TEST(TileWorkerJob, UnknownOrMalformedArgumentsAreRefused) {
    std::vector<std::string> argv = TileWorkerJob{}.to_argv();
    EXPECT_THROW(TileWorkerJob::from_argv({}), UsageError);
    EXPECT_THROW(TileWorkerJob::from_argv({"--width=3"}), UsageError);
    for (const char* bad : {"--colour=3", "--width=3x", "--width=", "--alpha=2",
                            "--clock=abc", "--frame=1,2", "--declare=3", "scene.pov",
                            "--output_file_type=EX", "--aa-method=2"}) {
        std::vector<std::string> a = argv;
        a.push_back(bad);
        EXPECT_THROW(TileWorkerJob::from_argv(a), UsageError) << bad;
    }
}

}  // namespace
