#include "trace/prepared_scene.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "octree/giants.h"
#include "octree/overlap.h"
#include "octree/spatial_order.h"
#include "trace/convex_region.h"
#include "trace/csg_children.h"
#include "trace/cutaway_textures.h"
#include "trace/light_masks.h"
#include "trace/object_inside.h"
#include "trace/object_placement.h"
#include "trace/pov_slab_test.h"
#include "trace/render.h"
#include "trace/shapes/shape.h"
#include "trace/sphere_lanes.h"

namespace povwall::trace {
namespace {

struct WorldCrossing {
    // Every field from its arguments or a few stores: a CSG builds one for each crossing
    // of each child on every ray, and zeroing the whole first (rep stos) cost more than
    // the rest of building it.
    WorldCrossing(Real t_, const Object* leaf_, const ShapeHit& hit_, bool flip_)
        : t(t_), leaf(leaf_), hit(hit_), own_point(hit_.own_point), flip(flip_) {}
    WorldCrossing(Real t_, const Object* leaf_, bool flip_, const Vector3& given_)
        : t(t_), leaf(leaf_), given(given_), flip(flip_), has_normal(true) {}

    Real t;
    const Object* leaf;
    // Where the shape says the crossing is, when that is not at distance t along the ray
    // (a julia_fractal's later crossings: POV-Ray's depth there lags its point).
    Point3 point{0, 0, 0};
    // The outward normal is found only for the crossing a ray keeps (most crossings are
    // behind it, and a shadow ray keeps none): from the shape's hit, or given (a sphere
    // met in world space); `flip` negates it (an inverse object, a difference's cutter).
    Vector3 given{0, 0, 0};
    ShapeHit hit{};
    bool own_point = false;
    bool flip = false;
    bool has_normal = false;
    Point3 at(const Ray& ray) const { return own_point ? point : ray.at(t); }
    // `world`: the crossing's point.
    Vector3 normal(const Point3& world) const {
        const Vector3 n = has_normal ? given : leaf_world_normal(*leaf, hit, world);
        return flip ? -n : n;
    }
};

// World distances along a ray, [lo, hi), and whether any crossing there will do.
struct WantedRange {
    Real lo, hi;
    bool any = false;
};

}  // namespace

// An image_map is see-through off the image (once), with filter/transmit all, or where
// the file's alpha is below 1.
bool image_opaque(const ImageMapping& m) {
    if (m.once || m.all_filter != 0 || m.all_transmit != 0 || !m.pixels) return false;
    return !m.pixels->see_through;
}

bool pigment_opaque(const Pigment& p) {
    if (p.pattern->kind == PatternKind::ImageMap && p.pattern->image &&
        !image_opaque(*p.pattern->image))
        return false;
    if (p.colour.filter != 0 || p.colour.transmit != 0) {
        if (p.pattern->kind == PatternKind::Solid) return false;
    }
    for (const auto& e : p.maps->colour_map) {
        if (e.colour.filter != 0 || e.colour.transmit != 0) return false;
    }
    for (const auto& sub : p.maps->list) {
        if (!pigment_opaque(sub)) return false;
    }
    return true;
}

bool texture_opaque(const LayeredTexture& layers) {
    for (const Texture& t : layers) {
        if (!pigment_opaque(t.pigment)) return false;
        for (const auto& e : t.map->entries) {
            if (!texture_opaque(e)) return false;
        }
    }
    return true;
}

namespace {

bool inside_clips(const Object& o, const Point3& p);

// Leaf shape crossings along a world ray, in world distances, with outward world normals
// (`backwards`: appended last first).
void leaf_crossings(const Object& o, const Ray& ray, bool csg_child,
                    std::vector<WorldCrossing>& out, const WantedRange* wanted,
                    const RayFlags* flags, bool backwards) {
    // A sphere moved, turned or scaled evenly is a sphere in world space, met by the
    // world ray as it is (POV-Ray moves its centre and radius; only an ellipsoid works in
    // its own space): the same last bits as a sphere outside CSG, which decide hits on a
    // pattern's edge such as an onion's r = 1.
    Real scale = 1;
    if (const Sphere* s = std::get_if<Sphere>(&o.shape);
        s && is_similarity(o.transform, scale)) {
        const Sphere world{o.transform.point(s->centre), s->radius * scale};
        Crossings cs;
        intersect_sphere(world, ray.origin, ray.direction, cs);
        // Built where they stay: a copy of a local just written stalls on store
        // forwarding (this runs for every CSG child on every shadow ray).
        for (int k = 0; k < cs.n; ++k) {
            const Real t = cs.c[backwards ? cs.n - 1 - k : k].t;
            out.emplace_back(t, &o, o.inverse, sphere_normal(world, ray.at(t)));
        }
        return;
    }
    LocalRay local = leaf_ray(o, ray);
    if (!(local.length > 0)) return;
    // A clip filters the hits after the shape: a shape that stops at its first hit must
    // go on past clipped ones, as POV-Ray's (which tests clips before it stops). An
    // isosurface, and a mesh whose walk stops at its nearest hit, test their clip inside
    // their search, as POV-Ray's do.
    const bool clipped = !o.clipped_by.empty();
    const Isosurface* clipped_iso = clipped ? std::get_if<Isosurface>(&o.shape) : nullptr;
    const Mesh* clipped_mesh = clipped ? std::get_if<Mesh>(&o.shape) : nullptr;
    if (clipped_mesh && !mesh_stops_at_nearest(*clipped_mesh)) clipped_mesh = nullptr;
    local.csg_child = csg_child || (clipped && !clipped_iso);
    if (flags) local.restart = flags->restart;
    if (wanted && !local.csg_child) {
        local.nearest_only = true;
        local.want_lo = wanted->lo;
        local.want_hi = wanted->hi;
        local.any_crossing = wanted->any;
    }
    thread_local ShapeHits hits;
    hits.clear();
    if (clipped_iso || clipped_mesh) {
        struct Context {
            const Object& o;
            const Ray& ray;
        } context{o, ray};
        const ShapeClip clip{[](const void* c, Real t) {
                                 const auto& x = *static_cast<const Context*>(c);
                                 return inside_clips(x.o, x.ray.at(t));
                             },
                             &context};
        if (clipped_iso)
            shape_hits(*clipped_iso, local, clip, hits);
        else
            shape_hits(*clipped_mesh, local, &clip, hits);
    } else {
        leaf_hits(o, local, hits);
    }
    for (size_t k = 0; k < hits.size(); ++k) {
        const ShapeHit& h = hits[backwards ? hits.size() - 1 - k : k];
        WorldCrossing& c = out.emplace_back(h.t, &o, h, o.inverse);  // in place, as above
        if (h.own_point) c.point = o.transform.point(h.p);
    }
}

// Whether a shape under `o` (its clips and bounds included) searches from where a shadow
// ray restarts (RayFlags::restart): its crossings change with the restart.
bool searches_from_restart(const Object& o) {
    if (std::holds_alternative<Isosurface>(o.shape) ||
        std::holds_alternative<JuliaFractal>(o.shape) ||
        std::holds_alternative<Mesh>(o.shape))
        return true;
    if (const Csg* csg = std::get_if<Csg>(&o.shape)) {
        for (const Object& c : csg->children)
            if (searches_from_restart(c)) return true;
    }
    for (const Object& c : *o.clipped_by)
        if (searches_from_restart(c)) return true;
    for (const Object& c : *o.bounded_by)
        if (searches_from_restart(c)) return true;
    return false;
}

// The crossings of the objects one shadow ray met (PreparedScene::reuses_crossings_).
// POV-Ray's shadow ray restarts at each see-through surface and searches again
// (shading.cpp shadow_segment): each object on the way is asked again from each restart,
// and its crossings depend only on the ray and its flags, so they are computed once per
// ray (the CSG parts of glass chess pieces were asked once per surface crossed: 3/4 of a
// FreeCAD export's radiosity pretrace).
struct ShadowCrossings {
    uint64_t scene = 0;
    Ray ray;
    RayFlags flags;
    struct Entry {
        uint32_t id;
        std::vector<WorldCrossing> crossings;
    };
    std::vector<Entry> entries;
    size_t used = 0;
    static constexpr size_t kMostObjects = 64;

    // The entries of this ray (those of an earlier one are dropped).
    void start(uint64_t scene_serial, const Ray& r, const RayFlags& f) {
        const bool same = scene == scene_serial && r.origin == ray.origin &&
                          r.direction == ray.direction && f.primary == flags.primary &&
                          f.image == flags.image && f.reflection == flags.reflection &&
                          f.shadow == flags.shadow && f.photon == flags.photon &&
                          f.radiosity == flags.radiosity &&
                          f.frame_test == flags.frame_test;
        if (same) return;
        scene = scene_serial;
        ray = r;
        flags = f;
        used = 0;
    }
    const std::vector<WorldCrossing>* find(uint32_t id) const {
        for (size_t i = 0; i < used; ++i)
            if (entries[i].id == id) return &entries[i].crossings;
        return nullptr;
    }
    // A cleared list to fill for `id`, or null when the ray met too many.
    std::vector<WorldCrossing>* add(uint32_t id) {
        if (used == kMostObjects) return nullptr;
        if (used == entries.size()) entries.emplace_back();
        Entry& e = entries[used++];
        e.id = id;
        e.crossings.clear();
        return &e.crossings;
    }
};

bool inside_clips(const Object& o, const Point3& p) {
    for (const Object& c : *o.clipped_by) {
        if (!inside_object(c, p)) return false;
    }
    return true;
}

// `wanted`: the world distances the caller keeps the nearest crossing of, when it uses
// no other (a leaf outside CSG may then leave out the crossings beyond). `flags`: the
// ray's, for the children a CSG leaves out (csg_skips(); null: none left out);
// `inverted`: whether o's CSG ancestors were inverted an odd number of times.
void object_crossings(const Object& o, const Ray& ray, std::vector<WorldCrossing>& out,
                      bool csg_child = false, const WantedRange* wanted = nullptr,
                      const RayFlags* flags = nullptr, bool inverted = false,
                      bool backwards = false);

// POV-Ray's Ray_In_Bound: the ray passes when, for every bounding object, it meets it
// somewhere ahead (MIN_ISECT_DEPTH on, as Find_Intersection; the bound's own bounds and
// clips count) or starts inside it.
bool ray_in_bound(const std::vector<Object>& bound, const Ray& ray) {
    std::vector<WorldCrossing> cs;
    for (const Object& b : bound) {
        cs.clear();
        if (b.bounded_by.empty() || ray_in_bound(*b.bounded_by, ray))
            object_crossings(b, ray, cs);
        const bool meets = std::any_of(cs.begin(), cs.end(), [](const WorldCrossing& c) {
            return c.t >= kMinIsectDepth;
        });
        if (!meets && !inside_object(b, ray.origin)) return false;
    }
    return true;
}

void object_crossings(const Object& o, const Ray& ray, std::vector<WorldCrossing>& out,
                      bool csg_child, const WantedRange* wanted, const RayFlags* flags,
                      bool inverted, bool backwards) {
    size_t start = out.size();
    if (const Csg* csg = std::get_if<Csg>(&o.shape)) {
        // The children this ray does not see: neither their crossings nor (in a merge)
        // their insides count.
        inverted = inverted != o.inverse;
        const PovCsg pov = pov_csg(csg->kind, inverted);
        auto skipped = [&](size_t i) {
            return flags && csg_skips(pov, csg->children[i], *flags);
        };
        // In POV-Ray's push order: a plain union pushes its children's intersections as
        // they come; every other CSG collects each child's on a stack of its own and
        // moves them over from the top, reversing them (csg.cpp All_Intersections).
        const bool reversed = pov != PovCsg::Union || o.inverse || !o.clipped_by.empty();
        // Many children: only those whose box the ray's line meets, in their order
        // (trace/csg_children.h).
        const CsgChildIndex* index = csg_child_index(*csg);
        const CsgScratchLevel level(index != nullptr);
        const std::vector<uint32_t>* met = nullptr;
        if (index) {
            std::vector<uint32_t>& ids = csg_scratch(level.depth).children;
            ids.clear();
            index->surfaces.line_candidates(ray.origin, ray.direction, ids);
            for (uint32_t& e : ids) e = index->surface_children[e];
            ids.insert(ids.end(), index->surface_always.begin(),
                       index->surface_always.end());
            std::sort(ids.begin(), ids.end());
            met = &ids;
        }
        const size_t walked = met ? met->size() : csg->children.size();
        for (size_t n = 0; n < walked; ++n) {
            const size_t i = met ? (*met)[n] : n;
            // A child's bound is never removed: a ray outside it skips the child (its
            // inside still counts for the others' crossings).
            const Object& child = csg->children[i];
            if (skipped(i)) continue;
            if (!child.bounded_by.empty() && !ray_in_bound(*child.bounded_by, ray))
                continue;
            // POV-Ray inverts a difference's later children (a CSG among them turns into
            // its morphed kind: a union into an intersection of inverted children).
            const bool child_inverted =
                inverted != (csg->kind == CsgKind::Difference && i > 0 &&
                             std::holds_alternative<Csg>(child.shape));
            // The child's crossings go straight into `out` and are filtered there (no
            // buffer per CSG per ray).
            const size_t mark = out.size();
            object_crossings(child, ray, out, true, nullptr, flags, child_inverted,
                             reversed);
            // A union seen as a union keeps every crossing of its children: no inside
            // tests (text is a union of glyphs, each inside test a glyph outline walk).
            if (csg->kind == CsgKind::Union && pov != PovCsg::Intersection) continue;
            auto inside_sibling = [&](size_t j, const Point3& p) {
                return inside_object(csg->children[j], p,
                                     child_held_inverted(*csg, j, inverted));
            };
            size_t kept = mark;
            for (size_t k = mark; k < out.size(); ++k) {
                const Point3 p = out[k].at(ray);
                bool keep = true;
                if (index && pov == PovCsg::Merge) {
                    // Only the siblings that can decide are asked.
                    keep =
                        !inside_any_child(*index, inverted, p, i, skipped,
                                          [&](size_t j) { return inside_sibling(j, p); });
                } else if (index) {
                    keep = inside_every_child(*index, inverted, p, i, [&](size_t j) {
                        return inside_sibling(j, p);
                    });
                } else {
                    for (size_t j = 0; j < csg->children.size() && keep; ++j) {
                        if (j == i || skipped(j)) continue;
                        const bool in = inside_sibling(j, p);
                        keep = pov == PovCsg::Intersection ? in : !in;
                    }
                }
                if (!keep) continue;
                // A difference inverts its later children: each leaf under them that
                // POV-Ray's Invert turns inside out (a triangle, polygon, patch or
                // parametric keeps its normal).
                if (csg->kind == CsgKind::Difference && i > 0 &&
                    leaf_invertible(*out[k].leaf))
                    out[k].flip = !out[k].flip;
                if (kept != k) out[kept] = out[k];
                ++kept;
            }
            out.erase(out.begin() + ptrdiff_t(kept), out.end());
        }
        // An inverse CSG inverts each leaf under it (CSG::Invert), but a triangle,
        // polygon, patch or parametric keeps its normal.
        if (o.inverse) {
            for (size_t k = start; k < out.size(); ++k)
                if (leaf_invertible(*out[k].leaf)) out[k].flip = !out[k].flip;
        }
    } else {
        // A leaf appends its crossings in the order asked for; a CSG's are reversed where
        // they lie (below), 160 bytes a swap.
        leaf_crossings(o, ray, csg_child, out, wanted, flags, backwards);
        backwards = false;
    }
    // POV-Ray's bicubic_patch never tests its clips (only its box shrinks by them).
    if (!o.clipped_by.empty() && !std::holds_alternative<BicubicPatch>(o.shape)) {
        size_t w = start;
        for (size_t k = start; k < out.size(); ++k) {
            if (inside_clips(o, out[k].at(ray))) out[w++] = out[k];
        }
        // Outside CSG a julia_fractal stops at its first hit the clip keeps (POV-Ray
        // breaks after pushing it): a ray leaving its surface must not see the next.
        if (!csg_child && std::holds_alternative<JuliaFractal>(o.shape))
            w = std::min(w, start + 1);
        out.erase(out.begin() + ptrdiff_t(w), out.end());
    }
    if (backwards) std::reverse(out.begin() + ptrdiff_t(start), out.end());
}

// A leaf's bounds in the world, before its clips.
Bounds3 leaf_world_bounds(const Object& o) {
    const Bounds3 local = leaf_bounds(o);
    if (!local.empty() && local.infinite()) return Bounds3::everything();
    const Cylinder* cylinder = std::get_if<Cylinder>(&o.shape);
    const Cone* cone = std::get_if<Cone>(&o.shape);
    return cylinder && cylinder->radius != 0
               ? cylinder_world_bounds(*cylinder, o.transform)
           : cone ? cone_world_bounds(*cone, o.transform)
                  : o.transform.bounds(local);
}

// Where a plane leaf (`inverted`: as a difference's later part) counts points inside, as
// a half-space of the world: inside_plane's test, dot(n, q) - d < EPSILON at the point q
// in the plane's space, with q the inverse transform of the world point. False for
// anything but a plane.
static bool plane_half_space(const Object& o, bool inverted, HalfSpace& out) {
    const Plane* plane = std::get_if<Plane>(&o.shape);
    if (!plane) return false;
    const Real sign = inverted != o.inverse ? -1 : 1;
    out.normal = o.transform.normal(plane->normal) * sign;
    out.offset = sign * (plane->distance -
                         dot(plane->normal, o.transform.inverse_point({0, 0, 0}))) +
                 kPovEpsilon;
    return true;
}

// The bounds of where an object's surface can be met (`restricts` false), or of its
// inside when it cuts another's surface (an intersection's or difference's part, or a
// clip): a disc's inside is the half-space behind it, a height field's everything below
// its box, a solid mesh's (inside_vector) everything whose ray along that vector crosses
// its faces an odd number of times, far past its vertices, so as cutting parts they
// restrict nothing. bounded_by is no limit (it bounds the rays POV-Ray tests, not the
// hits).
Bounds3 object_bounds(const Object& o, bool restricts) {
    if (o.inverse) return Bounds3::everything();
    if (restricts && (std::holds_alternative<Disc>(o.shape) ||
                      std::holds_alternative<HeightField>(o.shape)))
        return Bounds3::everything();
    // A blob whose threshold its tolerance reaches holds every point no element's field
    // reaches (field 0 there).
    if (const Blob* blob = std::get_if<Blob>(&o.shape);
        restricts && blob && !(blob->data->threshold - kBlobInsideTolerance >= 0))
        return Bounds3::everything();
    if (const Mesh* m = std::get_if<Mesh>(&o.shape);
        restricts && m && m->data->inside_vector &&
        dot(*m->data->inside_vector, *m->data->inside_vector) != 0)
        return Bounds3::everything();
    if (const Csg* csg = std::get_if<Csg>(&o.shape)) {
        const bool cuts =
            csg->kind == CsgKind::Intersection || csg->kind == CsgKind::Difference;
        // Children carry world transforms already.
        Bounds3 b;
        bool first = true;
        for (const Object& c : csg->children) {
            const Bounds3 cb = object_bounds(c, cuts || restricts);
            if (csg->kind == CsgKind::Intersection) {
                if (cb.infinite()) continue;
                b = first ? cb : intersection(b, cb);
                first = false;
            } else if (csg->kind == CsgKind::Difference) {
                b = cb;
                break;
            } else {
                b.extend(cb);
            }
        }
        if (first && csg->kind == CsgKind::Intersection) b = Bounds3::everything();
        for (const Object& c : *o.clipped_by) {
            const Bounds3 cb = object_bounds(c, true);
            if (!cb.infinite()) b = intersection(b, cb);
        }
        // Plane parts and plane clips close the region where the other parts leave it
        // open: a prism made of planes has a finite surface.
        std::vector<HalfSpace> half_spaces;
        HalfSpace h;
        if (cuts) {
            for (size_t i = 0; i < csg->children.size(); ++i) {
                const Object& c = csg->children[i];
                const bool later = csg->kind == CsgKind::Difference && i > 0;
                if (later && !difference_inverts(c)) continue;
                if (plane_half_space(c, later, h)) half_spaces.push_back(h);
            }
        }
        for (const Object& c : *o.clipped_by) {
            if (plane_half_space(c, false, h)) half_spaces.push_back(h);
        }
        return half_spaces.empty() ? b : convex_region_bounds(b, half_spaces);
    }
    Bounds3 world = leaf_world_bounds(o);
    if (world.infinite() || std::holds_alternative<BicubicPatch>(o.shape)) return world;
    for (const Object& c : *o.clipped_by) {
        const Bounds3 cb = object_bounds(c, true);
        if (!cb.infinite()) world = intersection(world, cb);
    }
    return world;
}

Bounds3 object_bounds(const Object& o) { return object_bounds(o, false); }

// Whether POV-Ray may meet the object's surface outside its box: a disc cuts it (as an
// intersection's or a difference's part, or as a clip), a height field is part of an
// intersection or difference (solid below its box), a bounded_by of its own or of a
// part bounds the rays tested rather than the hits, or a bicubic_patch is clipped.
bool may_hit_outside_pov_box(const Object& o, bool restricts = false) {
    if (restricts && !o.inverse &&
        (std::holds_alternative<Disc>(o.shape) ||
         std::holds_alternative<HeightField>(o.shape)))
        return true;
    if (!o.bounded_by.empty() && !o.bounds_are_clips) return true;
    // A bicubic_patch's clips shrink its box and leave its surface whole.
    if (!o.clipped_by.empty() && std::holds_alternative<BicubicPatch>(o.shape))
        return true;
    for (const Object& c : *o.clipped_by)
        if (may_hit_outside_pov_box(c, true)) return true;
    if (const Csg* csg = std::get_if<Csg>(&o.shape)) {
        const bool cuts =
            csg->kind == CsgKind::Intersection || csg->kind == CsgKind::Difference;
        for (const Object& c : csg->children)
            if (may_hit_outside_pov_box(c, cuts || restricts)) return true;
    }
    return false;
}

// Whether a hit's distance may lag its point, so that it can lie before the object's
// bounds (a julia_fractal's later crossings, as POV-Ray reports them).
bool lags_its_depth(const Object& o) {
    if (const Csg* csg = std::get_if<Csg>(&o.shape))
        return std::any_of(csg->children.begin(), csg->children.end(), lags_its_depth);
    return std::holds_alternative<JuliaFractal>(o.shape);
}

size_t blend_faces(const Mesh& m) {
    if (m->texture_triples.empty()) return 0;
    return size_t(std::count_if(m->faces.begin(), m->faces.end(),
                                [](const Mesh::Face& f) { return f.texture <= -2; }));
}

size_t count_leaves(const Object& o) {
    size_t n = 1;
    if (auto c = std::get_if<Csg>(&o.shape)) {
        for (const auto& ch : c->children) n += count_leaves(ch);
    }
    if (auto m = std::get_if<Mesh>(&o.shape)) n += m->textures.size() + blend_faces(*m);
    if (auto b = std::get_if<Blob>(&o.shape)) n += b->element_textures.size();
    return n;
}

}  // namespace

bool inside_object(const Object& o, const Point3& p) {
    return inside_object(o, p, false);
}

bool inside_object(const Object& o, const Point3& p, bool inverted) {
    // POV-Ray's Inside_Object: outside a clip is outside, inverse or not (Invert leaves
    // the clips as they are).
    if (!o.clipped_by.empty() && !inside_clips(o, p)) return false;
    return inside_unclipped(o, p, inverted);
}

bool inside_unclipped(const Object& o, const Point3& p, bool inverted) {
    inverted = inverted != o.inverse;
    const Csg* csg = std::get_if<Csg>(&o.shape);
    if (!csg) {
        const Point3 q = o.transform.is_identity() ? p : o.transform.inverse_point(p);
        return inverted && leaf_invertible(o) ? leaf_inside_inverted(o, q)
                                              : leaf_inside(o, q);
    }
    // POV-Ray inverts a CSG by inverting every child and morphing it (a union or merge
    // into an intersection, an intersection into a merge); a difference is an
    // intersection whose later children are inverted once more.
    const bool any = pov_csg(csg->kind, inverted) != PovCsg::Intersection;
    if (csg->children.empty()) return false;
    auto inside_child = [&](size_t i) {
        return inside_object(csg->children[i], p, child_held_inverted(*csg, i, inverted));
    };
    if (const CsgChildIndex* index = csg_child_index(*csg)) {
        // Many children: only those that can decide are asked (trace/csg_children.h).
        return any ? inside_any_child(
                         *index, inverted, p, kNoChild, [](size_t) { return false; },
                         inside_child)
                   : inside_every_child(*index, inverted, p, kNoChild, inside_child);
    }
    for (size_t i = 0; i < csg->children.size(); ++i)
        if (inside_child(i) == any) return any;
    return !any;
}

Bounds3 object_world_bounds(const Object& obj) { return object_bounds(obj); }

Bounds3 object_inside_bounds(const Object& obj) { return object_bounds(obj, true); }

Bounds3 object_hit_bounds(const Object& obj) {
    Bounds3 b = object_bounds(obj);
    const Plane* plane = std::get_if<Plane>(&obj.shape);
    if (!plane || dot(plane->normal, plane->normal) == 0) return b;
    // The surface in world space: normal through the inverse transpose, and a point on
    // it through the transform.
    const Vector3 n = obj.transform.normal(plane->normal);
    const Point3 on = obj.transform.point(
        Point3{} + plane->normal * (plane->distance / dot(plane->normal, plane->normal)));
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
        if (n[a] == 0) continue;
        if (axis >= 0) return b;  // oblique: its surface reaches every box it crosses
        axis = a;
    }
    if (axis < 0 || !std::isfinite(on[axis])) return b;
    b.lo[axis] = std::max(b.lo[axis], on[axis]);
    b.hi[axis] = std::min(b.hi[axis], on[axis]);
    return b;
}

PreparedScene::PreparedScene(const Scene& scene, const RenderPlan* plan,
                             const PrepareOptions& options)
    : scene_(scene), plan_(plan ? *plan : make_render_plan(scene)), options_(options) {
    std::vector<const Object*> all;
    for (const Object& o : scene.objects) all.push_back(&o);
    build(all);
}

PreparedScene::PreparedScene(const Scene& scene,
                             const std::vector<uint32_t>& object_subset,
                             const RenderPlan* plan, const PrepareOptions& options)
    : scene_(scene), plan_(plan ? *plan : make_render_plan(scene)), options_(options) {
    std::vector<const Object*> some;
    for (uint32_t i : object_subset) some.push_back(&scene.objects[i]);
    build(some);
}

void PreparedScene::build(const std::vector<const Object*>& objects) {
    static std::atomic<uint64_t> next_serial{1};
    serial_ = next_serial.fetch_add(1, std::memory_order_relaxed);
    const Scene& scene = scene_;
    for (const Light& l : scene.lights) {
        if (l.projected_through) {
            light_masks_ = std::make_shared<const LightMasks>(scene);
            break;
        }
    }
    env_.noise_generator = scene.settings.noise_generator;
    env_.number_of_waves = scene.settings.number_of_waves;
    env_.quick_colours = plan_.quality.quick_colours();
    const PovWholeScene* whole = options_.whole_scene.get();
    pov_slab_tree_ = options_.pov_float_bounds &&
                     options_.pov_bounding_threshold != kPovBoundingOff &&
                     pov_frame_objects(scene, whole) >= options_.pov_bounding_threshold;
    pov_root_tested_ = pov_slab_tree_ && pov_slab_root(scene, pov_root_, whole);
    // The children of large CSGs get their boxes now that they are final.
    for (const Object* o : objects) index_csg_children(*o);
    for (const Light& l : scene.lights)
        for (const Object& o : l.looks_like) index_csg_children(o);
    size_t leaves = 0;
    for (const Object* o : objects)
        leaves += count_leaves(*o) + cutaway_material_count(*o);
    for (const Light& l : scene.lights) {
        for (const Object& o : l.looks_like)
            leaves += count_leaves(o) + cutaway_material_count(o);
    }
    materials_.reserve(leaves + 1);
    size_t blends = 0;
    auto count_blends = [&](auto& self, const Object& o) -> void {
        if (auto m = std::get_if<Mesh>(&o.shape)) blends += blend_faces(*m);
        if (auto c = std::get_if<Csg>(&o.shape))
            for (const Object& ch : c->children) self(self, ch);
    };
    for (const Object* o : objects) count_blends(count_blends, *o);
    for (const Light& l : scene.lights)
        for (const Object& o : l.looks_like) count_blends(count_blends, o);
    blends_.reserve(blends);  // materials point into it
    material_frame_.reserve(leaves + 1);
    // Each object's place in POV-Ray's object list, for exact ties (unknown when the
    // parse left objects out and the whole scene's list was not recorded).
    const bool frames_known = !scene.objects_filtered() || whole;
    PovFrameList frames;
    if (frames_known)
        frames = pov_frame_list(scene, options_.pov_bounding_threshold, whole);
    for (const Object* o : objects) {
        const size_t i = size_t(o - scene.objects.data());
        add_object(*o, frames_known && i < frames.first_of_object.size()
                           ? frames.first_of_object[i]
                           : ~0u);
    }
    // A light's looks_like object is visible but casts no shadow (it would block its
    // light). POV-Ray links the light to the scene, whole (a union it looks like is not
    // split), with no_shadow alone; its bounding-slab tree holds the object in the
    // light's place, so there the object's own flags are tested.
    const bool slab_tree =
        options_.pov_bounding_threshold != kPovBoundingOff &&
        pov_frame_objects(scene, whole) >= options_.pov_bounding_threshold;
    for (size_t l = 0; l < scene.lights.size(); ++l) {
        bool first = true;
        for (const Object& o : scene.lights[l].looks_like) {
            const size_t first_material = materials_.size();
            add_frame_object(o, frames_known && first ? frames.of_light[l] : ~0u);
            const FrameFlags flags{true, slab_tree && o.no_image,
                                   slab_tree && o.no_reflection,
                                   slab_tree && o.no_radiosity};
            for (size_t i = first_material; i < materials_.size(); ++i)
                materials_[i].frame = flags;
            first = false;
        }
    }
    std::sort(leaf_materials_.begin(), leaf_materials_.end());
    // General objects go into the octree by their placement bounds (narrower for a
    // turned lathe or sor).
    hits_within_bounds_.assign(kind_.size(), 0);
    for (uint32_t id = 0; id < kind_.size(); ++id) {
        if (kind_[id] != PrimKind::Object) continue;
        const Object& o = *objects_[index_[id]];
        bounds_[id] = object_placement_bounds(o, bounds_[id]);
        hits_within_bounds_[id] = !lags_its_depth(o);
    }
    reuses_crossings_.assign(kind_.size(), 0);
    for (uint32_t id = 0; id < kind_.size(); ++id) {
        if (kind_[id] != PrimKind::Object) continue;
        const Object& o = *objects_[index_[id]];
        // A leaf outside CSG may give only its crossings in the range asked for
        // (ShapeHits' nearest_only): those that do are asked each time.
        const bool nearest_only_leaf = std::holds_alternative<Blob>(o.shape) ||
                                       std::holds_alternative<Lathe>(o.shape) ||
                                       std::holds_alternative<Prism>(o.shape) ||
                                       std::holds_alternative<Glyph>(o.shape);
        reuses_crossings_[id] = !nearest_only_leaf && !searches_from_restart(o);
    }
    octree::BuildInput input;
    std::vector<uint32_t> bounded_ids;
    auto finite = [](const Bounds3& b) {
        return std::isfinite(b.lo.x) && std::isfinite(b.lo.y) && std::isfinite(b.lo.z) &&
               std::isfinite(b.hi.x) && std::isfinite(b.hi.y) && std::isfinite(b.hi.z);
    };
    for (uint32_t id = 0; id < kind_.size(); ++id) {
        // A sphere's bounds are not finite only when its centre or radius is not (a
        // division by zero in the scene, which POV-Ray warns about and goes on): it is
        // never hit, as in POV-Ray, and the packed sphere arrays have no place for it.
        if (kind_[id] == PrimKind::Sphere && !finite(bounds_[id])) continue;
        if (bounds_[id].infinite()) {
            unbounded_.push_back(id);
        } else {
            bounded_ids.push_back(id);
        }
    }
    // Spheres first (their ids then index spheres_ directly in the hot loop), numbered
    // along a Morton curve so that neighbours in space are neighbours in memory.
    auto first_other =
        std::stable_partition(bounded_ids.begin(), bounded_ids.end(),
                              [&](uint32_t id) { return kind_[id] == PrimKind::Sphere; });
    {
        std::vector<Bounds3> sphere_bounds;
        for (auto it = bounded_ids.begin(); it != first_other; ++it)
            sphere_bounds.push_back(bounds_[*it]);
        std::vector<uint32_t> spheres(bounded_ids.begin(), first_other);
        const std::vector<uint32_t> order = octree::morton_order(sphere_bounds);
        for (size_t i = 0; i < order.size(); ++i) bounded_ids[i] = spheres[order[i]];
    }
    // The octree indexes bounded primitives by their position in bounded_ids.
    input.bounds.reserve(bounded_ids.size());
    for (uint32_t id : bounded_ids) input.bounds.push_back(bounds_[id]);
    // A sky sphere or shell that dwarfs the rest stays out of the tree (an empty box is
    // left out) and is tested by every ray, as the unbounded ones are.
    const std::vector<uint32_t> giants = octree::giant_primitives(input.bounds);
    for (uint32_t i : giants) input.bounds[i] = Bounds3{};
    // Shapes other than spheres and triangles cost several simple tests each (POV-Ray's
    // box test first, then their own arithmetic: CSG, lathes, text). Weighing them by 4
    // in the split decision cut a text wall's and a lathe field's trace time by 1.5-2x
    // (docs/performance.md); 8 gave no more.
    input.cost.reserve(bounded_ids.size());
    for (uint32_t id : bounded_ids)
        input.cost.push_back(kind_[id] == PrimKind::Object ? 4.0f : 1.0f);
    // Exact (CGAL) cell tests: a sphere or triangle is referenced only by cells it
    // touches.
    input.overlaps = [&](uint32_t i, const Bounds3& cell) {
        uint32_t id = bounded_ids[i];
        if (kind_[id] == PrimKind::Sphere) {
            uint32_t s = index_[id];
            const SpherePrim& sp = spheres_[s];
            return octree::sphere_overlaps({sp.x, sp.y, sp.z}, sp.r, cell);
        }
        if (kind_[id] == PrimKind::Triangle) {
            const TrianglePrim& t = triangles_[index_[id]];
            return octree::triangle_overlaps(t.p[0], t.p[1], t.p[2], cell);
        }
        return true;
    };
    octree::BuildOptions build_options;
    build_options.flat_threshold = plan_.flat_threshold;
    build_options.threads = options_.threads;
    // Spheres are tested four or eight at a time (sphere_lanes.h), about three times
    // cheaper than one by one, so a node step is worth more tests: on the seed scene 12
    // and 16 were both about 7% faster than the default 8 (docs/performance.md).
    // Triangles and other shapes are still tested one by one and keep the default.
    const size_t sphere_refs = size_t(first_other - bounded_ids.begin());
    if (sphere_refs * 2 > bounded_ids.size()) build_options.traversal_cost = 12;
    if (options_.progress) {
        options_.progress->objects = bounded_ids.size();
        options_.progress->stage = RenderProgress::Stage::BuildingOctree;
    }
    tree_.build(input, build_options);
    // Re-map: store octree ids as primitive ids by permuting primitive arrays is avoided;
    // instead the bounded primitives are moved to the front so octree id == primitive id.
    std::vector<PrimKind> kind;
    std::vector<uint32_t> index, material;
    std::vector<Bounds3> bounds;
    // pov_ holds the non-spheres in the order they were added: their rank among them.
    std::vector<uint32_t> pov_rank(kind_.size(), 0);
    for (uint32_t id = 0, r = 0; id < kind_.size(); ++id) {
        if (kind_[id] != PrimKind::Sphere) pov_rank[id] = r++;
    }
    std::vector<PovPrim> pov;
    kind.reserve(kind_.size());
    index.reserve(kind_.size());
    material.reserve(kind_.size());
    bounds.reserve(kind_.size());
    pov.reserve(pov_.size());
    auto move_primitive = [&](uint32_t id) {
        kind.push_back(kind_[id]);
        index.push_back(index_[id]);
        material.push_back(material_[id]);
        bounds.push_back(bounds_[id]);
        if (kind_[id] != PrimKind::Sphere) pov.push_back(pov_[pov_rank[id]]);
    };
    for (uint32_t id : bounded_ids) move_primitive(id);
    // Bounded primitive i is now primitive i.
    std::vector<uint32_t> unbounded(giants.begin(), giants.end());
    for (uint32_t id : unbounded_) {
        unbounded.push_back(uint32_t(kind.size()));
        move_primitive(id);
    }
    // Spheres re-packed in primitive order: spheres_[id] for id < sphere_count_.
    std::vector<SpherePrim> spheres;
    spheres.reserve(spheres_.size());
    for (uint32_t id = 0; id < kind.size() && kind[id] == PrimKind::Sphere; ++id) {
        spheres.push_back(spheres_[index[id]]);
        index[id] = id;
    }
    sphere_count_ = uint32_t(spheres.size());
    spheres_ = std::move(spheres);
    kind_ = std::move(kind);
    index_ = std::move(index);
    material_ = std::move(material);
    bounds_ = std::move(bounds);
    pov_ = std::move(pov);
    unbounded_ = std::move(unbounded);
    lanes_.build(tree_.ids(), spheres_.data(), sphere_count_);
    hides_ = {};
    for (const Material& m : materials_) {
        for (size_t u = 0; u < kRayUses; ++u)
            hides_[u] = hides_[u] || frame_hides(m.frame, ray_flags(RayUse(u)));
    }
    // A box's resident scene is what it keeps: drop the growth slack of push_back.
    spheres_.shrink_to_fit();
    triangles_.shrink_to_fit();
    planes_.shrink_to_fit();
    objects_.shrink_to_fit();
    leaf_materials_.shrink_to_fit();
    material_frame_.shrink_to_fit();
    pov_.shrink_to_fit();
}

size_t PreparedScene::resident_bytes() const {
    auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    const auto& ts = tree_.stats();
    return sizeof(*this) + bytes(materials_) + bytes(material_frame_) + bytes(kind_) +
           bytes(index_) + bytes(material_) + bytes(bounds_) + bytes(spheres_) +
           bytes(triangles_) + bytes(planes_) + bytes(objects_) + bytes(unbounded_) +
           bytes(leaf_materials_) + bytes(pov_) + bytes(blends_) + lanes_.bytes() +
           size_t(ts.nodes) * sizeof(octree::Octree::Node) +
           ts.references * sizeof(uint32_t) +
           (ts.dense_top > 0 ? (size_t(1) << (3 * ts.dense_top)) : 0) *
               sizeof(octree::Octree::Node);
}

Material material_of(const Object& o, const LayeredTexture& texture) {
    Material m;
    m.texture = &texture;
    m.interior = o.interior ? &*o.interior : nullptr;
    m.object = &o;
    m.interior_id = interior_key(o);
    m.frame = FrameFlags{o.no_shadow, o.no_image, o.no_reflection, o.no_radiosity};
    m.radiosity_importance = o.radiosity_importance;
    m.double_illuminate = o.double_illuminate;
    m.uv_mapping = o.uv_mapping;
    m.global_lights = o.global_lights;
    m.light_group = o.light_group;
    m.opaque = texture_opaque(texture);
    if (!o.interior_texture->empty()) {
        m.interior_texture = &*o.interior_texture;
        m.opaque = m.opaque && texture_opaque(*o.interior_texture);
    }
    if (texture_is_plain(texture)) {
        m.plain = true;
        m.plain_colour = texture.front().pigment.colour;
        m.plain_finish = *texture.front().finish;
    }
    return m;
}

namespace {

// How far from corner `a` toward the side b-c the point `q` lies (0 at a, 1 on the side),
// as POV-Ray's smooth-triangle helper finds it: the line from a through q meets the side
// at b + s (c - b); each step solves in the first pair of axes whose determinant is not
// below EPSILON (1e-10, absolute).
Real corner_fraction(const Point3& q, const Point3& a, const Point3& b, const Point3& c) {
    constexpr Real kEpsilon = 1e-10;
    const Vector3 qa = q - a, cb = b - c, ba = b - a;
    // Determinants of the pairs (x, y), (x, z), (y, z) of the two directions q - a and
    // b - c.
    const Real dxy = qa.x * cb.y - qa.y * cb.x, dxz = qa.x * cb.z - qa.z * cb.x,
               dyz = qa.y * cb.z - qa.z * cb.y;
    Real s;
    if (dxy * dxy >= kEpsilon)
        s = (qa.x * ba.y - qa.y * ba.x) / dxy;
    else if (dxz * dxz >= kEpsilon)
        s = (qa.x * ba.z - qa.z * ba.x) / dxz;
    else if (dyz * dyz >= kEpsilon)
        s = (qa.y * ba.z - qa.z * ba.y) / dyz;
    else
        return 0;                                // q too close to a to tell
    const Vector3 side = (b + (c - b) * s) - a;  // from a to where the line meets b-c
    if (side.x * side.x >= kEpsilon) return qa.x / side.x;
    if (side.y * side.y >= kEpsilon) return qa.y / side.y;
    if (side.z * side.z >= kEpsilon) return qa.z / side.z;
    return 0;
}

}  // namespace

void blend_weights(const TextureBlend& b, const Point3& world, float (&w)[3]) {
    const Object& mesh = *b.mesh;
    const Point3 q =
        mesh.transform.is_identity() ? world : mesh.transform.inverse_point(world);
    const Point3* p = b.points;
    // In POV-Ray's precision: the fractions and weights are single-precision colour
    // values.
    for (int k = 0; k < 3; ++k)
        w[k] = float(1.0 - double(float(corner_fraction(q, p[k], p[(k + 1) % 3],
                                                        p[(k + 2) % 3]))));
    const float inverse = float(1.0 / double(w[0] + w[1] + w[2]));
    for (float& x : w) x *= inverse;
}

Material interior_side(const Material& m) {
    Material in = m;
    const LayeredTexture& texture = *m.interior_texture;
    in.texture = &texture;
    in.interior_texture = nullptr;
    in.blend = nullptr;  // the interior texture takes the place of the corners' too
    in.blob_blend = nullptr;
    in.plain = texture_is_plain(texture);
    if (in.plain) {
        in.plain_colour = texture.front().pigment.colour;
        in.plain_finish = *texture.front().finish;
    }
    return in;
}

uint32_t PreparedScene::add_material(const Object& o) {
    materials_.push_back(material_of(o, o.texture));
    material_frame_.push_back(adding_frame_);
    uint32_t index = uint32_t(materials_.size()) - 1;
    leaf_materials_.push_back({&o, index});
    const Blob* blob = std::get_if<Blob>(&o.shape);
    if (blob && !blob->element_textures.empty()) {
        // Each element's texture a material of its own (the blob's own texture, without
        // the blend, for an element given none), blended at the hit.
        BlobTextureBlend b;
        b.blob = &o;
        bool opaque = materials_[index].opaque;
        for (const LayeredTexture& t : blob->element_textures) {
            materials_.push_back(material_of(o, t.empty() ? o.texture : t));
            material_frame_.push_back(adding_frame_);
            b.elements.push_back(&materials_.back());
            opaque = opaque && materials_.back().opaque;
        }
        blob_blends_.push_back(std::move(b));
        Material& m = materials_[index];
        m.blob_blend = &blob_blends_.back();
        m.plain = false;
        m.opaque = opaque;
    }
    if (const Mesh* mesh = std::get_if<Mesh>(&o.shape);
        mesh && (!mesh->textures.empty() || !mesh->data->texture_triples.empty()))
        add_face_materials(o, *mesh, index);
    return index;
}

void PreparedScene::add_face_materials(const Object& o, const Mesh& m, uint32_t base) {
    std::vector<uint32_t> face_materials;
    for (const LayeredTexture& t : m.textures) {
        // Each face texture is a material of its own (plain or not by itself), in the
        // same place as the mesh's.
        materials_.push_back(material_of(o, t));
        material_frame_.push_back(material_frame_[base]);
        face_materials.push_back(uint32_t(materials_.size()) - 1);
    }
    // A face with a texture per corner: its own material, blending the corners'.
    auto blend_material = [&](const Mesh::Face& f) {
        const auto& triple = m->texture_triples[size_t(-2 - f.texture)];
        TextureBlend b;
        b.mesh = &o;
        Material mm = material_of(o, o.texture);
        mm.plain = false;
        for (int k = 0; k < 3; ++k) {
            b.points[k] = single_precision(m->vertices[f.v[k]]);
            b.corners[k] = &materials_[face_materials[size_t(triple[size_t(k)])]];
            mm.opaque = mm.opaque && b.corners[k]->opaque;
        }
        // POV-Ray turns some triangles by swapping their first two corners (with
        // their textures) where the dominant axis of (p2 - p0) x (p1 - p0) wants
        // it; the weights are found from the corners in that order.
        const Point3* p = b.points;
        const Vector3 n = cross(p[2] - p[0], p[1] - p[0]);
        const Real ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
        const int axis = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
        if ((p[1][u] - p[2][u]) * (p[1][v] - p[0][v]) <
            (p[1][v] - p[2][v]) * (p[1][u] - p[0][u])) {
            std::swap(b.points[0], b.points[1]);
            std::swap(b.corners[0], b.corners[1]);
        }
        blends_.push_back(b);
        mm.blend = &blends_.back();
        materials_.push_back(mm);
        material_frame_.push_back(material_frame_[base]);
        return uint32_t(materials_.size()) - 1;
    };
    std::vector<uint32_t> of_face(m->faces.size(), base);
    for (size_t fi = 0; fi < m->faces.size(); ++fi) {
        const Mesh::Face& f = m->faces[fi];
        if (f.texture >= 0 && size_t(f.texture) < face_materials.size())
            of_face[fi] = face_materials[size_t(f.texture)];
        else if (f.texture <= -2)
            of_face[fi] = blend_material(f);
    }
    face_materials_.emplace(&o, std::move(of_face));
}

const std::vector<uint32_t>* PreparedScene::mesh_face_materials(const Object& o) const {
    const auto it = face_materials_.find(&o);
    return it == face_materials_.end() ? nullptr : &it->second;
}

int blob_texture_weights(const BlobTextureBlend& b, const Point3& world, float min_weight,
                         std::vector<const Material*>& materials, std::vector<float>& w) {
    const Object& o = *b.blob;
    if (std::holds_alternative<Csg>(o.shape))
        return cutaway_texture_weights(b, world, min_weight, materials, w);
    const Blob& blob = std::get<Blob>(o.shape);
    const Point3 q = o.transform.is_identity() ? world : o.transform.inverse_point(world);
    materials.clear();
    w.clear();
    // POV-Ray's weights are single-precision colour values, summed and scaled so.
    float sum = 0;
    thread_local std::vector<uint32_t> near;
    blob_elements_at(*blob.data, q, near);
    for (const uint32_t i : near) {
        const Real d = std::fabs(blob_element_field(blob.data->elements[i], q));
        if (!(d > 0.0)) continue;
        materials.push_back(b.elements[i]);
        w.push_back(float(d));
        sum += float(d);
    }
    if (w.empty()) return 0;
    const float inverse = float(1.0 / double(sum));
    size_t kept = 0;
    for (size_t i = 0; i < w.size(); ++i) {
        const float x = w[i] * inverse;
        if (x < min_weight) continue;
        materials[kept] = materials[i];
        w[kept++] = x;
    }
    materials.resize(kept);
    w.resize(kept);
    return int(kept);
}

bool texture_is_plain(const LayeredTexture& layers) {
    if (layers.size() != 1) return false;
    const Texture& t = layers.front();
    return pigment_is_solid(t.pigment) && !t.normal && !t.map_pattern &&
           t.map->entries.empty();
}

const Material* PreparedScene::material_for(const Object* leaf) const {
    auto it = std::lower_bound(leaf_materials_.begin(), leaf_materials_.end(),
                               std::make_pair(leaf, uint32_t(0)));
    if (it != leaf_materials_.end() && it->first == leaf) return &materials_[it->second];
    return nullptr;
}

uint32_t PreparedScene::add_object(const Object& o, uint32_t frame) {
    const Csg* csg = std::get_if<Csg>(&o.shape);
    if (pov_splits_union(o)) {
        // A plain union is its children: each goes into the octree on its own and, as
        // POV-Ray links them, takes its own place in the object list. (Counted as they
        // are added: a union nested N deep, as scenes grow one in a loop, costs O(N).)
        uint32_t added = 0;
        for (const Object& c : csg->children) {
            const uint32_t n = add_object(c, frame);
            added += n;
            if (frame < kSameFrame) frame += n;
        }
        return added;
    }
    const size_t first = materials_.size();
    add_frame_object(o, frame);
    const FrameFlags flags = frame_flags(o);
    for (size_t i = first; i < materials_.size(); ++i) materials_[i].frame = flags;
    note_hits_beyond_box(o, first);
    return 1;
}

namespace {

// For a frame object whose surface POV-Ray may meet outside its box (beyond_box set): the
// hull of that surface and the box (empty for every other object).
Bounds3 beyond_box_hull(const Object& o, PovBBox& box) {
    if (!may_hit_outside_pov_box(o)) return {};
    box = pov_object_bbox(o);
    // An infinite box is keyed first in the walk, which always tests it.
    if (!pov_bbox_finite(box)) return {};
    const Bounds3 surface = object_bounds(o);
    if (surface.empty()) return {};
    const Bounds3 pov = pov_bbox_bounds(box);
    bool beyond = surface.infinite();
    for (int a = 0; a < 3 && !beyond; ++a) {
        // The box is single precision: only a surface beyond its rounding is beyond it.
        const Real margin = 1e-6 * (std::fabs(pov.lo[a]) + std::fabs(pov.hi[a])) + 1e-9;
        beyond = surface.lo[a] < pov.lo[a] - margin || surface.hi[a] > pov.hi[a] + margin;
    }
    if (!beyond) return {};
    Bounds3 hull = surface;
    hull.extend(pov);
    return hull;
}

}  // namespace

Bounds3 pov_walk_reach(const Object& obj) {
    Bounds3 reach;
    if (pov_splits_union(obj)) {
        for (const Object& c : std::get<Csg>(obj.shape).children)
            reach.extend(pov_walk_reach(c));
        return reach;
    }
    PovBBox box;
    return beyond_box_hull(obj, box);
}

void PreparedScene::note_hits_beyond_box(const Object& o, size_t first_material) {
    // Without the slab tree POV-Ray tests every object.
    if (!pov_slab_tree_ || first_material == materials_.size()) return;
    PovBBox box;
    if (!beyond_box_hull(o, box).empty())
        beyond_box_frames_.push_back(
            {uint32_t(first_material), uint32_t(materials_.size()), box});
}

const PreparedScene::BeyondBoxFrame* PreparedScene::beyond_box_frame(
    uint32_t material) const {
    auto it =
        std::upper_bound(beyond_box_frames_.begin(), beyond_box_frames_.end(), material,
                         [](uint32_t m, const BeyondBoxFrame& f) { return m < f.first; });
    if (it == beyond_box_frames_.begin()) return nullptr;
    --it;
    return material < it->end ? &*it : nullptr;
}

void PreparedScene::add_frame_object(const Object& o, uint32_t frame) {
    const Csg* csg = std::get_if<Csg>(&o.shape);
    if (frame != kSameFrame) {
        adding_frame_ = frame;
    }
    auto push = [&](PrimKind k, uint32_t index, uint32_t material, const Bounds3& b,
                    const PovPrim& pov = {}) {
        kind_.push_back(k);
        index_.push_back(index);
        material_.push_back(material);
        bounds_.push_back(b);
        if (k != PrimKind::Sphere) pov_.push_back(pov);
    };
    Real scale = 1;
    // (A bounded_by shrinks a shape's POV-Ray box: such spheres and planes take the
    // general path, which tests that box.)
    if (auto s = std::get_if<Sphere>(&o.shape);
        s && !s->pov_matrix && !o.inverse && o.clipped_by.empty() &&
        o.bounded_by.empty() && is_similarity(o.transform, scale)) {
        Point3 c = o.transform.point(s->centre);
        Real r = s->radius * scale;
        uint32_t index = uint32_t(spheres_.size());
        spheres_.push_back({c.x, c.y, c.z, r});
        push(PrimKind::Sphere, index, add_material(o), {c - Vector3(r), c + Vector3(r)});
        return;
    }
    if (auto pl = std::get_if<Plane>(&o.shape);
        pl && !o.inverse && o.clipped_by.empty() && o.bounded_by.empty() &&
        is_similarity(o.transform, scale)) {
        // Ground planes are tested by every ray: keep them out of the general object
        // path.
        Vector3 n = normalize(o.transform.normal(pl->normal));
        Point3 on = o.transform.point(pl->normal * pl->distance);
        planes_.push_back(
            {n, dot(n, on), kPlaneTolerance * scale});  // tolerance: world units
        push(PrimKind::Plane, uint32_t(planes_.size()) - 1, add_material(o),
             Bounds3::everything());
        return;
    }
    if (auto m = std::get_if<Mesh>(&o.shape); m && mesh_as_triangles(o)) {
        // (add_material gave the mesh's faces their materials: face_materials.)
        const uint32_t base = add_material(o);
        const std::vector<uint32_t>* face_materials = mesh_face_materials(o);
        // POV-Ray tests the mesh's box, then the triangle's in the mesh's tree.
        const PovPrim mesh_pov = pov_prim(o, kPovMeshTriangle);
        const bool mirrored =
            dot(cross(o.transform.vector({1, 0, 0}), o.transform.vector({0, 1, 0})),
                o.transform.vector({0, 0, 1})) < 0;
        for (size_t fi = 0; fi < m->data->faces.size(); ++fi) {
            const Mesh::Face& f = m->data->faces[fi];
            TrianglePrim tri;
            tri.mirrored = mirrored;
            tri.face = uint32_t(fi);
            Bounds3 b;
            for (int k = 0; k < 3; ++k) {
                // POV-Ray keeps a mesh's vertices in single precision.
                tri.p[k] = o.transform.point(single_precision(m->data->vertices[f.v[k]]));
                b.extend(tri.p[k]);
                if (f.n[k] >= 0 && size_t(f.n[k]) < m->data->normals.size()) {
                    // POV-Ray interpolates the unit normals in the mesh's space and
                    // then turns the result out: the turned normals are not made unit
                    // again (a non-uniform scale weighs them as it does).
                    tri.n[k] = o.transform.normal(normalize(m->data->normals[f.n[k]]));
                    tri.smooth = true;
                }
            }
            const uint32_t mat = face_materials ? (*face_materials)[fi] : base;
            triangles_.push_back(tri);
            push(PrimKind::Triangle, uint32_t(triangles_.size()) - 1, mat, b, mesh_pov);
        }
        return;
    }
    // Everything else goes through the general object path; CSG leaves get materials too.
    uint32_t mat;
    if (csg) {
        std::vector<const Object*> textured;
        for_each_leaf_and_csg(o, [&](const Object& leaf, const Object* named) {
            const uint32_t index = add_material(leaf);
            if (!leaf.texture.empty() || !named || materials_[index].blob_blend) return;
            // cutaway_textures: its surface shows the textures of the CSG's parts
            // (trace/cutaway_textures.h), each a material of this leaf.
            BlobTextureBlend b;
            b.blob = named;
            bool opaque = true;
            textured.clear();
            cutaway_textured_leaves(*named, textured);
            for (const Object* part : textured) {
                Material sub = material_of(leaf, part->texture);
                sub.interior_texture = nullptr;
                materials_.push_back(sub);
                material_frame_.push_back(adding_frame_);
                b.elements.push_back(&materials_.back());
                opaque = opaque && sub.opaque;
            }
            blob_blends_.push_back(std::move(b));
            Material& m = materials_[index];
            m.blob_blend = &blob_blends_.back();
            m.plain = false;
            m.opaque = opaque;
        });
        mat = 0;
    } else {
        mat = add_material(o);
    }
    objects_.push_back(&o);
    push(PrimKind::Object, uint32_t(objects_.size()) - 1, mat, object_bounds(o),
         pov_prim(o));
}

PreparedScene::PovPrim PreparedScene::pov_prim(const Object& o, uint8_t extra) const {
    PovPrim p;
    if (!options_.pov_float_bounds) return p;
    p.box = pov_object_bbox(o);
    p.tests = extra;
    if (pov_slab_tree_ && pov_bbox_finite(p.box)) p.tests |= kPovSlabTree;
    if (pov_tests_own_bbox(o)) p.tests |= kPovOwnBox;
    return p;
}

// Whether slab_tree_accepts(pov_sphere_bbox(c, r), PovRay(ray)) surely holds, decided in
// double without the float test: the midpoint of the ray's chord through the sphere
// (at tca = (c - o).d) lies inside the sphere's box by a margin m. Each float slab bound
// along axis a is (corner - o) / d_a with the corner, origin, 1/d_a and the two products
// rounded to float: off by less than 10 * 2^-24 * (|c| + r + |o|) / |d_a|, while the
// exact bounds lie m / |d_a| before and after tca. So with m beyond that error (32 *
// 2^-24 here) every entry stays below every exit, and the exits above tca > EPSILON. Rays
// with a component below 1e-20 (1/d beyond float) and coordinates beyond 1e15 are left to
// the float test, as are NaNs (every compare fails).
static inline bool pov_sphere_box_surely_accepts(Real cx, Real cy, Real cz, Real r,
                                                 const Ray& ray) {
    const Vector3& d = ray.direction;
    const Real ocx = cx - ray.origin.x, ocy = cy - ray.origin.y, ocz = cz - ray.origin.z;
    const Real tca = ocx * d.x + ocy * d.y + ocz * d.z;
    if (!(tca > 1e-6)) return false;
    const Real far = std::max({std::fabs(ocx - d.x * tca), std::fabs(ocy - d.y * tca),
                               std::fabs(ocz - d.z * tca)});
    const Real scale = std::max({std::fabs(cx), std::fabs(cy), std::fabs(cz)}) + r +
                       std::max({std::fabs(ray.origin.x), std::fabs(ray.origin.y),
                                 std::fabs(ray.origin.z)});
    auto representable = [](Real v) { return v == 0 || std::fabs(v) >= 1e-20; };
    return r - far > 32.0 / 16777216.0 * scale && scale < 1e15 && representable(d.x) &&
           representable(d.y) && representable(d.z);
}

bool PreparedScene::pov_accepts(uint32_t id, const PovRayOnce& pov_ray) const {
    auto root_accepts = [this](const PovRayOnce& r) {
        return r.root_accepts(
            [this](const PovRay& p) { return slab_tree_accepts(pov_root_, p); });
    };
    if (id < sphere_count_) {
        if (!pov_slab_tree_) return true;
        const SpherePrim& s = spheres_[id];
        return (!pov_root_tested_ || root_accepts(pov_ray)) &&
               (pov_sphere_box_surely_accepts(s.x, s.y, s.z, s.r, pov_ray.ray()) ||
                slab_tree_accepts(pov_sphere_bbox({s.x, s.y, s.z}, s.r), pov_ray.get()));
    }
    const PovPrim& p = pov_[id - sphere_count_];
    if (!p.tests) return true;
    const PovRay& r = pov_ray.get();
    if ((p.tests & kPovSlabTree) && pov_root_tested_ && !root_accepts(pov_ray))
        return false;
    if ((p.tests & kPovSlabTree) && !slab_tree_accepts(p.box, r)) return false;
    if ((p.tests & kPovOwnBox) &&
        !own_bbox_accepts(p.box, r, float(kMinIsectDepth),
                          std::numeric_limits<float>::infinity()))
        return false;
    if (p.tests & kPovMeshTriangle) {
        // The triangle's box in the mesh's tree, met by the ray in the mesh's space.
        const Object& mesh = *materials_[material_[id]].object;
        const TrianglePrim& t = triangles_[index_[id]];
        Point3 local[3];
        for (int k = 0; k < 3; ++k)
            local[k] = mesh.transform.is_identity()
                           ? t.p[k]
                           : mesh.transform.inverse_point(t.p[k]);
        const Ray& ray = pov_ray.ray();
        const Ray in_mesh =
            mesh.transform.is_identity() ? ray : mesh.transform.inverse_ray(ray);
        if (!slab_tree_accepts(pov_mesh_triangle_bbox(local), PovRay(in_mesh)))
            return false;
    }
    return true;
}

inline Real sphere_distance(const PreparedScene::SpherePrim& sp, const Ray& ray,
                            Real lo) {
    return sphere_distance(sp.x, sp.y, sp.z, sp.r, ray, lo);
}

// pov_accepts' first tests of a primitive in the slab tree, inline for the leaf loops
// (most candidates in a leaf fail them): whether the tree's root (when tested) or the
// primitive's box turns the ray away.
inline bool pov_slab_rejects(const PovBBox& box, bool root_tested, const PovBBox& root,
                             const PovRayOnce& pov_ray) {
    if (root_tested &&
        !pov_ray.root_accepts([&](const PovRay& r) { return slab_test(root, r); }))
        return true;
    return !slab_test(box, pov_ray.get());
}

// How many of a leaf's ids (sorted) are spheres: they come first.
inline size_t leading_spheres(const uint32_t* ids, size_t n, uint32_t sphere_count) {
    if (n == 0 || ids[n - 1] < sphere_count) return n;
    return size_t(std::lower_bound(ids, ids + n, sphere_count) - ids);
}

bool PreparedScene::test_primitive(uint32_t id, const Ray& ray, const PovRayOnce& pov_ray,
                                   Real t_min, Real t_max, Hit& hit, Real tie_tolerance,
                                   bool* tie, bool material_only,
                                   const RayFlags* flags) const {
    const Real lo = std::max(t_min, kMinIsectDepth);
    switch (kind_[id]) {
        case PrimKind::Sphere: {
            // Spheres are primitives 0 .. sphere_count_ - 1: spheres_[id] is this one.
            const Real t = sphere_distance(spheres_[id], ray, lo);
            if (!(t < t_max) || !pov_accepts(id, pov_ray)) return false;
            fill_sphere_hit(id, ray, t, hit);
            return true;
        }
        case PrimKind::Plane: {
            const PlanePrim& pl = planes_[index_[id]];
            // A ray pointing away from the plane misses it: the object-space depth below
            // would be negative. Decided without the square root and the three divisions
            // only where the direction's sign cannot change when it is normalised.
            const Real away = pl.distance - dot(pl.normal, ray.origin);
            const Real toward = dot(pl.normal, ray.direction);
            const Real scale = std::fabs(pl.normal.x * ray.direction.x) +
                               std::fabs(pl.normal.y * ray.direction.y) +
                               std::fabs(pl.normal.z * ray.direction.z);
            if (std::fabs(toward) > 1e-9 * scale && (away < 0) == (toward > 0) &&
                away != 0)
                return false;
            // Far outside [lo, t_max] (a black box's stretch of the ray, which an
            // infinite plane is tested on in every box it reaches): out without the exact
            // arithmetic. The margins dwarf the rounding between the two quotients.
            if (std::fabs(toward) > 1e-9 * scale) {
                const Real rough = away / toward;
                if (rough > t_max * (1 + 1e-7) + 1e-7 || rough < lo * (1 - 1e-7) - 1e-7)
                    return false;
            }
            // POV-Ray's arithmetic for a plane it keeps without a transform (translate,
            // rotate and uniform scale move its normal and distance): the depth along the
            // ray as given, -(n.o - d) / n.dir, with no re-normalisation, so that a face
            // lying on the plane (a box's, whose depth is (d - o) / dir along the same
            // axis) gives the very same bits and POV-Ray's test order decides
            // (planes.cpp Plane::Intersect).
            const Real nd = dot(pl.normal, ray.direction);
            if (std::fabs(nd) < kPovEpsilon) return false;
            const Real t = (pl.distance - dot(pl.normal, ray.origin)) / nd;
            if (!(t > pl.tolerance && t < kMaxDistance)) return false;
            if (!(t >= lo && t < t_max)) return false;
            hit.t = t;
            hit.prim = id;
            hit.point = ray.at(t);
            hit.normal = pl.normal;
            hit.material = &materials_[material_[id]];
            return true;
        }
        case PrimKind::Triangle: {
            const TrianglePrim& tri = triangles_[index_[id]];
            Crossings cs;
            intersect_triangle(tri.p, ray.origin, ray.direction, cs);
            if (!cs.n || cs.c[0].t < lo || cs.c[0].t >= t_max) return false;
            if (!pov_accepts(id, pov_ray)) return false;
            hit.t = cs.c[0].t;
            hit.prim = id;
            hit.point = ray.at(hit.t);
            if (tri.smooth) {
                hit.normal = normalize(smooth_triangle_normal(tri.p, tri.n, hit.point));
            } else {
                hit.normal = normalize(pov_triangle_normal(tri.p));
                if (tri.mirrored) hit.normal = -hit.normal;
            }
            hit.material = &materials_[material_[id]];
            hit.face = int32_t(tri.face);
            return true;
        }
        case PrimKind::Object: {
            const Object& obj = *objects_[index_[id]];
            // POV-Ray's bounding boxes first, as POV-Ray tests them before the shape: a
            // ray they turn away needs no crossings.
            if (!pov_accepts(id, pov_ray)) return false;
            if (pov_keeps_bound(obj) && !ray_in_bound(*obj.bounded_by, ray)) return false;
            thread_local std::vector<WorldCrossing> own;
            const std::vector<WorldCrossing>* found = nullptr;
            if (flags && flags->shadow && reuses_crossings_[id]) {
                thread_local ShadowCrossings reused;
                reused.start(serial_, ray, *flags);
                found = reused.find(id);
                if (!found) {
                    if (std::vector<WorldCrossing>* fill = reused.add(id)) {
                        // All its crossings (a CSG passes no wanted range to its
                        // children, and these leaves give all theirs anyway).
                        object_crossings(obj, ray, *fill, false, nullptr, flags);
                        found = fill;
                    }
                }
            }
            if (!found) {
                own.clear();
                const WantedRange wanted{lo, t_max, material_only};
                object_crossings(obj, ray, own, false, &wanted, flags);
                found = &own;
            }
            const std::vector<WorldCrossing>& crossings = *found;
            // The crossings are in the order POV-Ray pops them last (object_crossings):
            // of equal depths it keeps the last.
            const WorldCrossing* best = nullptr;
            for (const auto& c : crossings) {
                if (c.t >= lo && c.t < t_max && (!best || c.t <= best->t)) best = &c;
            }
            if (!best) return false;
            if (tie) {
                for (const auto& c : crossings) {
                    if (c.leaf != best->leaf && c.t >= lo &&
                        std::fabs(c.t - best->t) <= tie_tolerance * std::fabs(best->t))
                        *tie = true;
                }
            }
            hit.t = best->t;
            hit.prim = id;
            hit.point = best->at(ray);
            // (material_only: a leaf outside CSG may have given any of its crossings.)
            if (!material_only) hit.normal = best->normal(hit.point);
            // A leaf object's own material is the primitive's (add_material gave both);
            // a CSG's leaves are looked up.
            hit.material = best->leaf == &obj && !std::holds_alternative<Csg>(obj.shape)
                               ? &materials_[material_[id]]
                               : material_for(best->leaf);
            if (!hit.material) hit.material = &materials_[material_[id]];
            // A mesh's face with a texture of its own (clipped, inverse or in a CSG; a
            // mesh alone is triangles with their face materials).
            if (std::holds_alternative<Mesh>(best->leaf->shape)) {
                const std::vector<uint32_t>* faces = mesh_face_materials(*best->leaf);
                if (faces && size_t(best->hit.face) < faces->size())
                    hit.material = &materials_[(*faces)[size_t(best->hit.face)]];
            }
            hit.face = best->hit.face;
            hit.param = best->hit.param;
            hit.param2 = best->hit.param2;
            return true;
        }
    }
    return false;
}

void PreparedScene::fill_sphere_hit(uint32_t id, const Ray& ray, Real t, Hit& hit) const {
    const SpherePrim& sp = spheres_[id];
    hit.t = t;
    hit.prim = id;
    hit.point = ray.at(t);
    hit.normal = (hit.point - Point3{sp.x, sp.y, sp.z}) / sp.r;
    hit.material = &materials_[material_[id]];
}

template <class OnHit>
bool PreparedScene::for_sphere_hits(const uint32_t* ids, size_t spheres, const Ray& ray,
                                    Real lo, const Real& below, RayContext& ctx,
                                    OnHit&& on_hit) const {
    const size_t at = size_t(ids - tree_.ids().data());
    Real t[kMaxSphereRun];
    for (size_t done = 0; done < spheres; done += kMaxSphereRun) {
        const size_t m = std::min(kMaxSphereRun, spheres - done);
        const size_t p = at + done;
        // POV-Ray keeps no sphere hit at or past MAX_DISTANCE.
        uint64_t hits =
            sphere_distances(lanes_.run(p), m, ray, lo, std::min(below, kMaxDistance), t);
        ctx.tests += m;
        for (; hits; hits &= hits - 1) {
            const size_t i = size_t(__builtin_ctzll(hits));
            if (!(t[i] < below)) continue;  // `below` shrank since
            if (on_hit(ids[done + i], t[i], p + i)) return true;
        }
    }
    return false;
}

namespace {

// POV-Ray's test order, built on the first exact tie that needs it.
const PovTestOrder& built_pov_order(std::once_flag& once,
                                    std::unique_ptr<PovTestOrder>& order,
                                    const Scene& scene, size_t bounding_threshold,
                                    const PovWholeScene* whole) {
    std::call_once(once, [&] {
        order = std::make_unique<PovTestOrder>(
            pov_frame_list(scene, bounding_threshold, whole));
    });
    return *order;
}

// Frame objects met at one depth along one ray: the first ties are decided by a walk of
// POV-Ray's tree that stops at either object; from the third on, one full walk ranks
// every frame object the ray meets, so N coincident copies cost one walk per ray rather
// than N (320 coincident spheres took 17 s at 160x120 against POV-Ray's 0.9 s).
class TieRanks {
  public:
    bool worth_ranking() { return ++ties_ > 2; }
    // Whether frame `a` is tested before frame `b` along `ray`: PovTestOrder::tests_first
    // from the ranks (a frame the walk never reaches comes last).
    bool tests_first(const PovTestOrder& order, const Ray& ray, uint32_t a, uint32_t b) {
        if (!order.slab_tree()) return a < b;
        thread_local std::vector<uint32_t> rank, stamp;
        thread_local uint32_t generation = 0;
        if (!ranked_) {
            ranked_ = true;
            if (++generation == 0) {  // wrapped: no stale stamp may match
                std::fill(stamp.begin(), stamp.end(), 0u);
                generation = 1;
            }
            const std::vector<uint32_t> walk = order.order(ray);
            for (uint32_t i = 0; i < walk.size(); ++i) {
                const uint32_t f = walk[i];
                if (f >= rank.size()) {
                    rank.resize(f + 1);
                    stamp.resize(f + 1, 0u);
                }
                rank[f] = i;
                stamp[f] = generation;
            }
        }
        auto rank_of = [&](uint32_t f) {
            return f < stamp.size() && stamp[f] == generation ? rank[f] : ~0u;
        };
        const uint32_t ra = rank_of(a), rb = rank_of(b);
        return ra != ~0u && ra < rb;
    }

  private:
    int ties_ = 0;
    bool ranked_ = false;
};

// Whether POV-Ray keeps the candidate (material index `c`, frame object `fc`) over the
// nearest hit so far (`n`, `fn`) at the same depth. `order()` gives POV-Ray's test order;
// `ranks` (may be null) those of the ray's earlier ties.
template <class GetOrder>
bool pov_takes_at_tie(size_t c, uint32_t fc, size_t n, uint32_t fn, const Ray& ray,
                      GetOrder&& order, TieRanks* ranks) {
    if (fc == ~0u || fn == ~0u) return false;
    // Parts of one frame object: its CSG pushes the later child's intersections last and
    // takes the first it pops.
    if (fc == fn) return c > n;
    if (ranks && ranks->worth_ranking()) return ranks->tests_first(order(), ray, fc, fn);
    return order().tests_first(ray, fc, fn);
}

}  // namespace

bool PreparedScene::pov_takes(const Material& candidate, const Material& nearest,
                              const Ray& ray) const {
    const size_t c = size_t(&candidate - materials_.data()),
                 n = size_t(&nearest - materials_.data());
    return pov_takes_at_tie(
        c, material_frame_[c], n, material_frame_[n], ray,
        [this]() -> const PovTestOrder& {
            return built_pov_order(pov_order_once_, pov_order_, scene_,
                                   options_.pov_bounding_threshold,
                                   options_.whole_scene.get());
        },
        nullptr);
}

bool PreparedScene::closest_hit(const Ray& ray, Real t_min, Real t_max, RayUse use,
                                Hit& hit, RayContext& ctx, bool radiosity_ray,
                                Real ray_end) const {
    return closest_hit_without(ray, t_min, t_max, use, hit, ctx, radiosity_ray,
                               ray_end < 0 ? t_max : ray_end, {});
}

// Where `ray` enters `b` (its parameter; -infinity from inside or along an unbounded
// side), a hair early: a lower bound of every hit inside b.
static Real bounds_entry(const Bounds3& b, const Ray& ray) {
    Real entry = -kInfinity;
    for (int a = 0; a < 3; ++a) {
        const Real d = ray.direction[a];
        if (d == 0 || !std::isfinite(b.lo[a]) || !std::isfinite(b.hi[a])) continue;
        const Real near = ((d > 0 ? b.lo[a] : b.hi[a]) - ray.origin[a]) / d;
        entry = std::max(entry, near);
    }
    return entry - 1e-9 * std::fabs(entry);
}

bool PreparedScene::closest_hit_without(const Ray& ray, Real t_min, Real t_max,
                                        RayUse use, Hit& hit, RayContext& ctx,
                                        bool radiosity_ray, Real ray_end,
                                        const LeftOutFrames& left_out) const {
    bool found = false;
    const PovRayOnce pov_ray(ray);
    // pov_accepts() of a sphere, its common answer decided here without the call.
    // The sphere is read from its leaf's lanes (position `q` in lanes_, just loaded by
    // the distance test) rather than from spheres_ (a cache miss there was most of
    // the call's time).
    auto sphere_accepted = [&](uint32_t id, size_t q) {
        return !pov_slab_tree_ ||
               (!pov_root_tested_ &&
                pov_sphere_box_surely_accepts(lanes_.x[q], lanes_.y[q], lanes_.z[q],
                                              lanes_.r[q], ray)) ||
               pov_accepts(id, pov_ray);
    };
    // A general object whose POV-Ray boxes turn the ray away: test_primitive is false.
    auto box_rejects = [&](uint32_t id) {
        const PovPrim& p = pov_[id - sphere_count_];
        return kind_[id] == PrimKind::Object && (p.tests & kPovSlabTree) &&
               pov_slab_rejects(p.box, pov_root_tested_, pov_root_, pov_ray);
    };
    // Materials are only looked at when some object hides from this kind of ray or at a
    // tie: a sphere's candidate hit then costs no load of its (large) material.
    RayFlags flags = ray_flags(use);
    flags.radiosity = flags.radiosity || radiosity_ray;
    flags.restart = ctx.restart;
    const bool may_hide =
        hides_[size_t(use)] || (flags.radiosity && hides_[size_t(RayUse::Radiosity)]);
    const bool may_leave_out = may_hide || left_out.count;
    auto hidden = [&](uint32_t material) {
        return may_leave_out &&
               ((may_hide && frame_hides(materials_[material].frame, flags)) ||
                left_out.holds(material));
    };
    // Spheres: distance only; the nearest one's point and normal are computed once at the
    // end.
    const Real lo = std::max(t_min, kMinIsectDepth);
    uint32_t nearest_sphere = ~0u;
    // The nearest hit so far (its distance and material), and how far tests and the
    // traversal look: a little past it, so that a surface at exactly the same depth
    // (coincident faces) is met wherever its cell starts, and POV-Ray's order can choose
    // (pov_takes). Nothing beyond `best` is taken.
    Real best = t_max;
    uint32_t best_material = ~0u;  // index into materials_
    Real reach = t_max;
    const Real probe = ctx.tie_tolerance;
    bool tie = false;        // tie probe: two leaves within `probe` of each other
    Real other = kInfinity;  // tie probe: the nearest hit on another leaf
    // Hits lie at t >= lo > 0, and a relative margin of at least 1e-12 is thousands of
    // ulps: the product is strictly past t without a call to nextafter (it showed in
    // the seed scene's profile).
    const Real widen_factor = 1 + std::max(probe, Real(1e-12));
    auto widen = [&](Real t) { return std::min(t_max, t * widen_factor); };
    // Whether a hit at `t` on `m` becomes the nearest.
    TieRanks tie_ranks;
    auto pov_order = [this]() -> const PovTestOrder& {
        return built_pov_order(pov_order_once_, pov_order_, scene_,
                               options_.pov_bounding_threshold,
                               options_.whole_scene.get());
    };
    auto same_object = [&](uint32_t a, uint32_t b) {
        return materials_[a].object == materials_[b].object;
    };
    auto offer = [&](Real t, uint32_t m) {
        if (!found) return t < t_max;
        if (t < best) {
            if (probe > 0 && !same_object(m, best_material))
                other = std::min(other, best);
            return true;
        }
        if (same_object(m, best_material)) return false;
        if (probe > 0) other = std::min(other, t);
        return t == best && pov_takes_at_tie(m, material_frame_[m], best_material,
                                             material_frame_[best_material], ray,
                                             pov_order, &tie_ranks);
    };
    auto accept = [&](Real t, uint32_t m) {
        best = t;
        best_material = m;
        reach = widen(t);
        found = true;
    };
    auto consider = [&](uint32_t id) {
        ++ctx.tests;
        if (id < sphere_count_) {
            const Real t = sphere_distance(spheres_[id], ray, lo);
            const uint32_t m = material_[id];
            if (!(t < reach) || hidden(m) || !pov_accepts(id, pov_ray) || !offer(t, m))
                return;
            accept(t, m);
            nearest_sphere = id;
            return;
        }
        Hit h;
        bool inner_tie = false;
        if (!test_primitive(id, ray, pov_ray, t_min, reach, h, probe,
                            probe > 0 ? &inner_tie : nullptr, false, &flags))
            return;
        const uint32_t m = uint32_t(h.material - materials_.data());
        if (hidden(m)) return;
        tie = tie || inner_tie;
        if (!offer(h.t, m)) return;
        accept(h.t, m);
        hit = h;
        nearest_sphere = ~0u;
    };
    for (uint32_t id : unbounded_) consider(id);
    ctx.mailbox.next_ray();
    Real limit = reach;
    tree_.traverse(
        ray, t_min, limit,
        [&](const uint32_t* ids, size_t n, Real& tmax) {
            // A sphere spanning several leaves is simply tested again (cheaper than its
            // mailbox check).
            const size_t spheres = leading_spheres(ids, n, sphere_count_);
            for_sphere_hits(ids, spheres, ray, lo, reach, ctx,
                            [&](uint32_t id, Real t, size_t q) {
                                const uint32_t m = material_[id];
                                if (hidden(m) || !sphere_accepted(id, q) || !offer(t, m))
                                    return false;
                                accept(t, m);
                                nearest_sphere = id;
                                return false;
                            });
            for (size_t i = spheres; i < n; ++i) {
                const uint32_t id = ids[i];
                // Objects hidden from this ray kind can have a hit beyond a visible one:
                // a primitive seen in an earlier leaf was fully tested there.
                if (!ctx.mailbox.first_visit(id)) continue;
                if (box_rejects(id)) {
                    ++ctx.tests;
                    continue;
                }
                // Nothing of it before the nearest hit so far: left out, as POV-Ray's
                // slab tree leaves a box that starts past it (a ray through a stack of
                // see-through plates sharing a leaf tests the next plate, not the whole
                // stack). `reach` only shrinks, so neither this leaf's later tests nor a
                // later leaf would want it.
                if (reach < kInfinity && kind_[id] == PrimKind::Object &&
                    hits_within_bounds_[id] && bounds_entry(bounds_[id], ray) > reach) {
                    ++ctx.tests;
                    continue;
                }
                consider(id);
            }
            tmax = reach;
            return false;
        },
        [this](uint32_t first) { lanes_.prefetch(first); });
    if (nearest_sphere != ~0u) fill_sphere_hit(nearest_sphere, ray, best, hit);
    if (probe > 0 && found && (tie || other - best <= probe * std::fabs(best)))
        ++ctx.ties;
    if (found && !beyond_box_frames_.empty() && left_out.count < 4) {
        // The hit lies before where the ray enters its object's box: POV-Ray's walk met
        // that box only if no other object's hit nearer than the entry was found first
        // (those boxes are entered before it), and otherwise stopped there. The search
        // without it goes on to the entry even past t_max (the end of a black box's part
        // of the ray: the box holds every object there, BoxHost::build_boxes).
        const BeyondBoxFrame* frame = beyond_box_frame(best_material);
        Real entry;
        if (frame && slab_tree_entry(frame->box, pov_ray.get(), entry)) {
            const Real unit = length(ray.direction);
            if (best * unit < entry) {
                LeftOutFrames without = left_out;
                without.frame[without.count++] = frame;
                Hit nearer;
                const Real until = std::min(ray_end, entry / unit * (1 + 1e-12));
                if (closest_hit_without(ray, t_min, until, use, nearer, ctx,
                                        radiosity_ray, ray_end, without) &&
                    nearer.t * unit < entry) {
                    if (!(nearer.t <= t_max)) return false;  // a later box's hit
                    hit = nearer;
                    return true;
                }
                if (ray_end * unit < entry) return false;  // the ray ends before
            }
        }
    }
    return found;
}

bool PreparedScene::opaque_blocker(const Ray& ray, Real t_min, Real t_max,
                                   bool& transparent, RayContext& ctx, int light) const {
    transparent = false;
    const PovRayOnce pov_ray(ray);
    // pov_accepts() of a sphere, its common answer decided here without the call.
    // The sphere is read from its leaf's lanes (position `q` in lanes_, just loaded by
    // the distance test) rather than from spheres_ (a cache miss there was most of
    // the call's time).
    auto sphere_accepted = [&](uint32_t id, size_t q) {
        return !pov_slab_tree_ ||
               (!pov_root_tested_ &&
                pov_sphere_box_surely_accepts(lanes_.x[q], lanes_.y[q], lanes_.z[q],
                                              lanes_.r[q], ray)) ||
               pov_accepts(id, pov_ray);
    };
    // A general object whose POV-Ray boxes turn the ray away: test_primitive is false.
    auto box_rejects = [&](uint32_t id) {
        const PovPrim& p = pov_[id - sphere_count_];
        return kind_[id] == PrimKind::Object && (p.tests & kPovSlabTree) &&
               pov_slab_rejects(p.box, pov_root_tested_, pov_root_, pov_ray);
    };
    const Real lo = std::max(t_min, kMinIsectDepth);
    RayFlags shadow_flags = ray_flags(RayUse::Shadow);
    shadow_flags.restart = ctx.restart;
    // 1: an opaque shadow caster; 0: none; -1: a see-through one.
    // (Inside a CSG POV-Ray's shadow rays meet every child, no_shadow or not.)
    auto caster = [](const Material& m) {
        return m.frame.no_shadow ? 0 : m.opaque ? 1 : -1;
    };
    // `cached`: the light's last blocker, which POV-Ray tests on its own, without its
    // walk.
    auto meets_from = [&](uint32_t id, Real from, bool cached = false) {
        ++ctx.tests;
        if (id < sphere_count_) {
            if (!(sphere_distance(spheres_[id], ray, std::max(from, kMinIsectDepth)) <
                  t_max) ||
                !pov_accepts(id, pov_ray))
                return 0;
            return caster(materials_[material_[id]]);
        }
        Hit h;
        if (!test_primitive(id, ray, pov_ray, from, t_max, h, 0, nullptr, true,
                            &shadow_flags))
            return 0;
        const int kind = caster(*h.material);
        // An object POV-Ray may meet outside its box blocks only if its walk gets there
        // (closest_hit decides): taken as see-through, which sends the caller there.
        if (kind == 1 && !beyond_box_frames_.empty() && !cached &&
            beyond_box_frame(uint32_t(h.material - materials_.data())))
            return -1;
        return kind;
    };
    auto meets = [&](uint32_t id) { return meets_from(id, t_min); };
    uint32_t* cache = light >= 0 && size_t(light) < ctx.last_blocker.size()
                          ? &ctx.last_blocker[size_t(light)]
                          : nullptr;
    // POV-Ray tests the light's cached blocker once, where the shadow ray starts (t_min
    // still its 1e-3 tolerance), and takes any of its hits from MIN_ISECT_DEPTH (1e-4)
    // on, not only those past 1e-3 as the search that follows: so a surface's own
    // spurious hit near the lit point (a lathe's or sor's round-off root) shadows the
    // point when that surface blocked the light's previous shadow ray. Only for a sor or
    // lathe here: what the cache holds depends on the order rays are traced in, which
    // black boxes change, and other shapes meet a ray that close only where two surfaces
    // touch (images would then depend on the box split for a few pixels there).
    constexpr Real kShadowRayStart = 1e-3;  // POV-Ray's SHADOW_TOLERANCE
    auto round_off_near_start = [&](uint32_t id) {
        if (id < sphere_count_ || kind_[id] != PrimKind::Object) return false;
        const Object& o = *objects_[index_[id]];
        return std::holds_alternative<Sor>(o.shape) ||
               std::holds_alternative<Lathe>(o.shape);
    };
    const Real cache_from =
        cache && *cache != ~0u && t_min <= kShadowRayStart && round_off_near_start(*cache)
            ? kMinIsectDepth
            : t_min;
    if (cache && *cache != ~0u && meets_from(*cache, cache_from, true) == 1) return true;
    // True (and remembered) for an opaque caster; notes a see-through one.
    auto blocks = [&](uint32_t id, int r) {
        if (r < 0) transparent = true;
        if (r <= 0) return false;
        if (cache) *cache = id;
        return true;
    };
    for (uint32_t id : unbounded_) {
        if (blocks(id, meets(id))) return true;
    }
    ctx.mailbox.next_ray();
    Real limit = t_max;
    bool blocked = false;
    tree_.traverse(
        ray, t_min, limit,
        [&](const uint32_t* ids, size_t n, Real&) {
            const size_t spheres = leading_spheres(ids, n, sphere_count_);
            if (for_sphere_hits(ids, spheres, ray, lo, t_max, ctx,
                                [&](uint32_t id, Real, size_t q) {
                                    return sphere_accepted(id, q) &&
                                           blocks(id, caster(materials_[material_[id]]));
                                }))
                return blocked = true;
            for (size_t i = spheres; i < n; ++i) {
                if (!ctx.mailbox.first_visit(ids[i])) continue;
                if (box_rejects(ids[i])) {
                    ++ctx.tests;
                    continue;
                }
                if (blocks(ids[i], meets(ids[i]))) return blocked = true;
            }
            return false;
        },
        [this](uint32_t first) { lanes_.prefetch(first); });
    return blocked;
}

}  // namespace povwall::trace
