#include "trace/sphere_lanes.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define POVWALL_LANES_AVX 1
#endif

namespace povwall::trace {
namespace {

uint64_t distances_scalar(const SphereRun& s, size_t n, const Ray& ray, Real lo,
                          Real below, Real* t) {
    uint64_t mask = 0;
    for (size_t i = 0; i < n; ++i) {
        t[i] = sphere_distance(s.x[i], s.y[i], s.z[i], s.r[i], ray, lo);
        if (t[i] < below) mask |= uint64_t(1) << i;
    }
    return mask;
}

#ifdef POVWALL_LANES_AVX
// mask ? a : b per lane, for all-ones/all-zeros masks. Bitwise: GCC turned blendv into
// branches.
__attribute__((target("avx"))) inline __m256d select(__m256d mask, __m256d a, __m256d b) {
    return _mm256_or_pd(_mm256_and_pd(mask, a), _mm256_andnot_pd(mask, b));
}

// Only AVX (not AVX2 or FMA) is needed: 256-bit double arithmetic, compares and blends.
__attribute__((target("avx"))) uint64_t distances_avx(const SphereRun& s, size_t n,
                                                      const Ray& ray, Real lo, Real below,
                                                      Real* t) {
    const __m256d ox = _mm256_set1_pd(ray.origin.x), oy = _mm256_set1_pd(ray.origin.y),
                  oz = _mm256_set1_pd(ray.origin.z);
    const __m256d dx = _mm256_set1_pd(ray.direction.x),
                  dy = _mm256_set1_pd(ray.direction.y),
                  dz = _mm256_set1_pd(ray.direction.z);
    const __m256d eps = _mm256_set1_pd(kPovEpsilon),
                  tol = _mm256_set1_pd(kSphereTolerance), vlo = _mm256_set1_pd(lo),
                  inf = _mm256_set1_pd(kInfinity), vbelow = _mm256_set1_pd(below);
    uint64_t mask = 0;
    for (size_t i = 0; i < n; i += 4) {
        const __m256d ocx = _mm256_sub_pd(_mm256_loadu_pd(s.x + i), ox);
        const __m256d ocy = _mm256_sub_pd(_mm256_loadu_pd(s.y + i), oy);
        const __m256d ocz = _mm256_sub_pd(_mm256_loadu_pd(s.z + i), oz);
        const __m256d r = _mm256_loadu_pd(s.r + i);
        const __m256d tca =
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ocx, dx), _mm256_mul_pd(ocy, dy)),
                          _mm256_mul_pd(ocz, dz));
        const __m256d oc2 =
            _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ocx, ocx), _mm256_mul_pd(ocy, ocy)),
                          _mm256_mul_pd(ocz, ocz));
        const __m256d t2hc = _mm256_add_pd(_mm256_sub_pd(_mm256_mul_pd(r, r), oc2),
                                           _mm256_mul_pd(tca, tca));
        const __m256d hit = _mm256_cmp_pd(t2hc, eps, _CMP_GT_OQ);
        const __m256d th = _mm256_sqrt_pd(t2hc);  // NaN lanes are masked off by `hit`
        const __m256d near = _mm256_sub_pd(tca, th), far = _mm256_add_pd(tca, th);
        const __m256d near_ok = _mm256_and_pd(_mm256_cmp_pd(near, tol, _CMP_GT_OQ),
                                              _mm256_cmp_pd(near, vlo, _CMP_GE_OQ));
        const __m256d far_ok = _mm256_and_pd(_mm256_cmp_pd(far, tol, _CMP_GT_OQ),
                                             _mm256_cmp_pd(far, vlo, _CMP_GE_OQ));
        const __m256d d = select(near_ok, near, select(far_ok, far, inf));
        const __m256d dist = select(hit, d, inf);
        _mm256_storeu_pd(t + i, dist);
        mask |= uint64_t(_mm256_movemask_pd(_mm256_cmp_pd(dist, vbelow, _CMP_LT_OQ)))
                << i;
    }
    // Lanes past n read the next run's spheres.
    return n < 64 ? mask & ((uint64_t(1) << n) - 1) : mask;
}

const bool kHasAvx = [] {
    __builtin_cpu_init();  // static initialisers may run before libgcc's
    return __builtin_cpu_supports("avx") != 0;
}();
#endif

}  // namespace

uint64_t sphere_distances(const SphereRun& run, size_t n, const Ray& ray, Real lo,
                          Real below, Real* t) {
#ifdef POVWALL_LANES_AVX
    if (kHasAvx) return distances_avx(run, n, ray, lo, below, t);
#endif
    return distances_scalar(run, n, ray, lo, below, t);
}

}  // namespace povwall::trace
