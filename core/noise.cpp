// Tables: the hash permutation, the generator-3 gradients and permutation, the wave
// sources/frequencies and the pattern random table are all generated here the way POV-Ray
// 3.7 generates them (its 31-bit LCG, and MT19937 with the default seed for the pattern
// random table). Only the lattice-noise value table (noise_rtable.inc) is literal
// data: 3.7 ships it as numbers that do not come from any of its generators.
#include "core/noise.h"

#include <immintrin.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <random>

#include "core/math_constants.h"

namespace povwall {
namespace {

constexpr int kLatticeOffset = -10000;  // POV-Ray shifts lattice coordinates by this
constexpr int kPerlinEntries = 2048;    // gradient table size of the generator-3 noise
constexpr Real kRollover = 10000000.023157213;

// The 31-bit LCG POV-Ray uses for its tables: state*1812433253+12345, bits 16..30.
struct PovRand {
    uint32_t state;
    int next() {
        state = state * 1812433253u + 12345u;
        return int((state >> 16) & 0x7FFF);
    }
};

// The RTable literal: value k and its half are what each lattice corner reads.
constexpr Real kRValues[267] = {
#include "core/noise_rtable.inc"
};

struct Tables {
    uint16_t hash[8192];
    // rtab[2k] = value k, rtab[2k+1] = value k / 2, as POV-Ray lays them out.
    Real rtab[267 * 2];
    // Each value entry's four numbers a corner term reads, m[1], m[2], m[4], m[6] with m
    // = rtab + 2k, side by side for one vector load; and the three windows (8 entries
    // apart) of the vector noise.
    alignas(32) Real corner4[256][4];
    alignas(32) Real corner12[256][12];
    int perm[2 * (kPerlinEntries + 1)];
    Vector3 grad[2 * (kPerlinEntries + 1)];
    WaveTable waves;
    Real pattern_rands[32768];
};

Vector3 lattice_dnoise(const Tables& t, const Vector3& p);

Tables build_tables() {
    Tables t{};
    // Hash table: a seed-0 shuffle of 0..4095, then duplicated.
    for (int i = 0; i < 4096; ++i) t.hash[i] = uint16_t(i);
    PovRand rng{0};
    for (int i = 4095; i >= 0; --i) {
        int j = rng.next() % 4096;
        std::swap(t.hash[i], t.hash[j]);
    }
    for (int i = 0; i < 4096; ++i) t.hash[4096 + i] = t.hash[i];
    for (int i = 0; i < 267; ++i) {
        t.rtab[2 * i] = kRValues[i];
        t.rtab[2 * i + 1] = kRValues[i] * 0.5;
    }
    for (int k = 0; k < 256; ++k) {
        for (int w = 0; w < 3; ++w) {
            const Real* m = t.rtab + 2 * k + 8 * w;
            const Real four[4] = {m[1], m[2], m[4], m[6]};
            for (int j = 0; j < 4; ++j) {
                if (w == 0) t.corner4[k][j] = four[j];
                t.corner12[k][4 * w + j] = four[j];
            }
        }
    }
    // Generator 3: unit gradients by rejection sampling, then a pairwise shuffle, both
    // from the same LCG seeded with 1. The permutation's last slot starts at 0 and the
    // duplication is a forward copy that overlaps itself, exactly as POV-Ray does it.
    PovRand prng{1};
    for (int i = 0; i < kPerlinEntries; ++i) {
        Vector3 v;
        Real s;
        do {
            for (int j = 0; j < 3; ++j) {
                v[j] = Real((prng.next() % (kPerlinEntries << 1)) - kPerlinEntries) /
                       Real(kPerlinEntries);
            }
            s = dot(v, v);
        } while (s > 1.0 || s < 1.0e-5);
        t.grad[i] = v * (1.0 / std::sqrt(s));  // POV-Ray scales by the reciprocal
    }
    for (int i = 0; i < kPerlinEntries; ++i) t.perm[i] = i;
    for (int i = kPerlinEntries; i > 0; i -= 2) {
        int k = t.perm[i];
        int j = prng.next() % kPerlinEntries;
        t.perm[i] = t.perm[j];
        t.perm[j] = k;
    }
    for (int i = 0; i < kPerlinEntries + 2; ++i) {
        t.perm[kPerlinEntries + i] = t.perm[i];
        t.grad[kPerlinEntries + i] = t.grad[i];
    }
    // Wave sources: normalised vector noise at (i,0,0); frequencies from an LCG whose
    // signed state starts at -560851967.
    uint32_t state = uint32_t(int32_t(-560851967));
    for (int i = 0; i < kMaxWaves; ++i) {
        t.waves.source[i] = normalize(lattice_dnoise(t, Vector3(Real(i), 0, 0)));
        state = state * 1812433253u + 12345u;
        int r = int(int32_t(state) >> 16) & 0x7FFF;
        t.waves.frequency[i] = Real(r) * 0.000030518509476 + 0.01;
    }
    std::mt19937 mt;  // default seed 5489, as boost::mt19937
    for (Real& r : t.pattern_rands) r = Real(mt()) / 4294967296.0;
    return t;
}

// C's (int) as x86-64 computes it (POV-Ray's noise is that code): out of range and NaN
// give INT_MIN, without the undefined behaviour of a plain cast.
inline int x86_int(Real v) {
    return v > -2147483649.0 && v < 2147483648.0 ? int(v) : INT_MIN;
}

// Lattice cell and fractional offset of one coordinate (POV-Ray's "range fix").
inline void lattice_axis(Real v, int& cell, Real& frac) {
    // One conversion of the chosen value (no branch: the sign of a coordinate is as
    // good as random along a ray).
    const int tmp = x86_int(v >= 0 ? v : v - (1 - kPovEpsilon));
    // Wrapping as x86's int arithmetic does (a cell past INT_MAX - 10000).
    cell = int((unsigned(tmp) - unsigned(kLatticeOffset)) & 0xFFFu);
    frac = v - tmp;
}

inline Real scurve(Real a) { return a * a * (3.0 - 2.0 * a); }

struct Corners {
    int h00, h10, h01, h11;  // hashes of the four (x,y) columns
    int iz;
    Real fx, fy, fz;  // offsets from the low corner
    Real sx, sy, sz, tx, ty, tz;
};

inline Corners corners(const Tables& t, const Vector3& p) {
    Corners c;
    int ix, iy;
    lattice_axis(p.x, ix, c.fx);
    lattice_axis(p.y, iy, c.fy);
    lattice_axis(p.z, c.iz, c.fz);
    c.sx = scurve(c.fx);
    c.sy = scurve(c.fy);
    c.sz = scurve(c.fz);
    c.tx = 1 - c.sx;
    c.ty = 1 - c.sy;
    c.tz = 1 - c.sz;
    auto hash2 = [&](int a, int b) { return int(t.hash[int(t.hash[a]) ^ b]); };
    c.h00 = hash2(ix, iy);
    c.h10 = hash2(ix + 1, iy);
    c.h01 = hash2(ix, iy + 1);
    c.h11 = hash2(ix + 1, iy + 1);
    return c;
}

// The value-table entry of the corner (column hash, z cell), and its index into rtab.
inline int entry(const Tables& t, int column_hash, int z) {
    return t.hash[column_hash ^ z] & 0xFF;
}
inline int rindex(const Tables& t, int column_hash, int z) {
    return entry(t, column_hash, z) * 2;
}

// One corner's contribution: weight * (half value + linear gradient term).
inline Real corner_term(const Real* m, Real w, Real x, Real y, Real z) {
    return w * (m[1] + m[2] * x + m[4] * y + m[6] * z);
}

Real lattice_noise_raw(const Tables& t, const Vector3& p) {
    Corners c = corners(t, p);
    Real x0 = c.fx, y0 = c.fy, z0 = c.fz, x1 = c.fx - 1, y1 = c.fy - 1, z1 = c.fz - 1;
    Real txty = c.tx * c.ty, sxty = c.sx * c.ty, txsy = c.tx * c.sy, sxsy = c.sx * c.sy;
    const Real* r = t.rtab;
    Real sum = corner_term(r + rindex(t, c.h00, c.iz), txty * c.tz, x0, y0, z0);
    sum += corner_term(r + rindex(t, c.h10, c.iz), sxty * c.tz, x1, y0, z0);
    sum += corner_term(r + rindex(t, c.h01, c.iz), txsy * c.tz, x0, y1, z0);
    sum += corner_term(r + rindex(t, c.h11, c.iz), sxsy * c.tz, x1, y1, z0);
    sum += corner_term(r + rindex(t, c.h00, c.iz + 1), txty * c.sz, x0, y0, z1);
    sum += corner_term(r + rindex(t, c.h10, c.iz + 1), sxty * c.sz, x1, y0, z1);
    sum += corner_term(r + rindex(t, c.h01, c.iz + 1), txsy * c.sz, x0, y1, z1);
    sum += corner_term(r + rindex(t, c.h11, c.iz + 1), sxsy * c.sz, x1, y1, z1);
    return sum;
}

// Vector version: three consecutive table windows, 8 entries apart, per corner.
[[gnu::always_inline]] inline void add_corner(Vector3& acc, const Real* m, Real w, Real x,
                                              Real y, Real z) {
    acc.x += corner_term(m, w, x, y, z);
    acc.y += corner_term(m + 8, w, x, y, z);
    acc.z += corner_term(m + 16, w, x, y, z);
}

Vector3 lattice_dnoise(const Tables& t, const Vector3& p) {
    Corners c = corners(t, p);
    Real x0 = c.fx, y0 = c.fy, z0 = c.fz, x1 = c.fx - 1, y1 = c.fy - 1, z1 = c.fz - 1;
    Real txty = c.tx * c.ty, sxty = c.sx * c.ty, txsy = c.tx * c.sy, sxsy = c.sx * c.sy;
    const Real* r = t.rtab;
    // Same corner order as POV-Ray so the floating-point sums agree.
    Vector3 v{0, 0, 0};
    add_corner(v, r + rindex(t, c.h00, c.iz), txty * c.tz, x0, y0, z0);
    add_corner(v, r + rindex(t, c.h10, c.iz), sxty * c.tz, x1, y0, z0);
    add_corner(v, r + rindex(t, c.h11, c.iz), sxsy * c.tz, x1, y1, z0);
    add_corner(v, r + rindex(t, c.h01, c.iz), txsy * c.tz, x0, y1, z0);
    add_corner(v, r + rindex(t, c.h01, c.iz + 1), txsy * c.sz, x0, y1, z1);
    add_corner(v, r + rindex(t, c.h11, c.iz + 1), sxsy * c.sz, x1, y1, z1);
    add_corner(v, r + rindex(t, c.h10, c.iz + 1), sxty * c.sz, x1, y0, z1);
    add_corner(v, r + rindex(t, c.h00, c.iz + 1), txty * c.sz, x0, y0, z1);
    return v;
}

// The same sums with four corners at a time in AVX2 lanes: each lane does a corner term's
// operations in the scalar order (no fused multiply-add), and the terms are added up one
// by one in the scalar order, so the values are the scalar ones bit for bit.
#define POVWALL_AVX2 __attribute__((target("avx2")))

// The rows a, b, c, d (one corner's four numbers each) as four columns.
POVWALL_AVX2 inline void transpose4(__m256d a, __m256d b, __m256d c, __m256d d,
                                    __m256d out[4]) {
    const __m256d t0 = _mm256_unpacklo_pd(a, b), t1 = _mm256_unpackhi_pd(a, b);
    const __m256d t2 = _mm256_unpacklo_pd(c, d), t3 = _mm256_unpackhi_pd(c, d);
    out[0] = _mm256_permute2f128_pd(t0, t2, 0x20);
    out[1] = _mm256_permute2f128_pd(t1, t3, 0x20);
    out[2] = _mm256_permute2f128_pd(t0, t2, 0x31);
    out[3] = _mm256_permute2f128_pd(t1, t3, 0x31);
}

// w * (m1 + m2 x + m4 y + m6 z) for four corners whose numbers are m[0..3].
POVWALL_AVX2 inline __m256d terms4(const __m256d m[4], __m256d w, __m256d x, __m256d y,
                                   __m256d z) {
    __m256d s = _mm256_add_pd(m[0], _mm256_mul_pd(m[1], x));
    s = _mm256_add_pd(s, _mm256_mul_pd(m[2], y));
    s = _mm256_add_pd(s, _mm256_mul_pd(m[3], z));
    return _mm256_mul_pd(w, s);
}

POVWALL_AVX2 Real lattice_noise_raw_avx2(const Tables& t, const Vector3& p) {
    const Corners c = corners(t, p);
    const Real x1 = c.fx - 1, y1 = c.fy - 1, z1 = c.fz - 1;
    // Lanes: the corners (x0 y0), (x1 y0), (x0 y1), (x1 y1), as lattice_noise_raw.
    const __m256d X = _mm256_set_pd(x1, c.fx, x1, c.fx);
    const __m256d Y = _mm256_set_pd(y1, y1, c.fy, c.fy);
    const __m256d Wxy = _mm256_set_pd(c.sx * c.sy, c.tx * c.sy, c.sx * c.ty, c.tx * c.ty);
    alignas(32) Real term[8];
    for (int g = 0; g < 2; ++g) {
        const int z = c.iz + g;
        __m256d m[4];
        transpose4(_mm256_load_pd(t.corner4[entry(t, c.h00, z)]),
                   _mm256_load_pd(t.corner4[entry(t, c.h10, z)]),
                   _mm256_load_pd(t.corner4[entry(t, c.h01, z)]),
                   _mm256_load_pd(t.corner4[entry(t, c.h11, z)]), m);
        const __m256d W = _mm256_mul_pd(Wxy, _mm256_set1_pd(g ? c.sz : c.tz));
        _mm256_store_pd(term + 4 * g, terms4(m, W, X, Y, _mm256_set1_pd(g ? z1 : c.fz)));
    }
    Real sum = term[0];
    for (int k = 1; k < 8; ++k) sum += term[k];
    return sum;
}

POVWALL_AVX2 Vector3 lattice_dnoise_avx2(const Tables& t, const Vector3& p) {
    const Corners c = corners(t, p);
    const Real x1 = c.fx - 1, y1 = c.fy - 1, z1 = c.fz - 1;
    const Real txty = c.tx * c.ty, sxty = c.sx * c.ty, txsy = c.tx * c.sy,
               sxsy = c.sx * c.sy;
    // lattice_dnoise's corner order: (h00 h10 h11 h01) at z0, then (h01 h11 h10 h00)
    // at z1.
    const __m256d X = _mm256_set_pd(c.fx, x1, x1, c.fx);
    const int columns[2][4] = {{c.h00, c.h10, c.h11, c.h01},
                               {c.h01, c.h11, c.h10, c.h00}};
    const __m256d Y[2] = {_mm256_set_pd(y1, y1, c.fy, c.fy),
                          _mm256_set_pd(c.fy, c.fy, y1, y1)};
    const __m256d W[2] = {
        _mm256_mul_pd(_mm256_set_pd(txsy, sxsy, sxty, txty), _mm256_set1_pd(c.tz)),
        _mm256_mul_pd(_mm256_set_pd(txty, sxty, sxsy, txsy), _mm256_set1_pd(c.sz))};
    alignas(32) Real term[3][8];
    for (int g = 0; g < 2; ++g) {
        const int z = c.iz + g;
        const Real* rows[4];
        for (int k = 0; k < 4; ++k) rows[k] = t.corner12[entry(t, columns[g][k], z)];
        const __m256d Z = _mm256_set1_pd(g ? z1 : c.fz);
        for (int w = 0; w < 3; ++w) {
            __m256d m[4];
            transpose4(_mm256_load_pd(rows[0] + 4 * w), _mm256_load_pd(rows[1] + 4 * w),
                       _mm256_load_pd(rows[2] + 4 * w), _mm256_load_pd(rows[3] + 4 * w),
                       m);
            _mm256_store_pd(term[w] + 4 * g, terms4(m, W[g], X, Y[g], Z));
        }
    }
    Vector3 v{0, 0, 0};
    for (int k = 0; k < 8; ++k) {
        v.x += term[0][k];
        v.y += term[1][k];
        v.z += term[2][k];
    }
    return v;
}

#undef POVWALL_AVX2

inline void perlin_axis(Real v, int& b0, int& b1, Real& r0, Real& r1) {
    Real t = v + kRollover;
    int it = x86_int(std::floor(t));
    b0 = it & (kPerlinEntries - 1);
    b1 = (b0 + 1) & (kPerlinEntries - 1);
    r0 = t - it;
    r1 = r0 - 1.0;
}

inline Real lerp(Real t, Real a, Real b) { return a + t * (b - a); }

Real perlin_noise(const Tables& t, const Vector3& p) {
    int bx0, bx1, by0, by1, bz0, bz1;
    Real rx0, rx1, ry0, ry1, rz0, rz1;
    perlin_axis(p.x, bx0, bx1, rx0, rx1);
    perlin_axis(p.y, by0, by1, ry0, ry1);
    perlin_axis(p.z, bz0, bz1, rz0, rz1);
    int i = t.perm[bx0], j = t.perm[bx1];
    int b00 = t.perm[i + by0], b10 = t.perm[j + by0];
    int b01 = t.perm[i + by1], b11 = t.perm[j + by1];
    Real sx = scurve(rx0), sy = scurve(ry0), sz = scurve(rz0);
    auto at = [&](int g, Real x, Real y, Real z) {
        const Vector3& q = t.grad[g];
        return x * q.x + y * q.y + z * q.z;
    };
    Real a = lerp(sx, at(b00 + bz0, rx0, ry0, rz0), at(b10 + bz0, rx1, ry0, rz0));
    Real b = lerp(sx, at(b01 + bz0, rx0, ry1, rz0), at(b11 + bz0, rx1, ry1, rz0));
    Real c = lerp(sy, a, b);
    a = lerp(sx, at(b00 + bz1, rx0, ry0, rz1), at(b10 + bz1, rx1, ry0, rz1));
    b = lerp(sx, at(b01 + bz1, rx0, ry1, rz1), at(b11 + bz1, rx1, ry1, rz1));
    Real d = lerp(sy, a, b);
    return lerp(sz, c, d);
}

const Tables kTables = build_tables();

// AVX2 lanes where the CPU has them (the same values either way).
const bool kLanes = [] {
    __builtin_cpu_init();  // static initialisers may run before libgcc's
    return bool(__builtin_cpu_supports("avx2"));
}();

inline Real clamp01(Real v) { return v < 0 ? 0 : (v > 1 ? 1 : v); }

}  // namespace

namespace noise_detail {
bool has_lanes() { return kLanes; }
Real lattice_sum(const Vector3& p, bool lanes) {
    return lanes && kLanes ? lattice_noise_raw_avx2(kTables, p)
                           : lattice_noise_raw(kTables, p);
}
Vector3 lattice_vector(const Vector3& p, bool lanes) {
    return lanes && kLanes ? lattice_dnoise_avx2(kTables, p) : lattice_dnoise(kTables, p);
}
}  // namespace noise_detail

Real noise(const Vector3& p, int generator) {
    if (generator == 3) {
        // POV-Ray's empirical bias correction for this generator.
        return clamp01(0.5 * (1.59 * perlin_noise(kTables, p) + 0.985));
    }
    const Real sum = noise_detail::lattice_sum(p, true);
    if (generator == 1) return clamp01(sum + 0.5);
    // Range-corrected: maps the measured range [-1.05242, 0.988997] onto [0,1].
    return clamp01((sum + 1.05242) * 0.48985582);
}

Vector3 dnoise(const Vector3& p) { return noise_detail::lattice_vector(p, true); }

Real turbulence(const Vector3& p, const TurbulenceParams& t, int generator) {
    // Generators 2 and 3 stretch each octave's noise (2n - 0.5); only the first is
    // clipped.
    bool stretch = generator != 1 && generator != 0;
    Real value = stretch ? clamp01(2.0 * noise(p, generator) - 0.5) : noise(p, generator);
    Real l = t.lambda, o = t.omega;
    for (int i = 2; i <= t.octaves; ++i) {
        Real n = noise(p * l, generator);
        value += o * (stretch ? 2.0 * n - 0.5 : n);
        if (i < t.octaves) {
            l *= t.lambda;
            o *= t.omega;
        }
    }
    return value;
}

Vector3 dturbulence(const Vector3& p, const TurbulenceParams& t) {
    Vector3 result = dnoise(p);
    Real l = t.lambda, o = t.omega;
    for (int i = 2; i <= t.octaves; ++i) {
        result += dnoise(p * l) * o;
        if (i < t.octaves) {
            l *= t.lambda;
            o *= t.omega;
        }
    }
    return result;
}

Real cycloidal(Real v) {
    constexpr Real kTwoPi = 2 * kPi;
    if (v >= 0.0) return std::sin(((v - std::floor(v)) * 50000.0) / 50000.0 * kTwoPi);
    return -std::sin(((0.0 - (v + std::floor(0.0 - v))) * 50000.0) / 50000.0 * kTwoPi);
}

Real triangle_wave(Real v) {
    Real offset = v >= 0.0 ? v - std::floor(v) : v + 1.0 + std::floor(std::fabs(v));
    return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

const WaveTable& wave_table() { return kTables.waves; }

int hash3d(int x, int y, int z) {
    const uint16_t* h = kTables.hash;
    return h[int(h[int(h[x & 0xfff]) ^ (y & 0xfff)]) ^ (z & 0xfff)];
}

Real pattern_random(size_t index) { return kTables.pattern_rands[index % 32768]; }

}  // namespace povwall
