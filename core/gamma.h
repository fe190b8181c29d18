// A transfer curve as POV-Ray 3.7 names them in a scene (`assumed_gamma 2.2`,
// `assumed_gamma srgb`, an image's `gamma`): a power law or sRGB's piecewise curve.
#pragma once

#include <algorithm>
#include <cmath>

namespace povwall {

struct GammaCurve {
    enum class Kind { Power, Srgb } kind = Kind::Power;
    float decoding_exponent = 1.0f;  // Power: linear = encoded^exponent

    static GammaCurve power(float decoding_exponent) {
        return {Kind::Power, decoding_exponent};
    }
    static GammaCurve srgb() { return {Kind::Srgb, 1.0f}; }

    // Exactly linear: values pass as they are (assumed_gamma 1, and no assumed_gamma).
    bool is_linear() const { return kind == Kind::Power && decoding_exponent == 1.0f; }
    // The same curve: transcoding between them is the identity.
    bool matches(const GammaCurve& o) const {
        if (kind != o.kind) return false;
        return kind == Kind::Srgb ||
               std::fabs(1.0 - decoding_exponent / o.decoding_exponent) <= 0.01;
    }
    // Encoded value to linear. sRGB's linear segment runs on below 0; a power law
    // clamps at 0, as POV-Ray's curves do.
    float decode(float v) const {
        if (kind == Kind::Srgb)
            return v < 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
        return std::pow(std::max(v, 0.0f), decoding_exponent);
    }
    float encode(float v) const {
        if (kind == Kind::Srgb)
            return v <= 0.0031308f ? v * 12.92f
                                   : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
        return std::pow(std::max(v, 0.0f), 1.0f / decoding_exponent);
    }
};

}  // namespace povwall
