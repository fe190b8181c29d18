// Anti-aliasing in waves (the black boxes' way): the blocks replayed against samples
// traced wave by wave give the one-process image bit for bit, in a few waves.
#include "trace/sample_waves.h"

#include <gtest/gtest.h>

#include "scene_builder.h"
#include "trace/camera_interiors.h"
#include "trace/focal_blur.h"
#include "trace/render.h"
#include "trace/tracer.h"

namespace povwall::trace {
namespace {

using namespace povwall::test;

// Spheres in front of a checkered wall: edges and a texture for the anti-aliasing.
Scene spheres_on_checker_scene() {
    Scene s;
    s.camera.location = {0, 0, -5};
    s.background = Colour(Rgb{0.5f, 0.5f, 0.5f});
    s.objects.push_back(object(Sphere{{0, 0, 0}, 1.2}, {}, {solid({0.9f, 0.1f, 0.1f})}));
    s.objects.push_back(
        object(Sphere{{1.3, 0.8, -1}, 0.4}, {}, {solid({0.1f, 0.2f, 0.9f})}));
    s.lights.push_back(point_light({-3, 4, -6}));
    return s;
}

// Traces every wave in this process, as render_scene traces its samples.
struct OneProcessWaves {
    RenderPlan plan;
    PreparedScene prepared;
    CameraInteriors interiors;
    Tracer tracer;
    const Scene& scene;
    const RenderSettings& settings;
    OneProcessWaves(const Scene& s, const RenderSettings& rs)
        : plan(make_render_plan(s, false, rs.quality)),
          prepared(s, &plan),
          interiors(s),
          tracer(prepared),
          scene(s),
          settings(rs) {
        prepared.set_alpha_background(rs.alpha);
    }
    void operator()(const std::vector<SamplePosition>& wave, std::vector<float>& rgbt) {
        CameraSamples samples(tracer, scene.camera, interiors, settings);
        for (size_t i = 0; i < wave.size(); ++i)
            EXPECT_TRUE(samples.sample(wave[i].x, wave[i].y, &rgbt[i * 4]));
    }
};

struct Case {
    int method, depth;
    double threshold;
    bool jitter, alpha;
    int block_size;
    size_t max_waves;
};

TEST(SampleWaves, ReplayedBlocksGiveTheOneProcessImageInAFewWaves) {
    const Scene scene = spheres_on_checker_scene();
    for (const Case& c :
         {Case{1, 3, 0.3, true, false, 32, 3}, Case{1, 2, 0.1, false, true, 8, 3},
          Case{1, 4, 0.0, true, false, 5, 2}, Case{1, 3, 1.0, true, false, 16, 3},
          Case{2, 3, 0.3, true, false, 32, 3}, Case{2, 4, 0.1, true, true, 7, 4},
          Case{2, 1, 0.1, false, false, 32, 1}}) {
        SCOPED_TRACE(::testing::Message()
                     << "+AM" << c.method << " +R" << c.depth << " +A" << c.threshold
                     << " +BS" << c.block_size);
        RenderSettings rs;
        rs.width = 64;
        rs.height = 48;
        rs.threads = 2;
        rs.antialias = true;
        rs.aa_method = c.method;
        rs.aa_depth = c.depth;
        rs.aa_threshold = c.threshold;
        rs.aa_jitter = c.jitter;
        rs.alpha = c.alpha;
        rs.block_size = c.block_size;
        rs.first_col = 3;  // a render area not at the image's corner
        rs.first_row = 2;
        const Image direct = render_scene(scene, rs);
        OneProcessWaves one(scene, rs);
        WaveStats waves;
        const Image replayed = render_in_waves(
            rs, sampler_settings(rs, scene),
            [&](const std::vector<SamplePosition>& w, std::vector<float>& rgbt) {
                one(w, rgbt);
            },
            &waves);
        EXPECT_EQ(replayed.rgba, direct.rgba);
        EXPECT_LE(waves.samples.size(), c.max_waves);
        // The first wave: every pixel's centre and the area's border, or the corners.
        const size_t first = c.method == 1 ? size_t(61 * 46 + 61 + 46) : size_t(62 * 47);
        ASSERT_FALSE(waves.samples.empty());
        EXPECT_EQ(waves.samples[0], first);
    }
}

// Focal blur in waves: the rays go out by (sample, index), batch by batch, and every
// unfinished sample asks for its next batch after each wave, so the one-process image
// comes back in about as many waves as the 37-point grid has batches (8), a few more
// with anti-aliasing.
TEST(SampleWaves, FocalBlurRaysInWavesGiveTheOneProcessImage) {
    Scene scene = spheres_on_checker_scene();
    scene.camera.aperture = 0.4;
    scene.camera.blur_samples = 37;
    scene.camera.blur_samples_min = 7;
    scene.camera.focal_distance = 5;
    for (const auto& [method, max_waves] : {std::pair{0, 8}, {1, 16}, {2, 24}}) {
        SCOPED_TRACE(::testing::Message() << "+AM" << method);
        RenderSettings rs;
        rs.width = 32;
        rs.height = 24;
        rs.threads = 2;
        rs.antialias = method != 0;
        rs.aa_method = method != 0 ? method : 1;
        rs.aa_threshold = 0.2;
        const Image direct = render_scene(scene, rs);
        OneProcessWaves one(scene, rs);
        const FocalBlur blur(scene.camera, one.prepared.pattern_env());
        WaveStats waves;
        size_t rays = 0;
        const Image replayed = render_in_waves(
            rs, sampler_settings(rs, scene),
            [&](const std::vector<SamplePosition>& w, std::vector<float>& rgbt) {
                for (size_t i = 0; i < w.size(); ++i) {
                    ASSERT_GE(w[i].ray, 0);  // only focal-blur rays
                    const std::optional<Ray> ray =
                        sample_camera_ray(scene.camera, &blur, w[i], rs.width, rs.height);
                    ASSERT_TRUE(ray.has_value());
                    TraceRay r;
                    r.ray = *ray;
                    one.interiors.seed(r.ray.origin, r.interiors);
                    const TraceResult res = one.tracer.trace(r);
                    rgbt[i * 4] = res.colour.r;
                    rgbt[i * 4 + 1] = res.colour.g;
                    rgbt[i * 4 + 2] = res.colour.b;
                    rgbt[i * 4 + 3] = 0;
                }
                rays += w.size();
            },
            &waves, &blur);
        EXPECT_EQ(replayed.rgba, direct.rgba);
        EXPECT_LE(waves.samples.size(), size_t(max_waves));
        EXPECT_GE(rays, size_t(32 * 24 * 7));  // at least the first batch everywhere
    }
}

// A source without a sample: the block says so instead of using a made-up colour.
TEST(SampleWaves, ABlockMissingASampleIsNotFinished) {
    struct Missing final : SampleSource {
        SamplePosition lack;
        bool sample(Real x, Real y, float* rgbt) override {
            rgbt[0] = rgbt[1] = rgbt[2] = x >= 2 ? 1.0f : 0.0f;  // an edge
            rgbt[3] = 0;
            return !(x == lack.x && y == lack.y);
        }
    } source;
    SamplerSettings s;
    s.threshold = 0.5;
    s.depth = 2;
    s.encoding.identity = true;
    float out[16 * 4];
    for (int method : {1, 2}) {
        s.method = method;
        PixelSampler sampler(s);
        source.lack = {-100, -100};
        EXPECT_TRUE(sampler.render_block({0, 0, 4, 4}, source, out));
        source.lack = method == 1 ? SamplePosition{0, 3} : SamplePosition{3.5, 3.5};
        EXPECT_FALSE(sampler.render_block({0, 0, 4, 4}, source, out));
    }
    // +AM1: a supersample of the pixel at the edge.
    s.method = 1;
    PixelSampler sampler(s);
    source.lack = {1.75, 0.25};
    EXPECT_FALSE(sampler.render_block({0, 0, 4, 4}, source, out));
    // +AM2: the centre of a pixel whose corners lie across the edge.
    s.method = 2;
    PixelSampler sampler2(s);
    source.lack = {2, 0};
    EXPECT_FALSE(sampler2.render_block({0, 0, 4, 4}, source, out));
}

}  // namespace
}  // namespace povwall::trace
