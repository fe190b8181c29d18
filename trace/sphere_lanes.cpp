#include "trace/sphere_lanes.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define POVWALL_LANES_AVX 1  // chosen at run time by what the CPU has
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
        // Most lanes miss (a leaf holds a few dozen spheres, a ray meets one or two):
        // no square root when all four do.
        if (_mm256_movemask_pd(hit) == 0) {
            _mm256_storeu_pd(t + i, inf);
            continue;
        }
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

// Eight lanes, the same operations; compares give mask registers, so no selects by bits.
__attribute__((target("avx512f"))) uint64_t distances_avx512(const SphereRun& s, size_t n,
                                                             const Ray& ray, Real lo,
                                                             Real below, Real* t) {
    const __m512d ox = _mm512_set1_pd(ray.origin.x), oy = _mm512_set1_pd(ray.origin.y),
                  oz = _mm512_set1_pd(ray.origin.z);
    const __m512d dx = _mm512_set1_pd(ray.direction.x),
                  dy = _mm512_set1_pd(ray.direction.y),
                  dz = _mm512_set1_pd(ray.direction.z);
    const __m512d eps = _mm512_set1_pd(kPovEpsilon),
                  tol = _mm512_set1_pd(kSphereTolerance), vlo = _mm512_set1_pd(lo),
                  inf = _mm512_set1_pd(kInfinity), vbelow = _mm512_set1_pd(below);
    uint64_t mask = 0;
    for (size_t i = 0; i < n; i += 8) {
        const __m512d ocx = _mm512_sub_pd(_mm512_loadu_pd(s.x + i), ox);
        const __m512d ocy = _mm512_sub_pd(_mm512_loadu_pd(s.y + i), oy);
        const __m512d ocz = _mm512_sub_pd(_mm512_loadu_pd(s.z + i), oz);
        const __m512d r = _mm512_loadu_pd(s.r + i);
        const __m512d tca =
            _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(ocx, dx), _mm512_mul_pd(ocy, dy)),
                          _mm512_mul_pd(ocz, dz));
        const __m512d oc2 =
            _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(ocx, ocx), _mm512_mul_pd(ocy, ocy)),
                          _mm512_mul_pd(ocz, ocz));
        const __m512d t2hc = _mm512_add_pd(_mm512_sub_pd(_mm512_mul_pd(r, r), oc2),
                                           _mm512_mul_pd(tca, tca));
        const __mmask8 hit = _mm512_cmp_pd_mask(t2hc, eps, _CMP_GT_OQ);
        if (hit == 0) {  // all eight miss (as above)
            _mm512_storeu_pd(t + i, inf);
            continue;
        }
        // Lanes that miss keep inf (and GCC 12 warns on the unmasked form's undefined
        // source).
        const __m512d th = _mm512_mask_sqrt_pd(inf, hit, t2hc);
        const __m512d near = _mm512_sub_pd(tca, th), far = _mm512_add_pd(tca, th);
        const __mmask8 near_ok = _mm512_cmp_pd_mask(near, tol, _CMP_GT_OQ) &
                                 _mm512_cmp_pd_mask(near, vlo, _CMP_GE_OQ);
        const __mmask8 far_ok = _mm512_cmp_pd_mask(far, tol, _CMP_GT_OQ) &
                                _mm512_cmp_pd_mask(far, vlo, _CMP_GE_OQ);
        __m512d dist = _mm512_mask_blend_pd(far_ok, inf, far);
        dist = _mm512_mask_blend_pd(near_ok, dist, near);
        dist = _mm512_mask_blend_pd(hit, inf, dist);
        _mm512_storeu_pd(t + i, dist);
        mask |= uint64_t(_mm512_cmp_pd_mask(dist, vbelow, _CMP_LT_OQ)) << i;
    }
    return n < 64 ? mask & ((uint64_t(1) << n) - 1) : mask;
}

#endif

const LaneWidth kWidest = [] {
#ifdef POVWALL_LANES_AVX
    __builtin_cpu_init();  // static initialisers may run before libgcc's
    if (__builtin_cpu_supports("avx512f")) return LaneWidth::Eight;
    if (__builtin_cpu_supports("avx")) return LaneWidth::Four;
#endif
    return LaneWidth::One;
}();

}  // namespace

LaneWidth widest_lanes() { return kWidest; }

uint64_t sphere_distances(LaneWidth width, const SphereRun& run, size_t n, const Ray& ray,
                          Real lo, Real below, Real* t) {
    switch (width) {
#ifdef POVWALL_LANES_AVX
        case LaneWidth::Eight:
            return distances_avx512(run, n, ray, lo, below, t);
        case LaneWidth::Four:
            return distances_avx(run, n, ray, lo, below, t);
#endif
        default:
            return distances_scalar(run, n, ray, lo, below, t);
    }
}

namespace {
// The widest kernel, chosen once: each leaf's call goes straight to it.
using Distances = uint64_t (*)(const SphereRun&, size_t, const Ray&, Real, Real, Real*);
const Distances kWidestDistances = [] {
    switch (kWidest) {
#ifdef POVWALL_LANES_AVX
        case LaneWidth::Eight:
            return &distances_avx512;
        case LaneWidth::Four:
            return &distances_avx;
#endif
        default:
            return &distances_scalar;
    }
}();
}  // namespace

uint64_t sphere_distances(const SphereRun& run, size_t n, const Ray& ray, Real lo,
                          Real below, Real* t) {
    return kWidestDistances(run, n, ray, lo, below, t);
}

}  // namespace povwall::trace
