// POV-Ray's single-precision bounding boxes, and the two tests a ray must pass before
// POV-Ray 3.7 intersects an object at all.
//
// POV-Ray keeps every object's bounding box as a lower-left corner and lengths in
// `float` (BBOX_VAL, 3.7:source/backend/frame.h:725; Make_BBox_from_min_max rounds the
// double min and max - min). A ray meets those boxes in single precision too:
// - the bounding-slab tree (bounding method 1, the default) tests each finite frame-level
//   object's box with the origin and the inverse direction rounded to float
//   (Check_And_Enqueue with Rayinfo, 3.7:source/backend/bounding/bbox.cpp:591-737,
//   bbox.h:59-93). It is used when the scene has at least Bounding_Threshold
//   frame-level objects, light sources included (boundingtask.cpp:147);
// - Find_Intersection then tests the object's own box again, all in float
//   (ObjectBase::Intersect_BBox / Intersect_BBox_Dir, 3.7:source/backend/scene/
//   objects.cpp:958-1022), except for the shapes that skip it: box, sphere, plane,
//   triangle and poly (their Intersect_BBox returns true).
// An object whose box the ray misses in that arithmetic is not intersected. For objects
// much larger than the float spacing of their coordinates (about 6e-8 of them) this
// changes nothing but the last bits at silhouettes; objects near that spacing (a 1e-7
// box at x = 1.3) or far from the origin (1e-3 at 1e6) lose parts or vanish entirely.
// Rays reach these tests with their double origin and unit direction, as POV-Ray's rays.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/scene.h"

namespace povwall::trace {

class PovWholeScene;

constexpr Real kBoundHuge = 2e10;       // BOUND_HUGE: the size of an infinite box
constexpr Real kCriticalLength = 1e6;   // a CSG box longer than this becomes infinite
constexpr Real kSmallTolerance = 1e-3;  // padding of flat polygon and disc boxes
// The Bounding_Threshold POV-Ray runs with: the povray.ini installed beside povray 3.7
// (/etc/povray/3.7/povray.ini) sets 3 (the backend's own default is 1).
constexpr size_t kPovBoundingThreshold = 3;
// A Bounding_Threshold no scene reaches: bounding off (-MB, Bounding=off).
constexpr size_t kPovBoundingOff = ~size_t(0);

// A BBOX: lower-left corner and lengths, single precision.
struct PovBBox {
    float lo[3] = {0, 0, 0};
    float len[3] = {0, 0, 0};
};

// Make_BBox_from_min_max: the corner and the lengths (computed in double) rounded to
// float.
PovBBox pov_bbox(const Bounds3& b);
// The box's extent as POV-Ray reads it back in double: lo, lo + len.
Bounds3 pov_bbox_bounds(const PovBBox& b);
// Finite in POV-Ray's sense: volume at most BOUND_HUGE (INFINITE_VOLUME), so the object
// goes into the bounding-slab tree.
bool pov_bbox_finite(const PovBBox& b);

// A ray as the float box tests see it: origin rounded to float, 1/direction computed in
// double and rounded to float, the direction normalised first (POV-Ray's rays are unit).
struct PovRay {
    float origin[3];
    float inv[3];
    bool nonzero[3];
    explicit PovRay(const Ray& ray);
    // A direction taken as it is (a shape's own ray, already made unit its own way).
    PovRay(const Point3& origin, const Vector3& unit_direction);
};

// One ray's PovRay, made when first asked for (most rays meet no primitive whose POV-Ray
// boxes are checked), and the answer of the root box, asked once: the tests of every
// candidate along the ray share them.
class PovRayOnce {
  public:
    explicit PovRayOnce(const Ray& ray) : ray_(ray) {}
    const Ray& ray() const { return ray_; }
    const PovRay& get() const {
        if (!made_) made_.emplace(ray_);
        return *made_;
    }
    template <class Test>
    bool root_accepts(Test&& test) const {
        if (root_ < 0) root_ = test(get()) ? 1 : 0;
        return root_ == 1;
    }

  private:
    const Ray& ray_;
    mutable std::optional<PovRay> made_;
    mutable int8_t root_ = -1;
};

// The bounding-slab tree's test of a leaf's box (Check_And_Enqueue): per axis the entry
// (corner - origin) * inv in float, the exit that plus length * inv in double; a ray
// parallel to an axis must start inside the slab (float compare). True unless the slabs
// leave an empty interval or one ending below EPSILON (1e-10).
bool slab_tree_accepts(const PovBBox& box, const PovRay& ray);
// The same test, and where it accepts, the distance it files the box under in its
// priority queue: the largest slab entry (-BOUND_HUGE along an axis the ray is parallel
// to; negative when the origin is inside).
bool slab_tree_entry(const PovBBox& box, const PovRay& ray, Real& entry);

// The object's own box test (Intersect_BBox_Dir): everything in float, corners lo and
// lo + len, slabs met in x, y, z order; true when the interval meets (mind, maxd).
bool own_bbox_accepts(const PovBBox& box, const PovRay& ray, float mind, float maxd);

// The box POV-Ray computes for a frame-level object: each shape's Compute_BBox (a sphere
// centre +- radius, a box's, torus's, cylinder's, cone's or disc's canonical box through
// its transform (Recompute_BBox), a triangle's corners +- EPSILON, a polygon's corners
// widened where flat, a mesh's single-precision vertices), CSG boxes from their
// children's, bounded_by and then clipped_by boxes when smaller. The infinite box
// (BOUND_HUGE) for planes and inverse CSG.
PovBBox pov_object_bbox(const Object& o);
// Sphere::Compute_BBox: corner centre - radius, lengths 2 radius.
PovBBox pov_sphere_bbox(const Point3& centre, Real radius);
// A mesh triangle's box in the mesh's own space (Mesh::get_triangle_bbox): its corners,
// single precision like the mesh's vertices.
PovBBox pov_mesh_triangle_bbox(const Point3 (&p)[3]);

// The infinite box (BOUND_HUGE each way).
PovBBox pov_infinite_bbox();
// POV-Ray's canonical frame of a cylinder, cone or disc along `up` (unit): the images of
// x and y under the rotation that takes z to `up` (Compute_Coordinate_Transform).
void pov_canonical_frame(Vector3 up, Vector3& ex, Vector3& ey);
// Recompute_BBox: the eight corners of a box in a shape's canonical space, placed by
// `place` (canonical -> world), clipped at the largest box POV-Ray allows.
Bounds3 pov_corners_bounds(const Bounds3& canonical,
                           const std::function<Point3(const Point3&)>& place);
// pov_bbox of a box in the shape's own space through its transform.
PovBBox pov_transformed_bbox(const Bounds3& local, const CompactTransform& xf);
// A cylinder's or cone's box: its canonical box [-1,1]^2 x [z0,1] scaled by the radius
// and the height of the frame along `axis` from `origin`, through the transform.
Bounds3 pov_axial_bounds(const CompactTransform& xf, const Point3& origin,
                         const Vector3& axis, Real radius, Real height, Real z0);

// Rotation and uniform scale (plus translation): a sphere stays a sphere.
bool is_similarity(const Transform& t, Real& scale);

// Whether Find_Intersection tests this object's own box (shapes without their own
// Intersect_BBox): everything but box, sphere, plane, triangle and smooth triangle.
bool pov_tests_own_bbox(const Object& o);

// The root of POV-Ray's bounding-slab tree when the ray tests it: in a scene without
// infinite objects (no plane, no infinite CSG), the box around every frame-level object's
// box (calc_bbox: corners min, max of corner + length in double, rounded again). Every
// ray meets it first, so an object at its high side loses what the rounding of its
// lengths cuts off. False when the root is infinite (it then holds the infinite objects
// and is never tested) or the scene's objects are not all here. The nodes between the
// root and the objects are not modelled: their grouping is POV-Ray's sort_and_split.
// `whole`: the whole scene's record when `scene` holds only some of its objects
// (trace/pov_order.h).
bool pov_slab_root(const Scene& scene, PovBBox& root,
                   const PovWholeScene* whole = nullptr);

// Frame-level objects as POV-Ray links them: plain unions (pov_splits_union(), core/
// scene.h) are opened into their children, everything else counts once; light sources
// count too. POV-Ray builds its bounding-slab tree when this reaches
// kPovBoundingThreshold.
size_t pov_frame_objects(const Scene& scene, const PovWholeScene* whole = nullptr);
// The frame-level objects one object becomes (1, or a plain union's children's).
size_t pov_frame_object_count(const Object& o);

// Calls visit(f) for each frame-level object `o` stands for, in order: a plain union is
// opened into its children (pov_splits_union), recursively; anything else is one.
template <class Visit>
void pov_for_frame_objects(const Object& o, Visit&& visit) {
    if (pov_splits_union(o)) {
        for (const Object& c : std::get<Csg>(o.shape).children)
            pov_for_frame_objects(c, visit);
        return;
    }
    visit(o);
}

}  // namespace povwall::trace
