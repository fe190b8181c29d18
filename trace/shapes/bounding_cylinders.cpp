#include "trace/shapes/bounding_cylinders.h"

#include <algorithm>
#include <cmath>

namespace povwall::trace {

namespace {

// The ray's crossings of one plane (n = 1) or cylinder (n = 2): distances and, for a
// plane, the squared radius there, for a cylinder the height.
struct ElementHits {
    int n;
    Real d[2], w[2];
};

}  // namespace

void bounding_cylinder_intervals(const BoundingCylinders& b, const Point3& p,
                                 const Vector3& d, std::vector<SegmentInterval>& out) {
    out.clear();
    // Scratch kept per thread: no allocation per ray once grown.
    thread_local std::vector<ElementHits> planes, cylinders;
    planes.resize(b.heights.size());
    cylinders.resize(b.radii2.size());
    const Real a = d.x * d.x + d.z * d.z;
    const Real bb = p.x * d.x + p.z * d.z;
    const Real c = p.x * p.x + p.z * p.z;
    const bool crosses_planes = d.y < -kPovEpsilon || d.y > kPovEpsilon;
    for (size_t i = 0; i < b.heights.size(); ++i) {
        planes[i].n = 0;
        if (!crosses_planes) continue;
        const Real k = (b.heights[i] - p.y) / d.y;
        planes[i] = {1, {k, 0}, {k * (a * k + 2.0 * bb) + c, 0}};
    }
    for (size_t i = 0; i < b.radii2.size(); ++i) {
        cylinders[i].n = 0;
        if (!(b.radii2[i] > kPovEpsilon)) continue;
        Real disc = bb * bb - a * (c - b.radii2[i]);
        if (!(disc > 0)) continue;
        disc = std::sqrt(disc);
        const Real k0 = (-bb + disc) / a, k1 = (-bb - disc) / a;
        cylinders[i] = {2, {k0, k1}, {p.y + k0 * d.y, p.y + k1 * d.y}};
    }
    for (uint32_t s = 0; s < b.segments.size(); ++s) {
        const BoundingCylinders::Segment& e = b.segments[s];
        const Real r1 = b.radii2[e.r1], r2 = b.radii2[e.r2];
        const Real h1 = b.heights[e.h1], h2 = b.heights[e.h2];
        Real dist[6];
        int n = 0;
        for (uint32_t h : {e.h2, e.h1}) {
            const ElementHits& pl = planes[h];
            if (pl.n && pl.w[0] >= r1 && pl.w[0] <= r2) dist[n++] = pl.d[0];
        }
        for (uint32_t r : {e.r1, e.r2}) {
            const ElementHits& cy = cylinders[r];
            if (!cy.n) continue;
            for (int j = 0; j < 2; ++j)
                if (cy.w[j] >= h1 && cy.w[j] <= h2) dist[n++] = cy.d[j];
        }
        for (int i = 1; i < n; ++i)  // at most 6: insertion sort
            for (int j = i; j > 0 && dist[j] < dist[j - 1]; --j)
                std::swap(dist[j], dist[j - 1]);
        // Where the ray enters: an even count gives entry and exit pairs; the first
        // pair ahead (0 when the ray starts inside it). Any other count: the first.
        Real entry;
        if (n == 0) continue;
        if (n == 2 || n == 4) {
            if (dist[0] > kPovEpsilon)
                entry = dist[0];
            else if (dist[1] > kPovEpsilon)
                entry = 0;
            else if (n == 4 && dist[2] > kPovEpsilon)
                entry = dist[2];
            else if (n == 4 && dist[3] > kPovEpsilon)
                entry = 0;
            else
                continue;
        } else {
            entry = dist[0];
        }
        auto at = std::find_if(out.begin(), out.end(), [&](const SegmentInterval& x) {
            return !(entry > x.entry);
        });
        out.insert(at, {entry, s});
    }
}

}  // namespace povwall::trace
