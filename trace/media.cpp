#include "trace/media.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/math_constants.h"
#include "trace/photon_map.h"
#include "trace/shapes/common.h"  // kMaxDistance: POV-Ray's MAX_DISTANCE (a spot cone's open end)

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
// agree); ours depend only on the ray, the stretch and which sample it is (not on the
// order samples are taken), so every mode agrees.
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
    Real uniform(uint64_t sample) const {  // [0, 1)
        const uint64_t h = mix(state_ ^ mix(sample));
        return Real(h >> 11) * (1.0 / 9007199254740992.0);
    }

  private:
    uint64_t state_;
};

constexpr Real kSmallTolerance = 1e-3;  // its SMALL_TOLERANCE

// The part [s0, s1] of the stretch that light `light` lights (distances from its start).
struct LightSpan {
    size_t light;
    Real s0, s1;
};
struct LitInterval {
    bool lit;
    Real s0, s1;
};
struct SampleInterval {
    bool lit;
    Real s0, ds;
};

// POV-Ray's ComputeSpotLightInterval: where a ray from O along D is inside the spot's
// falloff cone (one nappe); false if nowhere.
bool spot_interval(const Light& l, const Point3& O, const Vector3& D, Real& d1,
                   Real& d2) {
    const Real cos_falloff = std::cos(l.falloff * kPi / 180);
    const Real m = 1 / (cos_falloff * cos_falloff);
    const Vector3 axis = normalize(l.point_at - l.location);
    const Vector3 V = O - l.location;
    const Real k1 = dot(D, axis), k2 = dot(V, axis), len = length(V);
    const bool inside = len > kPovEpsilon && k2 / len >= cos_falloff;
    if (k1 <= 0 && k2 < 0) return false;
    const Real k3 = dot(V, D), k4 = dot(V, V);
    const Real a = 1 - k1 * k1 * m, b = k3 - k1 * k2 * m, c = k4 - k2 * k2 * m;
    if (a == 0) {
        if (!inside) return false;
        d1 = 0;
        d2 = -c / b;
        return true;
    }
    Real d = b * b - a * c;
    if (d > kPovEpsilon) {
        d = std::sqrt(d);
        Real t1 = (-b + d) / a, t2 = (-b - d) / a;
        if (t1 > t2) std::swap(t1, t2);
        const Real l1 = k2 + t1 * k1, l2 = k2 + t2 * k1;
        if (l1 <= 0 && l2 <= 0) return false;  // the other nappe
        if (l1 <= 0) {
            if (inside) {
                t1 = 0;
                t2 = t2 > 0 ? t2 : kMaxDistance;
            } else {
                t1 = t2;
                t2 = kMaxDistance;
            }
        } else if (l2 <= 0) {
            if (inside) {
                t2 = t1;
                t1 = 0;
            } else {
                t2 = kMaxDistance;
            }
        }
        d1 = t1;
        d2 = t2;
        return true;
    }
    if (d > -kPovEpsilon) {  // tangent
        d1 = inside ? 0 : -b / a;
        d2 = inside ? -b / a : kMaxDistance;
        return true;
    }
    return false;
}

// POV-Ray's ComputeCylinderLightInterval: where the ray is within the falloff radius of
// the light's axis, in front of the light.
bool cylinder_interval(const Light& l, const Point3& O, const Vector3& D, Real& d1,
                       Real& d2) {
    const Vector3 axis = normalize(l.point_at - l.location);
    const Vector3 V = O - l.location;
    const Real k1 = dot(D, axis), k2 = dot(V, axis);
    if (k1 <= 0 && k2 < 0) return false;
    const Real a = 1 - k1 * k1;
    if (a == 0) return false;
    const Real k3 = dot(V, D), k4 = dot(V, V);
    const Real b = k3 - k1 * k2, c = k4 - k2 * k2 - l.falloff * l.falloff;
    Real d = b * b - a * c;
    if (!(d > kPovEpsilon)) return false;
    d = std::sqrt(d);
    Real t1 = (-b + d) / a, t2 = (-b - d) / a;
    if (t1 > t2) std::swap(t1, t2);
    const Real l1 = k2 + t1 * k1, l2 = k2 + t2 * k1;
    if (l1 <= 0 && l2 <= 0) return false;
    if (l1 <= 0)
        t1 = 0;
    else if (l2 <= 0)
        t2 = (kMaxDistance - k2) / k1;
    d1 = t1;
    d2 = t2;
    return true;
}

// POV-Ray's ComputeMediaLightInterval: the lights that light media (media_interaction
// on; shadowless lights never do), each with the part of [0, L] it lights, and the lit
// and unlit intervals they make. Spans keep the lights' order; the intervals come from
// the sorted starts and ends, each lit one standing for all lights.
void light_intervals(const MediaLights& in, const Point3& O, const Vector3& D, Real L,
                     std::vector<LightSpan>& spans, std::vector<LitInterval>& lits) {
    spans.clear();
    lits.clear();
    for (size_t i = 0; i < in.lights.size(); ++i) {
        const Light& l = in.lights[i];
        if (!l.media_interaction || l.shadowless) continue;
        if (l.light_group == 0 ? !in.global_lights : l.light_group != in.light_group)
            continue;
        Real t1 = 0, t2 = L;
        bool keep = true;
        if (l.kind == Light::Kind::Spot || l.kind == Light::Kind::Cylinder) {
            keep = (l.kind == Light::Kind::Spot ? spot_interval(l, O, D, t1, t2)
                                                : cylinder_interval(l, O, D, t1, t2)) &&
                   t1 < L && t2 > kSmallTolerance;
        }
        if (keep) spans.push_back({i, std::max(t1, Real(0)), std::min(t2, L)});
    }
    if (spans.empty()) return;
    thread_local std::vector<Real> starts, ends;
    starts.clear();
    ends.clear();
    for (const LightSpan& s : spans) {
        starts.push_back(s.s0);
        ends.push_back(s.s1);
    }
    std::sort(starts.begin(), starts.end());
    std::sort(ends.begin(), ends.end());
    if (starts[0] > 0) lits.push_back({false, 0, starts[0]});
    lits.push_back({true, starts[0], ends[0]});
    for (size_t i = 1; i < starts.size(); ++i) {
        if (starts[i] > lits.back().s1) {
            const Real end = lits.back().s1;
            lits.push_back({false, end, starts[i]});
            lits.push_back({true, starts[i], ends[i]});
        } else if (ends[i] > lits.back().s1) {
            lits.back().s1 = ends[i];
        }
    }
    if (lits.back().s1 < L) lits.push_back({false, lits.back().s1, L});
}

// POV-Ray's ComputeMediaSampleInterval, then the unlit ends it pads the list with.
void sample_intervals(const std::vector<LitInterval>& lits, const Media& im, Real L,
                      std::vector<SampleInterval>& out) {
    out.clear();
    const size_t n_lits = lits.size();
    const size_t n = std::max(size_t(im.intervals), n_lits);
    if (n_lits == 1) {
        const LitInterval& li = lits[0];
        if (!li.lit && im.density.empty()) {
            out.push_back({false, li.s0, li.s1 - li.s0});
        } else {
            const Real delta = (li.s1 - li.s0) / Real(n);
            for (size_t i = 0; i < n; ++i)
                out.push_back({li.lit, li.s0 + delta * Real(i), delta});
        }
    } else {
        Real sum = 0;
        for (const LitInterval& li : lits) sum += li.lit ? im.ratio : 1 - Real(im.ratio);
        size_t remaining = n;
        for (size_t i = 0; i < n_lits; ++i) {
            const LitInterval& li = lits[i];
            const Real weight = li.lit ? im.ratio : 1 - Real(im.ratio);
            size_t k = size_t(weight / sum * Real(n)) + 1;
            k = std::min(k, remaining - n_lits + i + 1);
            const Real delta = (li.s1 - li.s0) / Real(k);
            for (size_t j = 0; j < k; ++j)
                out.push_back({li.lit, li.s0 + delta * Real(j), delta});
            remaining -= k;
        }
    }
    if (out.front().s0 > 0) out.insert(out.begin(), {false, 0, out.front().s0});
    const Real last_end = out.back().s0 + out.back().ds;
    if (last_end < L) out.push_back({false, last_end, L - last_end});
}

float phase_of(const Media& m, Real alpha) {
    switch (m.scattering_type) {
        case 2:  // Mie hazy
            return float(0.576655375 * (1 + 9 * std::pow(0.5 * (1 + alpha), 8.0)));
        case 3:  // Mie murky
            return float(0.495714547 * (1 + 50 * std::pow(0.5 * (1 + alpha), 32.0)));
        case 4:  // Rayleigh
            return float(0.799372013 * (1 + alpha * alpha));
        case 5: {  // Henyey-Greenstein
            const Real g = m.eccentricity, g2 = g * g;
            const Real base = 1 + g2 - 2 * g * alpha;
            // |g| = 1 head-on gives 0/0 where POV-Ray gives NaN; the lobe is a point
            // there, 0 elsewhere: take 0.
            if (!(base > 0)) return 0;
            return float((1 - g2) / std::pow(base, 1.5));
        }
        default:  // isotropic, and unknown types as POV-Ray
            return 1;
    }
}

class Integrator {
  public:
    Integrator(std::span<const Media* const> list, const Ray& ray, Real t0, bool shadow,
               const PatternEnv& env, std::span<const LightSpan> spans,
               MediaLightProbe* probe, const PhotonMap* photons, bool scattering)
        : list_(list),
          ray_(ray),
          t0_(t0),
          shadow_(shadow),
          env_(env),
          spans_(spans),
          probe_(probe),
          photons_(photons),
          scattering_(scattering),
          draws_(ray, t0) {}

    // The source (emission and, in a lit interval, scattered light) and the extinction
    // at distance d from the stretch's start.
    Coefficients at(Real d, bool lit, uint64_t sample) const {
        const Point3 p = ray_.at(t0_ + d);
        Coefficients c;
        Rgb scattering{0.0f};
        for (const Media* m : list_) {
            Rgb rho{1.0f};
            for (const Pigment& density : m->density)
                rho *= evaluate_pigment(density, p, env_).rgb;
            c.extinction += rho * m->extinction();
            if (!shadow_) {
                c.emission += rho * m->emission;
                if (scattering_) scattering += rho * m->scattering;
            }
        }
        if (lit && scattering_ && !shadow_) {
            for (const LightSpan& s : spans_) {
                if (!(d >= s.s0 && d <= s.s1)) continue;
                Vector3 to_light;
                const Rgb light = probe_->arriving(s.light, p, to_light, sample);
                if (light.is_black()) continue;
                c.emission +=
                    scattering * light * media_phase(list_, to_light, ray_.direction);
            }
        }
        if (photons_ && scattering_ && !shadow_) {
            // POV-Ray's ComputeMediaPhotons: the flux of the photons around, each by
            // the phase for its direction, over the sphere they were gathered in.
            thread_local std::vector<const Photon*> found;
            const double r = photons_->gather(p, nullptr, found);
            Rgb sum{0.0f};
            for (const Photon* ph : found)
                sum += PhotonMap::flux(*ph) *
                       media_phase(list_, PhotonMap::incoming(*ph), ray_.direction);
            c.emission += scattering * sum * float(3.0 / (kPi * r * r * r * 4.0));
        }
        return c;
    }

    // Method 3's sample at fraction f of an interval: the unattenuated source and the
    // optical depth, both times the interval's length.
    struct Sample {
        Rgb source, depth;
    };
    Sample sample3(const SampleInterval& iv, Real f, uint64_t sample) const {
        const Coefficients c = at(iv.s0 + f * iv.ds, iv.lit, sample);
        return {c.emission * float(iv.ds), c.extinction * float(iv.ds)};
    }

    // POV-Ray's recursive refinement of method 3 between fractions a and b. Its
    // midpoints are numbered as a heap (`node`: 1 the first, 2 node and 2 node + 1 the
    // halves' ones) after `base`.
    Sample refine(const SampleInterval& iv, Real a, Real b, const Sample& s1,
                  const Sample& s3, int level, float threshold, float jitter,
                  uint64_t base, uint64_t node) {
        const Real mid = (a + b) / 2;
        const uint64_t id = base + node - 1;
        const Sample s2 = sample3(iv, mid + jitter * (b - a) * (draw(id) - 0.5), id);
        if (level <= 0)
            return {(s1.source + s2.source + s3.source) / 3.0f,
                    (s1.depth + s2.depth + s3.depth) / 3.0f};
        Sample r;
        if (distance(s1.source, s2.source) > threshold) {
            const Sample h =
                refine(iv, a, mid, s1, s2, level - 1, threshold, jitter, base, 2 * node);
            r = {h.source * 0.5f, h.depth * 0.5f};
        } else {
            r = {s1.source / 3.0f + s2.source / 6.0f, s1.depth / 3.0f + s2.depth / 6.0f};
        }
        if (distance(s2.source, s3.source) > threshold) {
            const Sample h = refine(iv, mid, b, s2, s3, level - 1, threshold, jitter,
                                    base, 2 * node + 1);
            r.source += h.source * 0.5f;
            r.depth += h.depth * 0.5f;
        } else {
            r.source += s2.source / 6.0f + s3.source / 3.0f;
            r.depth += s2.depth / 6.0f + s3.depth / 3.0f;
        }
        return r;
    }

    Real draw(uint64_t sample) const { return draws_.uniform(sample); }

  private:
    static float distance(const Rgb& a, const Rgb& b) {
        return std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b);
    }
    std::span<const Media* const> list_;
    const Ray& ray_;
    Real t0_;
    bool shadow_;
    const PatternEnv& env_;
    std::span<const LightSpan> spans_;
    MediaLightProbe* probe_;
    const PhotonMap* photons_;
    bool scattering_;
    Draws draws_;
};

Rgb exp_neg(const Rgb& d) { return {std::exp(-d.r), std::exp(-d.g), std::exp(-d.b)}; }

bool constant_or_plain(const Media& m) {
    // POV-Ray looks at the head of its density list: the last block given.
    return m.density.empty() || m.density.back().pattern->kind == PatternKind::Solid;
}

}  // namespace

float media_phase(std::span<const Media* const> list, const Vector3& to_light,
                  const Vector3& view) {
    const Real alpha = dot(to_light, view);
    float k = 0;
    for (const Media* m : list) k += phase_of(*m, alpha);
    return k / float(list.size());
}

bool media_has_extinction(std::span<const Media* const> list) {
    for (const Media* m : list) {
        const Rgb e = m->extinction();
        if (e.r != 0 || e.g != 0 || e.b != 0) return true;
    }
    return false;
}

Rgb deposit_media_photons(std::span<const Media* const> list, const Ray& ray, Real t1,
                          const MediaLights& lights, const PatternEnv& env,
                          const Rgb& colour, MediaPhotonSink& sink) {
    const Media* im = list[0];
    bool extinction = false, scattering = false, collect = false;
    for (const Media* m : list) {
        if (m->intervals > im->intervals) im = m;
        extinction = extinction || !m->absorption.is_black() || m->scatters();
        scattering = scattering || m->scatters();
        collect = collect || m->collect;
    }
    if (!extinction) return colour;
    thread_local std::vector<LightSpan> spans;
    thread_local std::vector<LitInterval> lits;
    thread_local std::vector<SampleInterval> intervals;
    light_intervals(lights, ray.origin, ray.direction, t1, spans, lits);
    if (lits.empty()) lits.push_back({false, 0, t1});
    sample_intervals(lits, *im, t1, intervals);
    Rgb depth{0.0f};
    bool emptied = false;
    for (const SampleInterval& iv : intervals) {
        // As many steps as the photons' spacing here fits, at most max_steps (then
        // spaced wider, each photon carrying more).
        const double spacing = sink.spread_at_unit * (sink.parallel ? 1 : sink.travelled);
        int steps = int(iv.ds / (spacing * sink.spacing_factor));
        double factor = sink.spacing_factor;
        if (steps > sink.max_steps) {
            steps = sink.max_steps;
            factor = iv.ds / (spacing * steps);
        }
        Rgb od{0.0f};
        for (int j = 0; j < steps; ++j) {
            const Real d0 =
                (j + 0.5 + sink.draw() * sink.step_jitter - 0.5 * sink.step_jitter) /
                steps;
            const Real along = iv.s0 + d0 * iv.ds;
            const Point3 p = ray.at(along);
            for (const Media* m : list) {
                Rgb rho{1.0f};
                for (const Pigment& density : m->density)
                    rho *= evaluate_pigment(density, p, env).rgb;
                od += rho * m->extinction() * float(iv.ds);
            }
            if (scattering && collect)
                sink.store(p, along,
                           colour * float(factor * sink.spread_at_unit *
                                          (sink.parallel ? 1 : sink.travelled + along)));
        }
        // POV-Ray divides the interval's optical depth by its sample count: 0 / 0 for
        // an interval too short for one step, which turns the photon's colour into
        // NaNs it then stores as black photons.
        if (steps == 0)
            emptied = true;
        else
            depth += od / float(steps);
    }
    if (emptied) return Rgb{0.0f};
    return colour * exp_neg(depth);
}

MediaEffect media_effect(std::span<const Media* const> list, const Ray& ray, Real t0,
                         Real t1, bool shadow, const PatternEnv& env,
                         const MediaLights* lights) {
    MediaEffect out;
    if (list.empty() || !(t1 > t0)) return out;
    if (shadow && !media_has_extinction(list)) return out;
    // The controlling media: the first with the most intervals; the smallest threshold.
    const Media* im = list[0];
    float threshold = im->aa_threshold;
    bool fast = shadow;
    bool scattering = false;
    for (const Media* m : list) {
        if (m->intervals > im->intervals) im = m;
        threshold = std::min(threshold, m->aa_threshold);
        fast = fast && constant_or_plain(*m);
        scattering = scattering || m->scatters();
    }
    const Real L = t1 - t0;
    // A viewing ray is split where the lights light it (scattering or not); a shadow
    // ray is one unlit interval.
    // Scratch per kind of ray: a viewing ray's probe traces shadow rays, whose media
    // come back here while the viewing ray's are in use.
    struct Scratch {
        std::vector<LightSpan> spans;
        std::vector<LitInterval> lits;
        std::vector<SampleInterval> intervals;
    };
    thread_local Scratch scratch[2];
    auto& [spans, lits, intervals] = scratch[shadow ? 1 : 0];
    spans.clear();
    lits.clear();
    if (!shadow && lights)
        light_intervals(*lights, ray.at(t0), ray.direction, L, spans, lits);
    if (lits.empty()) lits.push_back({false, 0, L});
    sample_intervals(lits, *im, L, intervals);
    if (lights && lights->photon) scattering = false;
    MediaLightProbe* probe = lights ? lights->probe : nullptr;
    if (scattering && !shadow && !spans.empty() && !probe)
        throw std::logic_error("media scattering without shadow tests");
    const PhotonMap* photons =
        lights && lights->media_photons && lights->media_photons->size() > 0
            ? lights->media_photons
            : nullptr;
    Integrator in(list, ray, t0, shadow, env, spans, probe, photons,
                  scattering && (!spans.empty() || photons));
    Rgb te_total{0.0f}, od_total{0.0f};
    // Sample ids: each interval numbers the samples it may take (method 3: its S + 1
    // ends, then the midpoints each sub-interval's refinement may ask for).
    const bool adaptive = im->method == 3 && !fast;
    const int S = std::max(2, im->samples_min / 2 + 1);
    const uint64_t per_sub = (uint64_t(1) << std::min(im->aa_level, 40)) - 1;
    const uint64_t stride =
        adaptive ? uint64_t(S + 1) + uint64_t(S) * per_sub : uint64_t(im->samples_min);
    // Black boxes trace the shadow rays of every sample refinement may ask for.
    if (lights && lights->every_sample && scattering) threshold = -1;
    for (size_t i = 0; i < intervals.size(); ++i) {
        const SampleInterval& iv = intervals[i];
        const uint64_t base = i * stride;
        Rgb te{0.0f}, od{0.0f};
        int count = 0;
        if (adaptive) {
            const Real dd = 1.0 / (S + 1);
            const float jitter = im->jitter;
            Integrator::Sample previous =
                in.sample3(iv, dd * jitter * (in.draw(base) - 0.5), base);
            for (int j = 1; j <= S; ++j) {
                const uint64_t end = base + uint64_t(j);
                const Integrator::Sample next =
                    in.sample3(iv, j * dd + dd * jitter * (in.draw(end) - 0.5), end);
                const Integrator::Sample r = in.refine(
                    iv, (j - 1) * dd, j * dd, previous, next, im->aa_level - 1, threshold,
                    jitter, base + uint64_t(S + 1) + uint64_t(j - 1) * per_sub, 1);
                te += r.source * exp_neg(od / float(S));
                od += r.depth;
                previous = next;
            }
            count = S;
        } else {
            const int n = fast ? 1 : im->samples_min;
            for (int j = 0; j < n; ++j) {
                const uint64_t id = base + uint64_t(j);
                const Real f = im->method == 2 && !fast
                                   ? (j + 0.5) / n + in.draw(id) * im->jitter / n
                                   : in.draw(id);
                const Real u = f * iv.ds;
                const Coefficients c = in.at(iv.s0 + u, iv.lit, id);
                if (!shadow)
                    te += c.emission * float(iv.ds) * exp_neg(c.extinction * float(u));
                od += c.extinction * float(iv.ds);
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
