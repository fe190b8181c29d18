// Virtual walls: axis-parallel planes cutting space into a grid of black boxes.
//
// Only interior walls are stored; the outermost boxes extend to infinity, so every point
// of space belongs to exactly one box and infinite objects (planes) simply touch many
// boxes. A point lying exactly on a wall belongs to the box on the wall's high side; a
// ray walk starting on a wall starts in the box it moves into, so routing is
// deterministic for rays on walls or along axes, and a ray forwarded at a wall never
// bounces back.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "core/math.h"

namespace povwall::distrib {

class VirtualWalls {
  public:
    VirtualWalls() = default;
    // `walls[axis]` must be sorted ascending; each list of k walls makes k+1 slabs.
    explicit VirtualWalls(std::array<std::vector<Real>, 3> walls);

    // nx*ny*nz equal slabs of `scene` (the outer slabs extend to infinity).
    static VirtualWalls uniform(const Bounds3& scene, int nx, int ny, int nz);
    // Walls at quantiles of primitive centres along each axis, so that each slab holds
    // about the same number of primitives (the cost estimate used for adaptive walls).
    static VirtualWalls balanced(std::span<const Bounds3> primitives, int nx, int ny,
                                 int nz);
    // The same from the primitives' centres per axis, sorted (sorted_centres): sorted
    // once for several sets of walls.
    static std::array<std::vector<Real>, 3> sorted_centres(
        std::span<const Bounds3> primitives);
    static VirtualWalls balanced(const std::array<std::vector<Real>, 3>& sorted_centres,
                                 int nx, int ny, int nz);

    int box_count() const { return slabs_[0] * slabs_[1] * slabs_[2]; }
    std::array<int, 3> slabs() const { return slabs_; }
    const std::vector<Real>& walls(int axis) const { return walls_[axis]; }
    int box_index(std::array<int, 3> cell) const {
        return (cell[2] * slabs_[1] + cell[1]) * slabs_[0] + cell[0];
    }
    std::array<int, 3> cell_of(int box) const;
    // The box's region; outer faces are infinite.
    Bounds3 box_bounds(int box) const;
    int locate(const Point3& p) const;
    // Boxes whose region overlaps `b` (closed intervals: touching counts).
    std::vector<int> boxes_overlapping(const Bounds3& b) const;

    struct Segment {
        int box;
        Real t_enter, t_exit;  // the ray is inside `box` for t in [t_enter, t_exit]
    };
    // Calls visit(segment) for each box the ray crosses for t in [t_min, t_max], in
    // order; stops early when visit returns true. NaN directions visit nothing.
    template <class Visit>
    void walk(const Ray& ray, Real t_min, Real t_max, Visit&& visit) const;

    // Where a walk stands: at the start of the segment in `cell`, with the distance to
    // the next wall along each axis. A walk stopped by its visitor can be continued
    // later (in another box) from here, with no new search of the walls.
    struct WalkState {
        std::array<int, 3> cell{};
        Real wall_t[3] = {};
        Real t = 0;
    };
    // False for a ray that visits nothing (NaN, or t_min > t_max).
    bool start_walk(const Ray& ray, Real t_min, Real t_max, WalkState& at) const;
    // As walk() from `at`; when visit returns true, `at` stays at the visited segment.
    template <class Visit>
    void continue_walk(const Ray& ray, WalkState& at, Real t_max, Visit&& visit) const;

  private:
    int slab_of(int axis, Real v) const;
    int slab_of_directed(int axis, Real v, Real direction) const;
    Real next_wall(const Ray& ray, const std::array<int, 3>& cell, int axis) const;
    std::array<std::vector<Real>, 3> walls_;
    std::array<int, 3> slabs_{1, 1, 1};
};

inline bool VirtualWalls::start_walk(const Ray& ray, Real t_min, Real t_max,
                                     WalkState& at) const {
    if (!(t_min <= t_max)) return false;
    const Point3 start = ray.at(t_min);
    for (int a = 0; a < 3; ++a) {
        if (std::isnan(start[a]) || std::isnan(ray.direction[a])) return false;
    }
    // A start exactly on a wall belongs to the side the ray moves into, so a ray
    // forwarded at a wall never bounces back to the box it left.
    at.cell = {slab_of_directed(0, start.x, ray.direction.x),
               slab_of_directed(1, start.y, ray.direction.y),
               slab_of_directed(2, start.z, ray.direction.z)};
    for (int a = 0; a < 3; ++a) at.wall_t[a] = next_wall(ray, at.cell, a);
    at.t = t_min;
    return true;
}

// Distance to the next wall along `axis` in the direction of travel from `cell` (the
// same expression every time, so every box that walks this ray gets the same distances).
inline Real VirtualWalls::next_wall(const Ray& ray, const std::array<int, 3>& cell,
                                    int axis) const {
    const Real d = ray.direction[axis];
    if (d > 0 && cell[axis] < slabs_[axis] - 1)
        return (walls_[axis][cell[axis]] - ray.origin[axis]) / d;
    if (d < 0 && cell[axis] > 0)
        return (walls_[axis][cell[axis] - 1] - ray.origin[axis]) / d;
    return kInfinity;
}

template <class Visit>
void VirtualWalls::continue_walk(const Ray& ray, WalkState& at, Real t_max,
                                 Visit&& visit) const {
    for (;;) {
        const Real t_next = std::min(std::min(at.wall_t[0], at.wall_t[1]), at.wall_t[2]);
        Real t_exit = std::min(std::max(t_next, at.t), t_max);
        // A start rounded onto the near side of a wall gives an empty segment: step over
        // it without visiting, the same way whichever box computes the walk.
        if (t_next > at.t || t_next >= t_max) {
            if (visit(Segment{box_index(at.cell), at.t, t_exit})) return;
        }
        if (t_next >= t_max) return;
        // Step every axis whose wall lies at t_next (corners and edges cross at once).
        for (int a = 0; a < 3; ++a) {
            if (at.wall_t[a] != t_next) continue;
            at.cell[a] += ray.direction[a] > 0 ? 1 : -1;
            at.wall_t[a] = next_wall(ray, at.cell, a);
        }
        at.t = std::max(t_next, at.t);
    }
}

template <class Visit>
void VirtualWalls::walk(const Ray& ray, Real t_min, Real t_max, Visit&& visit) const {
    WalkState at;
    if (start_walk(ray, t_min, t_max, at)) continue_walk(ray, at, t_max, visit);
}

}  // namespace povwall::distrib
