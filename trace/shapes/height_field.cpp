#include "trace/shapes/height_field.h"

#include <algorithm>
#include <cmath>

#include "core/math_constants.h"
#include "trace/pov_bounds.h"
#include "trace/shapes/oracle_math.h"
#include "trace/shapes/sort_hits.h"

namespace povwall::trace {
namespace {

constexpr Real kStartTolerance = 1e-6;  // HFIELD_TOLERANCE: the nearest depth tried
constexpr Real kSnap = 0.001;           // HFIELD_OFFSET: how far a block entry may miss
constexpr Real kEdge = 1e-4;            // a triangle's (s, u) margin
constexpr Real kBoxClose = 1e-6;        // Box::Intersect's CLOSE_TOLERANCE

Real sign_of(Real v) { return v >= 0 ? 1.0 : -1.0; }

// Box::Intersect without a transform (its slab order and close tolerance): the depths
// where the ray enters and leaves the field's box, the entry at least 0.
bool box_depths(const HeightFieldData& d, const Point3& P, const Vector3& D, Real& tmin,
                Real& tmax) {
    const Real lo[3] = {0, d.floor_y, 0};
    const Real hi[3] = {Real(d.width - 1), d.top_y, Real(d.depth - 1)};
    tmin = 0;
    tmax = kBoundHuge;
    for (int a = 0; a < 3; ++a) {
        const Real close = a == 0 ? 0 : kBoxClose;
        if (D[a] < -kPovEpsilon || D[a] > kPovEpsilon) {
            const bool down = D[a] < 0;
            Real t = ((down ? lo[a] : hi[a]) - P[a]) / D[a];
            if (t < tmin) return false;
            if (t <= tmax - close) tmax = t;
            t = ((down ? hi[a] : lo[a]) - P[a]) / D[a];
            if (t >= tmin + close) {
                if (t > tmax) return false;
                tmin = t;
            }
        } else if (P[a] < lo[a] || P[a] > hi[a]) {
            return false;
        }
    }
    return tmax >= kStartTolerance;
}

// One ray through the grid, in POV-Ray's order: blocks, then cells by a DDA. A field
// outside CSG stops at the first cell that yields a hit (IS_CHILD_OBJECT unset).
class Walk {
  public:
    Walk(const HeightFieldData& d, const LocalRay& r, Real mindist, Real maxdist,
         ShapeHits& out)
        : d_(d),
          O_(r.origin),
          D_(r.direction),
          mindist_(mindist),
          maxdist_(maxdist),
          all_(r.csg_child),
          out_(out) {}

    // The cell (x, z) for ray heights in [y1, y2]: its two triangles.
    bool cell(int x, int z, Real y1, Real y2) {
        x = std::min(x, d_.max_x);
        z = std::min(z, d_.max_z);
        const Real h1 = d_.at(x, z), h2 = d_.at(x + 1, z), h3 = d_.at(x, z + 1),
                   h4 = d_.at(x + 1, z + 1);
        const Real lo23 = std::min(h2, h3), hi23 = std::max(h2, h3);
        if (std::max(std::max(h1, h4), hi23) < y1 ||
            std::min(std::min(h1, h4), lo23) > y2)
            return false;
        bool found = false;
        if (std::max(h1, hi23) >= y1 && std::min(h1, lo23) <= y2) {
            const Vector3 N{h1 - h2, 1, h1 - h3};
            const Point3 P0{Real(x), h1, Real(z)};
            Real t;
            if (plane_depth(N, P0, t)) {
                const Real s = O_.x + t * D_.x - Real(x), u = O_.z + t * D_.z - Real(z);
                if (s >= -kEdge && u >= -kEdge && s + u <= 1 + kEdge) {
                    push(t, kHeightFieldLower, x, z);
                    found = true;
                }
            }
        }
        if (std::max(h4, hi23) >= y1 && std::min(h4, lo23) <= y2) {
            const Vector3 N{h3 - h4, 1, h2 - h4};
            const Point3 P0{Real(x + 1), h4, Real(z + 1)};
            Real t;
            if (plane_depth(N, P0, t)) {
                const Real s = O_.x + t * D_.x - Real(x), u = O_.z + t * D_.z - Real(z);
                if (s <= 1 + kEdge && u <= 1 + kEdge && s + u >= 1 - kEdge) {
                    push(t, kHeightFieldUpper, x, z);
                    found = true;
                }
            }
        }
        return found;
    }

    // The DDA over one block's cells from `start` (its entry point); true when a cell
    // hit.
    bool dda(const Point3& start, const HeightFieldBlock& b) {
        Real px = start.x, pz = start.z;
        const int xmin = b.xmin, xmax = std::min(b.xmax + 1, d_.max_x);
        const int zmin = b.zmin, zmax = std::min(b.zmax + 1, d_.max_z);
        const Real ymin = std::min(start.y, b.ymin) - kPovEpsilon;
        const Real ymax = std::max(start.y, b.ymax) + kPovEpsilon;
        // An entry just outside the block (round-off) is moved in; farther off, the block
        // is skipped.
        auto snap = [](Real& p, int lo, int hi) {
            if (p < Real(lo)) {
                if (p < Real(lo) - kSnap) return false;
                p = Real(lo);
            } else if (p > Real(hi) + 1.0 - kPovEpsilon) {
                if (p > Real(hi) + 1.0 + kPovEpsilon) return false;
                p = Real(hi) + 1.0 - kPovEpsilon;
            }
            return true;
        };
        if (!snap(px, xmin, xmax) || !snap(pz, zmin, zmax)) return false;
        const bool x_drives = std::fabs(D_.x) >= std::fabs(D_.z);
        // In the driving axis's terms: a (driving) and c (crossing).
        const Real da = x_drives ? D_.x : D_.z, dc = x_drives ? D_.z : D_.x;
        const Real pa = x_drives ? px : pz, pc = x_drives ? pz : px;
        const int amin = x_drives ? xmin : zmin, amax = x_drives ? xmax : zmax;
        const int cmin = x_drives ? zmin : xmin, cmax = x_drives ? zmax : xmax;
        const Real delta = std::fabs(dc / da);
        int a = int(pa), c = int(pc);
        const Real a0 = pa - std::floor(pa), c0 = pc - std::floor(pc);
        const int sa = int(sign_of(da)), sc = int(sign_of(dc));
        const Real ea = da >= 0 ? 1.0 - a0 : a0;
        Real error = dc >= 0 ? c0 + delta * ea - 1.0 : -(c0 - delta * ea);
        const Real deltay = D_.y / std::fabs(da);
        Real neary = start.y - (da >= 0 ? a0 : 1.0 - a0) * deltay;
        Real fary = neary + deltay;
        // The z-driven loop widens its height test once more (as POV-Ray's).
        const Real slack = x_drives ? 0 : kPovEpsilon;
        bool found = false;
        auto test = [&](int ia, int ic, Real y1, Real y2) {
            return x_drives ? cell(ia, ic, y1, y2) : cell(ic, ia, y1, y2);
        };
        do {
            const Real y1 = std::min(neary, fary), y2 = std::max(neary, fary);
            if (test(a, c, y1, y2)) {
                if (!all_) return true;
                found = true;
            }
            if (error > kPovEpsilon) {
                c += sc;
                if (c < cmin || c > cmax) break;
                if (test(a, c, y1, y2)) {
                    if (!all_) return true;
                    found = true;
                }
                error -= 1;
            } else if (error > -kPovEpsilon) {
                c += sc;
                error -= 1;
            }
            a += sa;
            error += delta;
            neary = fary;
            fary += deltay;
        } while (neary >= ymin - slack && neary <= ymax + slack && a >= amin &&
                 a <= amax && c >= cmin && c <= cmax);
        return found;
    }

    // The walk over the block grid from `start`.
    bool blocks(const Point3& start) {
        const Real ymin = Real(d_.min_height) - kPovEpsilon;
        const Real ymax = Real(d_.max_height) + kPovEpsilon;
        const bool dx_zero = std::fabs(D_.x) < kPovEpsilon,
                   dz_zero = std::fabs(D_.z) < kPovEpsilon;
        const int sx = int(sign_of(D_.x)), sz = int(sign_of(D_.z));
        // Signed, as POV-Ray's (it can be negative).
        const Real maxdv = D_.x > D_.z ? D_.x : D_.z;
        int x = int(start.x / Real(d_.block_width_x));
        int z = int(start.z / Real(d_.block_width_z));
        Point3 near_p = start;
        Real neary = start.y;
        bool found = false;
        do {
            const HeightFieldBlock& b = d_.block(x, z);
            const Real k1 =
                dx_zero ? kBoundHuge
                        : ((sx >= 0 ? Real(b.xmax) + 1.0 : Real(b.xmin)) - O_.x) / D_.x;
            const Real k2 =
                dz_zero ? kBoundHuge
                        : ((sz >= 0 ? Real(b.zmax) + 1.0 : Real(b.zmin)) - O_.z) / D_.z;
            Real dist;
            int nx, nz;
            if (dz_zero || (!dx_zero && k1 < k2 - kPovEpsilon / maxdv && k1 > 0)) {
                dist = k1;
                nx = x + sx;
                nz = z;
            } else if (dz_zero || (!dx_zero && k1 < k2 + kPovEpsilon / maxdv && k1 > 0)) {
                dist = k1;
                nx = x + sx;
                nz = z + sz;
            } else {
                dist = k2;
                nx = x;
                nz = z + sz;
            }
            const Point3 far_p = O_ + D_ * dist;
            const Real y1 = std::min(neary, far_p.y), y2 = std::max(neary, far_p.y);
            if (y1 <= b.ymax + kPovEpsilon && y2 >= b.ymin - kPovEpsilon &&
                dda(near_p, b)) {
                if (!all_) return true;
                found = true;
            }
            x = nx;
            z = nz;
            near_p = far_p;
            neary = far_p.y;
        } while (x >= 0 && x < d_.blocks_x && z >= 0 && z < d_.blocks_z &&
                 neary >= ymin && neary <= ymax);
        return found;
    }

  private:
    // The ray's depth on a triangle's plane (normal N through P0), within the box's
    // depths; false for a ray nearly parallel to it.
    bool plane_depth(const Vector3& N, const Point3& P0, Real& t) const {
        const Real dot_nd = dot(N, D_);
        if (!(dot_nd > kPovEpsilon || dot_nd < -kPovEpsilon)) return false;
        t = dot(N, P0 - O_) / dot_nd;
        return t >= mindist_ && t <= maxdist_;
    }

    void push(Real t, int face, int x, int z) {
        ShapeHit h{t, O_ + D_ * t, face};
        h.param = Real(x);
        h.param2 = Real(z);
        out_.push_back(h);
    }

    const HeightFieldData& d_;
    Point3 O_;
    Vector3 D_;
    Real mindist_, maxdist_;
    bool all_;
    ShapeHits& out_;
};

// The triangle's normal of the cell (x, z): POV-Ray's, unnormalised.
Vector3 triangle_normal(const HeightFieldData& d, int face, int x, int z) {
    if (face == kHeightFieldLower) {
        const Real y1 = d.at(x, z);
        return {y1 - d.at(x + 1, z), 1, y1 - d.at(x, z + 1)};
    }
    const Real y1 = d.at(x + 1, z + 1);
    return {d.at(x, z + 1) - y1, 1, d.at(x + 1, z) - y1};
}

// The smooth normal at object point p: the four vertex normals of its cell, each through
// `to_world` and normalised, blended bilinearly (not normalised).
template <class ToWorld>
Vector3 blended_normal(const HeightFieldData& d, const Point3& p, ToWorld&& to_world) {
    const int px = std::min(int(p.x), d.max_x), pz = std::min(int(p.z), d.max_z);
    const Real fx = p.x - Real(px), fz = p.z - Real(pz);
    auto n = [&](int x, int z) {
        const auto& s = d.normals[size_t(z) * size_t(d.width) + size_t(x)];
        const Vector3 w = to_world(Vector3{Real(s[0]), Real(s[1]), Real(s[2])});
        return w * (1.0 / length(w));
    };
    const Vector3 n00 = n(px, pz), n10 = n(px + 1, pz), n01 = n(px, pz + 1),
                  n11 = n(px + 1, pz + 1);
    const Real u = 1.0 - fx, v = 1.0 - fz;
    Vector3 r;
    for (int a = 0; a < 3; ++a) {
        r[a] = v * (u * n00[a] + fx * n10[a]) + fz * (u * n01[a] + fx * n11[a]);
    }
    return r;
}

}  // namespace

void shape_hits(const HeightField& h, const LocalRay& r, ShapeHits& out) {
    const HeightFieldData& d = *h.data;
    const Point3& O = r.origin;
    const Vector3& D = r.direction;
    Real depth1, depth2;
    if (!box_depths(d, O, D, depth1, depth2)) return;
    if (depth1 < kStartTolerance) {
        depth1 = kStartTolerance;
        if (depth1 > depth2) return;
    }
    const size_t first = out.size();
    const Point3 start = O + D * depth1;
    Walk walk(d, r, depth1, depth2, out);
    if (std::fabs(D.x) < kPovEpsilon && std::fabs(D.z) < kPovEpsilon) {
        // A vertical ray: its one cell, over all heights ahead.
        const Real fary = D.y >= 0 ? 65536.0 : 0.0;
        walk.cell(int(start.x), int(start.z), std::min(start.y, fary),
                  std::max(start.y, fary));
    } else if (d.blocks_x <= 1 && d.blocks_z <= 1) {
        walk.dda(start, d.blocks[0]);
    } else {
        walk.blocks(start);
    }
    stable_sort_by_depth(out, first);
}

Vector3 shape_normal(const HeightField& h, const ShapeHit& hit) {
    const HeightFieldData& d = *h.data;
    if (!d.normals.empty())
        return blended_normal(d, hit.p, [](const Vector3& v) { return v; });
    return triangle_normal(d, hit.face, int(hit.param), int(hit.param2));
}

Vector3 height_field_world_normal(const HeightField& h, const ShapeHit& hit,
                                  const CompactTransform& xf) {
    const HeightFieldData& d = *h.data;
    if (d.normals.empty() || xf.is_identity())
        return normalize(xf.is_identity() ? shape_normal(h, hit)
                                          : xf.normal(shape_normal(h, hit)));
    return normalize(
        blended_normal(d, hit.p, [&](const Vector3& v) { return xf.normal(v); }));
}

bool shape_inside(const HeightField& h, const Point3& p) {
    const HeightFieldData& d = *h.data;
    const Real water = d.floor_y;
    if (p.x < 0 || p.x >= Real(d.width - 1) || p.z < 0 || p.z >= Real(d.depth - 1))
        return false;
    if (p.y >= d.top_y) return false;
    if (p.y < water) return true;
    int px = int(p.x), pz = int(p.z);
    const Real fx = p.x - Real(px), fz = p.z - Real(pz);
    Vector3 n;
    Real y1;
    if (fx + fz < 1.0) {
        y1 = std::max(d.at(px, pz), water);
        const Real y2 = std::max(d.at(px + 1, pz), water);
        const Real y3 = std::max(d.at(px, pz + 1), water);
        n = {y1 - y2, 1, y1 - y3};
    } else {
        px = int(std::ceil(p.x));
        pz = int(std::ceil(p.z));
        y1 = std::max(d.at(px, pz), water);
        const Real y2 = std::max(d.at(px - 1, pz), water);
        const Real y3 = std::max(d.at(px, pz - 1), water);
        n = {y2 - y1, 1, y3 - y1};
    }
    const Point3 q{Real(px), y1, Real(pz)};
    return dot(p, n) < dot(q, n);
}

Bounds3 shape_bounds(const HeightField& h) {
    const HeightFieldData& d = *h.data;
    return {{0, d.floor_y, 0}, {Real(d.width - 1), d.top_y, Real(d.depth - 1)}};
}

PovBBox shape_pov_bbox(const HeightField& h, const CompactTransform& xf) {
    // POV-Ray stores the box in single precision before it transforms it: the margin of
    // 0.001 is below the float spacing of large heights (0.0039 at 65535).
    return pov_transformed_bbox(pov_bbox_bounds(pov_bbox(shape_bounds(h))), xf);
}

bool shape_oracle_first(const HeightField& h, const OracleRay& r, OracleBest& best) {
    // Every cell's two triangles whose box the ray's line passes near (a double slab test
    // with a margin; the crossing itself in 50 digits), above the box's floor.
    const HeightFieldData& d = *h.data;
    const Point3 o{double(r.o.x), double(r.o.y), double(r.o.z)};
    const Vector3 dir{double(r.d.x), double(r.d.y), double(r.d.z)};
    for (int z = 0; z <= d.max_z; ++z) {
        for (int x = 0; x <= d.max_x; ++x) {
            const Real h1 = d.at(x, z), h2 = d.at(x + 1, z), h3 = d.at(x, z + 1),
                       h4 = d.at(x + 1, z + 1);
            const Real lo[3] = {Real(x) - 0.01, std::min({h1, h2, h3, h4}) - 0.01,
                                Real(z) - 0.01};
            const Real hi[3] = {Real(x) + 1.01, std::max({h1, h2, h3, h4}) + 0.01,
                                Real(z) + 1.01};
            Real tmin = -kBoundHuge, tmax = kBoundHuge;
            bool miss = false;
            for (int a = 0; a < 3 && !miss; ++a) {
                if (std::fabs(dir[a]) < 1e-300) {
                    miss = o[a] < lo[a] || o[a] > hi[a];
                    continue;
                }
                Real t1 = (lo[a] - o[a]) / dir[a], t2 = (hi[a] - o[a]) / dir[a];
                if (t1 > t2) std::swap(t1, t2);
                tmin = std::max(tmin, t1);
                tmax = std::min(tmax, t2);
                miss = tmin > tmax;
            }
            if (miss || tmax < 0) continue;
            const V3 a{HP(x), HP(h1), HP(z)}, b{HP(x + 1), HP(h2), HP(z)},
                c{HP(x), HP(h3), HP(z + 1)}, e{HP(x + 1), HP(h4), HP(z + 1)};
            const V3 lower[3] = {a, b, c}, upper[3] = {e, c, b};
            // Below the box's floor (a water level) the triangles are never reached.
            for (const V3* tri : {lower, upper}) {
                OracleBest one;
                one.floor = best.floor;
                oracle_triangle(tri, r, one);
                if (isfinite(one.t) && r.o.y + one.t * r.d.y >= HP(d.floor_y))
                    best.offer(one.t, 0);
            }
        }
    }
    return true;
}

}  // namespace povwall::trace
