// Solver unit tests on polynomials with exactly representable coefficients and known
// roots.
#include "trace/roots.h"

#include <gtest/gtest.h>

#include <cmath>

#include "trace/oracle.h"
#include "trace/shapes/shape.h"

namespace povwall::trace {
namespace {

TEST(Roots, StableQuadraticKeepsTheSmallRoot) {
    // x^2 - (1e8 + 1e-8) x + 1 = (x - 1e8)(x - 1e-8).
    const Real b = -(1e8 + 1e-8);
    Real r[2];
    ASSERT_EQ(solve_quadratic(1, b, 1, r), 2);
    EXPECT_NEAR(r[0], 1e-8, 1e-8 * 1e-15);
    EXPECT_NEAR(r[1], 1e8, 1e8 * 1e-15);
    // The textbook formula cancels: the small root comes out wrong in the leading digits.
    ASSERT_EQ(solve_quadratic_naive(1, b, 1, r), 2);
    EXPECT_GT(std::fabs(r[0] - 1e-8) / 1e-8, 1e-3);
}

// (x - 3/2)(x - 3/2 - e)(x - 3)(x - 3 - e): close pairs, as a thin torus's tube
// crossings. Coefficients are exact doubles for e = 2^-13 and 2^-20.
struct ClosePairs {
    Real e;
    Real c[5];
};
const ClosePairs kClosePairs[] = {
    {1.0 / 8192,
     {20.25247199088335, -40.50357062369585, 29.25164796411991, -9.000244140625, 1}},
    {1.0 / 1048576,
     {20.250019311909, -40.50002789497785, 29.25001287460418, -9.000001907348633, 1}},
};

void expect_pairs(const Real* r, int n, Real e, Real tol) {
    ASSERT_EQ(n, 4);
    EXPECT_NEAR(r[0], 1.5, tol);
    EXPECT_NEAR(r[1], 1.5 + e, tol);
    EXPECT_NEAR(r[2], 3.0, tol);
    EXPECT_NEAR(r[3], 3.0 + e, tol);
}

TEST(Roots, QuarticMethodsSeparateClosePairs) {
    for (const auto& p : kClosePairs) {
        SCOPED_TRACE(p.e);
        Real r[4];
        // Plain double evaluation limits any method to ~eps |c| / |p'(root)| ~ 2e-9 on
        // the 2^-20 pair (double Sturm sits there); compensated Newton polishing gets
        // ~1e-15.
        {
            SCOPED_TRACE("ferrari");
            expect_pairs(r, solve_quartic_ferrari(p.c, r), p.e, 1e-14);
        }
        {
            SCOPED_TRACE("sturm");
            expect_pairs(r, solve_quartic_sturm(p.c, 0, 10, r), p.e, 5e-9);
        }
        {
            SCOPED_TRACE("auto");
            expect_pairs(r, solve_quartic(p.c, 0, 10, r), p.e, 1e-14);
        }
        expect_pairs(r, oracle_quartic_roots(p.c, 0, 10, r), p.e, 1e-15);
    }
}

TEST(Roots, QuarticIntervalKeepsOnlyRootsInside) {
    const Real* c = kClosePairs[0].c;
    Real r[4];
    ASSERT_EQ(solve_quartic_sturm(c, 2, 10, r), 2);
    EXPECT_NEAR(r[0], 3.0, 1e-12);
    ASSERT_EQ(solve_quartic(c, 2, 10, r), 2);
    EXPECT_NEAR(r[1], 3.0 + 1.0 / 8192, 1e-12);
    EXPECT_EQ(solve_quartic(c, 3.5, 10, r), 0);
}

TEST(Roots, QuarticDistinctRootsExact) {
    // (x-1)(x-2)(x-3)(x-4), leading coefficient 2 (the solvers normalise).
    const Real c[5] = {48, -100, 70, -20, 2};
    Real r[4];
    for (int m = 0; m < 3; ++m) {
        int n = m == 0   ? solve_quartic_ferrari(c, r)
                : m == 1 ? solve_quartic_sturm(c, 0, 5, r)
                         : solve_quartic(c, 0, 5, r);
        ASSERT_EQ(n, 4) << m;
        for (int i = 0; i < 4; ++i) EXPECT_NEAR(r[i], i + 1, 1e-13) << m;
    }
}

// A ray-torus quartic (minor/major 1e-4, grazing) on which double-precision Sturm loses
// the second root of a close pair; the tracer's solver must keep both (the oracle's
// 50-digit roots are the truth).
TEST(Roots, StiffTorusQuarticKeepsBothRoots) {
    const Real c[5] = {3.8013863242988122, -5.7798781583571266, 6.0006456412687479,
                       -4.0008000000000017, 1};
    const Real lo = 0.23605094425582429, hi = 1.7643490557441746;
    Real truth[4], r[4];
    ASSERT_EQ(oracle_quartic_roots(c, lo, hi, truth), 2);
    ASSERT_EQ(solve_quartic(c, lo, hi, r), 2);
    EXPECT_NEAR(r[0], truth[0], 1e-11);
    EXPECT_NEAR(r[1], truth[1], 1e-11);
}

TEST(Roots, ThinTorusFaceOnCrossingsExact) {
    // Straight down through the tube of a torus with minor radius 1e-4: t = 5 -+ 1e-4.
    for (Real minor : {1e-4, 1e-3, 0.5, 0.999}) {
        Torus t;
        t.major = 1;
        t.minor = minor;
        Crossings cs;
        intersect_torus(t, {1, 5, 0}, {0, -1, 0}, cs);
        ASSERT_EQ(cs.n, 2) << minor;
        EXPECT_NEAR(cs.c[0].t, 5 - minor, 1e-12) << minor;
        EXPECT_NEAR(cs.c[1].t, 5 + minor, 1e-12) << minor;
    }
}

TEST(Roots, SlabTestsWithZeroAndTinyDirectionComponents) {
    Box b{{0, 0, 0}, {1, 1, 1}};
    Crossings cs;
    // Parallel to the x = 0 face and lying in it: POV-Ray's closed slabs count it as
    // inside.
    intersect_box(b, {0, 0.5, -1}, {0, 0, 1}, cs);
    ASSERT_EQ(cs.n, 2);
    EXPECT_EQ(cs.c[0].t, 1);
    EXPECT_EQ(cs.c[1].t, 2);
    // Just outside that face: parallel, so a miss (no division by zero, no NaN).
    cs.n = 0;
    intersect_box(b, {-1e-300, 0.5, -1}, {0, 0, 1}, cs);
    EXPECT_EQ(cs.n, 0);
    // A tiny but real x component: enters through x = 0 where the line meets it.
    cs.n = 0;
    const Real dx = 1e-9;
    Vector3 d = normalize(Vector3{dx, 0, 1});
    intersect_box(b, {-1e-10, 0.5, -1}, d, cs);
    ASSERT_EQ(cs.n, 2);
    EXPECT_NEAR(cs.c[0].t, 1.0, 1e-12);
    for (int i = 0; i < cs.n; ++i) EXPECT_TRUE(std::isfinite(cs.c[i].t));
}

}  // namespace
}  // namespace povwall::trace
