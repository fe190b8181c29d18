#include "distrib/virtual_walls.h"

#include <algorithm>

namespace povwall::distrib {

VirtualWalls::VirtualWalls(std::array<std::vector<Real>, 3> walls)
    : walls_(std::move(walls)) {
    for (int a = 0; a < 3; ++a) {
        std::sort(walls_[a].begin(), walls_[a].end());
        walls_[a].erase(std::unique(walls_[a].begin(), walls_[a].end()), walls_[a].end());
        slabs_[a] = int(walls_[a].size()) + 1;
    }
}

VirtualWalls VirtualWalls::uniform(const Bounds3& scene, int nx, int ny, int nz) {
    std::array<std::vector<Real>, 3> walls;
    const int n[3] = {nx, ny, nz};
    for (int a = 0; a < 3; ++a) {
        if (scene.empty() || std::isinf(scene.lo[a]) || std::isinf(scene.hi[a])) continue;
        for (int i = 1; i < n[a]; ++i) {
            walls[a].push_back(scene.lo[a] + (scene.hi[a] - scene.lo[a]) * i / n[a]);
        }
    }
    return VirtualWalls(std::move(walls));
}

VirtualWalls VirtualWalls::balanced(std::span<const Bounds3> primitives, int nx, int ny,
                                    int nz) {
    return balanced(sorted_centres(primitives), nx, ny, nz);
}

std::array<std::vector<Real>, 3> VirtualWalls::sorted_centres(
    std::span<const Bounds3> primitives) {
    std::array<std::vector<Real>, 3> centres;
    for (int a = 0; a < 3; ++a) {
        for (const Bounds3& b : primitives) {
            if (!b.empty() && !b.infinite())
                centres[a].push_back((b.lo[a] + b.hi[a]) * 0.5);
        }
        std::sort(centres[a].begin(), centres[a].end());
    }
    return centres;
}

VirtualWalls VirtualWalls::balanced(
    const std::array<std::vector<Real>, 3>& sorted_centres, int nx, int ny, int nz) {
    std::array<std::vector<Real>, 3> walls;
    const int n[3] = {nx, ny, nz};
    for (int a = 0; a < 3; ++a) {
        const std::vector<Real>& centres = sorted_centres[a];
        if (centres.empty()) continue;
        for (int i = 1; i < n[a]; ++i) {
            walls[a].push_back(centres[centres.size() * size_t(i) / size_t(n[a])]);
        }
    }
    return VirtualWalls(std::move(walls));
}

std::array<int, 3> VirtualWalls::cell_of(int box) const {
    return {box % slabs_[0], (box / slabs_[0]) % slabs_[1],
            box / (slabs_[0] * slabs_[1])};
}

Bounds3 VirtualWalls::box_bounds(int box) const {
    auto cell = cell_of(box);
    Bounds3 b = Bounds3::everything();
    for (int a = 0; a < 3; ++a) {
        if (cell[a] > 0) b.lo[a] = walls_[a][cell[a] - 1];
        if (cell[a] < slabs_[a] - 1) b.hi[a] = walls_[a][cell[a]];
    }
    return b;
}

int VirtualWalls::slab_of(int axis, Real v) const {
    // upper_bound: a value equal to a wall lands on the wall's high side.
    const auto& w = walls_[axis];
    return int(std::upper_bound(w.begin(), w.end(), v) - w.begin());
}

int VirtualWalls::slab_of_directed(int axis, Real v, Real direction) const {
    const auto& w = walls_[axis];
    // Every walk starts here, three times: for the few walls of an axis a count beats a
    // binary search (it was 7 % of a 4x4x4 render).
    if (w.size() <= 16) {
        int n = 0;
        if (direction < 0) {
            for (Real x : w) n += x < v;
        } else {
            for (Real x : w) n += x <= v;
        }
        return n;
    }
    if (direction < 0) return int(std::lower_bound(w.begin(), w.end(), v) - w.begin());
    return int(std::upper_bound(w.begin(), w.end(), v) - w.begin());
}

int VirtualWalls::locate(const Point3& p) const {
    return box_index({slab_of(0, p.x), slab_of(1, p.y), slab_of(2, p.z)});
}

std::vector<int> VirtualWalls::boxes_overlapping(const Bounds3& b) const {
    std::vector<int> out;
    if (b.empty()) return out;
    std::array<int, 3> lo, hi;
    for (int a = 0; a < 3; ++a) {
        const auto& w = walls_[a];
        // Touching a wall from below counts for the box above it as well.
        lo[a] = int(std::lower_bound(w.begin(), w.end(), b.lo[a]) - w.begin());
        hi[a] = int(std::upper_bound(w.begin(), w.end(), b.hi[a]) - w.begin());
        lo[a] = std::min(lo[a], hi[a]);
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
        for (int j = lo[1]; j <= hi[1]; ++j)
            for (int i = lo[0]; i <= hi[0]; ++i) out.push_back(box_index({i, j, k}));
    return out;
}

}  // namespace povwall::distrib
