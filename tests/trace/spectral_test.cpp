// Dispersion's wavelength bands (trace/spectral.h) against POV-Ray 3.7's numbers.
#include "trace/spectral.h"

#include <gtest/gtest.h>

#include <cmath>

namespace povwall::trace {
namespace {

// POV-Ray's band i of n: its middle and width in single precision.
TEST(Spectral, BandsSplitVioletToRedEvenly) {
    const SpectralBand first(0, 7), last(6, 7);
    EXPECT_EQ(first.wavelength, float(380 + 350 * (0.5 / 7)));
    EXPECT_EQ(last.wavelength, float(380 + 350 * (6.5 / 7)));
    EXPECT_EQ(first.bandwidth, float(350.0 / 7));
}

// The index of refraction of a band: ior * dispersion^-((wavelength - 555) / 350), so
// violet bends most when the dispersion ratio is above 1 and the middle band not at all.
TEST(Spectral, BandIndexScalesByTheDispersionPower) {
    const SpectralBand violet(0, 7), middle(3, 7);
    EXPECT_DOUBLE_EQ(middle.ior(1.5, 1.2), 1.5);
    EXPECT_DOUBLE_EQ(violet.ior(1.5, 1.2),
                     1.5 * std::pow(1.2, -(double(violet.wavelength) - 555) / 350));
    EXPECT_GT(violet.ior(1.5, 1.2), 1.5);
}

// With 70 bands each band spans one 5-nm step of POV-Ray's hue integral, so a band's hue
// is 70 times the step: these are POV-Ray 3.7's table entries (spectral.cpp) at 380,
// 385, 440, 445, 595, 600, 725 and 730 nm.
TEST(Spectral, HuesAreTheStepsOfPovRaysHueIntegral) {
    auto expect_hue = [](int band, float r, float g, float b) {
        const Rgb h = SpectralBand(band, 70).hue();
        EXPECT_NEAR(h.r, r * 70, 1e-4) << band;
        EXPECT_NEAR(h.g, g * 70, 1e-4) << band;
        EXPECT_NEAR(h.b, b * 70, 1e-4) << band;
    };
    expect_hue(0, 0.0029f - 0.0009f, 0, 0.0113f - 0.0038f);   // 380-385 nm
    expect_hue(12, 0.0404f - 0.0404f, 0, 0.3106f - 0.2753f);  // 440-445 nm
    expect_hue(43, 0.1215f - 0.0979f, 0.6340f - 0.5937f, 0);  // 595-600 nm
    expect_hue(69, 0.9947f - 0.9849f, 0, 0);                  // 725-730 nm
}

// The hues of any split average to POV-Ray's integral over 380-730 nm (nearly white).
TEST(Spectral, SplitHuesAverageToTheWholeIntegral) {
    for (int n : {2, 3, 7, 12, 40}) {
        Rgb sum(0.0f);
        for (int i = 0; i < n; ++i) sum += SpectralBand(i, n).hue();
        sum *= 1.0f / float(n);
        EXPECT_NEAR(sum.r, 0.9947 - 0.0009, 2e-5) << n;
        EXPECT_NEAR(sum.g, 1.0, 2e-5) << n;
        EXPECT_NEAR(sum.b, 1.0 - 0.0038, 2e-5) << n;
    }
}

}  // namespace
}  // namespace povwall::trace
