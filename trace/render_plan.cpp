#include "trace/render_plan.h"

#include <cstdio>

#include "octree/octree.h"
#include "trace/prepared_scene.h"
#include "trace/shapes/shape.h"

namespace povwall::trace {
namespace {

// Calls `fn` for every texture layer list an object can show (CSG children, mesh face
// textures, interior textures), maps included.
template <typename Fn>
void for_each_texture(const LayeredTexture& layers, Fn&& fn) {
    fn(layers);
    for (const Texture& t : layers) {
        for (const auto& m : t.map->entries) for_each_texture(m, fn);
    }
}

template <typename Fn>
void for_each_object_texture(const Object& o, Fn&& fn) {
    for_each_texture(o.texture, fn);
    for_each_texture(*o.interior_texture, fn);
    if (auto c = std::get_if<Csg>(&o.shape)) {
        for (const Object& ch : c->children) for_each_object_texture(ch, fn);
    }
    if (auto m = std::get_if<Mesh>(&o.shape)) {
        for (const auto& t : m->textures) for_each_texture(t, fn);
    }
    if (auto b = std::get_if<Blob>(&o.shape)) {
        for (const auto& t : b->element_textures) for_each_texture(t, fn);
    }
}

template <typename Fn>
void for_each_scene_texture(const Scene& scene, Fn&& fn) {
    for (const Object& o : scene.objects) for_each_object_texture(o, fn);
    for (const Light& l : scene.lights) {
        for (const Object& o : l.looks_like) for_each_object_texture(o, fn);
    }
}

// Primitives as PreparedScene makes them: plain unions are opened, meshes give triangles.
void count_primitives(const Object& o, size_t& finite, size_t& infinite) {
    if (pov_splits_union(o)) {
        for (const Object& ch : std::get<Csg>(o.shape).children)
            count_primitives(ch, finite, infinite);
        return;
    }
    bool bounded = !object_world_bounds(o).infinite();
    size_t n = 1;
    // A mesh traced as triangles gives one a face; copies are traced whole.
    if (auto m = std::get_if<Mesh>(&o.shape); m && mesh_as_triangles(o))
        n = m->data->faces.size();
    (bounded ? finite : infinite) += n;
}

// Some object with a transparent texture has an interior whose ior bends rays. Under
// cutaway_textures a part without a texture shows its CSG's (trace/cutaway_textures.h):
// any of them transparent counts for every part.
bool any_refracting(const Object& o, bool transparent_above) {
    bool transparent = transparent_above || !texture_opaque(o.texture) ||
                       !texture_opaque(*o.interior_texture);
    if (const Csg* c = std::get_if<Csg>(&o.shape);
        c && c->cutaway_textures && !transparent)
        for_each_object_texture(o, [&](const LayeredTexture& layers) {
            transparent = transparent || !texture_opaque(layers);
        });
    if (transparent && o.interior && o.interior->ior != 1.0f) return true;
    if (auto c = std::get_if<Csg>(&o.shape)) {
        for (const Object& ch : c->children) {
            if (any_refracting(ch, transparent)) return true;
        }
    }
    return false;
}

// A flat surface cannot stand between one of its own points and a light: the segment
// toward the light leaves its plane at once. (A convex solid can: a point whose bumped
// normal turns toward a light behind its face, or a camera inside it, sees the light
// through the solid, which POV-Ray's shadow ray meets.) Affine transforms keep this.
bool flat_surface(const Object& o) {
    if (o.inverse || !o.clipped_by.empty() || o.double_illuminate) return false;
    return std::holds_alternative<Plane>(o.shape) ||
           std::holds_alternative<Disc>(o.shape) ||
           std::holds_alternative<Triangle>(o.shape) ||
           std::holds_alternative<Polygon>(o.shape);
}

const char* light_kind(const Light& l) {
    if (l.area) return "area light";
    switch (l.kind) {
        case Light::Kind::Spot:
            return "spotlight";
        case Light::Kind::Cylinder:
            return "cylinder light";
        case Light::Kind::Parallel:
            return "parallel light";
        default:
            return "point light";
    }
}

}  // namespace

size_t estimate_prepared_bytes(const Object& o) {
    // Per primitive: kind, index, material id, bounds, mailbox stamp, ~3.5 octree
    // references (measured on the demo scene) and its geometry; a material per non-mesh
    // leaf.
    constexpr size_t kPerPrimitive = 1 + 4 + 4 + sizeof(Bounds3) + 4 + 14;
    constexpr size_t kMaterial = sizeof(Material) + 16;
    if (pov_splits_union(o)) {
        size_t n = 0;
        for (const Object& ch : std::get<Csg>(o.shape).children)
            n += estimate_prepared_bytes(ch);
        return n;
    }
    if (auto m = std::get_if<Mesh>(&o.shape)) {
        if (mesh_as_triangles(o))
            return kMaterial * (1 + m->textures.size()) +
                   m->data->faces.size() * (kPerPrimitive + sizeof(TrianglePrim));
    }
    // A sphere's record, and its copy per octree reference in the leaves' lanes (about
    // 3 references a sphere on 100,000 spheres).
    if (std::holds_alternative<Sphere>(o.shape))
        return kPerPrimitive + kMaterial + 4 * sizeof(Real) + 3 * 4 * sizeof(Real);
    // Other shapes (and CSG other than union) stay one Object primitive; CSG materials
    // per leaf.
    auto leaves_of = [](const Object& x, auto& self) -> size_t {
        auto cx = std::get_if<Csg>(&x.shape);
        if (!cx) return 1;
        size_t n = 0;
        for (const Object& ch : cx->children) n += self(ch, self);
        return n;
    };
    size_t leaves = leaves_of(o, leaves_of);
    if (auto b = std::get_if<Blob>(&o.shape)) leaves += b->element_textures.size();
    return kPerPrimitive + sizeof(void*) + kMaterial * leaves;
}

namespace {

// malloc's header and rounding per heap block.
constexpr size_t kHeapBlock = 16;

size_t heap_bytes(size_t bytes) { return bytes ? bytes + kHeapBlock : 0; }

size_t model_bytes(const HeapValue<PatternSpec>& p) {
    return p.allocated() ? heap_bytes(sizeof(PatternSpec)) +
                               heap_bytes(p->warps.size() * sizeof(Warp))
                         : 0;
}
size_t model_bytes(const Pigment& p);
size_t model_bytes(const Normal& n) {
    size_t b = model_bytes(n.pattern) + heap_bytes(n.map_values.size() * sizeof(float)) +
               heap_bytes(n.slope_map.size() * sizeof(SlopeMapEntry)) +
               heap_bytes(n.list.size() * sizeof(Normal));
    for (const Normal& e : n.list) b += model_bytes(e);
    return b;
}
size_t model_bytes(const Pigment& p) {
    size_t b = model_bytes(p.pattern) +
               (p.maps.allocated() ? heap_bytes(sizeof(PigmentMaps)) : 0) +
               heap_bytes(p.maps->colour_map.size() * sizeof(ColourMapEntry)) +
               heap_bytes(p.maps->map_values.size() * sizeof(float)) +
               heap_bytes(p.maps->list.size() * sizeof(Pigment));
    for (const Pigment& e : p.maps->list) b += model_bytes(e);
    return b;
}
size_t model_bytes(const LayeredTexture& layers) {
    size_t b = heap_bytes(layers.size() * sizeof(Texture));
    for (const Texture& t : layers) {
        b += model_bytes(t.pigment) +
             (t.normal ? heap_bytes(sizeof(Normal)) + model_bytes(*t.normal) : 0);
        // A finish shared by several textures counts its share in each.
        if (t.finish.holders() > 0)
            b += heap_bytes(sizeof(Finish)) / size_t(t.finish.holders());
        if (t.map_pattern) b += heap_bytes(sizeof(PatternSpec));
        if (t.map.allocated()) b += heap_bytes(sizeof(TextureMap));
        b += heap_bytes(t.map->values.size() * sizeof(float)) +
             heap_bytes(t.map->entries.size() * sizeof(LayeredTexture));
        for (const LayeredTexture& m : t.map->entries) b += model_bytes(m);
    }
    return b;
}
size_t model_bytes_of_list(const std::vector<Object>& objects) {
    size_t b = heap_bytes(objects.size() * sizeof(Object));
    for (const Object& o : objects) b += estimate_model_bytes(o) - sizeof(Object);
    return b;
}

}  // namespace

size_t estimate_model_bytes(const Object& o) {
    // The Object itself (held in a vector: no block of its own), then what it points to.
    size_t b = sizeof(Object) + model_bytes(o.texture) +
               model_bytes(*o.interior_texture) + model_bytes_of_list(*o.clipped_by) +
               model_bytes_of_list(*o.bounded_by) +
               (o.interior ? heap_bytes(sizeof(Interior)) : 0);
    if (o.interior_texture.allocated()) b += heap_bytes(sizeof(LayeredTexture));
    if (o.clipped_by.allocated()) b += heap_bytes(sizeof(std::vector<Object>));
    if (o.bounded_by.allocated()) b += heap_bytes(sizeof(std::vector<Object>));
    if (auto m = std::get_if<Mesh>(&o.shape)) {
        // The shared data and its face tree, a share of them for each copy.
        const MeshData& d = *m->data;
        const size_t shared =
            heap_bytes(d.vertices.size() * sizeof(Point3)) +
            heap_bytes(d.normals.size() * sizeof(Vector3)) +
            heap_bytes(d.faces.size() * sizeof(Mesh::Face)) +
            heap_bytes(d.faces.size() / 2 * sizeof(BoxTree::Node) + d.faces.size() * 4);
        b += shared / m->copies + heap_bytes(m->textures.size() * sizeof(LayeredTexture));
        for (const LayeredTexture& t : m->textures) b += model_bytes(t);
    } else if (auto bl = std::get_if<Blob>(&o.shape)) {
        b += heap_bytes(bl->element_textures.size() * sizeof(LayeredTexture));
        for (const LayeredTexture& t : bl->element_textures) b += model_bytes(t);
    } else if (auto st = std::get_if<SmoothTriangle>(&o.shape)) {
        if (st->n.allocated()) b += heap_bytes(sizeof(std::array<Vector3, 3>));
    } else if (auto p = std::get_if<Polygon>(&o.shape)) {
        b += heap_bytes(p->points.size() * sizeof(Point3));
    } else if (auto c = std::get_if<Csg>(&o.shape)) {
        b += model_bytes_of_list(c->children) +
             heap_bytes(c->lights.size() * sizeof(Light));
    }
    return b;
}

bool shading_is_linear(const Scene& scene) {
    bool linear = true;
    for_each_scene_texture(scene, [&](const LayeredTexture& layers) {
        for (const Texture& t : layers) {
            if (t.finish->reflection_exponent != 1) linear = false;
        }
    });
    return linear;
}

RenderPlan make_render_plan(const Scene& scene, bool everything_on, int quality) {
    RenderPlan plan;
    plan.everything_on = everything_on;
    plan.quality = Quality::of(quality);
    bool reflective = false, transparent = false;
    for_each_scene_texture(scene, [&](const LayeredTexture& layers) {
        for (const Texture& t : layers) {
            if (!t.finish->reflection_max.is_black() ||
                !t.finish->reflection_min.is_black())
                reflective = true;
        }
        if (!texture_opaque(layers)) transparent = true;
    });
    bool refracting = false;
    for (const Object& o : scene.objects)
        refracting = refracting || any_refracting(o, false);
    for (const Object& o : scene.objects)
        count_primitives(o, plan.finite_primitives, plan.infinite_primitives);
    plan.reflection_rays = everything_on || reflective;
    plan.transmission_rays = everything_on || transparent;
    plan.refraction_rays = everything_on || refracting;

    // Who can cast a shadow: top-level objects without no_shadow (looks_like objects
    // never do). None, or one opaque flat surface that is the whole scene: no shadow ray
    // can be blocked.
    size_t casters = 0;
    for (const Object& o : scene.objects) casters += frame_flags(o).no_shadow ? 0 : 1;
    size_t looks_like = 0;
    for (const Light& l : scene.lights) looks_like += l.looks_like.size();
    const bool lone_flat = scene.objects.size() == 1 && looks_like == 0 && casters == 1 &&
                           !transparent && flat_surface(scene.objects[0]);
    for (const Light& l : scene.lights) {
        LightPlan lp;
        if (l.shadowless) {
            lp.shadow_rays = false;
            lp.reason = "shadowless: no shadow rays";
        } else if (everything_on) {
            lp.reason = "shadow rays (plan forced on)";
        } else if (casters == 0) {
            lp.shadow_rays = false;
            lp.unoccluded = true;
            lp.reason = "no object casts shadows: no shadow rays";
        } else if (lone_flat && !l.area) {
            lp.shadow_rays = false;
            lp.unoccluded = true;
            lp.reason =
                "the only object is flat and cannot shadow itself: no shadow rays";
        } else if (l.area) {
            lp.reason = "shadow rays (" + std::to_string(l.area->size1 * l.area->size2) +
                        "-sample area grid, adaptive " +
                        std::to_string(l.area->adaptive) + ")";
        } else {
            lp.reason = "shadow rays";
        }
        // (An area_illumination light's samples each have their own cone.)
        const bool sampled_cone = l.area && l.area->illumination;
        if (!everything_on && !sampled_cone &&
            (l.kind == Light::Kind::Spot || l.kind == Light::Kind::Cylinder)) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "; none outside its %g-degree falloff %s",
                          l.falloff, l.kind == Light::Kind::Spot ? "cone" : "cylinder");
            if (lp.shadow_rays) lp.reason += buf;
        }
        plan.lights.push_back(lp);
    }
    plan.skip_unlit_shadow_rays = !everything_on;
    plan.flat_threshold = everything_on ? 0 : octree::BuildOptions{}.flat_threshold;
    bool area_shadows = false;
    for (size_t l = 0; l < scene.lights.size(); ++l)
        area_shadows =
            area_shadows || (scene.lights[l].area && plan.lights[l].shadow_rays);
    // Scattering media: a stretch's light comes from its samples' shadow rays, taken
    // (method 3's refinement) once they are all in.
    const bool media_shadows = first_scattering_media(scene) && plan.quality.atmosphere();
    plan.parents_required =
        (area_shadows && plan.quality.area_lights() && plan.quality.shadows()) ||
        media_shadows;
    plan.parent_tracking =
        everything_on || !shading_is_linear(scene) || plan.parents_required;
    plan.parent_reason =
        everything_on ? "parent tracking (plan forced on)"
        : plan.parents_required
            ? (media_shadows ? "scattering media: each stretch's samples are lit "
                               "(POV-Ray's adaptive rule) once their shadow rays are "
                               "in, in the parent table"
                             : "area-light shadows: each lit point's grid is averaged "
                               "(POV-Ray's adaptive rule) once its samples are in, in "
                               "the parent table")
        : plan.parent_tracking
            ? "a reflection exponent makes shading non-linear: parents wait "
              "for their children in each box's parent table"
            : "shading is linear: contributions go straight to the pixel, no "
              "parent table";
    return plan;
}

std::vector<std::string> explain_plan(const RenderPlan& plan, const Scene& scene) {
    std::vector<std::string> out;
    if (plan.everything_on)
        out.push_back("plan forced on (--plan all): nothing is left out");
    out.push_back(plan.reflection_rays ? "reflective materials: reflection rays on"
                                       : "no reflective materials: reflection rays off");
    if (!plan.transmission_rays) {
        out.push_back("no transparent materials: transmission and refraction rays off");
    } else {
        out.push_back(
            plan.refraction_rays
                ? "transparent materials with ior: refraction rays on"
                : "transparent materials, no ior change: straight transmission rays "
                  "only");
    }
    if (scene.lights.empty()) out.push_back("no light sources: no shadow rays");
    for (size_t i = 0; i < plan.lights.size(); ++i) {
        out.push_back("light " + std::to_string(i + 1) + " (" +
                      light_kind(scene.lights[i]) + "): " + plan.lights[i].reason);
    }
    if (plan.skip_unlit_shadow_rays && !scene.lights.empty())
        out.push_back(
            "points a light does not reach (back faces, outside spot cones): no "
            "shadow ray");
    char buf[160];
    if (plan.finite_primitives < size_t(plan.flat_threshold)) {
        std::snprintf(buf, sizeof buf,
                      "%zu bounded primitives (< %d): no octree, a flat list",
                      plan.finite_primitives, plan.flat_threshold);
    } else {
        std::snprintf(buf, sizeof buf, "%zu bounded primitives: octree",
                      plan.finite_primitives);
    }
    out.push_back(buf);
    if (plan.infinite_primitives) {
        out.push_back(
            std::to_string(plan.infinite_primitives) +
            " unbounded primitives (planes, unbounded CSG): tested by every ray");
    }
    if (scene.settings.radiosity) {
        out.push_back(
            plan.quality.level >= 9
                ? "radiosity: pretrace passes (pretrace_start down to pretrace_end) fill "
                  "the irradiance cache, each pass reading the cache frozen after the "
                  "one "
                  "before and its blocks' entries merged in block order; the final "
                  "render reads the cache and reuses what a block gathers only in that "
                  "block (docs/radiosity.md)"
                : "radiosity: off below +Q9");
    }
    out.push_back(plan.parent_reason);
    return out;
}

}  // namespace povwall::trace
