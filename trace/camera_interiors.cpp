#include "trace/camera_interiors.h"

#include <algorithm>
#include <cmath>

#include "core/mesh_camera.h"
#include "trace/object_inside.h"
#include "trace/pov_bounds.h"
#include "trace/prepared_scene.h"

namespace povwall::trace {
namespace {

bool contains(const Bounds3& b, const Point3& p) {
    return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y &&
           p.z >= b.lo.z && p.z <= b.hi.z;
}

}  // namespace

CameraInteriors::CameraInteriors(const Scene& scene) {
    const Camera& cam = scene.camera;
    using Kind = Camera::Kind;
    // Where camera rays start: the location, or the image rectangle (orthographic) or
    // line (cylinder 3, 4) around it. Bounds of these, to sort the candidates out.
    Bounds3 origins;
    origins.extend(cam.location);
    per_ray_ = cam.kind == Kind::Orthographic || cam.kind == Kind::Cylinder3 ||
               cam.kind == Kind::Cylinder4;
    if (per_ray_) {
        const Vector3 up = cam.kind == Kind::Cylinder4 ? Vector3{0, 0, 0} : cam.up * 0.5;
        const Vector3 right =
            cam.kind == Kind::Cylinder3 ? Vector3{0, 0, 0} : cam.right * 0.5;
        for (int sx = -1; sx <= 1; sx += 2)
            for (int sy = -1; sy <= 1; sy += 2)
                origins.extend(cam.location + right * Real(sx) + up * Real(sy));
    }
    if (cam.kind == Kind::Mesh) {
        // From the faces (moved along their unit normals by location.z), each ray its
        // own. POV-Ray takes the interiors of the first ray's start for all: the same
        // while the faces lie in the same objects.
        per_ray_ = true;
        for (const MeshCamera::Part& part : cam.mesh->meshes) {
            Bounds3 b;
            Real longest = 1;  // smooth normals need not be unit
            for (const MeshCamera::Face& f : part.faces) {
                for (const Point3& p : f.p) b.extend(p);
                for (const Vector3& n : f.n) longest = std::max(longest, length(n));
            }
            if (b.empty()) continue;
            const Real reach = std::fabs(cam.location.z) * longest;
            b.lo -= Vector3(reach);
            b.hi += Vector3(reach);
            origins.extend(part.transform.bounds(b));
        }
    }
    if (cam.aperture != 0 && cam.blur_samples > 0) {
        // Focal blur starts rays at points of the aperture around the location (within
        // its radius times 1 + the jitter, well inside this cube).
        per_ray_ = true;
        const Real reach = std::fabs(cam.aperture) * 2;
        origins.extend(cam.location + Vector3{reach, reach, reach});
        origins.extend(cam.location - Vector3{reach, reach, reach});
    }
    for (const Object& o : scene.objects) collect(o, origins);
    materials_.reserve(candidates_.size());
    for (const Object* o : candidates_) materials_.push_back(material_of(*o, o->texture));
    if (!per_ray_) fill(cam.location, fixed_);
}

// POV-Ray's top-level objects after it splits plain unions (not clipped, bounded,
// inverted or a merge) into their children, recursively.
void CameraInteriors::collect(const Object& o, const Bounds3& origins) {
    if (pov_splits_union(o)) {
        for (const Object& c : std::get<Csg>(o.shape).children) collect(c, origins);
        return;
    }
    if (intersection(object_world_bounds(o), origins).empty()) return;
    candidates_.push_back(&o);
    // POV-Ray tests its own (float) box of the object: an inverted shape keeps its
    // finite box, so a camera outside that box is not inside the inverted shape.
    bounds_.push_back(pov_bbox_bounds(pov_object_bbox(o)));
}

void CameraInteriors::fill(const Point3& origin, InteriorStack& out) const {
    out = InteriorStack{};
    for (size_t i = 0; i < candidates_.size(); ++i) {
        // The object's own Inside, as POV-Ray's InitRayContainerState asks it: its
        // clips are not tested (its box is already cut to theirs).
        if (contains(bounds_[i], origin) && inside_unclipped(*candidates_[i], origin))
            out.push(&materials_[i]);
    }
}

void CameraInteriors::seed(const Point3& origin, InteriorStack& out) const {
    if (per_ray_)
        fill(origin, out);
    else
        out = fixed_;
}

}  // namespace povwall::trace
