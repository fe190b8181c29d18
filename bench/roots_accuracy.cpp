// The accuracy pass behind docs/numerics.md: each quartic method's roots on ray-torus
// quartics against the 50-digit oracle (Sturm isolation in boost::multiprecision), per
// minor/major ratio. Error is absolute, in units of the ray parameter (the torus has
// major radius 1), and a root counts as missed when the oracle has it and the method has
// nothing within 1e-3 * minor.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "bench/roots_cases.h"
#include "core/pov_polysolve.h"
#include "trace/oracle.h"
#include "trace/roots.h"
#include "trace/roots_sturm.h"
#include "trace/shapes/oracle_math.h"

using namespace povwall;

namespace {

struct Score {
    long roots = 0, missed = 0, spurious = 0;
    std::vector<double> err;
};

void score(Score& s, const double* truth, int nt, const double* got, int ng,
           double ratio) {
    s.roots += nt;
    std::vector<bool> used(ng, false);
    for (int i = 0; i < nt; ++i) {
        int best = -1;
        for (int j = 0; j < ng; ++j) {
            if (!used[j] && (best < 0 || std::fabs(got[j] - truth[i]) <
                                             std::fabs(got[best] - truth[i])))
                best = j;
        }
        if (best < 0 || std::fabs(got[best] - truth[i]) > 1e-3 * ratio) {
            ++s.missed;
            continue;
        }
        used[best] = true;
        s.err.push_back(std::fabs(got[best] - truth[i]));
    }
    for (int j = 0; j < ng; ++j) s.spurious += !used[j];
}

// A polynomial of degree n as a lathe's or prism's spline segment gives one: real roots
// in [0, 1] (a quarter of them in pairs 1e-7 apart: a ray grazing the profile), the rest
// in complex pairs close to the axis (near misses), times a random scale. Highest power
// first.
std::vector<double> spline_like_polynomial(int n, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> c{1};  // ascending build, reversed at the end
    auto times = [&](const std::vector<double>& f) {
        std::vector<double> r(c.size() + f.size() - 1, 0);
        for (size_t i = 0; i < c.size(); ++i)
            for (size_t j = 0; j < f.size(); ++j) r[i + j] += c[i] * f[j];
        c = r;
    };
    int left = n;
    while (left > 0) {
        if (left >= 2 && u(rng) < 0.4) {
            const double re = u(rng), im = 1e-4 + 0.3 * u(rng) * u(rng);
            times({re * re + im * im, -2 * re, 1});
            left -= 2;
        } else if (left >= 2 && u(rng) < 0.25) {
            const double r = u(rng);
            times({-r, 1});
            times({-(r + 1e-7), 1});
            left -= 2;
        } else {
            times({-u(rng), 1});
            left -= 1;
        }
    }
    const double scale = std::pow(10.0, 6 * u(rng) - 3);
    std::vector<double> high(c.rbegin(), c.rend());
    for (double& x : high) x *= scale;
    return high;
}

// Roots in [0, 1] of c (highest power first) by each method, and the reference: Sturm
// isolation and Newton in 50 digits on the same double coefficients.
void degree_table() {
    std::printf(
        "\n| degree | method | roots | missed | spurious | median abs err | max abs err "
        "| "
        "ns per call |\n|---|---|---|---|---|---|---|---|\n");
    for (int n = 2; n <= 6; ++n) {
        std::mt19937_64 rng(uint64_t(n) * 7919);
        std::vector<std::vector<double>> cases;
        for (int i = 0; i < 4000; ++i) cases.push_back(spline_like_polynomial(n, rng));
        std::vector<std::vector<double>> truth;
        for (const auto& c : cases) {
            trace::SturmPoly<trace::HP> p;
            p.degree = n;
            for (int i = 0; i <= n; ++i) p.c[i] = trace::HP(c[size_t(n - i)]);
            trace::HP r[6];
            const int k =
                trace::sturm_real_roots(p, trace::HP(-1e-300), trace::HP(1), r, 6);
            std::vector<double> t;
            for (int i = 0; i < k; ++i) t.push_back(double(r[i]));
            truth.push_back(t);
        }
        const char* names[] = {"POV-Ray's rule (closed form to 4, then Sturm)",
                               "POV-Ray's Sturm (sturm keyword)", "ours: Sturm + Newton"};
        for (int m = 0; m < 3; ++m) {
            if (m == 1 && n < 3) continue;  // sturm applies from degree 3
            auto solve = [&](const std::vector<double>& c, double* got) {
                int ng = 0;
                if (m < 2) {
                    double all[6];
                    const int k = pov_solve_polynomial(n, c.data(), all, m == 1);
                    for (int i = 0; i < k; ++i)
                        if (all[i] >= 0 && all[i] <= 1) got[ng++] = all[i];
                } else {
                    trace::SturmPoly<double> p;
                    p.degree = n;
                    for (int i = 0; i <= n; ++i) p.c[i] = c[size_t(n - i)];
                    ng = trace::sturm_real_roots(p, -1e-300, 1.0, got, 6);
                }
                return ng;
            };
            Score sc;
            for (size_t i = 0; i < cases.size(); ++i) {
                double got[6];
                const int ng = solve(cases[i], got);
                score(sc, truth[i].data(), int(truth[i].size()), got, ng, 1.0);
            }
            // Time: the whole set, best of five passes.
            double best = kInfinity, sink = 0;
            for (int pass = 0; pass < 5; ++pass) {
                const auto t0 = std::chrono::steady_clock::now();
                for (const auto& c : cases) {
                    double got[6];
                    sink += solve(c, got);
                }
                const std::chrono::duration<double, std::nano> dt =
                    std::chrono::steady_clock::now() - t0;
                best = std::min(best, dt.count() / double(cases.size()));
            }
            auto& e = sc.err;
            std::sort(e.begin(), e.end());
            std::printf("| %d | %s | %ld | %ld | %ld | %.2g | %.2g | %.0f |\n", n,
                        names[m], sc.roots, sc.missed, sc.spurious,
                        e.empty() ? 0.0 : e[e.size() / 2], e.empty() ? 0.0 : e.back(),
                        sink > 0 ? best : best);
        }
    }
}

}  // namespace

int main() {
    std::printf(
        "| minor/major | method | roots | missed | spurious | median abs err | max abs "
        "err |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (double ratio : bench::kRatios) {
        auto cases = bench::torus_cases(ratio, 4000);
        const char* names[] = {"ferrari (no polish)", "ferrari + newton",
                               "ferrari + compensated newton", "sturm", "auto (switch)"};
        Score scores[5];
        for (const auto& c : cases) {
            double truth[4], got[4];
            int nt = trace::oracle_quartic_roots(c.q.c, c.q.lo, c.q.hi, truth);
            for (int m = 0; m < 5; ++m) {
                int ng = 0;
                if (m < 3) {
                    double all[4];
                    int n =
                        trace::solve_quartic_ferrari(c.q.c, all, trace::QuarticPolish(m));
                    for (int i = 0; i < n; ++i)
                        if (all[i] > c.q.lo && all[i] <= c.q.hi) got[ng++] = all[i];
                } else if (m == 3) {
                    ng = trace::solve_quartic_sturm(c.q.c, c.q.lo, c.q.hi, got);
                } else {
                    ng = trace::solve_quartic(c.q.c, c.q.lo, c.q.hi, got);
                }
                score(scores[m], truth, nt, got, ng, ratio);
            }
        }
        for (int m = 0; m < 5; ++m) {
            auto& e = scores[m].err;
            std::sort(e.begin(), e.end());
            std::printf("| %g | %s | %ld | %ld | %ld | %.2g | %.2g |\n", ratio, names[m],
                        scores[m].roots, scores[m].missed, scores[m].spurious,
                        e.empty() ? 0.0 : e[e.size() / 2], e.empty() ? 0.0 : e.back());
        }
    }
    // End to end: intersect_torus (POV-Ray's own solver, as the tracer uses it)
    // against the oracle's first hit on the exact geometry (not on the rounded
    // coefficients).
    std::printf(
        "\n| minor/major | rays | hit/miss disagreements | median rel err | max rel err "
        "|\n");
    std::printf("|---|---|---|---|---|\n");
    for (double ratio : bench::kRatios) {
        auto cases = bench::torus_cases(ratio, 4000);
        Scene scene;
        Object obj;
        obj.shape = Torus{1, ratio};
        scene.objects.push_back(obj);
        long disagree = 0;
        std::vector<double> err;
        for (const auto& c : cases) {
            trace::Crossings cs;
            trace::intersect_torus(std::get<Torus>(obj.shape), c.origin, c.dir, cs);
            double fast = kInfinity;
            for (int i = 0; i < cs.n; ++i)
                if (cs.c[i].t >= trace::kMinIsectDepth) fast = std::min(fast, cs.c[i].t);
            trace::OracleHit truth = trace::oracle_first_hit(scene, {c.origin, c.dir}, 0);
            if (truth.hit != std::isfinite(fast)) {
                ++disagree;
                continue;
            }
            if (truth.hit) err.push_back(std::fabs(fast - truth.t) / truth.t);
        }
        std::sort(err.begin(), err.end());
        std::printf("| %g | %zu | %ld | %.2g | %.2g |\n", ratio, cases.size(), disagree,
                    err.empty() ? 0.0 : err[err.size() / 2],
                    err.empty() ? 0.0 : err.back());
    }

    // Quadratics: a radius-1e5 ground sphere, ray origins 1e-4 to 1 above it (the camera
    // or a secondary ray close to the ground), aimed down at up to ~8 degrees off
    // vertical. Both methods get the same double coefficients (c = h (2R + h), exact to
    // an ulp); the reference is the nearer root in long double.
    std::printf(
        "\n| quadratic | rays | median rel err | max rel err |\n|---|---|---|---|\n");
    for (int method = 0; method < 2; ++method) {
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> u(0, 1);
        std::vector<double> err;
        for (int i = 0; i < 4000; ++i) {
            const double R = 1e5, h = std::pow(10.0, -4 + 4 * u(rng));
            double dx = 0.3 * (u(rng) - 0.5), dy = -1;
            const double len = std::sqrt(dx * dx + dy * dy);
            dy /= len;
            const double b = 2 * (R + h) * dy, c = h * (2 * R + h);
            double r[2];
            int n = method ? trace::solve_quadratic(1, b, c, r)
                           : trace::solve_quadratic_naive(1, b, c, r);
            if (n < 1) continue;
            long double lb = b, lc = c;
            long double q = -0.5L * (lb - std::sqrt(lb * lb - 4 * lc));  // b < 0
            long double near = lc / q;
            err.push_back(std::fabs((double)((r[0] - near) / near)));
        }
        std::sort(err.begin(), err.end());
        std::printf(
            "| %s | %zu | %.2g | %.2g |\n",
            method ? "stable (q = -(b + sign(b) sqrt)/2)" : "naive (-b - sqrt)/2a",
            err.size(), err[err.size() / 2], err.back());
    }
    degree_table();
}
