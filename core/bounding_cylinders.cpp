// POV-Ray's bounding cylinders of lathe and sor segments (scene.h).
#include "core/scene.h"

namespace povwall {

namespace {

// The index of `v` in `list` (exact equality), appended when new.
uint32_t index_of(std::vector<Real>& list, Real v) {
    for (size_t i = 0; i < list.size(); ++i)
        if (list[i] == v) return uint32_t(i);
    list.push_back(v);
    return uint32_t(list.size() - 1);
}

}  // namespace

BoundingCylinders make_bounding_cylinders(const std::vector<Real>& r1,
                                          const std::vector<Real>& r2,
                                          const std::vector<Real>& h1,
                                          const std::vector<Real>& h2) {
    BoundingCylinders b;
    std::vector<Real> radii;
    for (size_t i = 0; i < r1.size(); ++i) {
        BoundingCylinders::Segment s;
        s.r1 = index_of(radii, r1[i]);
        s.r2 = index_of(radii, r2[i]);
        s.h1 = index_of(b.heights, h1[i]);
        s.h2 = index_of(b.heights, h2[i]);
        b.segments.push_back(s);
    }
    // Squared as POV-Ray stores them: a negative lathe radius becomes a positive one.
    for (Real r : radii) b.radii2.push_back(r * r);
    return b;
}

}  // namespace povwall
