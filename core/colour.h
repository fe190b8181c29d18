// Colours: RGB for light transport, RGBFT (filter, transmit) for pigments as POV-Ray has them.
#pragma once

#include <algorithm>
#include <cmath>

namespace povwall {

struct Rgb {
    float r = 0, g = 0, b = 0;

    constexpr Rgb() = default;
    constexpr Rgb(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
    constexpr explicit Rgb(float s) : r(s), g(s), b(s) {}

    constexpr Rgb operator+(const Rgb& o) const { return {r + o.r, g + o.g, b + o.b}; }
    constexpr Rgb operator-(const Rgb& o) const { return {r - o.r, g - o.g, b - o.b}; }
    constexpr Rgb operator*(const Rgb& o) const { return {r * o.r, g * o.g, b * o.b}; }
    constexpr Rgb operator*(float s) const { return {r * s, g * s, b * s}; }
    constexpr Rgb operator/(float s) const { return {r / s, g / s, b / s}; }
    constexpr Rgb& operator+=(const Rgb& o) { r += o.r; g += o.g; b += o.b; return *this; }
    constexpr Rgb& operator*=(const Rgb& o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
    constexpr Rgb& operator*=(float s) { r *= s; g *= s; b *= s; return *this; }
    constexpr bool operator==(const Rgb& o) const = default;
    constexpr float max_component() const { return std::max(r, std::max(g, b)); }
    // POV-Ray's greyscale weights (GREY_SCALE in colour.h of 3.7 uses 0.297/0.589/0.114).
    constexpr float grey() const { return r * 0.297f + g * 0.589f + b * 0.114f; }
    constexpr bool is_black() const { return r == 0 && g == 0 && b == 0; }
};
constexpr Rgb operator*(float s, const Rgb& c) { return c * s; }

// A pigment colour: rgb plus filter (tinted transparency) and transmit (plain transparency).
struct Colour {
    Rgb rgb;
    float filter = 0, transmit = 0;

    constexpr Colour() = default;
    constexpr Colour(Rgb c, float f = 0, float t = 0) : rgb(c), filter(f), transmit(t) {}
    constexpr Colour operator+(const Colour& o) const {
        return {rgb + o.rgb, filter + o.filter, transmit + o.transmit};
    }
    constexpr Colour operator*(float s) const { return {rgb * s, filter * s, transmit * s}; }
    constexpr bool operator==(const Colour& o) const = default;
    constexpr bool opaque() const { return filter == 0 && transmit == 0; }
};

}  // namespace povwall
