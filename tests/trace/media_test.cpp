// Media integration (trace/media.h) against the closed forms of POV-Ray's rules, and on
// extreme stretches.
#include "trace/media.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace povwall::trace {
namespace {

const Ray kRay{{0, 0, 0}, {0, 0, 1}};

MediaEffect effect(const Media& m, Real length, bool shadow = false) {
    const Media* list[] = {&m};
    return media_effect(list, kRay, 0, length, shadow, PatternEnv{});
}

TEST(Media, ConstantEmissionAddsEmissionTimesLengthInEveryMethod) {
    for (int method : {1, 2, 3}) {
        SCOPED_TRACE(method);
        Media m;
        m.method = method;
        m.emission = {0.5f, 0.25f, 1};
        const MediaEffect e = effect(m, 3);
        EXPECT_FLOAT_EQ(e.add.r, 1.5f);
        EXPECT_FLOAT_EQ(e.add.b, 3.0f);
        EXPECT_EQ(e.mul.r, 1.0f);
    }
}

TEST(Media, AbsorptionTransmitsExponentiallyAndShadowRaysGetNoEmission) {
    Media m;
    m.absorption = {0.2f, 1, 0};
    m.emission = {1, 1, 1};
    for (bool shadow : {false, true}) {
        const MediaEffect e = effect(m, 2, shadow);
        EXPECT_FLOAT_EQ(e.mul.r, std::exp(-0.4f));
        EXPECT_FLOAT_EQ(e.mul.g, std::exp(-2.0f));
        EXPECT_EQ(e.mul.b, 1.0f);
        EXPECT_FLOAT_EQ(e.mul_transmit, e.mul.grey());
        if (shadow) {
            EXPECT_EQ(e.add.r, 0.0f);
        }
    }
}

// Method 3 on a uniform source: POV-Ray's left Riemann sum over S = samples/2 + 1
// sub-intervals, (s L / S) sum_j exp(-j sigma L / S).
TEST(Media, MethodThreeIsPovRaysLeftSumOverItsSubIntervals) {
    Media m;  // 3.7 defaults: method 3, samples 10: S = 6
    m.emission = {1, 1, 1};
    m.absorption = {0.7f, 0.7f, 0.7f};
    const Real L = 2.5;
    const int S = 6;
    double expected = 0;
    for (int j = 0; j < S; ++j) expected += L / S * std::exp(-j * 0.7 * L / S);
    const MediaEffect e = effect(m, L);
    EXPECT_NEAR(e.add.r, expected, 1e-5);
    EXPECT_NEAR(e.mul.r, std::exp(-0.7 * L), 1e-6);
}

// POV-Ray's "infinite" depth (rays that miss): no overflow to inf or NaN, the far end
// is gone, and a source saturates; a zero-length or reversed stretch changes nothing.
TEST(Media, ExtremeStretchesStayFinite) {
    Media m;
    m.absorption = {1e-3f, 1e-3f, 1e-3f};
    m.emission = {0.02f, 0.02f, 0.02f};
    const MediaEffect far = effect(m, 2e10);
    EXPECT_EQ(far.mul.r, 0.0f);
    EXPECT_TRUE(std::isfinite(far.add.r));
    EXPECT_GT(far.add.r, 1e6f);
    for (Real length : {0.0, -1.0}) {
        const MediaEffect none = effect(m, length);
        EXPECT_EQ(none.mul.r, 1.0f);
        EXPECT_EQ(none.add.r, 0.0f);
    }
    Media thick;
    thick.absorption = {1e30f, 1e30f, 1e30f};
    const MediaEffect opaque = effect(thick, 1);
    EXPECT_EQ(opaque.mul.g, 0.0f);
    EXPECT_FALSE(std::isnan(opaque.add.g));
}

// Densities multiply, and a density of zero removes the medium.
TEST(Media, DensitiesMultiplyChannelByChannel) {
    Media m;
    m.method = 2;
    m.samples_min = m.samples_max = 1;
    m.emission = {1, 1, 1};
    Pigment half, tint;
    half.colour.rgb = {0.5f, 0.5f, 0.5f};
    tint.colour.rgb = {1, 0, 0.25f};
    m.density = {half, tint};
    const MediaEffect e = effect(m, 4);
    EXPECT_FLOAT_EQ(e.add.r, 2.0f);
    EXPECT_EQ(e.add.g, 0.0f);
    EXPECT_FLOAT_EQ(e.add.b, 0.5f);
}

// POV-Ray's phase values (no 1/(4 pi)), averaged over the list; Henyey-Greenstein at
// eccentricity +-1 stays finite where POV-Ray's formula divides 0 by 0.
TEST(Media, PhaseFunctionsArePovRaysAndFinite) {
    Media iso, hazy, murky, rayleigh, hg;
    hazy.scattering_type = 2;
    murky.scattering_type = 3;
    rayleigh.scattering_type = 4;
    hg.scattering_type = 5;
    const Vector3 z{0, 0, 1}, x{1, 0, 0};
    auto phase = [&](const Media& m, const Vector3& to_light) {
        const Media* list[] = {&m};
        return media_phase(list, to_light, z);
    };
    EXPECT_FLOAT_EQ(phase(iso, x), 1.0f);
    EXPECT_FLOAT_EQ(phase(hazy, z), float(0.576655375 * 10));
    EXPECT_FLOAT_EQ(phase(murky, z), float(0.495714547 * 51));
    EXPECT_FLOAT_EQ(phase(rayleigh, x), float(0.799372013));
    EXPECT_FLOAT_EQ(phase(rayleigh, -z), float(0.799372013 * 2));
    hg.eccentricity = 0.5f;
    EXPECT_FLOAT_EQ(phase(hg, z), float(0.75 / std::pow(0.25, 1.5)));
    for (float g : {1.0f, -1.0f}) {
        hg.eccentricity = g;
        for (const Vector3& d : {z, -z, x}) EXPECT_TRUE(std::isfinite(phase(hg, d)));
        EXPECT_EQ(phase(hg, x), 0.0f);
    }
    // An emitting media in the list counts as isotropic in the average.
    const Media* list[] = {&rayleigh, &iso};
    EXPECT_FLOAT_EQ(media_phase(list, -z, z), float((0.799372013 * 2 + 1) / 2));
}

}  // namespace
}  // namespace povwall::trace
