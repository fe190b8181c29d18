// Naive uniform grid, the baseline the octree has to beat on uniform sphere scenes.
#include <algorithm>

#include "bench/scene.h"

namespace povwall::bench {

void UniformGrid::build(const Spheres& s) {
    box_ = Bounds3{};
    for (size_t i = 0; i < s.size(); ++i) box_.extend(s.bounds(i));
    const Vector3 d = box_.diagonal();
    // About one cell per sphere, cells as cubic as the box allows.
    const Real cell = std::cbrt(d.x * d.y * d.z / Real(std::max<size_t>(s.size(), 1)));
    for (int a = 0; a < 3; ++a) res_[a] = std::clamp(int(d[a] / cell), 1, 512);
    cell_ = {d.x / res_[0], d.y / res_[1], d.z / res_[2]};
    const size_t cells = size_t(res_[0]) * res_[1] * res_[2];
    std::vector<std::vector<uint32_t>> lists(cells);
    auto index = [&](Real v, int a) {
        return std::clamp(int((v - box_.lo[a]) / cell_[a]), 0, res_[a] - 1);
    };
    for (uint32_t i = 0; i < s.size(); ++i) {
        Bounds3 b = s.bounds(i);
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) lo[a] = index(b.lo[a], a), hi[a] = index(b.hi[a], a);
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x)
                    lists[(size_t(z) * res_[1] + y) * res_[0] + x].push_back(i);
    }
    start_.assign(cells + 1, 0);
    ids_.clear();
    for (size_t c = 0; c < cells; ++c) {
        start_[c] = uint32_t(ids_.size());
        ids_.insert(ids_.end(), lists[c].begin(), lists[c].end());
    }
    start_[cells] = uint32_t(ids_.size());
}

Real UniformGrid::closest(const Spheres& s, const Ray& ray, octree::Mailbox& mb,
                          uint64_t& tests) const {
    Real best = kInfinity;
    // Clip the ray to the grid box.
    Real t0 = 0, t1 = kInfinity;
    for (int a = 0; a < 3; ++a) {
        Real inv = 1 / ray.direction[a];
        Real ta = (box_.lo[a] - ray.origin[a]) * inv,
             tb = (box_.hi[a] - ray.origin[a]) * inv;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (!(t0 <= t1)) return best;
    mb.next_ray();
    const Point3 p = ray.at(t0);
    int c[3], step[3], end[3];
    Real t_next[3], t_delta[3];
    for (int a = 0; a < 3; ++a) {
        c[a] = std::clamp(int((p[a] - box_.lo[a]) / cell_[a]), 0, res_[a] - 1);
        Real d = ray.direction[a];
        if (d > 0) {
            step[a] = 1, end[a] = res_[a];
            t_next[a] = (box_.lo[a] + (c[a] + 1) * cell_[a] - ray.origin[a]) / d;
            t_delta[a] = cell_[a] / d;
        } else if (d < 0) {
            step[a] = -1, end[a] = -1;
            t_next[a] = (box_.lo[a] + c[a] * cell_[a] - ray.origin[a]) / d;
            t_delta[a] = -cell_[a] / d;
        } else {
            step[a] = 0, end[a] = -2;
            t_next[a] = kInfinity;
            t_delta[a] = kInfinity;
        }
    }
    for (;;) {
        const size_t cell = (size_t(c[2]) * res_[1] + c[1]) * res_[0] + c[0];
        for (uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
            uint32_t id = ids_[k];
            if (!mb.first_visit(id)) continue;
            ++tests;
            hit_sphere(s, id, ray, best);
        }
        int a = t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2)
                                      : (t_next[1] < t_next[2] ? 1 : 2);
        if (best <= t_next[a]) break;  // the hit lies in a cell already visited
        c[a] += step[a];
        if (c[a] == end[a]) break;
        t_next[a] += t_delta[a];
    }
    return best;
}

}  // namespace povwall::bench
