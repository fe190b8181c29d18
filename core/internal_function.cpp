// functions.inc's internal functions (see core/internal_function.h). Each is written from
// POV-Ray 3.7's definition, keeping its order of operations (and its quirks: integer
// divisions that give 0, parameters it ignores, a parameter used twice), since
// isosurfaces and the function pattern must see exactly POV-Ray's values. `a` holds x, y,
// z and then the parameters; `p` below is the parameters alone (functions.inc's P0, P1,
// ...).
#include "core/internal_function.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include "core/noise.h"

namespace povwall {

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766560;
constexpr double kRadiansPerDegree = 0.01745329251994329576;

// The noise the noise-based functions sample: their generator parameter is taken as an
// int & 3, and POV-Ray's noise treats 0 as the original generator 1.
double noise_of(const Vector3& v, int generator) {
    return noise(v, generator == 0 ? 1 : generator);
}
// The octave weights of a fractal function: entry i is pow(lacunarity^(i+1), exponent)
// as std::pow gives it, the frequency multiplied up one octave at a time. They repeat at
// every call with the same parameters, so each thread keeps the last table (octaves past
// kKept are computed at each call).
class OctaveWeights {
  public:
    static constexpr long kKept = 64;
    double at(long i, double frequency) const {
        return i < long(count_) ? weights_[i] : std::pow(frequency, exponent_);
    }
    static const OctaveWeights& of(double lacunarity, double exponent, double octaves) {
        thread_local OctaveWeights last;
        const size_t want = octaves > 0 ? size_t(std::min(octaves, double(kKept))) : 0;
        if (!(last.lacunarity_ == lacunarity && last.exponent_ == exponent &&
              last.count_ >= want)) {
            last.lacunarity_ = lacunarity;
            last.exponent_ = exponent;
            double frequency = 1.0;
            for (size_t i = 0; i < want; ++i) {
                frequency *= lacunarity;
                last.weights_[i] = std::pow(frequency, exponent);
            }
            last.count_ = want;
        }
        return last;
    }

  private:
    double lacunarity_ = 0, exponent_ = 0;
    size_t count_ = 0;
    double weights_[kKept] = {};
};

// C's (int) conversion as x86-64 does it (out of range and NaN give INT_MIN), without
// the undefined behaviour of a plain cast.
int c_int(double v) {
    if (!(v > -2147483649.0 && v < 2147483648.0)) return INT_MIN;
    return int(v);
}
int generator_parameter(double v) { return c_int(v) & 3; }

// ------------------------------------------------------------- noise-based functions

// f_hetero_mf: a heterogeneous multifractal. p: H, lacunarity, octaves (its fraction
// weighs one more octave), offset, the power of the running signal each increment is
// scaled by, noise generator.
double hetero_mf(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const int generator = generator_parameter(p[5]);
    Vector3 v(a[0], a[1], a[2]);
    double signal = (noise_of(v, generator) * 2.0 - 1.0) + p[3];
    v *= p[1];
    const double octave_weight = std::pow(p[1], -p[0]);
    double weight = octave_weight;
    for (int i = 1; i < p[2]; i++) {
        double increment = ((noise_of(v, generator) * 2.0 - 1.0) + p[3]) * weight;
        for (int k = c_int(p[4]); k > 0; --k) increment *= signal;
        signal += increment;
        v *= p[1];
        weight *= octave_weight;
    }
    const double fraction = p[2] - c_int(p[2]);
    if (fraction != 0.0) {
        const double increment = ((noise_of(v, generator) * 2.0 - 1.0) + p[3]) * weight;
        signal += fraction * increment * signal;
    }
    return signal;
}

// f_ridge: p: lambda, octaves (with a fraction), omega, offset, ridge, noise generator.
double ridge(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const int generator = generator_parameter(p[5]);
    const Vector3 at(a[0], a[1], a[2]);
    const double lambda = p[0], omega = p[2], offset = p[3], crest = p[4];
    const int octaves = c_int(p[1]);
    const double crest_scale = 1.0 / std::max(crest, 1.0 - crest);
    const double scale = 1.0 / std::max(offset, 1.0 - offset);
    const double fraction = p[1] - double(octaves);
    double frequency = lambda, amplitude = omega, total = 1.0;
    double v = std::fabs(noise_of(at, generator) - crest) * crest_scale;
    double value = v - offset;
    for (int i = 2; i <= octaves; i++) {
        v = std::fabs(noise_of(at * frequency, generator) - crest) * crest_scale;
        value += amplitude * (v - offset);
        total += amplitude;
        frequency *= lambda;
        amplitude *= omega;
    }
    if (0.0 != fraction) {
        v = std::fabs(noise_of(at * frequency, generator) - crest) * crest_scale;
        value += amplitude * (v - offset) * fraction;
        total += amplitude * fraction;
    }
    return value * scale / total;
}

// f_ridged_mf: Musgrave's ridged multifractal. p: H, lacunarity, octaves, offset, gain,
// noise generator. POV-Ray computes the octaves' weights lacunarity^-H once, at the first
// call of each declared function, and keeps them: a scene that calls one declared
// f_ridged_mf with different H, lacunarity or octaves gets the first call's weights
// there. povwall computes them from each call's parameters (the same values whenever a
// declared function is called with one set of them, as scenes do).
double ridged_mf(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const int generator = generator_parameter(p[5]);
    Vector3 v(a[0], a[1], a[2]);
    auto ridged = [&](const Vector3& at) {
        double s = noise_of(at, generator) * 2.0 - 1.0;
        if (s < 0.0) s = -s;
        s = p[3] - s;
        return s * s;
    };
    double signal = ridged(v);
    double result = signal;
    double frequency = 1.0;  // lacunarity^i, multiplied up as POV-Ray builds its table
    const OctaveWeights& weights = OctaveWeights::of(p[1], -p[0], std::ceil(p[2]) - 1);
    for (int i = 1; i < p[2]; i++) {
        frequency *= p[1];
        v *= p[1];
        double weight = signal * p[4];
        if (weight > 1.0) weight = 1.0;
        if (weight < 0.0) weight = 0.0;
        signal = ridged(v);
        signal *= weight;
        result += signal * weights.at(i - 1, frequency);
    }
    return result;
}

double noise3d(const double* a, const FunctionHooks& hooks) {
    return noise(Vector3(a[0], a[1], a[2]), hooks.noise_generator);
}

double noise_generator(const double* a, const FunctionHooks&) {
    return noise_of(Vector3(a[0], a[1], a[2]), generator_parameter(a[3]));
}

// internal(77) is the trap of `function { pattern { } }`; written directly it has no
// pattern, and POV-Ray gives 0.
double pattern_without_pattern(const double*, const FunctionHooks&) { return 0.0; }

// ------------------------------------------------------------- coordinates, spheres

double ph(const double* a, const FunctionHooks&) {
    return std::atan2(std::sqrt(a[0] * a[0] + a[2] * a[2]), a[1]);
}

double r(const double* a, const FunctionHooks&) {
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

double th(const double* a, const FunctionHooks&) { return std::atan2(a[0], a[2]); }

double sphere(const double* a, const FunctionHooks&) {
    return -a[3] + std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

// f_ellipsoid: p: the scales of x, y, z (no offset: the surface is at threshold 1).
double ellipsoid(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    return std::sqrt(a[0] * a[0] * p[0] * p[0] + a[1] * a[1] * p[1] * p[1] +
                     a[2] * a[2] * p[2] * p[2]);
}

// f_torus: p: major radius, minor radius.
double torus(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double out = std::sqrt(a[0] * a[0] + a[2] * a[2]) - p[0];
    return -p[1] + std::sqrt(out * out + a[1] * a[1]);
}

// f_superellipsoid: p: east-west exponent e, north-south exponent n (1 - the
// superellipsoid's inside-outside function).
double superellipsoid(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double e = 2 / p[0], n = 1 / p[1];
    const double xy = std::pow(std::fabs(a[0]), e) + std::pow(std::fabs(a[1]), e);
    return 1 - std::pow((std::pow(xy, p[0] * n) + std::pow(std::fabs(a[2]), 2 * n)),
                        p[1] * .5);
}

// f_rounded_box: the distance outside a box of half sizes p[1], p[2], p[3] whose edges
// are rounded with radius p[0] (less 1e-6, as POV-Ray).
double rounded_box(const double* a, const FunctionHooks&) {
    const double radius = a[3];
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
        const double inner = a[4 + k] - radius;  // the rounding's centre, each side
        const double above = a[k] < inner ? 0 : a[k] - inner;
        const double below = a[k] > -inner ? 0 : -inner - a[k];
        const double d = std::max(below, above);
        sum = k == 0 ? d * d : sum + d * d;
    }
    return -radius + std::sqrt(sum) - 1e-6;
}

// ------------------------------------------------------------------ helices, spirals

// The distance of (u, v) from the origin in the section shape helices and spirals share:
// 1 a circle, 0 a square, otherwise the superellipse of that exponent.
double section_distance(double u, double v, double shape) {
    if (shape != 0) {
        const double e = 2. / shape;
        return std::pow((std::pow(std::fabs(u), e) + std::pow(std::fabs(v), e)),
                        shape * .5);
    }
    return std::max(std::fabs(u), std::fabs(v));
}

// f_helix1: p[0] helices of minor radius p[2] wound around a torus-like core of major
// radius p[3] along y; p[1] turns per unit of y, p[4] stretches the section along the
// winding, p[5] its shape (1 circle, 2 diamond, other superellipse exponents, 0 a
// square) turned by p[6] degrees.
double helix1(const double* a, const FunctionHooks&) {
    const double x = a[0], y = a[1], z = a[2];
    const double* p = a + 3;
    const double count = p[0], frequency = p[1], minor = p[2], major = p[3];
    const double stretch = p[4], section = p[5], turn = p[6];
    const double r = std::sqrt(x * x + z * z);
    // The axis itself: atan2 of a point just off it.
    double angle = std::atan2(z, x == 0 && z == 0 ? 1e-6 : x);
    angle = std::fmod(angle * count + y * frequency * count, kTwoPi);
    if (angle < 0) angle += kTwoPi;
    double across = (angle - M_PI) / stretch / (frequency * count);
    double out = r - major;
    double dist;
    if (section == 1) {
        dist = std::sqrt(out * out + across * across);
    } else {
        if (turn != 0) {
            const double c = std::cos(turn * kRadiansPerDegree);
            const double s = std::sin(turn * kRadiansPerDegree);
            const double turned = out * c - across * s;
            across = out * s + across * c;
            out = turned;
        }
        dist = section_distance(out, across, section);
    }
    return -minor + std::min(major + r, dist);
}

// f_helix2: one helix of minor radius p[2] whose centre line turns around y at radius
// p[3], p[1] radians per unit of y; p[5] the section's shape (p[0], p[4], p[6] unused).
double helix2(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double angle = a[1] * p[1];
    const double c = std::cos(angle), s = std::sin(angle);
    const double dx = a[0] - p[3] * c;
    const double dz = a[2] - p[3] * s;
    const double u = dx * c + dz * s;
    const double v = (-dx * s + dz * c);
    if (p[5] == 1) return (std::sqrt(u * u + v * v) - p[2]);
    return section_distance(u, v, p[5]) - p[2];
}

// f_helical_torus: p: major radius, number of winding strands, twists per turn, fatness
// of the strands' bumps, their offset, minor radius, section stretch, the bumps'
// frequency, the section's stretch along the strand, the bumps' phase per turn.
double helical_torus(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    double x = a[0];
    const double y = a[1], z = a[2];
    double radial = std::sqrt(x * x + z * z);
    if (x == 0 && z == 0) x = 0.000001;
    const double around = std::atan2(x, z);
    double t = std::atan2(radial - p[0], y);
    const double r = std::sqrt((radial - p[0]) * (radial - p[0]) + y * y);
    double strand = std::fmod(around * p[1] + t * p[2], kTwoPi);
    if (strand < 0) strand += kTwoPi;
    t = std::atan2((strand - M_PI) * p[8], r - p[5]);
    t = std::cos(t * p[7] + around * p[9]) * p[3] + p[4];
    radial = p[4] + p[5] - p[0] - radial;
    strand = strand - M_PI;
    t = t -
        std::min(std::sqrt((r - p[5]) * (r - p[5]) + strand * strand * p[6]), (r + p[5]));
    return -std::max(radial, t);
}

// f_spiral: p: distance between the windings, thickness, outer radius, (unused),
// (unused), the section's shape.
double spiral(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    double x = a[0];
    const double y = a[1], z = a[2];
    double r = std::sqrt(x * x + z * z);
    if (x == 0 && z == 0) x = 0.000001;  // also moves the point for the distance below
    r = r + p[0] * std::atan2(z, x) / kTwoPi;
    double d = std::fmod(r, p[0]) - p[0] * 0.5;
    if (p[5] == 1) {
        d = std::sqrt(d * d + y * y);
    } else if (p[5] != 0) {
        const double e = 2 / p[5];
        d = std::pow((std::pow(std::fabs(d), e) + std::pow(std::fabs(y), e)), 1. / e);
    } else {
        d = std::max(std::fabs(d), std::fabs(y));
    }
    r = std::sqrt(x * x + y * y + z * z);
    return -std::min(p[2] - r, p[1] - std::min(d, r));
}

// ---------------------------------------------------------------- tilings and meshes

// The hexagonal tiling of f_hex_x and f_hex_y: the point folded into one triangle of a
// hexagon cell, (u, v); `turned` says it is past 30 degrees and must be turned by 60.
struct HexFold {
    double u, v;
    bool turned;
};
HexFold hex_fold(double x, double y) {
    double u = std::fabs(std::fmod(std::fabs(x), std::sqrt(3.0)) - std::sqrt(3.0) / 2);
    double v = std::fabs(std::fmod(std::fabs(y), 3) - 1.5);
    const double u2 = std::sqrt(3.0) / 2 - u;
    const double v2 = 1.5 - v;
    if ((u * u + v * v) > (u2 * u2 + v2 * v2)) {
        u = u2;
        v = v2;
    }
    return {u, v, !(std::atan2(v, u) < M_PI / 6)};
}

double hex_x(const double* a, const FunctionHooks&) {
    const HexFold f = hex_fold(a[0], a[1]);
    if (!f.turned) return f.u;
    return std::cos(M_PI / 3) * f.u + std::sin(M_PI / 3) * f.v;
}

double hex_y(const double* a, const FunctionHooks&) {
    const HexFold f = hex_fold(a[0], a[1]);
    if (!f.turned) return f.v;
    return std::fabs(-std::sin(M_PI / 3) * f.u + std::cos(M_PI / 3) * f.v);
}

// f_mesh1: two crossed families of threads weaving over and under. p: distance between
// threads along x and along z, the threads' relative thickness, their amplitude, their
// relative thickness along y.
double mesh1(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x = a[0], y = a[1], z = a[2];
    // Minus the distance to the nearest thread of one family: `across` measured across
    // the threads (period 2 * spacing), `wave` the thread's height there.
    auto thread = [&](double across, double spacing, double wave) {
        double d = std::fmod(across, spacing * 2);
        if (d < 0) d += spacing * 2;
        d = std::fabs(d - spacing) * p[2];
        const double h = (y + wave) * p[4];
        return -std::sqrt(h * h + d * d);
    };
    const double along_z = std::cos(z * (M_PI / p[1])) * p[3];
    const double along_x = std::cos(x * (M_PI / p[0])) * p[3];
    double nearest = thread(x, p[0], -along_z);
    nearest = std::max(thread(x - p[0], p[0], along_z), nearest);
    nearest = std::max(thread(z, p[1], along_x), nearest);
    return -std::max(thread(z - p[1], p[1], -along_x), nearest);
}

// f_polytubes: p[0] tubes around y at the distance p[1] + p[2] y + ... + p[5] y^4.
double polytubes(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double y = a[1], y2 = y * y;
    const double radius = p[1] + p[2] * y + p[3] * y2 + p[4] * y2 * y + p[5] * y2 * y2;
    double nearest = -10000;
    for (int i = 0; i < c_int(p[0]); i++) {
        const double dx = a[0] - radius * std::sin(2 * M_PI / p[0] * i);
        const double dz = a[2] - radius * std::cos(2 * M_PI / p[0] * i);
        nearest = std::max(nearest, -std::sqrt(dx * dx + dz * dz));
    }
    return -nearest;
}

// f_poly4: a surface of revolution around y of radius p[0] + p[1] y + ... + p[4] y^4
// (never below -5).
double poly4(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double y = a[1], y2 = y * y;
    double radius = (p[0] + p[1] * y + p[2] * y2 + p[3] * y2 * y + p[4] * y2 * y2);
    if (radius < -5.) radius = -5.;
    return (-radius + std::sqrt(a[0] * a[0] + a[2] * a[2]));
}

// ------------------------------------------------------------------ blobs and spikes

// f_blob: two blob components on x at -+p[0]/2, strengths p[1] and p[3], inverse radii
// p[2] and p[4].
double blob(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x = a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    const double half = p[0] * 0.5;
    double left = ((x + half) * (x + half) + y2 + z2) * p[2] * p[2];
    if (left > 1.) left = 1.;
    double right = ((x - half) * (x - half) + y2 + z2) * p[4] * p[4];
    if (right > 1) right = 1.;
    return -(p[1] * (1. - left) * (1. - left) + p[3] * (1. - right) * (1. - right));
}

// f_blob2: two gaussians, at the origin and at x = p[0]. p: distance, inverse size,
// strength, threshold.
double blob2(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x = a[0], x2 = x * x, y2 = a[1] * a[1], z2 = a[2] * a[2];
    const double sum = std::exp(-(x2 + y2 + z2) * p[1]) +
                       std::exp(-((x - p[0]) * (x - p[0]) + y2 + z2) * p[1]);
    return (p[3] - sum * p[2]);
}

// The three gaussians stretched along x, y and z that f_cross_ellipsoids,
// f_flange_cover, f_isect_ellipsoids and f_spikes combine. p[0]: eccentricity, p[1]:
// inverse size.
struct Ellipsoids {
    double along_z, along_y, along_x;
};
Ellipsoids ellipsoids(const double* a) {
    const double* p = a + 3;
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    return {std::exp(-(x2 * p[0] + y2 * p[0] + z2) * p[1]),
            std::exp(-(x2 * p[0] + y2 + z2 * p[0]) * p[1]),
            std::exp(-(x2 + y2 * p[0] + z2 * p[0]) * p[1])};
}

// p[2]: strength, p[3]: threshold.
double cross_ellipsoids(const double* a, const FunctionHooks&) {
    const Ellipsoids e = ellipsoids(a);
    const double m = std::max(std::max(e.along_z, e.along_y), e.along_x);
    return (a[6] - m * a[5]);
}

double flange_cover(const double* a, const FunctionHooks&) {
    const Ellipsoids e = ellipsoids(a);
    return (a[6] - (e.along_z + e.along_y + e.along_x) * a[5]);
}

double isect_ellipsoids(const double* a, const FunctionHooks&) {
    const Ellipsoids e = ellipsoids(a);
    const double m = std::min(std::min(e.along_z, e.along_y), e.along_x);
    return (a[6] - m * a[5]);
}

// f_spikes: a central gaussian (inverse size p[3], strength p[4]) less the three
// ellipsoids; p[2] scales the whole.
double spikes(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    const Ellipsoids e = ellipsoids(a);
    const double sum =
        std::exp(-(x2 + y2 + z2) * p[3]) * p[4] - e.along_z - e.along_y - e.along_x;
    return (-sum * p[2]);
}

// f_spikes_2d: a height field y = p[0] cos(p[1] x) cos(p[2] z) exp(-p[3] (x^2 + z^2)).
double spikes_2d(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x = a[0], z = a[2];
    return (-(p[0] * std::cos(p[1] * x) * std::cos(p[2] * z) *
                  std::exp(-p[3] * (x * x + z * z)) -
              a[1]));
}

// f_comma: a comma shape of size p[0].
double comma(const double* a, const FunctionHooks&) {
    const double s = a[3];
    double x = a[0];
    const double y = a[1], z = a[2];
    if ((x == 0) && (z == 0)) x = 0.0001;
    const double angle = std::atan2(z, x);
    const double r = std::sqrt((x + s * 0.25) * (x + s * 0.25) + z * z);
    double tail = std::cos(angle * 0.5) * s * 0.5 -
                  std::sqrt((r - s * 0.75) * (r - s * 0.75) + y * y);
    tail = std::min(z, tail);
    const double head =
        s * 0.5 - std::sqrt((x - s * 0.5) * (x - s * 0.5) + z * z + y * y);
    return -std::max(tail, head);
}

// f_quantum: a hydrogen orbital's probability density (p[0] unused).
double quantum(const double* a, const FunctionHooks&) {
    double x = a[0];
    const double y = a[1], z = a[2];
    if ((x == 0) && (z == 0)) x = 1e-6;
    double r = std::sqrt(x * x + z * z);
    const double c = std::cos(std::atan2(r, y));
    r = std::sqrt(r * r + y * y) * 2.;
    const double psi = r * r * std::exp(-r * 0.33333333) * (3. * c * c - 1);
    return (psi * psi - 12.0) * (-0.1);
}

// ---------------------------------------------------------- algebraic surfaces

// Most algebraic surfaces give their polynomial times the field strength p[0], kept in
// [-10, 10] (a NaN gives 10, as POV-Ray's std::min/std::max order has it).
double field(double strength, double polynomial) {
    return std::min(10., std::max(strength * polynomial, -10.));
}

// f_bicorn: p[1] scale.
double bicorn(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    const double s2 = p[1] * p[1];
    const double q = (x2 + z2 + 2 * p[1] * a[1] - s2);
    return field(p[0], (y2 * (s2 - (x2 + z2)) - q * q));
}

// f_bifolia: p[1] scale.
double bifolia(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x2 = a[0] * a[0], z2 = a[2] * a[2];
    const double r2 = x2 + a[1] * a[1] + z2;
    return field(p[0], -(r2 * r2 - p[1] * (x2 + z2) * a[1]));
}

// f_boy_surface: p[1] scales the polynomial.
double boy_surface(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x = a[0], y = a[1], z = a[2];
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    const double w = 1 - z, rho2 = x2 + y2;
    const double poly =
        p[1] * (64 * w * w * w * z2 * z - 48 * w * w * z2 * (3 * x2 + 3 * y2 + 2 * z2) +
                12 * w * z *
                    (27 * rho2 * rho2 - 24 * z2 * rho2 +
                     36 * std::sqrt(2.0) * y * z * (y2 - 3 * x2) + 4 * z2 * z2) +
                (9 * x2 + 9 * y2 - 2 * z2) *
                    (-81 * rho2 * rho2 - 72 * z2 * rho2 +
                     108 * std::sqrt(2.0) * x * z * (x2 - 3 * y2) + 4 * z2 * z2));
    return field(p[0], poly);
}

double crossed_trough(const double* a, const FunctionHooks&) {
    return field(a[3], (a[0] * a[0] * a[2] * a[2] - a[1]));
}

double cubic_saddle(const double* a, const FunctionHooks&) {
    const double x = a[0], y = a[1];
    return field(a[3], -(x * x * x - y * y * y - a[2]));
}

// f_cushion and f_odd: one polynomial, its x2 y2 term written both ways round.
double cushion(const double* a, const FunctionHooks&) {
    const double z = a[2];
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = z * z;
    return field(
        a[3], (z2 * x2 - z2 * z2 - 2 * z * x2 + 2 * z2 * z + x2 - z2 -
               (x2 - z) * (x2 - z) - y2 * y2 - 2 * x2 * y2 - y2 * z2 + 2 * y2 * z + y2));
}

double odd(const double* a, const FunctionHooks&) {
    const double z = a[2];
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = z * z;
    return field(
        a[3], (z2 * x2 - z2 * z2 - 2 * z * x2 + 2 * z2 * z + x2 - z2 -
               (x2 - z) * (x2 - z) - y2 * y2 - 2 * y2 * x2 - y2 * z2 + 2 * y2 * z + y2));
}

double devils_curve(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    return field(a[3],
                 -(x2 * x2 + 2 * x2 * z2 - 0.36 * x2 - y2 * y2 + 0.25 * y2 + z2 * z2));
}

// f_dupin_cyclid: the inversion (radius p[5]) of a torus of radii p[1], p[2] displaced
// by p[3] along x and p[4] along y.
double dupin_cyclid(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x = a[0], y = a[1];
    const double x2 = x * x, y2 = y * y, z2 = a[2] * a[2];
    const double k2 = p[5] * p[5];
    const double b2 = p[2] * p[2], d2 = p[4] * p[4];
    const double outer = b2 - d2 - (p[3] + p[1]) * (p[3] + p[1]);
    const double inner = b2 - d2 - (p[3] - p[1]) * (p[3] - p[1]);
    const double c2 = p[3] * p[3], a2 = p[1] * p[1];
    const double poly =
        -(outer * inner * (x2 * x2 + y2 * y2 + z2 * z2) +
          2 * (outer * inner * (x2 * y2 + x2 * z2 + y2 * z2)) +
          2 * k2 *
              ((-d2 - c2 + b2 + a2) * (2 * x * p[3] + 2 * y * p[4] - k2) -
               4 * p[4] * b2 * y) *
              (x2 + y2 + z2) +
          4 * k2 * k2 * (p[3] * x + p[4] * y) * (-k2 + p[4] * y + p[3] * x) +
          4 * k2 * k2 * a2 * y2 + k2 * k2 * k2 * k2);
    return field(p[0], poly);
}

// f_enneper: |z| below 0.2 taken as 0.2 where z divides. POV-Ray's constants 2/3, 1/4,
// 8/9 and 2/9 are integer divisions, so 0.
double enneper(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    const double z = std::fabs(a[2]) < 0.2 ? 0.2 : a[2];
    const double u = ((y2 - x2) / (2 * z) + 2 * z2 / 9 + 0.0);
    const double v = ((y2 - x2) / (4 * z) - 0.0 * (x2 + y2 + 0.0 * z2) + 0.0);
    return field(a[3], -(u * u * u - 6 * v * v));
}

// f_folium_surface: p[1] neck width, p[2] divergence.
double folium_surface(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    return field(p[0], ((y2 + z2) * (1 + (p[2] - 4 * p[1]) * a[0]) + x2 * (1 + p[2])));
}

double glob(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0];
    return field(a[3],
                 (0.5 * x2 * x2 * a[0] + 0.5 * x2 * x2 - (a[1] * a[1] + a[2] * a[2])));
}

double heart(const double* a, const FunctionHooks&) {
    const double z = a[2];
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = z * z;
    const double s = (2 * x2 + y2 + z2 - 1);
    return field(a[3], -(s * s * s - 0.1 * x2 * z2 * z - y2 * z2 * z));
}

double hunt_surface(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    const double s = (x2 + y2 + z2 - 13), t = (3 * x2 + y2 - 4 * z2 - 12);
    return field(a[3], -(4 * s * s * s + 27 * t * t));
}

// The quartic tori: p[1] major radius, p[2] minor radius.
double hyperbolic_torus(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    const double R2 = p[1] * p[1], r2 = p[2] * p[2];
    return field(p[0], -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * z2 - 2 * (R2 + r2) * x2 +
                         y2 * y2 - 2 * y2 * z2 + 2 * (R2 - r2) * y2 + z2 * z2 +
                         2 * (R2 + r2) * z2 + (R2 - r2) * (R2 - r2)));
}

double parabolic_torus(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double z = a[2];
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = z * z;
    const double R2 = p[1] * p[1], r2 = p[2] * p[2];
    return field(p[0], -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * z - (R2 + r2) * x2 + y2 * y2 -
                         2 * y2 * z + (R2 - r2) * y2 + z2 + (R2 + r2) * z +
                         (R2 - r2) * (R2 - r2)));
}

double torus2(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    const double R2 = p[1] * p[1], r2 = p[2] * p[2];
    return field(p[0], -(x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2 +
                         2 * y2 * z2 - 2 * (R2 + r2) * x2 + 2 * (R2 - r2) * y2 -
                         2 * (R2 + r2) * z2 + (R2 - r2) * (R2 - r2)));
}

// f_kampyle_of_eudoxus: p[1] dimple, p[2] closeness.
double kampyle_of_eudoxus(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x2 = a[0] * a[0];
    return field(p[0], -((a[1] * a[1] + a[2] * a[2]) - p[2] * p[2] * x2 * x2 +
                         p[2] * p[2] * p[1] * p[1] * x2));
}

double klein_bottle(const double* a, const FunctionHooks&) {
    const double x = a[0], y = a[1], z = a[2];
    const double x2 = x * x, y2 = y * y, z2 = z * z;
    const double lower = (x2 + y2 + z2 - 2 * y - 1);
    return field(a[3], -((x2 + y2 + z2 + 2 * y - 1) * (lower * lower - 8 * z2) +
                         16 * x * z * lower));
}

double kummer_surface_v1(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    return field(a[3], -(x2 * x2 + y2 * y2 + z2 * z2 - x2 - y2 - z2 - x2 * y2 - x2 * z2 -
                         y2 * z2 + 1));
}

// f_kummer_surface_v2: p[1] rod width, p[2] divergence, p[3] rod length.
double kummer_surface_v2(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    return field(p[0],
                 -(x2 * x2 + y2 * y2 + z2 * z2 + p[1] * (x2 + y2 + z2) +
                   p[2] * (x2 * y2 + x2 * z2 + y2 * z2) + p[3] * a[0] * a[1] * a[2] - 1));
}

double lemniscate_of_gerono(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    return field(a[3], -(x2 * x2 - x2 + y2 + z2));
}

double mitre(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    return field(a[3], -(4 * x2 * (x2 + y2 + z2) - y2 * (1 - y2 - z2)));
}

double nodal_cubic(const double* a, const FunctionHooks&) {
    const double y = a[1], z = a[2];
    return field(a[3], -(y * y * y + z * z * z - 6 * y * z));
}

// f_ovals_of_cassini: p[1] major radius, p[2] filling, p[3] thickness.
double ovals_of_cassini(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    const double s = (x2 + y2 + z2 + p[1] * p[1]);
    return field(p[0], -(s * s - p[3] * p[1] * p[1] * (x2 + z2) - p[2] * p[2]));
}

double paraboloid(const double* a, const FunctionHooks&) {
    return field(a[3], -(a[0] * a[0] - a[1] + a[2] * a[2]));
}

double pillow(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    return field(a[3], (x2 * x2 + y2 * y2 + z2 * z2 - (x2 + y2 + z2)));
}

// f_piriform: the only one whose clamped field is negated.
double piriform(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0];
    return -field(a[3], -((x2 * x2 - x2 * a[0]) + a[1] * a[1] + a[2] * a[2]));
}

double quartic_paraboloid(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0], z2 = a[2] * a[2];
    return field(a[3], -(x2 * x2 + z2 * z2 - a[1]));
}

double quartic_saddle(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0], z2 = a[2] * a[2];
    return field(a[3], -(x2 * x2 - z2 * z2 - a[1]));
}

// f_quartic_cylinder: p[1] the egg's diameter, p[2] the tube's width.
double quartic_cylinder(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x2 = a[0] * a[0], z2 = a[2] * a[2];
    return field(p[0], -((x2 + z2) * a[1] * a[1] + p[2] * p[2] * (x2 + z2) -
                         p[2] * p[2] * p[1] * p[1]));
}

double steiners_roman(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    return field(a[3], -(x2 * y2 + x2 * z2 + y2 * z2 + a[0] * a[1] * a[2]));
}

// f_strophoid: p[1] bulb size, p[2] sharpness, p[3] fatness.
double strophoid(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const double x = a[0], x2 = x * x;
    const double f2 = p[3] * p[3];
    return field(
        p[0], -((p[2] - x) * (a[1] * a[1] + a[2] * a[2]) - f2 * p[1] * x2 - f2 * x2 * x));
}

double torus_gumdrop(const double* a, const FunctionHooks&) {
    const double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
    return field(a[3], -(4 * (x2 * x2 + (y2 + z2) * (y2 + z2)) + 17 * x2 * (y2 + z2) -
                         20 * (x2 + y2 + z2) + 17));
}

double umbrella(const double* a, const FunctionHooks&) {
    return field(a[3], -(a[0] * a[0] - a[1] * a[2] * a[2]));
}

// f_witch_of_agnesi: p[1] the spike's width.
double witch_of_agnesi(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    return field(p[0], -(p[1] * (a[1] - 1) + (a[0] * a[0] + a[2] * a[2]) * a[1]));
}

// ----------------------------------------------------------------- the 2d curves

// A 2d curve in x and y, as POV-Ray's _2d functions and f_algbr_cyl* take the point: when
// the "SOR switch" is on (> 0) the curve is revolved around y: x becomes the distance
// from the y axis less the SOR offset, then (x, y) is turned by the SOR angle (degrees).
struct CurvePoint {
    double x, y, x2, y2;
};
CurvePoint curve_point(const double* a, double sor_switch, double sor_offset,
                       double sor_degrees) {
    CurvePoint c{a[0], a[1], a[0] * a[0], a[1] * a[1]};
    if (sor_switch > 0) {
        const double radial = std::sqrt(c.x2 + a[2] * a[2]) - sor_offset;
        const double angle = sor_degrees * kRadiansPerDegree;
        if (angle != 0) {
            c.x = radial * std::cos(angle) - c.y * std::sin(angle);
            c.y = radial * std::sin(angle) + c.y * std::cos(angle);
        } else {
            c.x = radial;
        }
        c.x2 = c.x * c.x;
        c.y2 = c.y * c.y;
    }
    return c;
}

// The f_algbr_cyl* fields: the polynomial times p[0], kept in [-p[1], p[1]].
double limited(const double* p, double polynomial) {
    return std::min(p[1], std::max(p[0] * polynomial, -p[1]));
}

// f_algbr_cyl1 mirrors the curve in x after squaring it, and negates its field.
double algbr_cyl1(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const CurvePoint c = curve_point(a, p[2], p[3], p[4]);
    return -limited(p, -(c.x2 * std::fabs(c.x) - c.x2 + c.y2));
}

double algbr_cyl2(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const CurvePoint c = curve_point(a, p[2], p[3], p[4]);
    const double x2 = c.x2, y2 = c.y2, y = c.y;
    return limited(p, -(2 * x2 * x2 - 3 * x2 * y + y2 - 2 * y2 * y + y2 * y2));
}

double algbr_cyl3(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const CurvePoint c = curve_point(a, p[2], p[3], p[4]);
    const double x2 = c.x2, y2 = c.y2;
    return limited(p, -(x2 * x2 + x2 * y2 - 2 * x2 * c.y - c.x * y2 + y2));
}

double algbr_cyl4(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const CurvePoint c = curve_point(a, p[2], p[3], p[4]);
    const double x2 = c.x2, y2 = c.y2;
    return limited(p, -(x2 * x2 + y2 * y2 + 2 * x2 * y2 + 3 * x2 * c.y - y2 * c.y));
}

// f_devils_curve_2d: p[1] x factor, p[2] y factor; SOR p[3], p[4], p[5].
double devils_curve_2d(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const CurvePoint c = curve_point(a, p[3], p[4], p[5]);
    return field(p[0], -(c.x2 * (c.x2 - p[1] * p[1]) - c.y2 * (c.y2 - p[2] * p[2])));
}

// f_folium_surface_2d: p[1] neck width, p[2] divergence; SOR p[3], p[4], p[5].
double folium_surface_2d(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const CurvePoint c = curve_point(a, p[3], p[4], p[5]);
    return field(p[0], -(c.y2 * (1 + (p[2] - 4 * p[1]) * c.x) + c.x2 * (1 + p[2])));
}

// f_kampyle_of_eudoxus_2d: p[1] dimple, p[2] closeness; SOR p[3], p[4], p[5]. POV-Ray
// multiplies by p[1] p[2] where the 3d surface has p[1] p[1].
double kampyle_of_eudoxus_2d(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const CurvePoint c = curve_point(a, p[3], p[4], p[5]);
    return field(p[0],
                 -(c.y2 - p[2] * p[2] * c.x2 * c.x2 + p[2] * p[2] * p[1] * p[2] * c.x2));
}

// f_lemniscate_of_gerono_2d: p[1] size, p[2] width; SOR p[3], p[4], p[5].
double lemniscate_of_gerono_2d(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const CurvePoint c = curve_point(a, p[3], p[4], p[5]);
    return field(p[0],
                 -(c.y2 - p[2] * p[2] * p[1] * p[1] * c.x2 + p[2] * p[2] * c.x2 * c.x2));
}

// f_piriform_2d: p[1], p[2] size factors, p[3] fatness; SOR p[4], p[5], p[6].
double piriform_2d(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const CurvePoint c = curve_point(a, p[4], p[5], p[6]);
    return field(p[0], -(c.y * c.y - p[1] * p[3] * p[3] * c.x2 * c.x -
                         p[2] * p[3] * p[3] * c.x2 * c.x2));
}

// f_strophoid_2d: p[1] bulb size, p[2] sharpness, p[3] fatness; SOR p[4], p[5], p[6].
double strophoid_2d(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const CurvePoint c = curve_point(a, p[4], p[5], p[6]);
    const double f2 = p[3] * p[3];
    return field(p[0], -((p[2] - c.x) * c.y2 - f2 * p[1] * c.x2 - f2 * c.x2 * c.x));
}

// f_witch_of_agnesi_2d: p[1] the spike's size, p[2] its height; SOR p[3], p[4], p[5].
double witch_of_agnesi_2d(const double* a, const FunctionHooks&) {
    const double* p = a + 3;
    const CurvePoint c = curve_point(a, p[3], p[4], p[5]);
    return field(p[0], -(p[1] * p[1] * c.y + c.x2 * c.y - p[2]));
}

// --------------------------------------------------------------------------- table

using InternalFn = double (*)(const double* a, const FunctionHooks& hooks);
struct InternalEntry {
    int extra;      // parameters after x, y, z (POV-Ray's table)
    InternalFn fn;  // null: not implemented
};

// Indexed by N of internal(N).
constexpr InternalEntry kInternals[] = {
    {5, algbr_cyl1},               // 0 f_algbr_cyl1
    {5, algbr_cyl2},               // 1 f_algbr_cyl2
    {5, algbr_cyl3},               // 2 f_algbr_cyl3
    {5, algbr_cyl4},               // 3 f_algbr_cyl4
    {2, bicorn},                   // 4 f_bicorn
    {2, bifolia},                  // 5 f_bifolia
    {5, blob},                     // 6 f_blob
    {4, blob2},                    // 7 f_blob2
    {2, boy_surface},              // 8 f_boy_surface
    {1, comma},                    // 9 f_comma
    {4, cross_ellipsoids},         // 10 f_cross_ellipsoids
    {1, crossed_trough},           // 11 f_crossed_trough
    {1, cubic_saddle},             // 12 f_cubic_saddle
    {1, cushion},                  // 13 f_cushion
    {1, devils_curve},             // 14 f_devils_curve
    {6, devils_curve_2d},          // 15 f_devils_curve_2d
    {6, dupin_cyclid},             // 16 f_dupin_cyclid
    {3, ellipsoid},                // 17 f_ellipsoid
    {1, enneper},                  // 18 f_enneper
    {4, flange_cover},             // 19 f_flange_cover
    {3, folium_surface},           // 20 f_folium_surface
    {6, folium_surface_2d},        // 21 f_folium_surface_2d
    {1, glob},                     // 22 f_glob
    {1, heart},                    // 23 f_heart
    {10, helical_torus},           // 24 f_helical_torus
    {7, helix1},                   // 25 f_helix1
    {7, helix2},                   // 26 f_helix2
    {1, hex_x},                    // 27 f_hex_x
    {1, hex_y},                    // 28 f_hex_y
    {6, hetero_mf},                // 29 f_hetero_mf
    {1, hunt_surface},             // 30 f_hunt_surface
    {3, hyperbolic_torus},         // 31 f_hyperbolic_torus
    {4, isect_ellipsoids},         // 32 f_isect_ellipsoids
    {3, kampyle_of_eudoxus},       // 33 f_kampyle_of_eudoxus
    {6, kampyle_of_eudoxus_2d},    // 34 f_kampyle_of_eudoxus_2d
    {1, klein_bottle},             // 35 f_klein_bottle
    {1, kummer_surface_v1},        // 36 f_kummer_surface_v1
    {4, kummer_surface_v2},        // 37 f_kummer_surface_v2
    {1, lemniscate_of_gerono},     // 38 f_lemniscate_of_gerono
    {6, lemniscate_of_gerono_2d},  // 39 f_lemniscate_of_gerono_2d
    {5, mesh1},                    // 40 f_mesh1
    {1, mitre},                    // 41 f_mitre
    {1, nodal_cubic},              // 42 f_nodal_cubic
    {1, odd},                      // 43 f_odd
    {4, ovals_of_cassini},         // 44 f_ovals_of_cassini
    {1, paraboloid},               // 45 f_paraboloid
    {3, parabolic_torus},          // 46 f_parabolic_torus
    {0, ph},                       // 47 f_ph
    {1, pillow},                   // 48 f_pillow
    {1, piriform},                 // 49 f_piriform
    {7, piriform_2d},              // 50 f_piriform_2d
    {5, poly4},                    // 51 f_poly4
    {6, polytubes},                // 52 f_polytubes
    {1, quantum},                  // 53 f_quantum
    {1, quartic_paraboloid},       // 54 f_quartic_paraboloid
    {1, quartic_saddle},           // 55 f_quartic_saddle
    {3, quartic_cylinder},         // 56 f_quartic_cylinder
    {0, r},                        // 57 f_r
    {6, ridge},                    // 58 f_ridge
    {6, ridged_mf},                // 59 f_ridged_mf
    {4, rounded_box},              // 60 f_rounded_box
    {1, sphere},                   // 61 f_sphere
    {5, spikes},                   // 62 f_spikes
    {4, spikes_2d},                // 63 f_spikes_2d
    {6, spiral},                   // 64 f_spiral
    {1, steiners_roman},           // 65 f_steiners_roman
    {4, strophoid},                // 66 f_strophoid
    {7, strophoid_2d},             // 67 f_strophoid_2d
    {2, superellipsoid},           // 68 f_superellipsoid
    {0, th},                       // 69 f_th
    {2, torus},                    // 70 f_torus
    {3, torus2},                   // 71 f_torus2
    {1, torus_gumdrop},            // 72 f_torus_gumdrop
    {1, umbrella},                 // 73 f_umbrella
    {2, witch_of_agnesi},          // 74 f_witch_of_agnesi
    {6, witch_of_agnesi_2d},       // 75 f_witch_of_agnesi_2d
    {0, noise3d},                  // 76 f_noise3d
    {0, pattern_without_pattern},  // 77 f_pattern
    {1, noise_generator},          // 78 f_noise_generator
};
constexpr int kInternalCount = int(sizeof(kInternals) / sizeof(kInternals[0]));
static_assert(kInternalCount == 79, "POV-Ray 3.7 has internal(0) ... internal(78)");

}  // namespace

int internal_extra(int n) {
    if (n < 0 || n >= kInternalCount || !kInternals[n].fn) return -1;
    return kInternals[n].extra;
}

double internal_function(int n, const double* a, const FunctionHooks& hooks) {
    return kInternals[n].fn(a, hooks);
}

}  // namespace povwall
