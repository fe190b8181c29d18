// Pattern values as POV-Ray 3.7 computes them (source/backend/pattern/pattern.cpp and
// warps.cpp of 3.7-stable, read for semantics; this is an independent implementation).
#include "trace/pattern.h"

#include <algorithm>
#include <cmath>

#include "core/math_constants.h"
#include "trace/pattern_internal.h"

namespace povwall::trace {
namespace detail {
namespace {

constexpr Real kCoordinateLimit = 1.0e17;

TurbulenceParams turb_params(const Warp* w) {
    TurbulenceParams t;
    if (w) {
        // POV-Ray clamps octaves to 1..10 when parsing.
        t.octaves = std::clamp(w->octaves, 1, 10);
        t.omega = w->omega;
        t.lambda = w->lambda;
    }
    return t;
}

Point3 apply_turbulence(const Warp& w, const Point3& p) {
    Vector3 d = dturbulence(p, turb_params(&w));
    return p + d * w.turbulence;
}

Point3 apply_repeat(const Warp& w, const Point3& p) {
    // POV-Ray's repeat warp works along the single axis whose component is non-zero.
    int axis = w.repeat.x != 0 ? 0 : (w.repeat.y != 0 ? 1 : 2);
    Real width = w.repeat[axis];
    if (width == 0) return p;
    Vector3 flip = w.flip;
    for (int i = 0; i < 3; ++i) flip[i] = flip[i] != 0 ? -1.0 : 1.0;
    Point3 r = p;
    float block =
        float(std::floor(p[axis] / width));  // POV-Ray keeps it single precision
    r[axis] = p[axis] - block * width;
    if (int(block) & 1) {
        r = r * flip;
        if (flip[axis] < 0) r[axis] = width + r[axis];
    }
    return r + w.offset * Real(block);
}

Point3 apply_black_hole(const Warp& w, const Point3& p) {
    Point3 centre = w.centre;
    if (w.repeat != Vector3(0, 0, 0)) {
        // POV-Ray's parser keeps repeated holes inside their cells: the centre is at
        // least one radius from the cell origin and the cell fits centre + radius +
        // uncertainty.
        Vector3 repeat = w.repeat;
        for (int i = 0; i < 3; ++i) {
            if (repeat[i] > 0.0) {
                centre[i] = std::max(centre[i], w.radius);
                repeat[i] = std::max(repeat[i], centre[i] + w.radius + w.turbulence[i]);
                if (repeat[i] < kPovEpsilon) repeat[i] = 0.0;
            }
        }
        int block[3] = {0, 0, 0};
        for (int i = 0; i < 3; ++i) {
            if (repeat[i] >= kPovEpsilon) block[i] = int(std::floor(p[i] / repeat[i]));
        }
        if (w.turbulence != Vector3(0, 0, 0)) {
            // Per-cell jitter of the centre from the pattern random table.
            size_t seed = size_t(hash3d(block[0], block[1], block[2]));
            centre.x += pattern_random(seed) * w.turbulence.x;
            centre.y += pattern_random(seed + 1) * w.turbulence.y;
            centre.z += pattern_random(seed + 2) * w.turbulence.z;
        }
        for (int i = 0; i < 3; ++i) centre[i] += repeat[i] * block[i];
    }
    Vector3 delta = p - centre;
    Real len = length(delta);
    if (len >= w.radius) return p;
    Real strength =
        std::min(std::pow((w.radius - len) / w.radius, w.falloff) * w.strength, 1.0);
    return p + delta * (w.inverse ? -strength : strength);
}

// Re-orients a mapping warp's (x, y, z) result the way POV-Ray does for non-z
// orientations.
Point3 orient(const Warp& w, Real x, Real y, Real z) {
    Vector3 o = normalize(w.orientation);  // POV-Ray normalises it when parsing
    if (o.x == 0.0 && o.y == 0.0 && o.z == 1.0) return {x, y, z};
    return {o.x * z + o.y * x + o.z * x, o.x * y + o.y * -z + o.z * y,
            o.x * -x + o.y * y + o.z * z};
}

// Angle of (x, z) from +x in [0, 2pi), as POV-Ray's mapping warps compute it.
Real xz_angle(Real x, Real z, Real len) {
    if (z == 0.0) return x > 0 ? 0.0 : kPi;
    Real theta = std::acos(x / len);
    return z < 0.0 ? 2 * kPi - theta : theta;
}

Real dist_factor(Real dist, Real exponent) {
    if (exponent == 1.0) return dist;
    if (exponent != 0.0) return std::pow(dist, exponent);
    return 1.0;
}

Point3 apply_mapping_warp(const Warp& w, const Point3& p) {
    Real x = p.x, y = p.y, z = p.z;
    switch (w.kind) {
        case Warp::Kind::Cylindrical: {
            Real len = std::sqrt(x * x + z * z);
            if (len == 0.0) return p;
            Real theta = xz_angle(x, z, len) / (2 * kPi) * dist_factor(len, w.dist_exp);
            return orient(w, theta, y, len);
        }
        case Warp::Kind::Spherical: {
            Real dist = std::sqrt(x * x + y * y + z * z);
            if (dist == 0.0) return p;
            x /= dist;
            y /= dist;
            z /= dist;
            Real phi = 0.5 + std::asin(y) / kPi;
            Real len = std::sqrt(x * x + z * z);
            Real theta = len == 0.0 ? 0.0 : xz_angle(x, z, len) / (2 * kPi);
            Real f = dist_factor(dist, w.dist_exp);
            return orient(w, theta * f, phi * f, dist);
        }
        case Warp::Kind::Toroidal: {
            Real len = std::sqrt(x * x + z * z);
            if (len == 0.0) return p;
            Real theta = -xz_angle(x, z, len);
            Real px = len - w.major_radius;
            len = std::sqrt(px * px + y * y);
            Real phi = std::acos(-px / len);
            if (y > 0.0) phi = 2 * kPi - phi;
            theta /= -2 * kPi;
            phi /= 2 * kPi;
            Real f = dist_factor(len, w.dist_exp);
            return orient(w, theta * f, phi * f, len);
        }
        case Warp::Kind::Planar:
            return orient(w, x, y, w.plane_offset);
        case Warp::Kind::Cubic:
            return cubic_warp(p);
        default:
            return p;
    }
}

// Pattern values of the individual patterns at a pattern-space point.

Real brick(const PatternSpec& s, const Point3& p) {
    Vector3 size = s.vector2 == Vector3(0, 0, 0) ? Vector3(8.0, 3.0, 4.5) : s.vector2;
    // POV-Ray keeps `mortar` minus 2e-10 in single precision: the default 0.5 stays 0.5,
    // so a face on a joint (the mortar's far edge plus 1e-10) reads as mortar.
    const Real mortar = float((s.scalar != 0 ? s.scalar : 0.5) - kPovEpsilon * 2.0);
    Real fudge = kPovEpsilon + mortar;
    Real x = p.x + fudge, y = p.y + fudge, z = p.z + fudge;
    auto frac = [](Real v) {
        v -= Real(int(v));  // truncation, then wrapped into [0,1)
        return v < 0 ? v + 1.0 : v;
    };
    if (frac(y / size.y) <= mortar / size.y) return 0;
    Real row = frac((y / size.y) * 0.5);
    bool odd = row <= 0.5;
    Real mw = mortar / size.x, md = mortar / size.z;
    if (frac(x / size.x) <= mw && odd) return 0;
    if (frac(x / size.x + 0.5) <= mw && !odd) return 0;
    if (frac(z / size.z) <= md && !odd) return 0;
    if (frac(z / size.z + 0.5) <= md && odd) return 0;
    return 1;
}

Real checker(const Point3& p) {
    int v = int(std::floor(p.x + kPovEpsilon) + std::floor(p.y + kPovEpsilon) +
                std::floor(p.z + kPovEpsilon));
    return (v & 1) ? 1.0 : 0.0;
}

Real hexagon(const Point3& p) {
    constexpr Real kXFactor = 0.5, kZFactor = 0.866025404;
    Real x = std::fabs(p.x);
    // Keep z positive without mirroring: 5.196152424 is six grid rows.
    Real z = p.z < 0.0 ? 5.196152424 - std::fabs(p.z) : p.z;
    Real xs = x / kXFactor, zs = z / kZFactor;
    xs -= std::floor(xs / 6.0) * 6.0;
    zs -= std::floor(zs / 6.0) * 6.0;
    int xm = int(std::floor(xs)) % 6, zm = int(std::floor(zs)) % 6;
    switch (xm) {
        case 0:
        case 5:
            return (zm == 0 || zm == 5) ? 0 : (zm <= 2 ? 1 : 2);
        case 2:
        case 3:
            return zm <= 1 ? 2 : (zm <= 3 ? 0 : 1);
        default: {
            Real xl = xs - xm, zl = zs - zm;
            if (((xm + zm) % 2) == 1) xl = 1.0 - xl;
            if (xl == 0.0) xl = 0.0001;
            bool below = (zl / xl) < 1.0;
            int r = zm % 3;  // rows 0/3, 1/4, 2/5 behave alike
            if (below) return r == 0 ? 0 : (r == 2 ? 1 : 2);
            return r == 0 ? 2 : (r == 2 ? 0 : 1);
        }
    }
}

Real granite(const Point3& p, int gen) {
    Real sum = 0, freq = 1.0;
    Vector3 base = p * 4.0;
    for (int i = 0; i < 6; ++i, freq *= 2.0) {
        Real n = noise(base * freq, gen);
        Real t = gen == 1 ? std::fabs(0.5 - n) : std::min(std::fabs(1.0 - 2.0 * n), 0.5);
        sum += t / freq;
    }
    return sum;
}

Real wrinkles(const Point3& p, int gen) {
    auto octave = [&](const Point3& q) {
        Real n = noise(q, gen);
        return gen == 1 ? n : std::clamp(n * 2.0 - 0.5, 0.0, 1.0);
    };
    Real value = octave(p), lambda = 2.0, omega = 0.5;
    for (int i = 1; i < 10; ++i) {
        value += omega * octave(p * lambda);
        lambda *= 2.0;
        omega *= 0.5;
    }
    return value / 2.0;
}

Real spiral_angle_term(const Point3& p, Real arms, Real& rad) {
    rad = std::sqrt(p.x * p.x + p.y * p.y);
    Real phi = 0;
    if (rad != 0.0) {
        phi = p.x < 0.0 ? 3.0 * kPi / 2 - std::asin(p.y / rad)
                        : kPi / 2 + std::asin(p.y / rad);
    }
    return arms * phi / (2 * kPi);
}

// The 81 cubes around a crackle cell (offsets -2..2 with at most one |2|), in POV-Ray's
// order.
struct CrackleCubes {
    int offset[81][3];
    CrackleCubes() {
        int n = 0;
        for (int x = -2; x <= 2; ++x)
            for (int y = -2; y <= 2; ++y)
                for (int z = -2; z <= 2; ++z)
                    if ((std::abs(x) == 2) + (std::abs(y) == 2) + (std::abs(z) == 2) <=
                        1) {
                        offset[n][0] = x;
                        offset[n][1] = y;
                        offset[n][2] = z;
                        ++n;
                    }
    }
};
const CrackleCubes kCrackleCubes;

// Crackle parameters live in the generic fields: vector = form (default <-1,1,0>),
// scalar = metric (default 2), vector2.x = offset, vector2.y != 0 means `solid`.
Real crackle(const PatternSpec& s, const Point3& p, int gen) {
    Vector3 form = s.vector == Vector3(0, 0, 0) ? Vector3(-1, 1, 0) : s.vector;
    Real metric = s.scalar != 0 ? s.scalar : 2.0;
    Real offset = s.vector2.x;
    bool square = metric == 2, unity = metric == 1;
    int fx = int(std::floor(p.x - kPovEpsilon)), fy = int(std::floor(p.y - kPovEpsilon)),
        fz = int(std::floor(p.z - kPovEpsilon));
    auto distance = [&](const Vector3& d) {
        if (square) return dot(d, d);
        if (unity) return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
        return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) +
               std::pow(std::fabs(d.z), metric);
    };
    // Nearest three cell nuclei; one random point per unit cube. Neighbouring samples
    // usually share a cell, so each thread keeps the last cell's 81 nuclei.
    struct Cache {
        bool valid = false;
        int x = 0, y = 0, z = 0;
        Point3 nucleus[81];
    };
    thread_local Cache cache;
    if (!cache.valid || cache.x != fx || cache.y != fy || cache.z != fz) {
        for (int i = 0; i < 81; ++i) {
            int cx = fx + kCrackleCubes.offset[i][0],
                cy = fy + kCrackleCubes.offset[i][1],
                cz = fz + kCrackleCubes.offset[i][2];
            size_t seed = size_t(hash3d(cx & 0xFFF, cy & 0xFFF, cz & 0xFFF));
            cache.nucleus[i] = {cx + pattern_random(seed), cy + pattern_random(seed + 1),
                                cz + pattern_random(seed + 2)};
        }
        cache.valid = true;
        cache.x = fx;
        cache.y = fy;
        cache.z = fz;
    }
    const Point3* nucleus = cache.nucleus;
    Real best[3];
    int best_index = 0;
    for (int i = 0; i < 3; ++i) best[i] = distance(nucleus[i] - p);
    if (best[1] < best[0]) {
        std::swap(best[0], best[1]);
        best_index = 1;
    }
    if (best[2] < best[0]) {
        std::swap(best[0], best[2]);
        best_index = 2;
    }
    if (best[2] < best[1]) std::swap(best[1], best[2]);
    for (int i = 3; i < 81; ++i) {
        Real d = distance(nucleus[i] - p);
        if (d < best[0]) {
            best[2] = best[1];
            best[1] = best[0];
            best[0] = d;
            best_index = i;
        } else if (d < best[1]) {
            best[2] = best[1];
            best[1] = d;
        } else if (d < best[2]) {
            best[2] = d;
        }
    }
    if (offset != 0) {
        Real add = square ? offset * offset : (unity ? offset : std::pow(offset, metric));
        for (Real& b : best) b += add;
    }
    Real tf;
    if (s.vector2.y != 0) {
        tf = noise(nucleus[best_index], gen);
    } else if (square) {
        tf = form.x * std::sqrt(best[0]) + form.y * std::sqrt(best[1]) +
             form.z * std::sqrt(best[2]);
    } else if (unity) {
        tf = form.x * best[0] + form.y * best[1] + form.z * best[2];
    } else {
        tf = form.x * std::pow(best[0], 1.0 / metric) +
             form.y * std::pow(best[1], 1.0 / metric) +
             form.z * std::pow(best[2], 1.0 / metric);
    }
    return std::max(std::min(tf, 1.0), 0.0);
}

// POV-Ray's density clip for boxed/spherical/cylindrical/planar: 1 at 0 falling to 0
// at 1.
Real clip_density(Real r) { return r < 0.0 ? 1.0 : (r > 1.0 ? 0.0 : 1.0 - r); }

// POV-Ray's slope pattern: the angle of the surface normal to a direction (or to the
// way toward point_at) as 0 (facing away) .. 1 (facing along it), rescaled to its
// low/high range, then mixed with the altitude of the pattern point along another
// direction; 0 where there is no surface.
Real slope_value(const PatternSpec::Slope& s, const Point3& p, const SurfaceAtHit* at) {
    if (!at) return 0;
    auto along = [](const Vector3& v, int axis, const Vector3& direction) {
        if (axis > 0) return v[axis - 1];
        if (axis < 0) return -v[-axis - 1];
        return dot(v, direction);
    };
    Real slope = s.point_at ? dot(at->normal, normalize(s.direction - at->point))
                            : along(at->normal, s.axis, s.direction);
    slope = std::clamp(slope, -1.0, 1.0);
    slope = (std::asin(slope) / kPi * 2 + 1.0) * 0.5;
    if (s.range != 0) slope = (slope - s.low) / s.range;
    // 1 is common exactly (a surface facing the direction): kept at the map's top.
    auto wrap = [](Real v) {
        return v < 0.0 ? 1.0 + std::fmod(v, 1.0) : std::fmod(v, 1.0);
    };
    if (s.altitude_share == 0) return slope == 1.0 ? slope - kPovEpsilon : wrap(slope);
    Real altitude = along(p, s.altitude_axis, s.altitude);
    if (s.altitude_range != 0) altitude = (altitude - s.altitude_low) / s.altitude_range;
    const Real value = s.share * slope + s.altitude_share * altitude;
    return value - 1.0 < kPovEpsilon && value >= 1.0 ? value - kPovEpsilon : wrap(value);
}

// POV-Ray's aoi: the angle between the surface normal and the ray, 0..1 for 0..180
// degrees (the normal faces the ray, so a surface hit head-on gives 1).
Real aoi_value(const SurfaceAtHit* at) {
    if (!at) return 0;
    const Real c = dot(normalize(at->normal), normalize(at->ray_direction));
    return std::acos(std::clamp(c, -1.0, 1.0)) / kPi;
}

Real raw_value(const PatternSpec& s, const Point3& p, const PatternEnv& env) {
    int gen = resolve_generator(s, env);
    const Warp* turb = classic_turbulence(s);
    switch (s.kind) {
        case PatternKind::Solid:
        case PatternKind::Average:
        case PatternKind::ImageMap:
            return 0;
        case PatternKind::Agate: {
            Real scale = s.scalar != 0 ? s.scalar : 1.0;  // agate_turb, default 1
            Real t = scale * turbulence(p, turb_params(turb), gen);
            Real n = 0.5 * (cycloidal(1.3 * t + 1.1 * p.z) + 1.0);
            return n < 0.0 ? 0.0 : std::pow(std::min(1.0, n), 0.77);
        }
        case PatternKind::Bozo:
        case PatternKind::Spotted:
        case PatternKind::Bumps:
            return noise(p, gen);
        case PatternKind::Brick:
            return brick(s, p);
        case PatternKind::Checker:
            return checker(p);
        case PatternKind::Crackle:
            return crackle(s, p, gen);
        case PatternKind::Function: {
            const double args[3] = {p.x, p.y, p.z};
            const Real r = evaluate_function(*s.function, args, function_hooks(env));
            return r > 1.0 ? std::fmod(r, 1.0) : r;  // POV-Ray wraps only above 1
        }
        case PatternKind::PigmentPattern:
            // Evaluated at this pattern's point: its own transforms go on top of ours.
            return evaluate_pigment(*s.pigment, p, env).rgb.grey();
        case PatternKind::Slope:
            return slope_value(*s.slope, p, env.surface);
        case PatternKind::Aoi:
            return aoi_value(env.surface);
        case PatternKind::Cells:
            return std::min(
                pattern_random(size_t(hash3d(int(std::floor(p.x + kPovEpsilon)),
                                             int(std::floor(p.y + kPovEpsilon)),
                                             int(std::floor(p.z + kPovEpsilon))))),
                1.0);
        case PatternKind::Dents: {
            Real n = noise(p, gen);
            return n * n * n;
        }
        case PatternKind::Gradient: {
            // POV-Ray normalises the gradient vector when parsing.
            Real r = dot(p, normalize(s.vector));
            return r > 1.0 ? std::fmod(r, 1.0) : r;
        }
        case PatternKind::Granite:
            return granite(p, gen);
        case PatternKind::Hexagon:
            return hexagon(p);
        case PatternKind::Leopard: {
            Real v = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3.0;
            return v * v;
        }
        case PatternKind::Mandel:
        case PatternKind::Julia:
        case PatternKind::Magnet:
            return fractal_value(s, p);
        case PatternKind::Square:
            return square_value(p);
        case PatternKind::Triangular:
            return triangular_value(p);
        case PatternKind::Cubic:
            return cubic_value(p);
        case PatternKind::Tiling:
            return tiling_value(int(s.scalar), p);
        case PatternKind::Pavement:
            return pavement_value(s.pavement, p);
        case PatternKind::Facets:  // a normal only (its value where a pattern is read)
            return 0;
        case PatternKind::Marble: {
            Real t =
                turb ? turb->turbulence.x * turbulence(p, turb_params(turb), gen) : 0.0;
            return p.x + t;
        }
        case PatternKind::Onion:
            return std::fmod(length(p), 1.0);
        case PatternKind::Quilted: {
            Vector3 v{p.x - std::floor(p.x) - 0.5, p.y - std::floor(p.y) - 0.5,
                      p.z - std::floor(p.z) - 0.5};
            v *= quilt_cubic(length(v), s.vector.x, s.vector.y);
            return (std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z)) / 3.0;
        }
        case PatternKind::Radial:
            if (std::fabs(p.x) < 0.001 && std::fabs(p.z) < 0.001) return 0.25;
            return 0.25 + (std::atan2(p.x, p.z) + kPi) / (2 * kPi);
        case PatternKind::Ripples:
        case PatternKind::Waves: {
            const WaveTable& w = wave_table();
            int n = std::clamp(env.number_of_waves, 1, kMaxWaves);
            Real sum = 0;
            for (int i = 0; i < n; ++i) {
                Real len = length(p - w.source[i]);
                if (len == 0.0) len = 1.0;
                if (s.kind == PatternKind::Ripples) {
                    sum += cycloidal(len * s.frequency + s.phase);
                } else {
                    Real f = w.frequency[i];
                    sum += cycloidal(len * s.frequency * f + s.phase) / f;
                }
            }
            return s.kind == PatternKind::Ripples ? 0.5 * (1.0 + sum / n)
                                                  : 0.2 * (2.5 + sum / n);
        }
        case PatternKind::Spiral1:
        case PatternKind::Spiral2: {
            Real t =
                turb ? turb->turbulence.x * turbulence(p, turb_params(turb), gen) : 0.0;
            Real rad;
            Real angle = spiral_angle_term(p, Real(int(s.scalar)), rad);
            if (s.kind == PatternKind::Spiral1) return p.z + rad + angle + t;
            return triangle_wave(rad) + triangle_wave(p.z + rad + angle + t);
        }
        case PatternKind::Wood: {
            Real x = p.x, y = p.y;
            if (turb) {
                Vector3 d = dturbulence(p, turb_params(turb));
                x += cycloidal((p.x + d.x) * turb->turbulence.x);
                y += cycloidal((p.y + d.y) * turb->turbulence.y);
            }
            return std::sqrt(x * x + y * y);
        }
        case PatternKind::Wrinkles:
            return wrinkles(p, gen);
        case PatternKind::Boxed:
            return clip_density(
                std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z))));
        case PatternKind::Cylindrical:
            return clip_density(std::sqrt(p.x * p.x + p.z * p.z));
        case PatternKind::Spherical:
            return clip_density(length(p));
        case PatternKind::Planar:
            return clip_density(std::fabs(p.y));
        case PatternKind::DensityFile:
            return s.density_file
                       ? density_file_value(*s.density_file, s.density_interpolation, p)
                       : 0;
        case PatternKind::ObjectInside:
            return s.object && inside_pattern_object(*s.object, p) ? 1.0 : 0.0;
        case PatternKind::ImagePattern:
            return s.image ? image_pattern_value(*s.image, p) : 0;
        case PatternKind::UvMapping:  // their entries are evaluated, never their value
        case PatternKind::MaterialMap:
            return 0;
    }
    return 0;
}

}  // namespace

Real quilt_cubic(Real t, Real p1, Real p2) {
    constexpr Real kInvSqrt34 = 1.154700538;
    Real it = 1 - t;
    return (t * t * t + 3.0 * t * it * it * p1 + 3.0 * t * t * it * p2) * kInvSqrt34;
}

const Warp* classic_turbulence(const PatternSpec& spec) {
    for (auto it = spec.warps.rbegin(); it != spec.warps.rend(); ++it) {
        if (it->kind == Warp::Kind::Turbulence && it->classic) return &*it;
    }
    return nullptr;
}

Point3 warp_point(const PatternSpec& spec, const Point3& world) {
    Point3 p = spec.transform.is_identity() ? world : spec.transform.inverse_point(world);
    const Warp* classic = classic_turbulence(spec);
    for (auto it = spec.warps.rbegin(); it != spec.warps.rend(); ++it) {
        const Warp& w = *it;
        if (&w == classic) continue;
        switch (w.kind) {
            case Warp::Kind::Turbulence:
                p = apply_turbulence(w, p);
                break;
            case Warp::Kind::Repeat:
                p = apply_repeat(w, p);
                break;
            case Warp::Kind::BlackHole:
                p = apply_black_hole(w, p);
                break;
            default:
                p = apply_mapping_warp(w, p);
                break;
        }
        if (!w.transform.is_identity()) p = w.transform.inverse_point(p);
    }
    if (classic && spec.kind != PatternKind::Marble && spec.kind != PatternKind::Wood) {
        p = apply_turbulence(*classic, p);
    }
    for (int i = 0; i < 3; ++i)
        p[i] = std::clamp(p[i], -kCoordinateLimit, kCoordinateLimit);
    return p;
}

namespace {
// n -> A^T n, A the linear part of the pattern->world transform.
Vector3 transpose_apply(const Transform& t, const Vector3& n) {
    const Matrix34& m = t.forward();
    return {m.m[0][0] * n.x + m.m[1][0] * n.y + m.m[2][0] * n.z,
            m.m[0][1] * n.x + m.m[1][1] * n.y + m.m[2][1] * n.z,
            m.m[0][2] * n.x + m.m[1][2] * n.y + m.m[2][2] * n.z};
}
}  // namespace

// With no_bump_scale POV-Ray leaves the normal's length as the transforms make it: a
// pattern scaled up by s lengthens the normal s times in pattern space, so the same
// displacement tilts it less, and taking it back out does not undo that.
Vector3 warp_normal(const PatternSpec& spec, const Vector3& n) {
    Vector3 r = spec.no_bump_scale ? n : normalize(n);
    if (!spec.transform.is_identity()) r = transpose_apply(spec.transform, r);
    for (auto it = spec.warps.rbegin(); it != spec.warps.rend(); ++it) {
        if (!it->transform.is_identity()) r = transpose_apply(it->transform, r);
    }
    return spec.no_bump_scale ? r : normalize(r);
}

Vector3 unwarp_normal(const PatternSpec& spec, const Vector3& n) {
    Vector3 r = spec.no_bump_scale ? n : normalize(n);
    for (const Warp& w : spec.warps) {
        if (!w.transform.is_identity()) r = w.transform.normal(r);
    }
    if (!spec.transform.is_identity()) r = spec.transform.normal(r);
    return spec.no_bump_scale ? r : normalize(r);
}

Real value_at(const PatternSpec& spec, const Point3& p, const PatternEnv& env) {
    Real value = raw_value(spec, p, env);
    // Quilted and image_pattern start at frequency 0, as POV-Ray's parser sets them; so
    // do the block and object patterns, whose entry number a frequency wraps as any
    // pattern's value (then blending the neighbouring entries, search_list).
    if (spec.frequency != 0.0)
        value = std::fmod(value * spec.frequency + spec.phase, 1.00001);
    if (value < 0.0) value -= std::floor(value);
    switch (spec.wave) {
        case WaveType::Ramp:
            break;
        case WaveType::Sine:
            value = (1.0 + cycloidal(value)) * 0.5;
            break;
        case WaveType::Triangle:
            value = triangle_wave(value);
            break;
        case WaveType::Scallop:
            value = std::fabs(cycloidal(value * 0.5));
            break;
        case WaveType::Cubic:
            value = value * value * (-2.0 * value + 3.0);
            break;
        case WaveType::Poly:
            value = std::pow(value, spec.wave_exponent);
            break;
    }
    return value;
}

}  // namespace detail

namespace {

// Patterns called from functions see no surface (POV-Ray passes none).
Real pattern_hook(const PatternSpec& spec, const Point3& p, const void* context) {
    return evaluate_pattern(spec, p,
                            static_cast<const PatternEnv*>(context)->at_surface(nullptr));
}

void pigment_hook(const Pigment& pigment, const Point3& p, const void* context,
                  float out[5]) {
    const Colour c = evaluate_pigment(
        pigment, p, static_cast<const PatternEnv*>(context)->at_surface(nullptr));
    out[0] = c.rgb.r, out[1] = c.rgb.g, out[2] = c.rgb.b;
    out[3] = c.filter, out[4] = c.transmit;
}

}  // namespace

FunctionHooks function_hooks(const PatternEnv& env) {
    FunctionHooks h;
    h.pattern = pattern_hook;
    h.pigment = pigment_hook;
    h.context = &env;
    h.noise_generator = env.noise_generator;
    return h;
}

FunctionHooks parse_time_function_hooks() {
    // One per thread: a parse sets it before each call (use_settings).
    static thread_local PatternEnv env;
    FunctionHooks h = function_hooks(env);
    h.use_settings = [](const void* context, int noise_generator, int number_of_waves) {
        auto* e = const_cast<PatternEnv*>(static_cast<const PatternEnv*>(context));
        e->noise_generator = noise_generator;
        e->number_of_waves = number_of_waves;
    };
    return h;
}

Real evaluate_pattern(const PatternSpec& spec, const Point3& world,
                      const PatternEnv& env) {
    if (spec.kind == PatternKind::Solid) return 0;
    return detail::value_at(spec, detail::warp_point(spec, world), env);
}

MapLookup search_list(int count, Real value) {
    // The longest list (cubic, triangular) has six entries.
    static constexpr float kEntryNumbers[] = {0, 1, 2, 3, 4, 5};
    return search_map(kEntryNumbers, std::min(count, 6), value);
}

MapLookup search_map(const float* values, int count, Real value) {
    MapLookup r;
    if (count <= 0) return r;
    if (value >= values[count - 1]) {
        r.prev = r.cur = count - 1;
        return r;
    }
    int c = 0;
    while (value > values[c]) ++c;
    r.cur = c;
    r.prev = c > 0 ? c - 1 : 0;
    if (r.prev != r.cur)
        r.fraction = (value - values[r.prev]) / (values[r.cur] - values[r.prev]);
    return r;
}

Point3 pattern_point(const PatternSpec& spec, const Point3& world) {
    return detail::warp_point(spec, world);
}

Vector3 normal_into_pattern(const PatternSpec& spec, const Vector3& n) {
    return detail::warp_normal(spec, n);
}

Vector3 normal_out_of_pattern(const PatternSpec& spec, const Vector3& n) {
    return detail::unwarp_normal(spec, n);
}

MapPick pick_map_entries(const PatternSpec& spec, const float* values, int count,
                         const Point3& world, const PatternEnv& env) {
    MapPick pick;
    if (spec.kind == PatternKind::UvMapping) {
        // The one entry, at the surface coordinates.
        pick.point = detail::uv_of(env);
        return pick;
    }
    pick.point = detail::warp_point(spec, world);
    if (spec.kind == PatternKind::MaterialMap) {
        // The entry the image's pixel names, never a blend.
        pick.lookup.prev = pick.lookup.cur =
            spec.image ? detail::material_map_index(*spec.image, pick.point, count) : 0;
        return pick;
    }
    Real value = detail::value_at(spec, pick.point, env);
    if (values == nullptr || count <= 0) {
        pick.lookup = search_list(detail::list_size(spec.kind), value);
        return pick;
    }
    pick.lookup = search_map(values, count, value);
    return pick;
}

}  // namespace povwall::trace
