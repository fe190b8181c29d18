// Camera projections and anti-aliasing sample patterns, against values worked out by hand
// from POV-Ray 3.7's definitions (the golden scenes check the same against POV-Ray
// itself).
#include "trace/render.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene_builder.h"
#include "trace/camera.h"
#include "trace/tracer.h"

namespace povwall::trace {
namespace {

using namespace povwall::test;

Camera unit_camera(Camera::Kind kind, Real angle) {
    Camera c;
    c.kind = kind;
    c.location = {0, 0, 0};
    c.direction = {0, 0, 1};
    c.right = {1, 0, 0};
    c.up = {0, 1, 0};
    c.angle = angle;
    return c;
}

void expect_vector_near(const Vector3& got, const Vector3& want) {
    EXPECT_NEAR(got.x, want.x, 1e-12);
    EXPECT_NEAR(got.y, want.y, 1e-12);
    EXPECT_NEAR(got.z, want.z, 1e-12);
}

const Real kHalf = std::sqrt(0.5);

TEST(CameraRay, FisheyeRadiusIsAngleFromTheAxis) {
    Camera c = unit_camera(Camera::Kind::Fisheye, 180);
    expect_vector_near(camera_ray(c, 50, 50, 100, 100)->direction, {0, 0, 1});
    expect_vector_near(camera_ray(c, 100, 50, 100, 100)->direction,
                       {1, 0, 0});  // rim: 90 deg
    expect_vector_near(camera_ray(c, 75, 50, 100, 100)->direction,
                       {kHalf, 0, kHalf});  // 45 deg
    expect_vector_near(camera_ray(c, 50, 0, 100, 100)->direction, {0, 1, 0});
    expect_vector_near(camera_ray(c, 25, 50, 100, 100)->direction, {-kHalf, 0, kHalf});
    EXPECT_FALSE(
        camera_ray(c, 100, 0, 100, 100).has_value());  // corner: outside the circle
    // The lengths of right and up squeeze the circle: right 2 puts the rim at x0 = 0.25.
    c.right = {2, 0, 0};
    expect_vector_near(camera_ray(c, 75, 50, 100, 100)->direction, {1, 0, 0});
    EXPECT_FALSE(camera_ray(c, 80, 50, 100, 100).has_value());
}

TEST(CameraRay, PanoramicSpansHalfATurnAndTanOfLatitude) {
    Camera c = unit_camera(Camera::Kind::Panoramic, 90);
    expect_vector_near(camera_ray(c, 0, 50, 100, 100)->direction, {-1, 0, 0});
    expect_vector_near(camera_ray(c, 50, 50, 100, 100)->direction, {0, 0, 1});
    expect_vector_near(camera_ray(c, 100, 50, 100, 100)->direction, {1, 0, 0});
    expect_vector_near(camera_ray(c, 50, 25, 100, 100)->direction,
                       {0, kHalf, kHalf});  // 45 deg up
    // Camera vectors are used unnormalised: a longer up tilts the same pixel further.
    c.up = {0, 2, 0};
    Vector3 d = camera_ray(c, 50, 25, 100, 100)->direction;
    EXPECT_NEAR(d.y / d.z, 2.0, 1e-12);
}

TEST(CameraRay, UltraWideAngleUsesSinesOfTheAngles) {
    Camera c = unit_camera(Camera::Kind::UltraWideAngle, 180);
    expect_vector_near(camera_ray(c, 100, 50, 100, 100)->direction, {1, 0, 0});
    expect_vector_near(camera_ray(c, 75, 50, 100, 100)->direction, {kHalf, 0, kHalf});
    Vector3 d = camera_ray(c, 75, 25, 100, 100)->direction;  // both 45 deg
    expect_vector_near(d, normalize(Vector3{kHalf, kHalf, 0.5}));
}

TEST(CameraRay, CylinderCamerasBendOneAxisOnly) {
    Camera c1 = unit_camera(Camera::Kind::Cylinder1, 180);
    c1.up = {0, 2, 0};  // up length scales the straight (vertical) axis
    expect_vector_near(camera_ray(c1, 100, 50, 100, 100)->direction, {1, 0, 0});
    expect_vector_near(camera_ray(c1, 50, 0, 100, 100)->direction, {0, kHalf, kHalf});

    Camera c2 = unit_camera(Camera::Kind::Cylinder2, 180);
    c2.right = {4, 0, 0};
    expect_vector_near(camera_ray(c2, 50, 0, 100, 100)->direction, {0, 1, 0});
    expect_vector_near(camera_ray(c2, 75, 50, 100, 100)->direction, {kHalf, 0, kHalf});

    Camera c3 = unit_camera(Camera::Kind::Cylinder3, 90);
    c3.location = {0, 1, 0};
    c3.up = {0, 3, 0};
    Ray r3 = *camera_ray(c3, 100, 0, 100, 100);
    expect_vector_near(r3.origin, {0, 2.5, 0});  // moved along up by y0 * |up|
    expect_vector_near(r3.direction, {kHalf, 0, kHalf});

    Camera c4 = unit_camera(Camera::Kind::Cylinder4, 90);
    c4.right = {2, 0, 0};
    Ray r4 = *camera_ray(c4, 25, 100, 100, 100);
    expect_vector_near(r4.origin, {-0.5, 0, 0});
    expect_vector_near(r4.direction, {0, -kHalf, kHalf});
}

TEST(CameraRay, SphericalLongitudeAcrossLatitudeUp) {
    Camera c = unit_camera(Camera::Kind::Spherical, 90);  // angle 360, 180
    expect_vector_near(camera_ray(c, 50, 50, 100, 100)->direction, {0, 0, 1});
    expect_vector_near(camera_ray(c, 75, 50, 100, 100)->direction, {1, 0, 0});
    expect_vector_near(camera_ray(c, 100, 50, 100, 100)->direction, {0, 0, -1});
    expect_vector_near(camera_ray(c, 50, 0, 100, 100)->direction, {0, 1, 0});
    c.h_angle = 180, c.v_angle = 90;
    expect_vector_near(camera_ray(c, 100, 50, 100, 100)->direction, {1, 0, 0});
    expect_vector_near(camera_ray(c, 50, 0, 100, 100)->direction, {0, kHalf, kHalf});
}

TEST(CameraRay, OmnimaxSeesNoMoreThan45DegreesBelowTheAxis) {
    Camera c = unit_camera(Camera::Kind::Omnimax, 90);  // square: no widening
    expect_vector_near(camera_ray(c, 50, 50, 100, 100)->direction, {0, 0, 1});
    // Radius r from the centre: 1.411269 r - 0.09439 r^3 + 0.25674 r^5 radians from the
    // axis.
    const Real r = 0.8,
               theta = 1.411269 * r - 0.09439 * r * r * r + 0.25674 * r * r * r * r * r;
    const std::optional<Ray> right = camera_ray(c, 90, 50, 100, 100);
    ASSERT_TRUE(right.has_value());
    EXPECT_NEAR(right->direction.x, std::sin(theta), 1e-9);
    EXPECT_NEAR(right->direction.z, std::cos(theta), 1e-9);
    // The rim lies past 90 degrees: seen only above the axis.
    EXPECT_FALSE(camera_ray(c, 100, 50, 100, 100).has_value());
    EXPECT_TRUE(camera_ray(c, 50, 1, 100, 100).has_value());
    EXPECT_FALSE(camera_ray(c, 50, 100, 100, 100).has_value());  // straight down
    EXPECT_FALSE(camera_ray(c, 100, 0, 100, 100).has_value());   // outside the circle
}

// A red sphere on grey: edges for the anti-aliasing to find.
Scene edge_scene() {
    Scene s;
    s.camera.location = {0, 0, -5};
    s.background = Colour(Rgb{0.5f, 0.5f, 0.5f});
    s.objects.push_back(object(Sphere{{0, 0, 0}, 1.2}, {}, {solid({0.9f, 0.1f, 0.1f})}));
    s.lights.push_back(point_light({-3, 4, -6}));
    return s;
}

struct Sampler {
    PreparedScene prepared;
    Tracer tracer;
    int w, h;
    const Scene& scene;
    Sampler(const Scene& s, int w_, int h_)
        : prepared(s), tracer(prepared), w(w_), h(h_), scene(s) {}
    Rgb at(Real px, Real py) {
        TraceRay r;
        r.ray = *camera_ray(scene.camera, px, py, w, h);
        return tracer.trace(r).colour;
    }
};

TEST(AntiAliasRecursive, DepthTwoAveragesTheQuartersOfAThreeByThreeGrid) {
    Scene s = edge_scene();
    RenderSettings rs;
    rs.width = 12;
    rs.height = 9;
    rs.threads = 1;
    rs.antialias = true;
    rs.aa_method = 2;
    rs.aa_depth = 2;
    rs.aa_threshold = 0;  // every square differs "enough": every pixel splits once
    rs.aa_jitter = false;
    Image img = render_scene(s, rs);
    Sampler smp(s, rs.width, rs.height);
    for (int y = 0; y < rs.height; ++y) {
        for (int x = 0; x < rs.width; ++x) {
            Rgb g[3][3];
            for (int j = 0; j < 3; ++j)
                for (int i = 0; i < 3; ++i) g[j][i] = smp.at(x + 0.5 * i, y + 0.5 * j);
            auto quarter = [&](int i, int j) {
                return (g[j][i] + g[j + 1][i] + g[j][i + 1] + g[j + 1][i + 1]) / 4.0f;
            };
            Rgb want =
                (quarter(0, 0) + quarter(0, 1) + quarter(1, 0) + quarter(1, 1)) / 4.0f;
            const float* p = img.pixel(x, y);
            EXPECT_FLOAT_EQ(p[0], want.r) << x << "," << y;
            EXPECT_FLOAT_EQ(p[1], want.g) << x << "," << y;
            EXPECT_FLOAT_EQ(p[2], want.b) << x << "," << y;
        }
    }
}

TEST(AntiAliasRecursive, FlatImageTracesOnlyThePixelCorners) {
    Scene s;
    s.background = Colour(Rgb{0.2f, 0.3f, 0.4f});
    RenderSettings rs;
    rs.width = 10;
    rs.height = 7;
    rs.threads = 2;
    rs.antialias = true;
    rs.aa_method = 2;
    rs.aa_depth = 4;
    RenderStats stats;
    Image img = render_scene(s, rs, &stats);
    EXPECT_EQ(stats.rays.camera, uint64_t(11 * 8));
    EXPECT_FLOAT_EQ(img.pixel(3, 3)[2], 0.4f);
}

TEST(AntiAliasRecursive, SubdividesOnlyWhereCornersDiffer) {
    Scene s = edge_scene();
    RenderSettings rs;
    rs.width = 32;
    rs.height = 24;
    rs.threads = 1;
    rs.antialias = true;
    rs.aa_method = 2;
    rs.aa_depth = 3;
    rs.aa_threshold = 0.1;
    rs.aa_jitter = false;
    RenderStats stats;
    Image img = render_scene(s, rs, &stats);
    const uint64_t corners = 33 * 25;
    EXPECT_GT(stats.rays.camera, corners);
    // Flat pixels far from the sphere keep the plain mean of their corners: the
    // background.
    EXPECT_FLOAT_EQ(img.pixel(0, 0)[0], 0.5f);
    EXPECT_FLOAT_EQ(img.pixel(31, 23)[1], 0.5f);
    // Depth 3 splits a pixel at most into 4 + 16 squares: 5 + 16 midpoint/centre samples.
    EXPECT_LT(stats.rays.camera, corners + 21 * 32 * 24);
}

// POV-Ray's jitter: its table's values (15-bit fractions printed to 6 decimals and read
// as floats) picked through its hash table by the sample's nominal position.
TEST(AntiAliasJitter, PovRaysTablesAndPositions) {
    struct Case {
        Real x, y;
        float jx, jy;
    };
    for (const Case& c :
         {Case{9.5, 20.0, -0.138641f, -0.134766f}, Case{10.0, 19.5, 0.390625f, 0.441437f},
          Case{-1.0, 5.0, 0.384796f, 0.378906f},
          Case{-0.33333333333333337, -0.33333333333333337, -0.400391f, 0.310577f}}) {
        Real jx, jy;
        pov_jitter(c.x, c.y, jx, jy);
        EXPECT_EQ(jx, Real(c.jx)) << c.x << ", " << c.y;
        EXPECT_EQ(jy, Real(c.jy)) << c.x << ", " << c.y;
    }
    // Every value lies in [-0.5, 0.5) and is a float printed with 6 decimals.
    for (int i = 0; i < 4096; ++i) {
        Real jx, jy;
        pov_jitter(i / 1021.0 + 1e-9, 0, jx, jy);
        ASSERT_GE(jx, -0.5);
        ASSERT_LT(jx, 0.5);
        EXPECT_EQ(float(jx), float(std::round(jx * 1e6) / 1e6));
    }
}

TEST(AntiAliasJitter, MovesOnlySupersampledPixelsAndRepeats) {
    Scene s = edge_scene();
    for (int method : {1, 2}) {
        RenderSettings rs;
        rs.width = 32;
        rs.height = 24;
        rs.threads = 1;
        rs.antialias = true;
        rs.aa_method = method;
        rs.aa_threshold = 0.1;
        rs.aa_jitter = false;
        Image plain = render_scene(s, rs);
        rs.aa_jitter = true;
        Image jittered = render_scene(s, rs);
        rs.threads = 3;
        EXPECT_EQ(render_scene(s, rs).rgba, jittered.rgba) << "method " << method;
        rs.aa_jitter_amount = 0;
        EXPECT_EQ(render_scene(s, rs).rgba, plain.rgba) << "method " << method;
        int changed = 0;
        for (int y = 0; y < rs.height; ++y) {
            for (int x = 0; x < rs.width; ++x) {
                float d = std::fabs(plain.pixel(x, y)[0] - jittered.pixel(x, y)[0]);
                if (d > 0) ++changed;
                // A jittered sample moves by at most half the sample spacing: a pixel's
                // colour can change but stays within the range of colours at the edge.
                EXPECT_LT(d, 0.5f) << x << "," << y;
            }
        }
        EXPECT_GT(changed, 10) << "method " << method;
        EXPECT_LT(changed, 32 * 24 / 3) << "method " << method;  // edges only
        EXPECT_EQ(plain.pixel(0, 0)[0], jittered.pixel(0, 0)[0]);
    }
}

}  // namespace
}  // namespace povwall::trace
