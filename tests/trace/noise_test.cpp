// Properties of the noise functions that POV-Ray's definitions imply; the exact values
// are checked against POV-Ray renders in pattern_test.cpp.
#include "core/noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace povwall::trace {
namespace {

TEST(Noise, ContinuousAcrossLatticeCellsIncludingNegative) {
    for (int gen : {1, 2, 3}) {
        for (double c : {-3.0, -1.0, 0.0, 1.0, 7.0, 4095.0, 4096.0}) {
            Vector3 a{c - 1e-9, 0.3, 0.7}, b{c + 1e-9, 0.3, 0.7};
            EXPECT_NEAR(noise(a, gen), noise(b, gen), 1e-6)
                << "gen " << gen << " x=" << c;
            Vector3 da = dnoise({0.4, c - 1e-9, 0.2}), db = dnoise({0.4, c + 1e-9, 0.2});
            EXPECT_NEAR(length(da - db), 0.0, 1e-6) << "y=" << c;
        }
    }
}

TEST(Noise, RangeIsClampedUnitInterval) {
    double lo = 1, hi = 0;
    for (int i = 0; i < 20000; ++i) {
        Vector3 p{i * 0.173, i * 0.0711 - 300, std::sin(i * 1.3) * 50};
        double v = noise(p, 2);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        ASSERT_GE(v, 0.0);
        ASSERT_LE(v, 1.0);
    }
    // Range-corrected noise spans most of [0,1].
    EXPECT_LT(lo, 0.15);
    EXPECT_GT(hi, 0.85);
}

TEST(Noise, SingleOctaveTurbulenceIsNoise) {
    TurbulenceParams one{1, 0.5, 2.0};
    Vector3 p{1.25, -2.5, 3.75};
    EXPECT_DOUBLE_EQ(turbulence(p, one, 1), noise(p, 1));
    EXPECT_DOUBLE_EQ(turbulence(p, one, 2), std::clamp(2 * noise(p, 2) - 0.5, 0.0, 1.0));
    EXPECT_EQ(dturbulence(p, one), dnoise(p));
}

TEST(Noise, WaveTableIsUnitSourcesAndPositiveFrequencies) {
    const WaveTable& w = wave_table();
    for (int i = 0; i < kMaxWaves; ++i) {
        EXPECT_NEAR(length(w.source[i]), 1.0, 1e-12);
        EXPECT_GE(w.frequency[i], 0.01);
        EXPECT_LE(w.frequency[i], 1.01);
    }
}

TEST(Noise, CycloidalAndTriangleWave) {
    EXPECT_NEAR(cycloidal(0.25), 1.0, 1e-12);
    EXPECT_NEAR(cycloidal(-0.25), -1.0, 1e-12);
    EXPECT_NEAR(cycloidal(3.75), -1.0, 1e-12);
    EXPECT_DOUBLE_EQ(triangle_wave(0.25), 0.5);
    EXPECT_DOUBLE_EQ(triangle_wave(-0.25), 0.5);
    EXPECT_DOUBLE_EQ(triangle_wave(1.75), 0.5);
}

// The lattice noise with four corners in AVX2 lanes gives the one-corner-at-a-time sums
// bit for bit: negative cells, exact integers, the 4096-cell wrap, coordinates beyond an
// int (C's conversion gives INT_MIN), infinities and NaN.
TEST(Noise, LanesGiveTheScalarSumsBitForBit) {
    if (!noise_detail::has_lanes()) GTEST_SKIP() << "no AVX2 on this CPU";
    std::vector<Vector3> points;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (double scale : {1e-3, 1.0, 37.0, 4096.0, 1e5, 3e9, 1e300})
        for (int i = 0; i < 2000; ++i)
            points.push_back(Vector3(u(rng), u(rng), u(rng)) * scale);
    for (double c : {-4097.0, -1.0, -0.0, 0.0, 1.0, 4095.0, 4096.0, 2147483647.5,
                     -2147483648.5, std::numeric_limits<double>::infinity()})
        points.push_back({c, c + 0.5, -c});
    points.push_back({std::nan(""), 0.25, 0.5});
    auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    for (const Vector3& p : points) {
        ASSERT_TRUE(
            same(noise_detail::lattice_sum(p, true), noise_detail::lattice_sum(p, false)))
            << p.x << " " << p.y << " " << p.z;
        const Vector3 a = noise_detail::lattice_vector(p, true),
                      b = noise_detail::lattice_vector(p, false);
        for (int k = 0; k < 3; ++k) ASSERT_TRUE(same(a[k], b[k])) << p.x << " axis " << k;
    }
}

}  // namespace
}  // namespace povwall::trace
