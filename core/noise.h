// POV-Ray 3.7's solid noise, reproduced exactly: lattice noise (noise_generator 1 and the
// range-corrected 2) and Perlin's improved-style gradient noise (3), their vector
// version, fractal turbulence, and the wave helpers patterns share. Tables are built once
// at start-up; evaluation never allocates.
#pragma once

#include "core/math.h"

namespace povwall {

// Scalar noise in [0,1] at `p` for noise_generator 1, 2 or 3 (anything else acts as 2).
Real noise(const Vector3& p, int generator);

// Vector noise (POV-Ray's DNoise); always the lattice generator, as in POV-Ray.
Vector3 dnoise(const Vector3& p);

struct TurbulenceParams {
    int octaves = 6;
    Real omega = 0.5, lambda = 2.0;
};

// Fractal sum of noise() (POV-Ray's Turbulence), generator-dependent as in POV-Ray.
Real turbulence(const Vector3& p, const TurbulenceParams& t, int generator);
// Fractal sum of dnoise() (POV-Ray's DTurbulence).
Vector3 dturbulence(const Vector3& p, const TurbulenceParams& t);

// sin(2*pi*v) as POV-Ray computes it (odd-symmetric, period 1).
Real cycloidal(Real v);
// Period-1 triangle wave 0 -> 1 -> 0.
Real triangle_wave(Real v);

// The wave sources and frequencies ripples/waves use. Entry i does not depend on
// global_settings number_of_waves, which only says how many entries are used.
constexpr int kMaxWaves = 64;
struct WaveTable {
    Vector3 source[kMaxWaves];
    Real frequency[kMaxWaves];
};
const WaveTable& wave_table();

// The lattice noise's sum of corner terms (before its generator's offset and clamp) and
// the vector noise, computed with AVX2 lanes when `lanes` and the CPU has them, else
// one corner at a time: the same values bit for bit (tests compare the two).
namespace noise_detail {
bool has_lanes();
Real lattice_sum(const Vector3& p, bool lanes);
Vector3 lattice_vector(const Vector3& p, bool lanes);
}  // namespace noise_detail

// POV-Ray's Hash3d over its noise permutation table (used by cells and crackle).
int hash3d(int x, int y, int z);
// POV-Ray's pattern random table: entry i % 32768 of the uniform [0,1) sequence of a
// default-seeded MT19937 (Boost's uniform_real over mt19937, which POV-Ray uses).
Real pattern_random(size_t index);

}  // namespace povwall
