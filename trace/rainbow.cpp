#include "trace/rainbow.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "core/hash_fold.h"
#include "core/math_constants.h"

namespace povwall::trace {
namespace {

// A uniform number in [0, 1) for rainbow `k` on `ray`.
Real draw(const Ray& ray, size_t k) {
    const double v[6] = {ray.origin.x,    ray.origin.y,    ray.origin.z,
                         ray.direction.x, ray.direction.y, ray.direction.z};
    uint64_t h = 0x7261696e626f7721ull;
    for (double d : v) h = splitmix_finish(h ^ std::bit_cast<uint64_t>(d));
    h = splitmix_finish(h ^ splitmix_finish(k + 1));
    return Real(h >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace

RainbowEffect rainbow_effect(const Scene& scene, const Ray& ray, Real depth,
                             const PatternEnv& env) {
    RainbowEffect out;
    Rgb mul{0.0f}, add{0.0f};
    float transmit = 1;
    int n = 0;
    // POV-Ray keeps its rainbows newest first.
    for (size_t i = scene.rainbows.size(); i-- > 0;) {
        const Rainbow& r = scene.rainbows[i];
        if (!r.pigment || r.distance == 0 || r.width == 0) continue;
        // The angle of the direction around the antisolar axis, from `up`.
        const Real x = dot(ray.direction, r.right);
        Real y = dot(ray.direction, r.up);
        const Real l = x * x + y * y;
        if (l > 0) y /= std::sqrt(l);
        const Real angle = std::fabs(std::acos(y));
        if (!(angle <= r.arc_angle)) continue;
        const Real along = dot(ray.direction, r.antisolar);
        if (!(along >= 0)) continue;
        Real index = (std::acos(along) - r.angle) / r.width;
        if (r.jitter > 0) index += (2 * draw(ray, i) - 1) * r.jitter;
        if (!(index >= 0 && index <= 1 - kPovEpsilon)) continue;
        const Colour c = evaluate_pigment(*r.pigment, Point3{index, 0, 0}, env);
        Real fade = 0;
        if (r.falloff_width > 0 && angle > r.falloff_angle) {
            fade = (angle - r.falloff_angle) / r.falloff_width;
            fade = (3 - 2 * fade) * fade * fade;
        }
        // Nearer than its distance the rainbow shows less; its colour's transmit is
        // the least it lets through.
        Real k = std::exp(-depth / r.distance);
        k = std::max(k, fade * (1 - c.transmit) + c.transmit);
        const Real ki = 1 - k;
        const float f = float(c.filter * ki);
        mul += (Rgb(1 - f) + c.rgb * f) * float(k);
        add += c.rgb * float(ki);
        transmit *= float(k) * c.transmit;
        ++n;
    }
    if (n == 0) return out;
    out.mul = mul * (1.0f / float(n));
    out.add = add * (1.0f / float(n));
    out.mul_transmit = transmit;
    return out;
}

}  // namespace povwall::trace
