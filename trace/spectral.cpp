#include "trace/spectral.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace povwall::trace {
namespace {

constexpr double kVioletWavelength = 380, kRedWavelength = 730;
constexpr double kBandwidth = kRedWavelength - kVioletWavelength;
constexpr double kCentre = (kVioletWavelength + kRedWavelength) / 2;

// The hue curve of POV-Ray before 3.7 (an RGB fit to colour-matching functions, `hc`
// running from 0.03 at the violet end to 0.964 at the red end), over 372.5-737.5 nm.
std::array<double, 3> hue_curve(double wavelength) {
    const double hc = 0.964 - 0.934 * (1 - (wavelength - 372.5) / 365);
    const auto sq = [](double x) { return x * x; };
    const double b = std::max(0.0, 0.98 * (1 - sq(4 * (hc - 0.28))));
    const double g = std::max(0.0, 0.97 * (1.1 - sq(4.5 * (hc - 0.57))));
    double r = 1.15 - sq(5 * (hc - 0.75));
    if (r < 0) r = std::max(0.0, 0.12 - sq(4 * (hc - 0.12)));  // violet's red hump
    return {r, g, b};
}

// POV-Ray 3.7 weights bands by the integral of that curve, tabulated every 5 nm from 375
// nm and normalised to 1 at the end: entry k sums the curve at the 5-nm bins' middles
// (377.5 nm, 382.5 nm, ...) below it, rounded to 4 decimals. (This rule gives all 222
// values of POV-Ray's table.)
constexpr int kTableSize = 74;
constexpr double kTableBase = 375, kTableStep = 5;

struct HueIntegral {
    std::array<std::array<double, 3>, kTableSize> entry{};
    HueIntegral() {
        double sum[3] = {0, 0, 0};
        for (int k = 0; k < kTableSize; ++k) {
            for (int c = 0; c < 3; ++c) entry[size_t(k)][size_t(c)] = sum[c];
            const std::array<double, 3> v =
                hue_curve(kTableBase + kTableStep * (k + 0.5));
            for (int c = 0; c < 3; ++c) sum[c] += v[size_t(c)];
        }
        for (auto& e : entry)
            for (int c = 0; c < 3; ++c)
                e[size_t(c)] = std::round(e[size_t(c)] / sum[c] * 1e4) / 1e4;
    }
    // Linear between entries, clamped to the table.
    Rgb at(double wavelength) const {
        double x = std::clamp((wavelength - kTableBase) / kTableStep, 0.0,
                              double(kTableSize - 1));
        const int i = std::min(int(x), kTableSize - 2);
        x -= i;
        const auto& a = entry[size_t(i)];
        const auto& b = entry[size_t(i) + 1];
        return Rgb(float((1 - x) * a[0] + x * b[0]), float((1 - x) * a[1] + x * b[1]),
                   float((1 - x) * a[2] + x * b[2]));
    }
};

const HueIntegral& hue_integral() {
    static const HueIntegral table;
    return table;
}

}  // namespace

SpectralBand::SpectralBand(int index, int count)
    : wavelength(float(kVioletWavelength + kBandwidth * ((index + 0.5) / count))),
      bandwidth(float(kBandwidth / float(count))) {}

double SpectralBand::ior(double ior, double dispersion) const {
    return ior * std::pow(dispersion, -(wavelength - kCentre) / kBandwidth);
}

Rgb SpectralBand::hue() const {
    const HueIntegral& t = hue_integral();
    // (Single precision where POV-Ray's is.)
    const Rgb d = t.at(wavelength + bandwidth / 2) - t.at(wavelength - bandwidth / 2);
    return d * float(kBandwidth / bandwidth);
}

}  // namespace povwall::trace
