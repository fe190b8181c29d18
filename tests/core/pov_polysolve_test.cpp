// POV-Ray's polynomial solver as reproduced (core/pov_polysolve.h): its root counts and
// order, and the quirks that decide pixels.
#include "core/pov_polysolve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace povwall {
namespace {

TEST(PovPolysolve, QuadraticOrderAndTangentWindow) {
    Real r[2];
    const Real two[3] = {1, -3, 2};  // (x - 1)(x - 2): larger root first
    ASSERT_EQ(pov_solve_polynomial(2, two, r, false), 2);
    EXPECT_EQ(r[0], 2);
    EXPECT_EQ(r[1], 1);
    // A discriminant within 1e-10 of zero: one root.
    const Real tangent[3] = {1, -2, 1 + 2e-11};
    ASSERT_EQ(pov_solve_polynomial(2, tangent, r, false), 1);
    EXPECT_EQ(r[0], 1);
    // Leading coefficients below 1e-10 are dropped: a linear equation.
    const Real linear[3] = {1e-11, 2, -4};
    ASSERT_EQ(pov_solve_polynomial(2, linear, r, false), 1);
    EXPECT_EQ(r[0], 2);
}

TEST(PovPolysolve, CubicClosedFormAndItsTripleRoot) {
    Real r[3];
    const Real three[4] = {1, -6, 11, -6};  // roots 1, 2, 3
    ASSERT_EQ(pov_solve_polynomial(3, three, r, false), 3);
    Real sorted[3] = {r[0], r[1], r[2]};
    std::sort(sorted, sorted + 3);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(sorted[i], i + 1, 1e-12);
    // (x - 1)^3: Q = R = 0 gives 0/0 in the trigonometric form: NaN roots.
    const Real triple[4] = {1, -3, 3, -1};
    ASSERT_EQ(pov_solve_polynomial(3, triple, r, false), 3);
    EXPECT_TRUE(std::isnan(r[0]));
}

TEST(PovPolysolve, SturmFindsOnlyRootsFromZeroToMaxDistance) {
    Real r[4];
    const Real three[4] = {1, -6, 11, -6};
    ASSERT_EQ(pov_solve_polynomial(3, three, r, true), 3);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(r[i], i + 1, 1e-11);  // ascending
    const Real signs[4] = {1, 0, -1, 0};  // x (x - 1)(x + 1): -1 is never reported
    const int n = pov_solve_polynomial(3, signs, r, true);
    for (int i = 0; i < n; ++i) EXPECT_GE(r[i], 0);
    // A sixth degree always goes through Sturm: (x^2 - 1)(x - 2)(x - 3)(x - 4)(x + 5).
    const Real six[7] = {1, -4, -20, 110, -101, -106, 120};
    Real r6[6];
    ASSERT_EQ(pov_solve_polynomial(6, six, r6, false), 4);
    const Real expect[4] = {1, 2, 3, 4};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(r6[i], expect[i], 1e-10);
}

TEST(PovPolysolve, QuarticRootEliminationAndDifficultCoefficients) {
    Real r[4];
    // (x - 1)(x - 2)(x - 3)(x - 4) by the closed form.
    const Real four[5] = {1, -10, 35, -50, 24};
    ASSERT_EQ(pov_solve_polynomial(4, four, r, false), 4);
    Real sorted[4] = {r[0], r[1], r[2], r[3]};
    std::sort(sorted, sorted + 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(sorted[i], i + 1, 1e-9);
    // A root near 0 (constant / linear below 1e-4) is eliminated: the cubic is solved.
    const Real near_zero[5] = {1, -6, 11, -6, 1e-6};
    EXPECT_EQ(pov_solve_polynomial(4, near_zero, r, false, 1e-4), 3);
    EXPECT_EQ(pov_solve_polynomial(4, near_zero, r, false, 0), 4);
}

TEST(PovPolysolve, HighDegreesUpToPovRaysMaxOrderGoThroughSturm) {
    // (x - 1)(x - 2)...(x - 8): the coefficients built exactly in doubles.
    Real c[kPovMaxOrder + 1] = {1};
    for (int k = 1; k <= 8; ++k)
        for (int i = k; i >= 1; --i) c[i] -= k * c[i - 1];
    Real r[kPovMaxOrder];
    ASSERT_EQ(pov_solve_polynomial(8, c, r, false), 8);
    for (int i = 0; i < 8; ++i) EXPECT_NEAR(r[i], i + 1, 1e-7);  // ascending
    // x^35 - 2^35 (c[0] = 1, c[35] = -2^35): one real root, 2.
    Real big[kPovMaxOrder + 1] = {1};
    big[kPovMaxOrder] = -std::ldexp(1.0, 35);
    // POV-Ray 3.7's own Solve_Polynomial returns this value too: its regula falsi stops
    // when |f(x) / x| < 1e-12, which at this slope (35 * 2^34) is 3e-9 short of 2.
    ASSERT_EQ(pov_solve_polynomial(kPovMaxOrder, big, r, false), 1);
    EXPECT_EQ(r[0], 1.9999999967268423);
}

// With `wanted`, Sturm may leave out roots above it; the roots at or below it are the
// whole search's, bit for bit and in its order (the search's path is kept: which
// intervals recurse, the regula falsi on entry, the iteration count). Polynomials with
// roots on both sides of 1, clusters, and random coefficients of every degree.
TEST(PovPolysolve, RootsUpToWantedAreTheWholeSearchsRoots) {
    auto expand = [](const std::vector<Real>& roots, Real scale) {
        std::vector<Real> c{scale};  // highest power first
        for (const Real r : roots) {
            c.push_back(0);
            for (size_t i = c.size() - 1; i > 0; --i) c[i] -= r * c[i - 1];
        }
        return c;
    };
    std::vector<std::vector<Real>> polys{
        expand({0.3, 0.7, 5, 20, 3000, -2}, 1),
        expand({0.999999, 1.000001, 1.5, 0.25, 40, 41}, -3e-4),
        expand({1e-3, 2e-3, 0.9, 7e5, 9e6, 12}, 2),
        expand({0.5, 0.5000001, 0.5000002, 2, 3, 4, 5, 6, 7, 8}, 1),
    };
    uint64_t state = 12345;
    auto uniform = [&] {  // reproducible on every platform
        state = state * 6364136223846793005u + 1442695040888963407u;
        return Real(state >> 11) * 0x1p-53 * 2 - 1;
    };
    for (int k = 0; k < 3000; ++k) {
        const int n = 3 + k % 8;
        std::vector<Real> c(size_t(n) + 1);
        for (Real& x : c) x = uniform() * std::pow(10.0, 3 * uniform());
        polys.push_back(c);
    }
    int kept = 0;
    for (const auto& c : polys) {
        const int n = int(c.size()) - 1;
        for (const Real wanted : {1.0, 0.5, 10.0}) {
            Real all[40], some[40];
            const int na = pov_solve_polynomial(n, c.data(), all, true);
            const int ns = pov_solve_polynomial(n, c.data(), some, true, 0, wanted);
            std::vector<Real> a, s;
            for (int i = 0; i < na; ++i)
                if (all[i] <= wanted) a.push_back(all[i]);
            for (int i = 0; i < ns; ++i)
                if (some[i] <= wanted) s.push_back(some[i]);
            ASSERT_EQ(a, s) << "degree " << n << ", wanted " << wanted;
            kept += int(a.size());
        }
    }
    EXPECT_GT(kept, 2000);  // the comparison saw roots
    // The first polynomial's roots up to 1, found with wanted = 1: exactly two.
    Real r[6];
    const int n = pov_solve_polynomial(6, polys[0].data(), r, true, 0, 1.0);
    std::vector<Real> low;
    for (int i = 0; i < n; ++i)
        if (r[i] <= 1) low.push_back(r[i]);
    ASSERT_EQ(low.size(), 2u);
    EXPECT_NEAR(low[0], 0.3, 1e-12);
    EXPECT_NEAR(low[1], 0.7, 1e-12);
}

}  // namespace
}  // namespace povwall
