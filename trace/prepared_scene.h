// The scene as the tracer uses it: world-space primitives in structure-of-arrays form, an
// octree over the bounded ones, and the ray queries (closest hit, shadow transmittance).
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "core/scene.h"
#include "octree/octree.h"
#include "trace/pattern.h"
#include "trace/pov_bounds.h"
#include "trace/pov_order.h"
#include "trace/ray_use.h"
#include "trace/render_plan.h"
#include "trace/sphere_lanes.h"

namespace povwall::trace {

class RadiosityGatherer;
namespace radiosity {
struct RadiosityRender;
}

// What a ray may see of an object, and where its surface description lives.
// Which interior an object has, for the interior stack: the parser's number of the
// interior (shared by a CSG's children, see Interior::id), or for a scene built without
// the parser, the object itself.
inline uintptr_t interior_key(const Object& o) {
    return o.interior && o.interior->id != 0 ? uintptr_t(o.interior->id)
                                             : reinterpret_cast<uintptr_t>(&o);
}

struct TextureBlend;
class SubsurfaceTracer;
class PhotonMap;

struct Material {
    const LayeredTexture* texture = nullptr;
    // The object's interior_texture (null: none): what a hit on the inside of its surface
    // shows (see shows_interior_texture()).
    const LayeredTexture* interior_texture = nullptr;
    const Interior* interior = nullptr;  // null: default interior (ior 1)
    const Object* object = nullptr;      // the leaf: its number on the wire
    uintptr_t interior_id = 0;           // interior_key(*object)
    // The flags of the frame object it is part of (ray_use.h): those decide whether a ray
    // passes the whole object by. Inside a CSG each node tests its children's flags by
    // its own rule (csg_skips()).
    FrameFlags frame;
    float radiosity_importance = 0;  // Object::radiosity_importance (<= 0: the default)
    bool double_illuminate = false;
    // Object::uv_mapping: its patterns are evaluated at the hit's (u, v, 0).
    bool uv_mapping = false;
    // Which lights light it (Object::global_lights, Object::light_group).
    bool global_lights = true;
    uint32_t light_group = 0;
    // No filter or transmit anywhere in its textures (interior_texture included).
    bool opaque = true;
    // The common texture (one layer, a solid pigment, no normal, no map) copied here, so
    // that shading reads this small record instead of the object's 1.4 KB Texture: its
    // cache misses were a third of spawn_children's time on the seed scene.
    bool plain = false;
    Colour plain_colour;
    Finish plain_finish;
    // A mesh face with a texture per corner (null: none): shading blends the three
    // corners' materials (see blend_weights()); `texture` is unused then.
    const TextureBlend* blend = nullptr;
    // A blob with textures on its components (null: none): shading blends the elements'
    // materials by the weights blob_texture_weights() gives.
    const struct BlobTextureBlend* blob_blend = nullptr;
    // A texture_map entry's stand-in (shading only): the map patterns it is nested in,
    // innermost first (its patterns are evaluated at the innermost's point, POV-Ray
    // nests pattern spaces); null: at the hit point.
    const struct TextureNesting* nesting = nullptr;
};

// One texture_map level a stand-in material is shaded in: the map pattern and the
// point in its space (shading keeps these on the stack while it shades the entry).
struct TextureNesting {
    const PatternSpec* pattern;
    Point3 point;
    const TextureNesting* outer;
};

// A blob's per-element materials (POV-Ray's Blob::Determine_Textures).
struct BlobTextureBlend {
    const Object* blob = nullptr;
    std::vector<const Material*> elements;  // one per element
};
// The elements touching a world point and their weights (|element field| there, in
// single precision, normalised to sum 1), in the element order, without those whose
// weight is below `min_weight` (POV-Ray leaves out textures under adc_bailout); returns
// their count.
int blob_texture_weights(const BlobTextureBlend& b, const Point3& world, float min_weight,
                         std::vector<const Material*>& materials, std::vector<float>& w);

// A mesh face with three textures (Mesh::texture_triples): POV-Ray blends them by the
// hit's weights toward each corner (Mesh::Determine_Textures), in mesh space.
struct TextureBlend {
    const Material* corners[3] = {};  // each corner's texture, as a face material
    Point3 points[3];                 // mesh space, single precision, POV-Ray's order
    const Object* mesh = nullptr;
};
// The three weights at a world point, normalised to sum 1 (POV-Ray's: each is 1 - the
// fraction of the way from its corner to the opposite side, in the triangle's plane, with
// POV-Ray's absolute EPSILON tests, so corners of tiny triangles weigh alike).
void blend_weights(const TextureBlend& b, const Point3& world, float (&w)[3]);

// The material of object `o` seen with `texture` (its own, or a mesh face's).
Material material_of(const Object& o, const LayeredTexture& texture);
// The same material seen from inside: its interior_texture in place of its texture
// (`m.interior_texture` must be set). A stand-in for shading one hit; interior stacks
// must keep naming `m`.
Material interior_side(const Material& m);

// A single colour everywhere: no pattern, list or colour map.
inline bool pigment_is_solid(const Pigment& p) {
    // (A quick_color makes it a pattern: low +Q levels show that colour instead.)
    return p.pattern->kind == PatternKind::Solid && p.maps->list.empty() &&
           p.maps->colour_map.empty() && !p.maps->quick_colour;
}
// Whether a texture is `plain` in the sense of Material::plain.
bool texture_is_plain(const LayeredTexture& layers);

enum class PrimKind : uint8_t { Sphere, Triangle, Plane, Object };

struct TrianglePrim {
    Point3 p[3];
    Vector3 n[3];
    bool smooth = false;
    uint32_t face = 0;  // its index in the mesh's faces (its texture coordinates)
    // The mesh's transform mirrors: the corners' normal points against the one POV-Ray
    // transforms from mesh space.
    bool mirrored = false;
};

struct Hit {
    Real t = kInfinity;
    uint32_t prim = 0;
    Point3 point;
    // World space, unit, outward with POV-Ray's sign for the surface (its raw normal:
    // flat triangles and polygons by their corners' order; not yet flipped toward the
    // ray).
    Vector3 normal;
    const Material* material = nullptr;
    // Where on the leaf's surface (its ShapeHit's face and parameters; a mesh triangle's
    // face index), for the surface coordinates uv_mapping reads (trace/uv_mapping.h).
    int32_t face = 0;
    Real param = 0, param2 = 0;
};

struct RayContext {
    octree::Mailbox mailbox;
    uint64_t tests = 0;
    // Tie probe (diagnostics, off while 0): closest_hit also looks for another surface
    // (another leaf object) within this relative distance of the nearest hit, and counts
    // the rays where it finds one in `ties`.
    Real tie_tolerance = 0;
    uint64_t ties = 0;
    // ... and the hits found on a jump of their surface's pattern (on_pattern_boundary,
    // counted by the tracer and shadow rays).
    uint64_t pattern_ties = 0;
    // Per light: the primitive that last blocked a shadow ray toward it. Neighbouring
    // points are usually shadowed by the same object, so it is tried first.
    std::vector<uint32_t> last_blocker;
    // The radiosity of the thread tracing with this context (trace/radiosity/gatherer.h);
    // null: none (no radiosity, or black boxes).
    RadiosityGatherer* radiosity = nullptr;
    // Subsurface light transport of that thread (trace/subsurface.h); null: none (the
    // scene has none, or black boxes).
    SubsurfaceTracer* subsurface = nullptr;
    // The restart point of the ray being traced (RayFlags::restart).
    Real restart = 0;
};

struct RenderProgress;

// How a scene is prepared, beside what its plan leaves out.
struct PrepareOptions {
    // Threads building the octree (0: every core): the render's --threads.
    int threads = 0;
    // POV-Ray's single-precision bounding-box tests (trace/pov_bounds.h) on every hit:
    // POV-Ray's image. Off: exact bounds, the rules the numerics oracle applies.
    bool pov_float_bounds = true;
    // POV-Ray's Bounding_Threshold (kPovBoundingOff: -MB): whether it builds its
    // bounding-slab tree, which decides its float box tests and its order of testing
    // objects (exact ties in depth, trace/pov_order.h).
    size_t pov_bounding_threshold = kPovBoundingThreshold;
    // The whole scene's object list when the parse kept only some objects (a black-box
    // worker): POV-Ray's ties and slab-tree tests are the whole scene's.
    std::shared_ptr<const PovWholeScene> whole_scene = nullptr;
    // Told when the octree build starts (not owned; may be null).
    RenderProgress* progress = nullptr;
};

class LightMasks;

class PreparedScene {
  public:
    // `plan`: what the scene leaves out (null: make_render_plan(scene)).
    explicit PreparedScene(const Scene& scene, const RenderPlan* plan = nullptr,
                           const PrepareOptions& options = {});
    // Only the given top-level objects (indices into scene.objects) and light looks_like
    // objects: the local scene of a black box. Materials still point into `scene`, so
    // object identity (interior stacks) is the same in every box.
    PreparedScene(const Scene& scene, const std::vector<uint32_t>& object_subset,
                  const RenderPlan* plan = nullptr, const PrepareOptions& options = {});

    const Scene& scene() const { return scene_; }
    // The threads the scene was prepared for (0: every core).
    int threads() const { return options_.threads; }
    const octree::Octree& tree() const { return tree_; }
    size_t primitive_count() const { return kind_.size(); }
    const PatternEnv& pattern_env() const { return env_; }
    const RenderPlan& plan() const { return plan_; }
    // Bytes held by the prepared primitives, materials and octree (a box's resident
    // scene).
    size_t resident_bytes() const;
    // +UA: the background's filter/transmit count (POV-Ray's alphaBackground).
    bool alpha_background() const { return alpha_background_; }
    void set_alpha_background(bool on) { alpha_background_ = on; }
    // The frame's photon map (trace/photon_map.h), built from the whole scene before
    // tracing; null: no photons.
    const PhotonMap* photons() const { return photons_.get(); }
    void set_photons(std::shared_ptr<const PhotonMap> map) { photons_ = std::move(map); }
    // The frame's radiosity pretrace (trace/radiosity/pretrace.h): the cache every
    // tracer made after it is set reads; null: no radiosity.
    const radiosity::RadiosityRender* radiosity() const { return radiosity_.get(); }
    void set_radiosity(std::shared_ptr<const radiosity::RadiosityRender> r) {
        radiosity_ = std::move(r);
    }
    // The lights' projected_through objects (trace/light_masks.h); null when no light
    // has one.
    const LightMasks* light_masks() const { return light_masks_.get(); }
    void init_context(RayContext& ctx) const {
        ctx.mailbox.resize(kind_.size());
        ctx.last_blocker.assign(scene_.lights.size(), ~0u);
    }

    // Nearest hit with t in (t_min, t_max), never closer than MIN_ISECT_DEPTH (1e-4),
    // respecting no_image / no_reflection / no_shadow / no_radiosity as POV-Ray does for
    // a ray of this use (ray_use.h). `radiosity_ray`: the ray is, or was spawned under, a
    // radiosity sample ray (POV-Ray's radiosity flag, which its child rays keep).
    // `ray_end`: where the ray ends when t_max only ends this search (a black box's part
    // of the ray; negative: at t_max), for POV-Ray's walk (beyond_box_frames_).
    bool closest_hit(const Ray& ray, Real t_min, Real t_max, RayUse use, Hit& hit,
                     RayContext& ctx, bool radiosity_ray = false,
                     Real ray_end = -1) const;

    // Shadow-ray fast path: true if an opaque, shadow-casting surface lies in (t_min,
    // t_max). Sets `transparent` when a see-through surface was met there (the caller
    // then needs the full product of filters). `light` >= 0 uses and updates
    // ctx.last_blocker[light].
    bool opaque_blocker(const Ray& ray, Real t_min, Real t_max, bool& transparent,
                        RayContext& ctx, int light = -1) const;

    using SpherePrim = SphereRecord;

  private:
    void build(const std::vector<const Object*>& objects);
    // `frame`: the object's index in POV-Ray's object list (plain unions are opened
    // first), ~0u when unknown, kSameFrame for a part of a frame object being added.
    static constexpr uint32_t kSameFrame = ~0u - 1;
    // Returns how many frame objects it added (pov_frame_object_count(obj)).
    uint32_t add_object(const Object& obj, uint32_t frame);
    // A frame object (one POV-Ray links to the scene whole): its primitives and
    // materials, which take its flags.
    void add_frame_object(const Object& obj, uint32_t frame);
    uint32_t add_material(const Object& obj);
    // The materials of a mesh's faces that have a texture of their own (texture_list
    // entries, and blends of three at corners), kept in face_materials_.
    void add_face_materials(const Object& o, const Mesh& m, uint32_t base);
    // Each face's material of a mesh that has face textures; null for other objects.
    const std::vector<uint32_t>* mesh_face_materials(const Object& o) const;
    // `tie`, when given: set when the object's nearest crossing has a crossing of another
    // of its leaves within `tie_tolerance` (relative) of it (CSG objects only).
    // `material_only`: only whether the ray meets the primitive in [t_min, t_max) and
    // the hit's material are used (a shadow test): a leaf shape outside CSG may give
    // any of its crossings there, and the normal is not computed. `flags`: the ray's,
    // for the CSG children it does not see (null: it sees all, as a shadow ray does).
    bool test_primitive(uint32_t id, const Ray& ray, const PovRayOnce& pov_ray,
                        Real t_min, Real t_max, Hit& hit, Real tie_tolerance = 0,
                        bool* tie = nullptr, bool material_only = false,
                        const RayFlags* flags = nullptr) const;
    // On an exact tie in depth: whether POV-Ray would see `candidate`'s surface rather
    // than `nearest`'s (trace/pov_order.h).
    bool pov_takes(const Material& candidate, const Material& nearest,
                   const Ray& ray) const;
    // POV-Ray's float bounding-box tests of primitive `id` (trace/pov_bounds.h): false
    // when POV-Ray would not intersect it with this ray at all. Asked only of hits.
    bool pov_accepts(uint32_t id, const PovRayOnce& pov_ray) const;
    // Frame objects whose surface POV-Ray can meet outside their box (object_bounds
    // beyond it: a disc's half-space keeping an intersection's parts, a bounded_by
    // smaller than the object, a clipped bicubic_patch): its walk of the slab tree stops
    // at the first box entered beyond the nearest hit found so far, so such an object's
    // hit counts only when no other is nearer than where the ray enters its box
    // (closest_hit). Their materials [first, end) and box, in material order.
    struct BeyondBoxFrame {
        uint32_t first, end;
        PovBBox box;
    };
    std::vector<BeyondBoxFrame> beyond_box_frames_;
    void note_hits_beyond_box(const Object& o, size_t first_material);
    const BeyondBoxFrame* beyond_box_frame(uint32_t material) const;
    // Frames closest_hit leaves out while it replays POV-Ray's walk.
    struct LeftOutFrames {
        const BeyondBoxFrame* frame[4];
        int count = 0;
        bool holds(uint32_t material) const {
            for (int i = 0; i < count; ++i)
                if (material >= frame[i]->first && material < frame[i]->end) return true;
            return false;
        }
    };
    bool closest_hit_without(const Ray& ray, Real t_min, Real t_max, RayUse use, Hit& hit,
                             RayContext& ctx, bool radiosity_ray, Real ray_end,
                             const LeftOutFrames& left_out) const;
    // The tests a primitive's POV-Ray object gets, and its box.
    enum : uint8_t { kPovSlabTree = 1, kPovOwnBox = 2, kPovMeshTriangle = 4 };
    struct PovPrim {
        PovBBox box;
        uint8_t tests = 0;
    };
    PovPrim pov_prim(const Object& o, uint8_t extra = 0) const;
    // Calls on_hit(id, t, q), in leaf order, for each of the first `spheres` ids of a
    // leaf whose sphere is hit at t < below (q: its position in lanes_) (`below` is read
    // again before each call: it may shrink) until on_hit returns true; returns whether
    // it did.
    template <class OnHit>
    [[gnu::always_inline]] inline bool for_sphere_hits(const uint32_t* ids,
                                                       size_t spheres, const Ray& ray,
                                                       Real lo, const Real& below,
                                                       RayContext& ctx,
                                                       OnHit&& on_hit) const;
    // The hit on sphere `id` at distance `t`.
    void fill_sphere_hit(uint32_t id, const Ray& ray, Real t, Hit& hit) const;
    const Material* material_for(const Object* leaf) const;
    std::vector<std::pair<const Object*, uint32_t>> leaf_materials_;  // sorted by pointer
    std::unordered_map<const Object*, std::vector<uint32_t>> face_materials_;
    // The POV-Ray frame object the materials being added belong to (add_object).
    uint32_t adding_frame_ = ~0u;
    // Per material: where POV-Ray tests its leaf, for exact ties in depth
    // (trace/pov_order.h): its frame-level object's index in POV-Ray's object list (~0u:
    // unknown, no tie rule). Leaves povwall splits off one frame object (a union with
    // bounded_by) share it; of those POV-Ray takes the later child's surface, and their
    // materials are made in child order.
    std::vector<uint32_t> material_frame_;
    // POV-Ray's test order (its object list and slab tree), built on the first tie.
    mutable std::once_flag pov_order_once_;
    mutable std::unique_ptr<PovTestOrder> pov_order_;

    const Scene& scene_;
    RenderPlan plan_;
    PrepareOptions options_;
    // POV-Ray would build its bounding-slab tree (enough frame-level objects), so every
    // finite object's box is tested in float.
    bool pov_slab_tree_ = false;
    // ... and tests its root box first (a scene without infinite objects).
    bool pov_root_tested_ = false;
    PovBBox pov_root_;
    // Per non-sphere primitive, in the order added until build() ends, then by id -
    // sphere_count_: spheres' boxes are computed from spheres_ when needed.
    std::vector<PovPrim> pov_;
    PatternEnv env_;
    bool alpha_background_ = false;
    std::shared_ptr<const PhotonMap> photons_;
    std::shared_ptr<const LightMasks> light_masks_;
    std::shared_ptr<const radiosity::RadiosityRender> radiosity_;
    std::vector<Material> materials_;  // reserved up front: pointers stay valid
    // Per RayUse: whether any frame object hides from that kind of ray.
    std::array<bool, kRayUses> hides_{};
    std::vector<TextureBlend> blends_;  // the same
    std::deque<BlobTextureBlend> blob_blends_;
    // Per primitive id.
    std::vector<PrimKind> kind_;
    std::vector<uint32_t> index_, material_;
    std::vector<Bounds3> bounds_;
    // Per primitive: whether every hit's distance is where the ray enters its bounds or
    // later (closest_hit_without leaves out objects that start past its nearest hit).
    std::vector<uint8_t> hits_within_bounds_;
    // Per primitive: a CSG whose crossings a shadow ray may reuse from one restart of
    // POV-Ray's see-through search to the next (no shape under it searches from where the
    // ray restarts: isosurface, julia_fractal, mesh).
    std::vector<uint8_t> reuses_crossings_;
    // Tells this scene's reused crossings from those of another scene at the same
    // address.
    uint64_t serial_ = 0;
    // Spheres in world space, one 32-byte record each (one cache line per candidate).
    // After build() the bounded spheres are primitives 0 .. sphere_count_-1 and
    // spheres_[id] is primitive id's sphere, so the hot loop needs neither kind_ nor
    // index_ for them.
    std::vector<SpherePrim> spheres_;
    uint32_t sphere_count_ = 0;
    // The spheres again in the order of the octree's references: a leaf's spheres (its
    // ids are sorted, spheres first) are side by side and tested four or eight at a time.
    SphereLanes lanes_;
    std::vector<TrianglePrim> triangles_;
    // Planes in world space: dot(normal, p) = distance; `tolerance` is POV-Ray's 1e-6
    // object-space depth tolerance in world units.
    struct PlanePrim {
        Vector3 normal;
        Real distance, tolerance;
    };
    std::vector<PlanePrim> planes_;
    std::vector<const Object*> objects_;
    std::vector<uint32_t> unbounded_;
    octree::Octree tree_;
};

// World-space bounds of an object (everything() when unbounded).
Bounds3 object_world_bounds(const Object& obj);
// World-space bounds of the points inside the object (as it is written, not inverted by
// a CSG around it): where it can cut another's surface.
Bounds3 object_inside_bounds(const Object& obj);
// Bounds of the points where a ray can hit the object: its world bounds, narrowed for a
// plane whose normal is parallel to an axis to its surface (a slab of zero width; its
// inside is a half-space, but rays meet it only on the surface).
Bounds3 object_hit_bounds(const Object& obj);

// Where a ray must be followed to decide whether POV-Ray's walk of its slab tree reaches
// the object's surface, when that surface can lie outside the object's POV-Ray box (see
// PreparedScene::closest_hit): the hull of the surface and the box; empty for every other
// object. A black box holding the object holds every object that overlaps this.
Bounds3 pov_walk_reach(const Object& obj);

// True when no pigment of the layers (maps included) has filter or transmit.
bool pigment_opaque(const Pigment& p);
bool texture_opaque(const LayeredTexture& layers);

// Whether a point is inside an object (CSG semantics, world space).
bool inside_object(const Object& obj, const Point3& p);

}  // namespace povwall::trace
