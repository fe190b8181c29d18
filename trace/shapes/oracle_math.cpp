#include "trace/shapes/oracle_math.h"

#include "trace/shapes/common.h"

namespace povwall::trace {

HP dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(const V3& a, const V3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

void oracle_quadratic(const HP& a, const HP& b, const HP& c, OracleBest& best, Real tol,
                      const std::function<bool(const HP&)>& keep) {
    if (a == 0) {
        if (b != 0 && keep(-c / b)) best.offer(-c / b, tol);
        return;
    }
    HP disc = b * b - 4 * a * c;
    if (disc < 0) return;
    HP s = sqrt(disc);
    for (HP r : {(-b - s) / (2 * a), (-b + s) / (2 * a)}) {
        if (keep(r)) best.offer(r, tol);
    }
}

void oracle_triangle(const V3 p[3], const OracleRay& r, OracleBest& best) {
    V3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    V3 pv = cross(r.d, e2);
    HP det = dot(e1, pv);
    if (det == 0) return;
    V3 tv = r.o - p[0];
    HP u = dot(tv, pv) / det;
    if (u < 0 || u > 1) return;
    V3 qv = cross(tv, e1);
    HP v = dot(r.d, qv) / det;
    if (v < 0 || u + v > 1) return;
    best.offer(dot(e2, qv) / det, kTriangleTolerance);
}

HP oracle_axis_frame(const V3& base, const V3& cap, V3& axis) {
    V3 a = cap - base;
    HP l = sqrt(dot(a, a));
    axis = l > 0 ? a * (HP(1) / l) : V3(HP(0), HP(1), HP(0));
    return l;
}

}  // namespace povwall::trace
