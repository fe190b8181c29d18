// Spheres tested four at a time: the lanes give the scalar test's bits, every lane, every
// run length, and the mask names exactly the spheres nearer than the bound.
#include "trace/sphere_lanes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace povwall::trace {
namespace {

struct Spheres {
    std::vector<Real> x, y, z, r;
    void add(Real cx, Real cy, Real cz, Real cr) {
        x.push_back(cx);
        y.push_back(cy);
        z.push_back(cz);
        r.push_back(cr);
    }
    void pad() {  // the seven entries a run may read past its end
        for (int i = 0; i < 7; ++i) add(kNaN, kNaN, kNaN, kNaN);
    }
    SphereRun run(size_t from) const { return {&x[from], &y[from], &z[from], &r[from]}; }
    static constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();
};

// Every width this CPU runs, the scalar one included.
std::vector<LaneWidth> widths() {
    std::vector<LaneWidth> w{LaneWidth::One};
    if (widest_lanes() >= LaneWidth::Four) w.push_back(LaneWidth::Four);
    if (widest_lanes() >= LaneWidth::Eight) w.push_back(LaneWidth::Eight);
    return w;
}

uint64_t bits(Real v) {
    uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
}

TEST(SphereLanes, KnownDistances) {
    Spheres s;
    s.add(0, 0, 5, 1);      // ahead: near root 4
    s.add(0, 0, 0, 2);      // around the origin: only the far root 2
    s.add(0, 0, -5, 1);     // behind: no root ahead
    s.add(0, 1, 5, 1);      // tangent (t2hc = 0): POV-Ray counts it a miss
    s.add(0, 0, 5.5, 0.5);  // near root 5 is at lo, so it counts
    s.pad();
    const Ray ray{{0, 0, 0}, {0, 0, 1}};
    for (LaneWidth w : widths()) {
        SCOPED_TRACE(int(w));
        Real t[8];
        const uint64_t mask = sphere_distances(w, s.run(0), 5, ray, 5, kInfinity, t);
        EXPECT_EQ(t[0], 6);          // the near root 4 is below lo = 5: the far one
        EXPECT_EQ(t[1], kInfinity);  // its far root 2 is below lo too
        EXPECT_EQ(t[2], kInfinity);
        EXPECT_EQ(t[3], kInfinity);
        EXPECT_EQ(t[4], 5);
        EXPECT_EQ(mask, 0b10001u);
        const uint64_t near = sphere_distances(w, s.run(0), 5, ray, 1e-4, 4.5, t);
        EXPECT_EQ(t[0], 4);
        EXPECT_EQ(t[1], 2);
        EXPECT_EQ(near, 0b00011u);  // 4 and 2 are below 4.5, 5 is not
    }
}

TEST(SphereLanes, EveryLaneGivesTheScalarBitsAndTheMask) {
    for (LaneWidth w : widths()) {
        SCOPED_TRACE(int(w));
        std::mt19937_64 rng(20261201);
        std::uniform_real_distribution<Real> pos(-20, 20), rad(0.01, 3), unit(-1, 1);
        Spheres s;
        for (int i = 0; i < 4000; ++i) s.add(pos(rng), pos(rng), pos(rng), rad(rng));
        s.pad();
        std::uniform_int_distribution<size_t> len(1, kMaxSphereRun), from(0, 4000 - 64);
        Real t[kMaxSphereRun];
        size_t hits = 0, compared = 0;
        for (int k = 0; k < 3000; ++k) {
            const size_t n = len(rng), f = from(rng);
            // Aimed near one sphere of the run (grazing some), from inside others.
            const size_t aim = f + std::uniform_int_distribution<size_t>(0, n - 1)(rng);
            Ray ray;
            ray.origin = {pos(rng), pos(rng), pos(rng)};
            const Point3 target{s.x[aim] + s.r[aim] * unit(rng),
                                s.y[aim] + s.r[aim] * unit(rng),
                                s.z[aim] + s.r[aim] * unit(rng)};
            ray.direction = normalize(target - ray.origin);
            const Real lo = k % 3 == 0 ? 1e-4 : rad(rng);
            const Real below = k % 2 ? kInfinity : 5 * rad(rng);
            const uint64_t mask = sphere_distances(w, s.run(f), n, ray, lo, below, t);
            for (size_t i = 0; i < n; ++i) {
                const Real want = sphere_distance(s.x[f + i], s.y[f + i], s.z[f + i],
                                                  s.r[f + i], ray, lo);
                ASSERT_EQ(bits(t[i]), bits(want)) << "ray " << k << " lane " << i;
                ASSERT_EQ((mask >> i) & 1, uint64_t(want < below))
                    << "ray " << k << " lane " << i;
                hits += want < kInfinity;
                ++compared;
            }
            if (n < 64) {
                ASSERT_EQ(mask >> n, 0u) << "lanes past the run are never reported";
            }
        }
        // Both outcomes were exercised.
        EXPECT_GT(hits, compared / 50);
        EXPECT_LT(hits, compared / 2);
    }
}

TEST(SphereLanes, PaddingNeverHits) {
    Spheres s;
    s.add(0, 0, 5, 1);
    s.pad();
    s.pad();  // the padding itself is tested as a run below: it needs its own
    const Ray ray{{0, 0, 0}, {0, 0, 1}};
    for (LaneWidth w : widths()) {
        Real t[8];
        EXPECT_EQ(sphere_distances(w, s.run(0), 1, ray, 1e-4, kInfinity, t), 1u);
        EXPECT_EQ(sphere_distances(w, s.run(1), 7, ray, 1e-4, kInfinity, t), 0u);
        for (int i = 0; i < 7; ++i) EXPECT_EQ(t[i], kInfinity);
    }
}

}  // namespace
}  // namespace povwall::trace
