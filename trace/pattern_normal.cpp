// Normal perturbation as POV-Ray 3.7's Perturb_Normal: the dedicated bumps/dents/ripples/
// waves/wrinkles/quilted/facets normals, any other pattern sampled at four points of a
// tetrahedron (accuracy) and scaled by bump_size, and normal_map blending.
#include <algorithm>
#include <cmath>

#include "trace/pattern.h"
#include "trace/pattern_internal.h"

namespace povwall::trace {
namespace {

// Tetrahedron directions POV-Ray samples pattern normals along.
constexpr Vector3 kPyramid[4] = {{0.942809041, -0.333333333, 0.0},
                                 {-0.471404521, -0.333333333, 0.816496581},
                                 {-0.471404521, -0.333333333, -0.816496581},
                                 {0.0, 1.0, 0.0}};

bool has_dedicated_normal(PatternKind k) {
    return k == PatternKind::Bumps || k == PatternKind::Dents ||
           k == PatternKind::Ripples || k == PatternKind::Waves ||
           k == PatternKind::Wrinkles || k == PatternKind::Quilted ||
           k == PatternKind::ImageMap || k == PatternKind::Facets;
}

// Adds the dedicated normal pattern's displacement at pattern-space point p to n.
void displace(const Normal& nm, const Point3& p, Vector3& n, const PatternEnv& env) {
    const PatternSpec& s = *nm.pattern;
    switch (s.kind) {
        case PatternKind::Bumps:
            n += dnoise(p) * nm.amount;
            break;
        case PatternKind::Dents: {
            Real v = noise(p, detail::resolve_generator(s, env));
            n += dnoise(p) * (v * v * v * nm.amount);
            break;
        }
        case PatternKind::Wrinkles: {
            Vector3 sum{0, 0, 0};
            Real scale = 1.0;
            for (int i = 0; i < 10; ++i, scale *= 2.0) {
                Vector3 d = dnoise(p * scale);
                sum += Vector3(std::fabs(d.x / scale), std::fabs(d.y / scale),
                               std::fabs(d.z / scale));
            }
            n += sum * nm.amount;
            break;
        }
        case PatternKind::Ripples:
        case PatternKind::Waves: {
            const WaveTable& w = wave_table();
            int count = std::clamp(env.number_of_waves, 1, kMaxWaves);
            for (int i = 0; i < count; ++i) {
                Vector3 d = p - w.source[i];
                Real len = length(d);
                if (len == 0.0) len = 1.0;
                Real scalar;
                if (s.kind == PatternKind::Ripples) {
                    scalar = cycloidal(len * s.frequency + s.phase) * nm.amount;
                } else {
                    Real f = w.frequency[i];
                    scalar = cycloidal(len * s.frequency * f + s.phase) * nm.amount / f;
                }
                n += d * (scalar / (len * Real(count)));
            }
            break;
        }
        case PatternKind::Quilted: {
            Vector3 v{p.x - std::floor(p.x) - 0.5, p.y - std::floor(p.y) - 0.5,
                      p.z - std::floor(p.z) - 0.5};
            v *= detail::quilt_cubic(length(v), s.vector.x, s.vector.y);
            n += v * nm.amount;
            break;
        }
        case PatternKind::ImageMap:
            if (s.image) detail::bump_map_normal(*s.image, nm.amount, p, n);
            break;
        case PatternKind::Facets:
            detail::facets_normal(s.facets, p, n);
            break;
        default:
            break;
    }
}

// The height a slope_map gives the pattern value: a cubic Hermite segment between the two
// neighbouring entries' heights and slopes (POV-Ray's Do_Slope_Map); no map: the value.
Real slope_mapped(const Normal& nm, Real value) {
    const std::vector<SlopeMapEntry>& map = nm.slope_map;
    if (map.empty()) return value;
    float values[256];
    int n = int(std::min<size_t>(map.size(), 256));
    for (int i = 0; i < n; ++i) values[i] = map[size_t(i)].value;
    MapLookup m = search_map(values, n, value);
    const SlopeMapEntry& cur = map[size_t(m.cur)];
    if (m.prev == m.cur) return cur.height;
    const SlopeMapEntry& prev = map[size_t(m.prev)];
    Real t = m.fraction, tt = t * t, ttt = tt * t;
    return ttt * (prev.slope + cur.slope + 2.0 * (prev.height - cur.height)) -
           tt * (2.0 * prev.slope + cur.slope + 3.0 * (prev.height - cur.height)) +
           t * prev.slope + prev.height;
}

}  // namespace

// POV-Ray's Perturb_Normal: unit length unless the pattern has no_bump_scale (then the
// caller normalises, as POV-Ray's Trace does; a normal_map normalises its blend).
Vector3 perturb_normal_unnormalised(const Normal& normal, const Point3& world,
                                    const Vector3& geometric, const PatternEnv& env) {
    const PatternSpec& spec = *normal.pattern;
    if (spec.kind == PatternKind::Solid) return normalize(geometric);
    if (spec.kind == PatternKind::UvMapping) {
        // The entry perturbs the world normal itself, at the surface coordinates (as
        // POV-Ray's: no warp of the normal into them).
        if (normal.list.empty()) return normalize(geometric);
        return normalize(perturb_normal_unnormalised(normal.list.front(),
                                                     detail::uv_of(env), geometric, env));
    }

    // normal_map: perturb by the two neighbouring normals and blend the results.
    if (spec.kind != PatternKind::Average && !normal.map_values.empty() &&
        !normal.list.empty()) {
        Point3 p = detail::warp_point(spec, world);
        Real value = detail::value_at(spec, p, env);
        int n = int(std::min(normal.map_values.size(), normal.list.size()));
        MapLookup m = search_map(normal.map_values.data(), n, value);
        Vector3 local = detail::warp_normal(spec, geometric);
        // Entries are evaluated at the warped point, as POV-Ray does.
        Vector3 cur =
            perturb_normal_unnormalised(normal.list[size_t(m.cur)], p, local, env);
        if (m.prev != m.cur) {
            Vector3 prev =
                perturb_normal_unnormalised(normal.list[size_t(m.prev)], p, local, env);
            cur = prev * (1.0 - m.fraction) + cur * m.fraction;
        }
        const Vector3 out = detail::unwarp_normal(spec, cur);
        return spec.no_bump_scale ? normalize(out) : out;
    }

    Vector3 n = detail::warp_normal(spec, geometric);
    Point3 p = detail::warp_point(spec, world);
    if (spec.kind == PatternKind::Average) {
        // Weighted mean of the entries' perturbed normals (weights: the entry values).
        Vector3 sum{0, 0, 0};
        float total = 0;
        size_t count = std::min(normal.map_values.size(), normal.list.size());
        for (size_t i = 0; i < count; ++i) {
            float w = normal.map_values[i];
            sum += perturb_normal_unnormalised(normal.list[i], p, n, env) * Real(w);
            total += w;
        }
        if (total != 0) n = sum / Real(total);
    } else if (has_dedicated_normal(spec.kind)) {
        displace(normal, p, n, env);
    } else {
        // POV-Ray keeps the accuracy (its default 0.02 too) in single precision.
        const Real accuracy =
            Real(static_cast<float>(normal.accuracy > 0 ? normal.accuracy : 0.02));
        Real amount = normal.amount * -5.0 * (0.02 / accuracy);
        for (const Vector3& dir : kPyramid) {
            Real v =
                slope_mapped(normal, detail::value_at(spec, p + dir * accuracy, env));
            n += dir * (v * amount);
        }
    }
    return detail::unwarp_normal(spec, n);
}

Vector3 perturb_normal(const Normal& normal, const Point3& world,
                       const Vector3& geometric, const PatternEnv& env) {
    const Vector3 n = perturb_normal_unnormalised(normal, world, geometric, env);
    return normal.pattern->no_bump_scale ? normalize(n) : n;
}

}  // namespace povwall::trace
