#include "trace/media.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

namespace povwall::trace {

namespace {

// Extinction and emission of the whole list at a point: each media's colours scaled by
// the product of its densities there.
struct Coefficients {
    Rgb extinction{0.0f}, emission{0.0f};
};

uint64_t mix(uint64_t x) {  // splitmix64's finaliser
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// POV-Ray draws media positions from a per-thread sequence (no two of its renders
// agree); ours depend only on the ray and the stretch, so every mode agrees.
class Draws {
  public:
    Draws(const Ray& ray, Real t0) {
        const double v[7] = {ray.origin.x,
                             ray.origin.y,
                             ray.origin.z,
                             ray.direction.x,
                             ray.direction.y,
                             ray.direction.z,
                             t0};
        uint64_t h = 0x6d656469612d3137ull;
        for (double d : v) h = mix(h ^ std::bit_cast<uint64_t>(d));
        state_ = h;
    }
    Real uniform() {  // [0, 1)
        state_ = mix(state_);
        return Real(state_ >> 11) * (1.0 / 9007199254740992.0);
    }

  private:
    uint64_t state_;
};

class Integrator {
  public:
    Integrator(std::span<const Media* const> list, const Ray& ray, bool shadow,
               const PatternEnv& env)
        : list_(list), ray_(ray), shadow_(shadow), env_(env), draws_(ray, 0) {}

    Coefficients at(Real t) const {
        const Point3 p = ray_.at(t);
        Coefficients c;
        for (const Media* m : list_) {
            Rgb rho{1.0f};
            for (const Pigment& d : m->density) rho *= evaluate_pigment(d, p, env_).rgb;
            c.extinction += rho * m->extinction();
            if (!shadow_) c.emission += rho * m->emission;
        }
        return c;
    }

    // Method 3's sample at fraction f of an interval: the unattenuated source and the
    // optical depth, both times the interval's length.
    struct Sample {
        Rgb source, depth;
    };
    Sample sample3(Real s0, Real ds, Real f) const {
        const Coefficients c = at(s0 + f * ds);
        return {c.emission * float(ds), c.extinction * float(ds)};
    }

    // POV-Ray's recursive refinement of method 3 between fractions a and b.
    Sample refine(Real s0, Real ds, Real a, Real b, const Sample& s1, const Sample& s3,
                  int level, float threshold, float jitter) {
        const Real mid = (a + b) / 2;
        const Sample s2 = sample3(s0, ds, mid + jitter * (b - a) * (draw() - 0.5));
        if (level <= 0)
            return {(s1.source + s2.source + s3.source) / 3.0f,
                    (s1.depth + s2.depth + s3.depth) / 3.0f};
        Sample r;
        if (distance(s1.source, s2.source) > threshold) {
            const Sample h = refine(s0, ds, a, mid, s1, s2, level - 1, threshold, jitter);
            r = {h.source * 0.5f, h.depth * 0.5f};
        } else {
            r = {s1.source / 3.0f + s2.source / 6.0f, s1.depth / 3.0f + s2.depth / 6.0f};
        }
        if (distance(s2.source, s3.source) > threshold) {
            const Sample h = refine(s0, ds, mid, b, s2, s3, level - 1, threshold, jitter);
            r.source += h.source * 0.5f;
            r.depth += h.depth * 0.5f;
        } else {
            r.source += s2.source / 6.0f + s3.source / 3.0f;
            r.depth += s2.depth / 6.0f + s3.depth / 3.0f;
        }
        return r;
    }

    Real draw() { return draws_.uniform(); }
    void reseed(Real t0) { draws_ = Draws(ray_, t0); }

  private:
    static float distance(const Rgb& a, const Rgb& b) {
        return std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b);
    }
    std::span<const Media* const> list_;
    const Ray& ray_;
    bool shadow_;
    const PatternEnv& env_;
    Draws draws_;
};

Rgb exp_neg(const Rgb& d) { return {std::exp(-d.r), std::exp(-d.g), std::exp(-d.b)}; }

bool constant_or_plain(const Media& m) {
    // POV-Ray looks at the head of its density list: the last block given.
    return m.density.empty() || m.density.back().pattern->kind == PatternKind::Solid;
}

}  // namespace

bool media_has_extinction(std::span<const Media* const> list) {
    for (const Media* m : list) {
        const Rgb e = m->extinction();
        if (e.r != 0 || e.g != 0 || e.b != 0) return true;
    }
    return false;
}

MediaEffect media_effect(std::span<const Media* const> list, const Ray& ray, Real t0,
                         Real t1, bool shadow, const PatternEnv& env) {
    MediaEffect out;
    if (list.empty() || !(t1 > t0)) return out;
    if (shadow && !media_has_extinction(list)) return out;
    // The controlling media: the first with the most intervals; the smallest threshold.
    const Media* im = list[0];
    float threshold = im->aa_threshold;
    bool fast = shadow;
    for (const Media* m : list) {
        if (m->intervals > im->intervals) im = m;
        threshold = std::min(threshold, m->aa_threshold);
        fast = fast && constant_or_plain(*m);
    }
    // Without lit scattering every stretch is unlit: one interval when the controlling
    // media is constant, else `intervals` equal ones.
    const int intervals = im->density.empty() ? 1 : im->intervals;
    const Real length = (t1 - t0) / intervals;
    Integrator in(list, ray, shadow, env);
    in.reseed(t0);
    Rgb te_total{0.0f}, od_total{0.0f};
    for (int i = 0; i < intervals; ++i) {
        const Real s0 = t0 + length * i, ds = length;
        Rgb te{0.0f}, od{0.0f};
        int count = 0;
        if (im->method == 3 && !fast) {
            const int S = std::max(2, im->samples_min / 2 + 1);
            const Real dd = 1.0 / (S + 1);
            const float jitter = im->jitter;
            Integrator::Sample previous =
                in.sample3(s0, ds, dd * jitter * (in.draw() - 0.5));
            for (int j = 1; j <= S; ++j) {
                const Integrator::Sample next =
                    in.sample3(s0, ds, j * dd + dd * jitter * (in.draw() - 0.5));
                const Integrator::Sample r =
                    in.refine(s0, ds, (j - 1) * dd, j * dd, previous, next,
                              im->aa_level - 1, threshold, jitter);
                te += r.source * exp_neg(od / float(S));
                od += r.depth;
                previous = next;
            }
            count = S;
        } else {
            const int n = fast ? 1 : im->samples_min;
            for (int j = 0; j < n; ++j) {
                const Real f = im->method == 2 && !fast
                                   ? (j + 0.5) / n + in.draw() * im->jitter / n
                                   : in.draw();
                const Real u = f * ds;
                const Coefficients c = in.at(s0 + u);
                if (!shadow)
                    te += c.emission * float(ds) * exp_neg(c.extinction * float(u));
                od += c.extinction * float(ds);
            }
            count = n;
        }
        te_total += te / float(count) * exp_neg(od_total);
        od_total += od / float(count);
    }
    out.mul = exp_neg(od_total);
    out.add = shadow ? Rgb{0.0f} : te_total;
    out.mul_transmit = out.mul.grey();
    return out;
}

}  // namespace povwall::trace
