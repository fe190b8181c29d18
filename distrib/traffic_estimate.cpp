#include "distrib/traffic_estimate.h"

#include <algorithm>
#include <cmath>

#include "trace/camera.h"
#include "trace/prepared_scene.h"
#include "trace/render_plan.h"

namespace povwall::distrib {
namespace {

// Where the finite objects are: a ray that leaves them meets nothing more.
Bounds3 finite_bounds(const Scene& scene) {
    Bounds3 world;
    for (const Object& o : scene.objects) {
        const Bounds3 b = trace::object_world_bounds(o);
        if (!b.infinite()) world.extend(b);
    }
    return world;
}

// The point where `ray` leaves `box` (slab test), or its origin when it never is inside.
Point3 exit_point(const Ray& ray, const Bounds3& box) {
    Real t_near = 0, t_far = kInfinity;
    for (int a = 0; a < 3; ++a) {
        const Real d = ray.direction[a], o = ray.origin[a];
        if (d == 0) {
            if (o < box.lo[a] || o > box.hi[a]) return ray.origin;
            continue;
        }
        Real t0 = (box.lo[a] - o) / d, t1 = (box.hi[a] - o) / d;
        if (t0 > t1) std::swap(t0, t1);
        t_near = std::max(t_near, t0);
        t_far = std::min(t_far, t1);
    }
    if (!(t_near <= t_far) || std::isinf(t_far)) return ray.origin;
    return ray.at(t_far);
}

// Whether the part of `ray` in `seg` can meet `reach`: its own bounds against it, as
// BoxHost::reaches decides (no division).
bool meets(const Bounds3& reach, const Ray& ray, const VirtualWalls::Segment& seg) {
    if (reach.empty()) return false;
    for (int a = 0; a < 3; ++a) {
        const Real p0 = ray.origin[a] + ray.direction[a] * seg.t_enter;
        const Real p1 = ray.origin[a] + ray.direction[a] * seg.t_exit;
        if (std::max(p0, p1) < reach.lo[a] || std::min(p0, p1) > reach.hi[a])
            return false;
    }
    return true;
}

}  // namespace

std::vector<PilotSegment> pilot_segments(const Scene& scene, int width, int height,
                                         int samples, int threads) {
    std::vector<PilotSegment> out;
    if (width <= 0 || height <= 0 || samples <= 0) return out;
    const trace::RenderPlan plan = trace::make_render_plan(scene);
    trace::PrepareOptions prepare;
    prepare.threads = threads;
    const trace::PreparedScene prepared(scene, &plan, prepare);
    trace::RayContext ctx;
    prepared.init_context(ctx);
    const Bounds3 world = finite_bounds(scene);
    if (world.empty()) return out;
    const bool bounce = plan.reflection_rays || plan.refraction_rays;
    const double step = std::max(1.0, std::sqrt(double(width) * height / samples));
    for (double y = step / 2; y < height; y += step) {
        for (double x = step / 2; x < width; x += step) {
            const std::optional<Ray> ray =
                trace::camera_ray(scene.camera, x, y, width, height);
            if (!ray) continue;
            trace::Hit hit;
            if (!prepared.closest_hit(*ray, 0, kInfinity, trace::RayUse::Camera, hit,
                                      ctx)) {
                out.push_back({ray->origin, exit_point(*ray, world), true});
                continue;
            }
            out.push_back({ray->origin, hit.point, true});
            for (const Light& l : scene.lights)
                out.push_back({hit.point, l.location, false});
            if (!bounce) continue;
            // One mirror bounce stands for the reflected and refracted rays.
            const Vector3 d = normalize(ray->direction);
            Vector3 n = normalize(hit.normal);
            if (dot(n, d) > 0) n = -n;
            const Ray mirror{hit.point, d - n * (2 * dot(d, n))};
            trace::Hit next;
            const bool again = prepared.closest_hit(mirror, 0, kInfinity,
                                                    trace::RayUse::Reflection, next, ctx);
            out.push_back(
                {hit.point, again ? next.point : exit_point(mirror, world), false});
        }
    }
    return out;
}

std::vector<ObjectExtent> object_extents(const Scene& scene) {
    std::vector<ObjectExtent> out;
    out.reserve(scene.objects.size());
    for (const Object& o : scene.objects)
        out.push_back({trace::object_world_bounds(o), trace::object_hit_bounds(o)});
    return out;
}

uint64_t estimated_crossings(const std::vector<PilotSegment>& segments,
                             const VirtualWalls& walls,
                             const std::vector<ObjectExtent>& objects) {
    // Each box's reach, as BoxHost computes it.
    std::vector<Bounds3> reach(size_t(walls.box_count()));
    for (const ObjectExtent& o : objects) {
        for (int b : walls.boxes_overlapping(o.world)) reach[size_t(b)].extend(o.hit);
    }
    for (size_t b = 0; b < reach.size(); ++b)
        reach[b] = intersection(reach[b], walls.box_bounds(int(b)));
    uint64_t crossings = 0;
    for (const PilotSegment& s : segments) {
        const Ray ray{s.from, s.to - s.from};  // t in [0, 1]
        int met = 0;
        walls.walk(ray, 0, 1, [&](const VirtualWalls::Segment& seg) {
            met += meets(reach[size_t(seg.box)], ray, seg);
            return false;
        });
        // A secondary ray starts in the box of its hit, a camera ray in the first box it
        // meets: each box met after that one is a crossing.
        crossings += uint64_t(std::max(met - 1, 0));
    }
    return crossings;
}

std::vector<std::array<int, 3>> box_grids(int boxes) {
    std::vector<std::array<int, 3>> grids;
    for (int x = 1; x <= boxes; ++x) {
        if (boxes % x) continue;
        for (int y = 1; y <= boxes / x; ++y) {
            if ((boxes / x) % y) continue;
            grids.push_back({x, y, boxes / x / y});
        }
    }
    return grids;
}

}  // namespace povwall::distrib
