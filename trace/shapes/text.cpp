#include "trace/shapes/text.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "trace/shapes/oracle_math.h"

namespace povwall::trace {
namespace {

// Face tags: the two caps; sides carry their segment's index.
constexpr int kFrontFace = -1;  // z = 0, normal -z
constexpr int kBackFace = -2;   // z = depth, normal +z

// POV-Ray's COEFF_LIMIT: a leading coefficient below it makes the equation linear.
constexpr Real kCoeffLimit = 1e-20;

// The curve's power-basis coefficients: x(s) = c[0] s^2 + c[1] s + c[2].
struct Quadratic {
    Real c[3];
    Real at(Real s) const { return (c[0] * s + c[1]) * s + c[2]; }
    Real slope(Real s) const { return 2.0 * c[0] * s + c[1]; }
};
Quadratic power_basis(const Real (&v)[3]) {
    return {{v[0] - 2.0 * v[1] + v[2], 2.0 * (v[1] - v[0]), v[0]}};
}

int line_crossing(const GlyphSegment& s, Real x, Real y) {
    const Real x0 = s.x[0], y0 = s.y[0], x1 = s.x[1], y1 = s.y[1];
    if (y0 == y1) return 0;
    if ((y0 < y) == (y1 < y)) return 0;
    const bool r0 = x0 > x, r1 = x1 > x;
    if (r0 && r1) return 1;
    if (!r0 && !r1) return 0;
    // POV-Ray compares the crossing through the line's slope and intercept.
    const Real m = (y1 - y0) / (x1 - x0);
    const Real b = (y1 - y) - m * (x1 - x);
    return b / m < kPovEpsilon ? 1 : 0;
}

int curve_crossings(const GlyphSegment& s, Real x, Real y) {
    const Real y0 = s.y[0], y1 = s.y[1], y2 = s.y[2];
    if ((y0 < y && y1 < y && y2 < y) || (y0 > y && y1 > y && y2 > y)) return 0;
    const Quadratic qy = power_basis(s.y);
    Real roots[2];
    const int k = glyph_solve_quad(qy.c[0], qy.c[1], y0 - y, roots);
    const Quadratic qx = power_basis(s.x);
    int crossings = 0;
    for (int i = 0; i < k; ++i) {
        const Real r = roots[i];
        // A root at an end counts only where y lies within that end's control span.
        if (r <= kPovEpsilon) {
            if ((y <= y0 && y < y1) || (y >= y0 && y > y1)) continue;
        } else if (r >= 1.0 - kPovEpsilon) {
            if ((y < y2 && y < y1) || (y > y2 && y > y1)) continue;
        }
        if (qx.at(r) > x) ++crossings;
    }
    return crossings;
}

// Calls f(i) for every segment i of the set (file order).
template <class F>
void for_each_segment(const GlyphOutline& g, const uint64_t* set, F&& f) {
    for (int w = 0; w < g.band_words; ++w) {
        for (uint64_t bits = set[w]; bits; bits &= bits - 1)
            f(size_t(w) * 64 + size_t(std::countr_zero(bits)));
    }
}

}  // namespace

int glyph_solve_quad(Real a, Real b, Real c, Real roots[2]) {
    b = -b;
    if (std::fabs(a) < kCoeffLimit) {
        if (std::fabs(b) < kCoeffLimit) return 0;
        const Real q = c / b;
        if (q >= 0.0 && q <= 1.0) {
            roots[0] = q;
            return 1;
        }
        return 0;
    }
    Real d = b * b - 4.0 * a * c;
    if (d < kPovEpsilon) return 0;
    d = std::sqrt(d);
    const Real two_a = 2.0 * a;
    int n = 0;
    for (Real q : {(b + d) / two_a, (b - d) / two_a}) {
        if (q >= 0.0 && q <= 1.0) roots[n++] = q;
    }
    return n;
}

bool inside_glyph_outline(const GlyphOutline& g, Real x, Real y) {
    // Above, below or right of every point, each segment's count below is exactly 0 (a
    // curve lies in its points' hull; the comparisons are against the points themselves
    // or a convex combination of them, which cannot exceed their largest). Left of them
    // it is not: every crossing counts there, so the loop decides.
    if (y > g.point_ymax || y < g.point_ymin || x > g.point_xmax) return false;
    int crossings = 0;
    auto count = [&](const GlyphSegment& s) {
        crossings += s.curve ? curve_crossings(s, x, y) : line_crossing(s, x, y);
    };
    if (g.band_words == 0) {
        for (const GlyphSegment& s : g.segments) count(s);
    } else {
        // The other bands' segments lie wholly above or below y: they count 0.
        for_each_segment(g, g.band_set(g.band(y)),
                         [&](size_t i) { count(g.segments[i]); });
    }
    return (crossings & 1) != 0;
}

Real glyph_curve_parameter(const GlyphSegment& s, Real x, Real y) {
    const Quadratic qx = power_basis(s.x), qy = power_basis(s.y);
    Real best = 0, best_err = INFINITY;
    auto consider = [&](Real t) {
        if (!std::isfinite(t)) return;
        t = std::clamp(t, 0.0, 1.0);
        const Real ex = qx.at(t) - x, ey = qy.at(t) - y;
        const Real err = ex * ex + ey * ey;
        if (err < best_err) {
            best_err = err;
            best = t;
        }
    };
    // The point solves both coordinates' quadratics: try each one's roots (one of them is
    // well conditioned wherever the curve is not degenerate).
    for (const auto& [q, v] : {std::pair{qx, x}, std::pair{qy, y}}) {
        const Real a = q.c[0], b = q.c[1], c = q.c[2] - v;
        if (std::fabs(a) < 1e-300) {
            if (b != 0) consider(-c / b);
            continue;
        }
        const Real disc = std::max(0.0, b * b - 4 * a * c);
        const Real sq = std::sqrt(disc);
        const Real qq = -0.5 * (b + std::copysign(sq, b));
        consider(qq / a);
        if (qq != 0) consider(c / qq);
    }
    consider(0);
    consider(1);
    // One Newton step on the squared distance polishes the root.
    const Real ex = qx.at(best) - x, ey = qy.at(best) - y;
    const Real dx = qx.slope(best), dy = qy.slope(best);
    const Real g = ex * dx + ey * dy,
               h = dx * dx + dy * dy + ex * 2 * qx.c[0] + ey * 2 * qy.c[0];
    if (h > 0) {
        const Real t = std::clamp(best - g / h, 0.0, 1.0);
        const Real fx = qx.at(t) - x, fy = qy.at(t) - y;
        if (fx * fx + fy * fy <= best_err) best = t;
    }
    return best;
}

void shape_hits(const Glyph& g, const LocalRay& r, ShapeHits& out) {
    const GlyphOutline& outline = *g.outline;
    const Point3& P = r.origin;
    const Vector3& D = r.direction;  // POV-Ray does not normalise it: t is world depth
    const Real depth = g.depth;
    const bool caps = std::fabs(D.z) >= kPovEpsilon;
    // The ray's points (x, y) at the two ends of the stretch where a wall crossing that
    // matters lies: the caps' planes, or a part of that (below).
    Real x_front = 0, y_front = 0, x_back = 0, y_back = 0;
    if (caps) {
        Real t = -P.z / D.z;
        const Real x = P.x + t * D.x, y = P.y + t * D.y;
        const Real t_front = t;
        t += depth / D.z;
        const Real t_back = t;
        const Real xb = P.x + t * D.x, yb = P.y + t * D.y;
        x_front = x;
        y_front = y;
        x_back = xb;
        y_back = yb;
        const bool front_counts = t_front > 0.0 && t_front > kGlyphTolerance;
        const bool back_counts = t_back > 0.0 && t_back > kGlyphTolerance;
        bool first_cap_hit = false;
        if (r.nearest_only) {
            // A wall crossing's depth passes the z test only between the caps' planes, up
            // to rounding (relative 1e-16 of z's terms and of the caps' depths, far below
            // `slack`): no crossing lies nearer than the cap the ray meets first, less
            // slack. Past the wanted range, none is wanted.
            const Real t_first = std::min(t_front, t_back);
            const Real slack =
                1e-12 * (std::fabs(P.z) + std::fabs(depth)) / std::fabs(D.z);
            if (t_first - slack >= r.want_hi) return;
            // A closest-hit query whose first cap is a crossing in range needs nothing
            // past that cap, not even the other cap. The caller keeps the last of equal
            // depths, so a wall crossing at or before it still can be the nearest: the
            // walls are searched on the ray's stretch from t_first - slack to t_first.
            const bool front_first = t_front < t_back, back_first = t_back < t_front;
            if (!r.any_crossing && (front_first || back_first) &&
                (front_first ? front_counts : back_counts) && t_first >= r.want_lo &&
                t_first < r.want_hi) {
                const Real xf = front_first ? x : xb, yf = front_first ? y : yb;
                if (inside_glyph_outline(outline, xf, yf)) {
                    out.push_back({t_first,
                                   {xf, yf, front_first ? 0.0 : depth},
                                   front_first ? kFrontFace : kBackFace});
                    const Real t_near = t_first - slack;
                    x_front = P.x + t_near * D.x;
                    y_front = P.y + t_near * D.y;
                    x_back = xf;
                    y_back = yf;
                    first_cap_hit = true;
                }
            }
        }
        if (!first_cap_hit) {
            // (A query that keeps only the range needs no cap outside it.)
            auto wanted = [&](Real t_cap) {
                return !r.nearest_only || (t_cap >= r.want_lo && t_cap < r.want_hi);
            };
            const size_t first = out.size();
            const bool front =
                front_counts && wanted(t_front) && inside_glyph_outline(outline, x, y);
            // (A shadow ray that needs any crossing stops at the front cap's.)
            if (front && r.ends_search(t_front)) {
                out.push_back({t_front, {x, y, 0.0}, kFrontFace});
                return;
            }
            const bool back =
                back_counts && wanted(t_back) && inside_glyph_outline(outline, xb, yb);
            if (front) out.push_back({t_front, {x, y, 0.0}, kFrontFace});
            if (back) out.push_back({t_back, {xb, yb, depth}, kBackFace});
            for (size_t i = first; i < out.size(); ++i)
                if (r.ends_search(out[i].t)) return;
        }
    }
    const bool use_x = std::fabs(D.x) >= kPovEpsilon;
    if (!use_x && std::fabs(D.y) < kPovEpsilon) return;  // parallel to the walls
    // The projected ray as the implicit line a x + b y + c = 0.
    const Real a = D.y, b = -D.x, c = P.y * D.x - P.x * D.y;
    bool ended = false;  // a crossing ended the search (r.any_crossing)
    auto push_side = [&](Real t, int index, Real x, Real y) {
        const Real z = P.z + t * D.z;
        if (z >= 0 && z <= depth && t > kGlyphTolerance) {
            out.push_back({t, {x, y, z}, index});
            ended = ended || r.ends_search(t);
        }
    };
    // The projected line's value at a point, and a margin far above the rounding of the
    // coefficients below (relative 1e-16) yet far below any real crossing's: a segment
    // whose points all lie further than it on one side has no crossing, nor does an
    // outline whose box does (a curve lies in its points' hull, where the line's value
    // is a convex combination of its values at the points).
    auto side = [&](Real x, Real y) { return a * x + b * y + c; };
    const Real margin = 1e-9 * (std::fabs(a) * std::max(std::fabs(outline.point_xmin),
                                                        std::fabs(outline.point_xmax)) +
                                std::fabs(b) * std::max(std::fabs(outline.point_ymin),
                                                        std::fabs(outline.point_ymax)) +
                                std::fabs(c));
    auto clear_of = [&](const Real* xs, const Real* ys, int count) {
        bool above = true, below = true;
        for (int k = 0; k < count; ++k) {
            const Real v = side(xs[k], ys[k]);
            above = above && v > margin;
            below = below && v < -margin;
        }
        return above || below;
    };
    if (std::isfinite(margin)) {
        const Real bx[4] = {outline.point_xmin, outline.point_xmax, outline.point_xmin,
                            outline.point_xmax};
        const Real by[4] = {outline.point_ymin, outline.point_ymin, outline.point_ymax,
                            outline.point_ymax};
        if (clear_of(bx, by, 4)) return;
    }
    // Where the depth comes from x, a wall crossing's x is the ray's at its depth, which
    // lies on the stretch: between x_front and x_back up to rounding (relative 1e-16 of
    // the coordinates), far below the margin. A segment whose points all lie
    // outside that range has none (a curve lies in its points' hull).
    Real x_lo = -kInfinity, x_hi = kInfinity;
    if (caps && use_x) {
        const Real m = 1e-7 * (std::fabs(P.x) + std::fabs(x_front) + std::fabs(x_back) +
                               std::max(std::fabs(outline.point_xmin),
                                        std::fabs(outline.point_xmax)));
        if (std::isfinite(m)) {
            x_lo = std::min(x_front, x_back) - m;
            x_hi = std::max(x_front, x_back) + m;
        }
    }
    // (A line's points are its two ends: its end stands in for the third.)
    auto beside_window = [&](const GlyphSegment& s) {
        const Real x2 = s.curve ? s.x[2] : s.x[1];
        return std::max({s.x[0], s.x[1], x2}) < x_lo ||
               std::min({s.x[0], s.x[1], x2}) > x_hi;
    };
    auto segment_clear = [&](const GlyphSegment& s) {
        const Real v0 = side(s.x[0], s.y[0]), v1 = side(s.x[1], s.y[1]);
        const Real v2 = s.curve ? side(s.x[2], s.y[2]) : v1;
        return std::min({v0, v1, v2}) > margin || std::max({v0, v1, v2}) < -margin;
    };
    // The crossings of a segment inside the window. Kept out of line: most segments of
    // a scan fail the window test (cross_segment), which then costs no call.
    auto solve_segment = [&](size_t i) __attribute__((noinline)) {
        const GlyphSegment& s = outline.segments[i];
        if (segment_clear(s)) return;
        if (!s.curve) {
            const Real d0 = s.x[1] - s.x[0], d1 = s.y[1] - s.y[0];
            const Real den = d1 * D.x - d0 * D.y;
            if (std::fabs(den) < kPovEpsilon) return;
            const Real u = (D.x * (P.y - s.y[0]) - D.y * (P.x - s.x[0])) / den;
            if (u < 0.0 || u > 1.0) return;
            const Real x = s.x[0] + u * d0, y = s.y[0] + u * d1;
            push_side(use_x ? (x - P.x) / D.x : (y - P.y) / D.y, int(i), x, y);
            return;
        }
        const Quadratic qx = power_basis(s.x), qy = power_basis(s.y);
        Real roots[2];
        const int k =
            glyph_solve_quad(a * qx.c[0] + b * qy.c[0], a * qx.c[1] + b * qy.c[1],
                             a * qx.c[2] + b * qy.c[2] + c, roots);
        for (int j = 0; j < k; ++j) {
            const Real u = roots[j];
            const Real x = u * u * qx.c[0] + u * qx.c[1] + qx.c[2];
            const Real y = u * u * qy.c[0] + u * qy.c[1] + qy.c[2];
            push_side(use_x ? (x - P.x) / D.x : (y - P.y) / D.y, int(i), x, y);
        }
    };
    auto cross_segment = [&](size_t i) {
        if (!ended && !beside_window(outline.segments[i])) solve_segment(i);
    };
    // A wall crossing lies on the stretch only: where the ray is there, its height runs
    // from y_front to y_back, so only the bands of that range can hold a crossing. The
    // margin covers a crossing's rounding off the projected line, stretched by the slope
    // when the depth comes from x.
    constexpr int kMaxWords = 16;
    if (caps && outline.band_words > 0 && outline.band_words <= kMaxWords) {
        const Real slope = use_x ? std::max(1.0, std::fabs(D.y / D.x)) : 1.0;
        const Real extent =
            std::max({std::fabs(outline.point_ymin), std::fabs(outline.point_ymax),
                      std::fabs(y_front), std::fabs(y_back)});
        const Real m = 1e-7 * extent * slope;
        const Real lo = std::min(y_front, y_back) - m, hi = std::max(y_front, y_back) + m;
        if (std::isfinite(lo) && std::isfinite(hi)) {
            const int b0 = outline.band(lo), b1 = outline.band(hi);
            uint64_t set[kMaxWords];
            for (int w = 0; w < outline.band_words; ++w) {
                uint64_t bits = 0;
                for (int band = b0; band <= b1; ++band) bits |= outline.band_set(band)[w];
                set[w] = bits;
            }
            for_each_segment(outline, set, cross_segment);
            return;
        }
    }
    for (size_t i = 0; i < outline.segments.size(); ++i) cross_segment(i);
}

Vector3 shape_normal(const Glyph& g, const ShapeHit& h) {
    if (h.face == kFrontFace) return {0, 0, -1};
    if (h.face == kBackFace) return {0, 0, 1};
    const GlyphSegment& s = g.outline->segments[size_t(h.face)];
    if (!s.curve) return {s.y[1] - s.y[0], -(s.x[1] - s.x[0]), 0};
    const Quadratic qx = power_basis(s.x), qy = power_basis(s.y);
    const Real u = glyph_curve_parameter(s, h.p.x, h.p.y);
    return {qy.slope(u), -qx.slope(u), 0};
}

bool shape_inside(const Glyph& g, const Point3& p) {
    return p.z >= 0.0 && p.z <= g.depth && inside_glyph_outline(*g.outline, p.x, p.y);
}

Bounds3 shape_bounds(const Glyph& g) {
    // The outline's own extent (a composite's points may leave POV-Ray's box): its point
    // box once indexed (the same minima and maxima of the same points in the same order).
    const GlyphOutline& o = *g.outline;
    Bounds3 b;
    if (o.band_words > 0) {
        b.lo = {o.point_xmin, o.point_ymin, 0};
        b.hi = {o.point_xmax, o.point_ymax, 0};
    } else {
        for (const GlyphSegment& s : o.segments) {
            for (int i = 0; i < (s.curve ? 3 : 2); ++i)
                b.extend(Point3{s.x[i], s.y[i], 0});
        }
    }
    if (b.empty()) b.extend(Point3{0, 0, 0});
    b.lo.z = std::min(0.0, g.depth);
    b.hi.z = std::max(0.0, g.depth);
    return b;
}

PovBBox shape_pov_bbox(const Glyph& g, const CompactTransform& xf) {
    const GlyphOutline& o = *g.outline;
    // Compute_BBox: the header box (em) padded by TTF_Tolerance in z, kept in single
    // precision, then its corners through the transform (Recompute_BBox).
    const PovBBox local = pov_bbox(Bounds3{{o.xmin, o.ymin, -kGlyphTolerance},
                                           {o.xmax, o.ymax, g.depth + kGlyphTolerance}});
    return pov_transformed_bbox(pov_bbox_bounds(local), xf);
}

bool shape_oracle_first(const Glyph& g, const OracleRay& r, OracleBest& best) {
    // POV-Ray's rule in 50 digits: the same caps and sides with its absolute thresholds
    // on the unnormalised direction (they decide which near-parallel and near-tangent
    // crossings exist), each crossing solved exactly; containment in double at the
    // high-precision points.
    const GlyphOutline& outline = *g.outline;
    const HP eps = kPovEpsilon;
    const V3 D = r.d * (HP(1) / r.world_per_object);  // the tracer's object direction
    // World parameters become object distances along the unit direction.
    auto offer = [&](const HP& t_world) {
        if (t_world > HP(kGlyphTolerance)) best.offer(t_world / r.world_per_object, 0);
    };
    const HP depth = g.depth;
    if (abs(D.z) >= eps) {
        for (const HP& z : {HP(0), depth}) {
            const HP t = (z - r.o.z) / D.z;
            const V3 p = r.o + D * t;
            if (t > 0 && inside_glyph_outline(outline, double(p.x), double(p.y)))
                offer(t);
        }
    }
    const bool use_x = abs(D.x) >= eps;
    if (!use_x && abs(D.y) < eps) return true;
    auto offer_side = [&](const HP& t) {
        const HP z = r.o.z + D.z * t;
        if (z >= 0 && z <= depth) offer(t);
    };
    const HP a = D.y, b = -D.x, c = r.o.y * D.x - r.o.x * D.y;
    for (const GlyphSegment& s : outline.segments) {
        const HP x0 = s.x[0], y0 = s.y[0];
        if (!s.curve) {
            const HP d0 = HP(s.x[1]) - x0, d1 = HP(s.y[1]) - y0;
            const HP den = d1 * D.x - d0 * D.y;
            if (abs(den) < eps) continue;
            const HP u = (D.x * (r.o.y - y0) - D.y * (r.o.x - x0)) / den;
            if (u < 0 || u > 1) continue;
            offer_side(use_x ? (x0 + u * d0 - r.o.x) / D.x : (y0 + u * d1 - r.o.y) / D.y);
            continue;
        }
        const HP x1 = s.x[1], y1 = s.y[1], x2 = s.x[2], y2 = s.y[2];
        const HP X2 = x0 - 2 * x1 + x2, X1 = 2 * (x1 - x0);
        const HP Y2 = y0 - 2 * y1 + y2, Y1 = 2 * (y1 - y0);
        const HP A = a * X2 + b * Y2, B = a * X1 + b * Y1, C = a * x0 + b * y0 + c;
        HP us[2];
        int k = 0;
        if (abs(A) < HP(1e-20)) {
            if (abs(B) >= HP(1e-20)) us[k++] = -C / B;
        } else {
            const HP disc = B * B - 4 * A * C;
            if (disc >= eps) {
                const HP sq = sqrt(disc);
                us[k++] = (-B + sq) / (2 * A);
                us[k++] = (-B - sq) / (2 * A);
            }
        }
        for (int j = 0; j < k; ++j) {
            const HP& u = us[j];
            if (u < 0 || u > 1) continue;
            offer_side(use_x ? ((X2 * u + X1) * u + x0 - r.o.x) / D.x
                             : ((Y2 * u + Y1) * u + y0 - r.o.y) / D.y);
        }
    }
    return true;
}

}  // namespace povwall::trace
