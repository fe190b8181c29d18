// Objects: shapes, CSG, object modifiers and transforms, and the top-level scene items.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <unordered_map>

#include "core/pov_frame.h"
#include "core/quadric.h"
#include "core/quadric_bounds.h"
#include "parser/interpreter.h"

namespace povwall::parser {

namespace {
// An object made from a declared one: an isosurface among its copies leaves the
// end-of-render messages to its original (POV-Ray's isCopy).
void mark_copy(Object& o) {
    if (auto* iso = std::get_if<Isosurface>(&o.shape)) iso->copy = true;
}
}  // namespace
namespace {

bool holds_parametric(const Object& o) {
    if (std::holds_alternative<Parametric>(o.shape)) return true;
    if (const Csg* csg = std::get_if<Csg>(&o.shape)) {
        for (const Object& c : csg->children)
            if (holds_parametric(c)) return true;
    }
    return false;
}

// Shapes the scene model does not have yet: used, they are a located "unsupported" error.
bool is_unsupported_shape(std::string_view w) {
    static constexpr std::string_view kNames[] = {"lemon"};
    for (std::string_view n : kNames) {
        if (w == n) return true;
    }
    return false;
}

void transform_pattern(PatternSpec& p, const Transform& t) {
    p.transform = p.transform.then(t);
}

void transform_normal(Normal& n, const Transform& t) {
    transform_pattern(n.pattern.edit(), t);
}

// Whether a texture was given anywhere in the object (POV-Ray's TEXTURED_OBJECT, which a
// CSG takes from its parts): a texture or interior texture, or one on every mesh face.
bool texture_given(const Object& obj) {
    if (!obj.texture.empty() || !obj.interior_texture->empty()) return true;
    if (const Mesh* m = std::get_if<Mesh>(&obj.shape))
        return !m->data->faces.empty() &&
               std::all_of(m->data->faces.begin(), m->data->faces.end(),
                           [](const Mesh::Face& f) { return f.texture != -1; });
    if (const Csg* csg = std::get_if<Csg>(&obj.shape))
        return std::any_of(csg->children.begin(), csg->children.end(), texture_given);
    return false;
}

// Whether cutaway_textures is on the CSG or on one inside it.
bool holds_cutaway(const Object& obj) {
    const Csg* csg = std::get_if<Csg>(&obj.shape);
    return csg &&
           (csg->cutaway_textures ||
            std::any_of(csg->children.begin(), csg->children.end(), holds_cutaway));
}

// POV-Ray's Post_Process where cutaway_textures counts (the flag comes down to every CSG
// inside): an object without a texture gets no default one when its parent is an
// intersection or difference with the flag, nor does a CSG with a texture given in a part
// (its parts without one then get the default each, unless it is such an intersection or
// difference). Elsewhere a CSG's default texture, which comes down to its parts without
// one, shows the same.
bool stays_untextured(const Object& obj, const Object* parent) {
    const Csg* up = parent ? std::get_if<Csg>(&parent->shape) : nullptr;
    if (up && up->cutaway_textures &&
        (up->kind == CsgKind::Intersection || up->kind == CsgKind::Difference))
        return true;
    return holds_cutaway(obj) && texture_given(obj);
}

// POV-Ray's box of a clip or CSG sibling, for a quadric's box (core/quadric_bounds.h);
// empty (the quadric refuses such siblings) without the trace/ queries.
PovBoxOf pov_box_of(const ParseOptions& options) {
    if (!options.object_queries) return {};
    return [q = options.object_queries](const Object& o) { return q->box(o); };
}

}  // namespace

// Pigment and normal map/list entries are evaluated at the outer pattern's point (as
// POV-Ray does), so a transform moves only the outer pattern.
void transform_pigment(Pigment& p, const Transform& t) {
    transform_pattern(p.pattern.edit(), t);
}

// An interior's media densities move with its object (POV-Ray's Interior::Transform).
void transform_interior(HeapOptional<Interior>& in, const Transform& t) {
    if (!in) return;
    bool has_density = false;
    for (const Media& m : in->media) has_density = has_density || !m.density.empty();
    if (!has_density) return;
    for (Media& m : in->media)
        for (Pigment& d : m.density) transform_pigment(d, t);
}

void transform_textures(LayeredTexture& layers, const Transform& t) {
    for (Texture& tex : layers) {
        transform_pigment(tex.pigment, t);
        if (tex.normal) transform_normal(*tex.normal, t);
        // Texture map entries are evaluated at the map pattern's point (as POV-Ray's):
        // they move with it.
        if (tex.map_pattern) transform_pattern(*tex.map_pattern, t);
    }
}

void Interpreter::transform_light(Light& l, const Transform& t,
                                  const TransformStep& step) {
    l.location = t.point(l.location);
    l.point_at = t.point(l.point_at);
    if (l.area) {
        l.area->axis1 = t.vector(l.area->axis1);
        l.area->axis2 = t.vector(l.area->axis2);
    }
    for (Object& o : l.looks_like) apply_transform(o, t, step);
    if (l.projected_through) {
        auto moved = std::make_shared<Object>(*l.projected_through);
        apply_transform(*moved, t, step);
        l.projected_through = std::move(moved);
    }
}

namespace {

// POV-Ray's sphere_sweep without a matrix moves its modeling spheres for translate,
// rotate and a uniform scale (radii scaled too) and rebuilds its segments; any other
// transform makes it keep one, into which every later transform goes.
bool move_sweep_spheres(SphereSweep& sweep, const Transform& t,
                        const TransformStep& step) {
    using Kind = TransformStep::Kind;
    const Vector3& v = step.amount;
    const bool uniform = step.kind != Kind::Scale || (v.x == v.y && v.x == v.z);
    if (sweep.has_matrix || step.kind == Kind::Matrix || !uniform) {
        sweep.has_matrix = true;
        return false;
    }
    std::vector<SweepSphere> moved = sweep.data->modeling;
    for (SweepSphere& m : moved) {
        m.centre = t.point(m.centre);
        if (step.kind == Kind::Scale) m.radius *= v.x;
    }
    sweep.data = std::make_shared<SphereSweepData>(
        make_sphere_sweep(sweep.data->spline, std::move(moved)));
    return true;
}

// Where POV-Ray starts keeping a matrix for a sphere (core/scene.h, SpherePovMatrix):
// the centre and radius it had then, and every transform from then on.
void note_sphere_pov_matrix(Sphere& sphere, const CompactTransform& before,
                            const Transform& t, const TransformStep& step) {
    using Kind = TransformStep::Kind;
    const Vector3& v = step.amount;
    if (sphere.pov_matrix) {
        auto kept = std::make_shared<SpherePovMatrix>(*sphere.pov_matrix);
        kept->rest = kept->rest.then(t);
        sphere.pov_matrix = std::move(kept);
        return;
    }
    if (step.kind != Kind::Matrix &&
        (step.kind != Kind::Scale || (v.x == v.y && v.x == v.z)))
        return;
    // Until now only moves, turns and uniform scales: a similarity, whose scale is the
    // length of a turned unit vector.
    const Real scale = before.is_identity() ? 1 : length(before.vector({1, 0, 0}));
    auto kept = std::make_shared<SpherePovMatrix>();
    kept->centre = before.point(sphere.centre);
    kept->radius = sphere.radius * scale;
    kept->rest = t;
    sphere.pov_matrix = std::move(kept);
}

}  // namespace

namespace {

// A cone as POV-Ray holds it (Compute_Cone_Data): the first point is its apex, the
// second its base; the wider end goes on top; the unit cone x^2 + y^2 = z^2 between
// z = dist and 1 in the frame of the full cone's tip, so rays meet it with POV-Ray's
// bits. Radii within 1e-10 make it POV-Ray's cylinder. Negative or infinite radii stay as
// written.
void pov_cone_frame(Cone c, Object& out) {
    out.shape = c;
    Point3 apex = c.base, base = c.cap;
    Real apex_r = c.base_radius, base_r = c.cap_radius;
    if (!(apex_r >= 0 && base_r >= 0 && std::isfinite(apex_r) && std::isfinite(base_r)))
        return;
    auto unit_axis = [](const Point3& to, const Point3& from, Real& len) {
        const Vector3 a = to - from;
        len = length(a);
        return a * (1.0 / len);
    };
    auto cylinder = [&](const Point3& top, const Point3& bottom, Real radius) {
        if (radius == 0) return;  // a line, never hit
        Real len;
        const Vector3 axis = unit_axis(top, bottom, len);
        out.transform = pov_coordinate_transform(bottom, axis, radius, len);
        out.shape = Cylinder{{0, 0, 0}, {0, 0, 1}, 1, c.open};
    };
    if (std::fabs(apex_r - base_r) < 1e-10) return cylinder(apex, base, apex_r);
    Real len;
    Vector3 axis = unit_axis(apex, base, len);
    if (apex_r < base_r) {
        std::swap(apex, base);
        std::swap(apex_r, base_r);
        axis = axis * -1.0;
    }
    const Real below = base_r * len / (apex_r - base_r);  // the tip before the base
    const Point3 tip = base - axis * below;
    const Real full = below + len;
    if ((apex_r - base_r) * len / full < 1e-10) return cylinder(apex, base, apex_r);
    const Real dist = below / full;
    out.transform = pov_coordinate_transform(tip, axis, apex_r, full);
    out.shape = Cone{{0, 0, dist}, {0, 0, 1}, dist, 1, c.open};
}

// Whether POV-Ray's Compute_Triangle swaps the first two corners: they wind the wrong
// way seen along the normal's largest component (ties broken as its max3_coordinate).
bool pov_triangle_swaps(const Point3 (&p)[3]) {
    const Vector3 n = cross(p[0] - p[1], p[2] - p[1]);
    const Real ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
    const int axis = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    // The two in-plane axes, in POV-Ray's order for each dominant axis.
    const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
    const Vector3 e31 = p[1] - p[2], e01 = p[1] - p[0];
    return e31[u] * e01[v] < e31[v] * e01[u];
}

bool mirrors(const Transform& t) {
    return dot(t.vector({1, 0, 0}), cross(t.vector({0, 1, 0}), t.vector({0, 0, 1}))) < 0;
}

// POV-Ray moves a triangle's corners at each transform and recomputes it
// (Compute_Triangle): the normal comes from the corners as they stand, then the first
// two are swapped if they wind the wrong way. The order a transform finds is thus the
// one the previous computation left, and the final normal is that order's. povwall
// keeps the corners and carries their normal by the transform, which a mirror turns
// against the moved corners' own: the corners are kept in POV-Ray's order, swapped
// while the transform mirrors.
void order_triangle_as_pov(Triangle& tri, const Transform& before,
                           const Transform& after) {
    if (Interpreter::degenerate_corners(tri.p)) return;
    Point3 world[3] = {before.point(tri.p[0]), before.point(tri.p[1]),
                       before.point(tri.p[2])};
    const bool mirrored_before = mirrors(before);
    if (mirrored_before) std::swap(world[0], world[1]);  // POV-Ray's order
    if ((mirrored_before != pov_triangle_swaps(world)) != mirrors(after))
        std::swap(tri.p[0], tri.p[1]);
}

// Compute_Smooth_Triangle's test: the vertex normals all on one side of the face.
bool normals_on_one_side(const Point3 (&p)[3], const std::array<Vector3, 3>& n) {
    const Vector3 face = cross(p[0] - p[1], p[2] - p[1]);
    int above = 0, below = 0;
    for (const Vector3& v : n) {
        const Real side = dot(face, v);
        above += side > 0;
        below += side < 0;
    }
    return above == 3 || below == 3;
}

// POV-Ray moves a smooth_triangle's corners and normals at each transform and checks it
// again (SmoothTriangle::Transform): normals not all on one side of the moved face make
// it degenerate, for good (a shear can turn one across). A zero first normal marks that,
// as at the parse.
void recheck_smooth_triangle(SmoothTriangle& tri, const Transform& after) {
    if ((*tri.n)[0] == Vector3{0, 0, 0}) return;
    Point3 p[3];
    std::array<Vector3, 3> n;
    for (int i = 0; i < 3; ++i) {
        p[i] = after.point(tri.p[i]);
        n[size_t(i)] = after.normal((*tri.n)[size_t(i)]);
    }
    if (!normals_on_one_side(p, n)) tri.n.edit()[0] = Vector3{0, 0, 0};
}

// POV-Ray recomputes a julia_fractal's box at each transform (Fractal::Compute_BBox),
// which clears the inverted flag its Invert set, however it was inverted: its own
// `inverse` (object { Julia inverse }), an inverse CSG around it (CSG::Invert inverts
// every child) or a difference it is a later part of. From then on it is held as it is:
// its flag undoes what the CSGs between the transformed object and it apply (`held`).
void settle_julia_inversion(Object& o, bool held) {
    if (std::holds_alternative<JuliaFractal>(o.shape)) {
        o.inverse = held;
        return;
    }
    Csg* csg = std::get_if<Csg>(&o.shape);
    if (!csg) return;
    const bool inverted = held != o.inverse;
    for (size_t i = 0; i < csg->children.size(); ++i) {
        Object& c = csg->children[i];
        // A difference inverts its later CSGs and julia_fractals (and other leaves,
        // which hold no julia).
        const bool later = csg->kind == CsgKind::Difference && i > 0 &&
                           (std::holds_alternative<Csg>(c.shape) ||
                            std::holds_alternative<JuliaFractal>(c.shape));
        settle_julia_inversion(c, inverted != later);
    }
}

// POV-Ray inverts a CSG by inverting its children and morphing it: a union or a merge
// into an intersection, an intersection into a merge. A union inverted twice (an inverse
// union subtracted, a union in a difference that is itself subtracted) is therefore a
// merge, which povwall's parity of inversions alone would take back to a union. Called
// once the object is placed, with the inversions the CSGs above it apply (`count`).
void settle_inverted_unions(Object& o, int count) {
    Csg* csg = std::get_if<Csg>(&o.shape);
    if (!csg) return;
    count += o.inverse ? 1 : 0;
    if (csg->kind == CsgKind::Union && count >= 2 && count % 2 == 0)
        csg->kind = CsgKind::Merge;
    for (size_t i = 0; i < csg->children.size(); ++i) {
        // A difference inverts its later parts (a CSG always).
        const bool later = csg->kind == CsgKind::Difference && i > 0;
        settle_inverted_unions(csg->children[i], count + (later ? 1 : 0));
    }
}

}  // namespace

void Interpreter::apply_transform(Object& obj, const Transform& t,
                                  const TransformStep& step) {
    transform_node(obj, t, step);
    settle_julia_inversion(obj, false);
}

void Interpreter::transform_node(Object& obj, const Transform& t,
                                 const TransformStep& step) {
    if (auto tri = std::get_if<Triangle>(&obj.shape))
        order_triangle_as_pov(*tri, obj.transform, obj.transform.then(t));
    if (auto tri = std::get_if<SmoothTriangle>(&obj.shape))
        recheck_smooth_triangle(*tri, obj.transform.then(t));
    Plane* plane = std::get_if<Plane>(&obj.shape);
    if (auto sphere = std::get_if<Sphere>(&obj.shape))
        note_sphere_pov_matrix(*sphere, obj.transform, t, step);
    if (auto sweep = std::get_if<SphereSweep>(&obj.shape);
        sweep && move_sweep_spheres(*sweep, t, step)) {
    } else if (plane && step.kind != TransformStep::Kind::Matrix &&
               obj.transform.is_identity()) {
        // POV-Ray folds translate, rotate and scale of a plane that keeps no matrix yet
        // (none before a `matrix` or `transform`) into its normal and offset, in its
        // order of sums (Plane::Translate, Rotate, Scale): rays meet it in world space,
        // to the last bit as POV-Ray's (trace() results that scenes feed back as new
        // origins depend on those bits), and an intersection's box is cut by the
        // folded plane (Compute_Plane_Min_Max without a matrix).
        Vector3& n = plane->normal;
        const Vector3& v = step.amount;
        if (step.kind == TransformStep::Kind::Translate) {
            plane->distance += n.x * v.x + n.y * v.y + n.z * v.z;
        } else if (step.kind == TransformStep::Kind::Rotate) {
            n = t.vector(n);
        } else {
            n = {n.x / v.x, n.y / v.y, n.z / v.z};
            const Real len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
            const Real inv = 1.0 / len;
            n = {n.x * inv, n.y * inv, n.z * inv};
            plane->distance /= len;
        }
    } else if (auto box = std::get_if<Box>(&obj.shape);
               box && obj.transform.is_identity() &&
               (step.kind == TransformStep::Kind::Translate ||
                step.kind == TransformStep::Kind::Scale)) {
        // POV-Ray moves and scales a box's corners while it has no matrix (until its
        // first rotate, matrix or transform; Box::Translate, Box::Scale), a negative
        // scale swapping them: coincident faces of boxes placed so stay exactly equal,
        // and its surface coordinates are taken in world space.
        Point3& lo = box->corner1;
        Point3& hi = box->corner2;
        const Vector3& v = step.amount;
        for (int a = 0; a < 3; ++a) {
            if (step.kind == TransformStep::Kind::Translate) {
                lo[a] += v[a];
                hi[a] += v[a];
            } else {
                lo[a] *= v[a];
                hi[a] *= v[a];
                if (lo[a] > hi[a]) std::swap(lo[a], hi[a]);
            }
        }
    } else if (auto patch = std::get_if<BicubicPatch>(&obj.shape)) {
        // POV-Ray keeps no matrix for a patch: its control points move, and its flat
        // pieces are cut again from them.
        auto moved = std::make_shared<BicubicPatchData>(*patch->data);
        for (Point3& p : moved->control) p = t.point(p);
        build_patch_pieces(*moved);
        patch->data = std::move(moved);
    } else if (auto quadric = std::get_if<Quadric>(&obj.shape)) {
        // POV-Ray keeps no matrix for a quadric: each step goes into its coefficients.
        quadric_transform(*quadric, t);
    } else {
        obj.transform = obj.transform.then(t);
    }
    // Under uv_mapping the textures are fixed to the surface coordinates.
    if (!obj.uv_mapping) {
        transform_textures(obj.texture, t);
        if (obj.interior_texture.allocated())
            transform_textures(obj.interior_texture.edit(), t);
    }
    transform_interior(obj.interior, t);
    if (auto csg = std::get_if<Csg>(&obj.shape)) {
        for (Object& child : csg->children) transform_node(child, t, step);
        for (Light& l : csg->lights) transform_light(l, t, step);
        if (csg->pov_box) move_pov_box(*csg->pov_box, t);
    }
    if (auto mesh = std::get_if<Mesh>(&obj.shape); mesh && !obj.uv_mapping) {
        // per-face textures move too
        for (LayeredTexture& tex : mesh->textures) transform_textures(tex, t);
    }
    if (auto blob = std::get_if<Blob>(&obj.shape)) {  // and a blob's component textures
        for (LayeredTexture& tex : blob->element_textures) transform_textures(tex, t);
    }
    if (obj.clipped_by.allocated()) {
        for (Object& o : obj.clipped_by.edit()) apply_transform(o, t, step);
    }
    if (obj.bounded_by.allocated()) {
        for (Object& o : obj.bounded_by.edit()) apply_transform(o, t, step);
    }
}

bool Interpreter::try_transform(const Token& t, Transform& out, TransformStep* step) {
    if (t.kind != TokenKind::Word) return false;
    std::string_view w = t.text;
    TransformStep kind;
    if (w == "translate") {
        kind = {TransformStep::Kind::Translate, parse_vector()};
        out = Transform::translate(kind.amount);
    } else if (w == "rotate") {
        kind = {TransformStep::Kind::Rotate, parse_vector()};
        out = Transform::rotate(kind.amount);
    } else if (w == "scale") {
        Token at = peek();
        Vector3 s = parse_vector();
        for (int i = 0; i < 3; ++i) {
            // POV-Ray's Parse_Scale_Vector, wherever `scale` is read: a 0 becomes 1.
            if (s[i] == 0) {
                s[i] = 1;
                warn(at, std::string("Illegal Value: Scale ") + "XYZ"[i] +
                             " by 0.0. Changed to 1.0.");
            }
        }
        out = Transform::scale(s);
        kind = {TransformStep::Kind::Scale, s};
    } else if (w == "matrix") {
        expect_punct('<', "to start the 12 matrix values");
        Real m[12];
        for (int i = 0; i < 12; ++i) {
            if (i) accept_punct(',');
            m[i] = parse_numeric(true).c[0];
        }
        expect_punct('>', "after the 12 matrix values");
        const Real det = m[0] * (m[4] * m[8] - m[5] * m[7]) -
                         m[1] * (m[3] * m[8] - m[5] * m[6]) +
                         m[2] * (m[3] * m[7] - m[4] * m[6]);
        if (det == 0) error(t, "singular transform: matrix has determinant 0");
        out = Transform::from_pov_matrix(m);
    } else if (w == "transform") {
        Token n = peek();
        if (is_punct(n, '{')) {
            next();
            out = parse_transform_block();
        } else {
            next();
            const Value* v = lookup(n);
            auto tp = v ? std::get_if<std::shared_ptr<Transform>>(v) : nullptr;
            if (!tp) expected("a transform identifier or '{'", n);
            out = **tp;
        }
    } else {
        return false;
    }
    if (step) *step = kind;
    return true;
}

// After `transform {`: transforms (and transform identifiers, and `inverse`) up to '}'.
Transform Interpreter::parse_transform_block() {
    Transform result;
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) return result;
        Transform step;
        if (try_transform(t, step)) {
            result = result.then(step);
        } else if (is_word(t, "inverse")) {
            result = result.inverse();
        } else if (t.kind == TokenKind::Word) {
            const Value* v = lookup(t);
            auto tp = v ? std::get_if<std::shared_ptr<Transform>>(v) : nullptr;
            if (!tp) expected("a transformation or '}'", t);
            result = result.then(**tp);
        } else {
            expected("a transformation or '}'", t);
        }
    }
}

namespace {
// POV-Ray's Convert_Filter_To_Transmit: a plain colour's filter, a colour map's entries'
// and a pigment map's entries' become transmit.
void filter_to_transmit(Pigment& p) {
    if (p.pattern->kind == PatternKind::Solid) {
        p.colour.transmit += p.colour.filter;
        p.colour.filter = 0;
        return;
    }
    if (!p.maps.allocated()) return;
    PigmentMaps& maps = p.maps.edit();
    for (ColourMapEntry& e : maps.colour_map) {
        e.colour.transmit += e.colour.filter;
        e.colour.filter = 0;
    }
    for (Pigment& entry : maps.list) filter_to_transmit(entry);
}
}  // namespace

void Interpreter::link_textures(LayeredTexture& onto, LayeredTexture&& layers,
                                const Token& at) {
    if (layers.empty()) return;
    if (!onto.empty() && onto.back().map_pattern)
        error(at, "cannot layer over a patterned texture");
    // Up to #version 3.1 a layer laid over another lets it through by transmit, not
    // filter (Link_Textures): every new layer but the lowest, and that one too over
    // earlier layers.
    if (language_version() <= 310) {
        for (size_t k = 0; k < layers.size(); ++k)
            if (k > 0 || !onto.empty()) filter_to_transmit(layers[k].pigment);
    }
    for (Texture& l : layers) onto.push_back(std::move(l));
    if (onto.size() > 1 && onto.back().map_pattern)
        error(at, "cannot layer a patterned texture over another");
}

bool Interpreter::try_object_modifier(Object& obj, const Token& t) {
    Transform tr;
    TransformStep step;
    if (try_transform(t, tr, &step)) {
        apply_transform(obj, tr, step);
        return true;
    }
    if (t.kind != TokenKind::Word) return false;
    std::string_view w = t.text;
    if (w == "texture") {
        // Each texture is a new layer on top (POV-Ray's Link_Textures).
        link_textures(obj.texture, parse_texture_block(), t);
    } else if (w == "pigment" || w == "finish" || w == "normal") {
        // A loose pigment, normal or finish edits the top layer, made from the default
        // texture when there is none; a patterned top layer cannot take one.
        if (obj.texture.empty())
            obj.texture.push_back(default_texture_);
        else if (obj.texture.back().map_pattern)
            error(t, "cannot layer over a patterned texture");
        Texture& top = obj.texture.back();
        if (w == "pigment") {
            parse_pigment_into(top.pigment);
        } else if (w == "finish") {
            parse_finish_into(top.finish);
        } else {
            parse_normal_into(top.normal);
        }
    } else if (w == "interior_texture") {
        LayeredTexture& inside = obj.interior_texture.edit();
        link_textures(inside, parse_texture_block(), t);
    } else if (w == "interior") {
        parse_interior_into(obj.interior);
    } else if (w == "material") {
        // The material works on the object's texture and interior: its textures are
        // layered on top, its interior block edits the object's, and its transforms move
        // the textures (not the object), as POV-Ray's Parse_Material.
        expect_punct('{', "after 'material'");
        for (;;) {
            Token m = next();
            if (is_punct(m, '}')) break;
            if (is_word(m, "texture")) {
                link_textures(obj.texture, parse_texture_block(), m);
            } else if (is_word(m, "interior_texture")) {
                link_textures(obj.interior_texture.edit(), parse_texture_block(), m);
            } else if (is_word(m, "interior")) {
                parse_interior_into(obj.interior);
            } else if (try_transform(m, tr)) {
                transform_textures(obj.texture, tr);
                if (obj.interior_texture.allocated())
                    transform_textures(obj.interior_texture.edit(), tr);
                transform_interior(obj.interior, tr);
            } else if (m.kind == TokenKind::Word && lookup(m) &&
                       std::holds_alternative<std::shared_ptr<Material>>(*lookup(m))) {
                auto mat = std::get<std::shared_ptr<Material>>(*lookup(m));
                link_textures(obj.texture, LayeredTexture(mat->texture), m);
                if (!mat->interior_texture.empty())
                    link_textures(obj.interior_texture.edit(),
                                  LayeredTexture(mat->interior_texture), m);
                obj.interior = mat->interior;
            } else {
                expected("texture, interior or '}' in material", m);
            }
        }
    } else if (w == "no_shadow") {
        obj.no_shadow = true;
    } else if (w == "no_image") {
        obj.no_image = parse_bool_opt();
    } else if (w == "no_reflection") {
        obj.no_reflection = parse_bool_opt();
    } else if (w == "no_radiosity") {
        obj.no_radiosity = parse_bool_opt();
    } else if (w == "dtag") {
        parse_string();  // a debugging tag: POV-Ray's release builds drop it
    } else if (w == "hierarchy") {
        // Bounding inside meshes: the image is the same. A height field's blocks decide
        // which of close hits it reports.
        if (auto hf = std::get_if<HeightField>(&obj.shape)) {
            hf->hierarchy = parse_bool_opt();
        } else if (auto blob = std::get_if<Blob>(&obj.shape)) {
            // Its bounding-sphere tree changes only the order of the field's sums.
            blob->hierarchy = parse_bool_opt();
        } else if (auto mesh = std::get_if<Mesh>(&obj.shape)) {
            const bool tree = parse_bool_opt();
            if (&obj == mesh_in_own_braces_) mesh->hierarchy = tree;
        } else {
            error(t, "'hierarchy' cannot be used with this object");
        }
    } else if (w == "hollow") {
        obj.hollow = parse_bool_opt();
        obj.hollow_given = true;
        // On a union, merge, intersection or difference (POV-Ray's difference is an
        // intersection) it goes at once to the leaves that did not say, through nested
        // CSG, as POV-Ray's parser does.
        auto pass_down = [&](auto& self, Object& o) -> void {
            if (!std::holds_alternative<Csg>(o.shape)) return;
            for (Object& c : std::get<Csg>(o.shape).children) {
                if (c.hollow_given) continue;
                if (std::holds_alternative<Csg>(c.shape))
                    self(self, c);
                else
                    c.hollow = obj.hollow;
            }
        };
        pass_down(pass_down, obj);
    } else if (w == "inverse" && (std::holds_alternative<BicubicPatch>(obj.shape) ||
                                  std::holds_alternative<Parametric>(obj.shape) ||
                                  std::holds_alternative<Triangle>(obj.shape) ||
                                  std::holds_alternative<SmoothTriangle>(obj.shape))) {
        // POV-Ray's Invert of these does nothing (trace/shapes/shape.h, leaf_invertible).
        warn(t, "Cannot invert a patch object.");
    } else if (w == "inverse" && std::holds_alternative<Polygon>(obj.shape)) {
        // Nor of a polygon, which is no patch object: no warning.
    } else if (w == "inverse") {
        obj.inverse = !obj.inverse;
        // POV-Ray inverts a CSG by inverting its children and morphing every CSG of the
        // tree (union and merge into intersection, intersection into merge): a union
        // never comes back, and its surfaces inside another child are gone. Kept as the
        // inverse of a merge, whose surfaces are those.
        auto morph = [](auto& self, Object& o) -> void {
            Csg* csg = std::get_if<Csg>(&o.shape);
            if (!csg) return;
            if (csg->kind == CsgKind::Union) csg->kind = CsgKind::Merge;
            for (Object& c : csg->children) self(self, c);
        };
        morph(morph, obj);
    } else if (w == "double_illuminate") {
        // On a CSG it goes at once to every node below, on or off (POV-Ray's
        // Set_CSG_Tree_Flag), so the outermost setting wins; unlike the ray flags it
        // does not come down when the object is placed.
        obj.double_illuminate = parse_bool_opt();
        auto set_tree = [&](auto& self, Object& o) -> void {
            if (auto csg = std::get_if<Csg>(&o.shape)) {
                for (Object& c : csg->children) {
                    c.double_illuminate = obj.double_illuminate;
                    self(self, c);
                }
            }
        };
        set_tree(set_tree, obj);
    } else if (w == "sturm") {
        bool* sturm = nullptr;
        if (auto torus = std::get_if<Torus>(&obj.shape)) sturm = &torus->sturm;
        if (auto prism = std::get_if<Prism>(&obj.shape)) sturm = &prism->sturm;
        if (auto ovus = std::get_if<Ovus>(&obj.shape)) sturm = &ovus->sturm;
        if (auto sor = std::get_if<Sor>(&obj.shape)) sturm = &sor->sturm;
        if (auto lathe = std::get_if<Lathe>(&obj.shape)) sturm = &lathe->sturm;
        if (auto poly = std::get_if<Poly>(&obj.shape)) sturm = &poly->sturm;
        if (auto blob = std::get_if<Blob>(&obj.shape)) sturm = &blob->sturm;
        if (!sturm) error(t, "'sturm' cannot be used with this object");
        *sturm = parse_bool_opt();
    } else if (w == "open") {
        auto cyl = std::get_if<Cylinder>(&obj.shape);
        auto cone = std::get_if<Cone>(&obj.shape);
        if (!cyl && !cone) error(t, "'open' cannot be used with this object");
        if (cyl) cyl->open = true;
        if (cone) cone->open = true;
    } else if (w == "clipped_by" || w == "bounded_by") {
        // (A bicubic_patch keeps its clips: POV-Ray ignores them for its hits but shrinks
        // its box by them, trace/prepared_scene.cpp.)
        // As POV-Ray: `bounded_by { clipped_by }` bounds by the clip, `clipped_by {
        // bounded_by }` clips by the bound; the lists are then one, and neither grows.
        expect_punct('{', "after ", w);
        const bool clip = w == "clipped_by";
        std::vector<Object>& list = clip ? obj.clipped_by.edit() : obj.bounded_by.edit();
        const std::string other = clip ? "bounded_by" : "clipped_by";
        if (obj.bounds_are_clips && !list.empty() &&
            obj.clipped_by->size() == obj.bounded_by->size())
            error(t, std::string("cannot add ") + (clip ? "clips" : "bounds") +
                         " after linking bounds and clips");
        if (Token o = next(); is_word(o, other)) {
            if (!list.empty())
                error(o, std::string("cannot link ") + (clip ? "bounds" : "clips") +
                             " with previous " + (clip ? "clips" : "bounds"));
            list = clip ? *obj.bounded_by : *obj.clipped_by;
            obj.bounds_are_clips = true;
            expect_punct('}', "after ", other);
        } else {
            // POV-Ray's Parse_Bound_Clip: objects, then transforms, each moving every
            // object of this block.
            const size_t first = list.size();
            bool moved = false;
            for (; !is_punct(o, '}'); o = next()) {
                Transform move;
                TransformStep move_step;
                if (try_transform(o, move, &move_step)) {
                    for (size_t i = first; i < list.size(); ++i)
                        apply_transform(list[i], move, move_step);
                    moved = true;
                    continue;
                }
                Object child;
                if (moved) expected("a transformation or '}'", o);
                if (!try_parse_object_or_identifier(o, child))
                    expected("an object or '}'", o);
                list.push_back(std::move(child));
            }
            // POV-Ray computes a quadric's box again from its clips.
            if (Quadric* q = std::get_if<Quadric>(&obj.shape);
                q && clip && !quadric_clip_bounds(*q, list, pov_box_of(options_)))
                unsupported(t,
                            "clipped_by on a quadric by shapes other than boxes, "
                            "planes and quadrics");
        }
    } else if (w == "photons") {
        parse_object_photons(obj);
    } else if (w == "radiosity") {
        parse_object_radiosity(obj);
    } else if (w == "split_union") {
        // How POV-Ray links a union: whole, its children keep their bounded_by.
        const Csg* csg = std::get_if<Csg>(&obj.shape);
        if (!csg || (csg->kind != CsgKind::Union && csg->kind != CsgKind::Merge))
            error(t, "split_union found in non-union object");
        obj.split_union = parse_float() != 0;  // a value is required
    } else if (w == "cutaway_textures") {
        const Csg* csg = std::get_if<Csg>(&obj.shape);
        if (!csg ||
            (csg->kind != CsgKind::Intersection && csg->kind != CsgKind::Difference))
            error(t,
                  "cutaway_textures can only be used with intersection and difference");
        // Its parts without a texture keep none (place_object); their surfaces show the
        // textures of the parts they lie in (trace/cutaway_textures.h).
        std::get<Csg>(obj.shape).cutaway_textures = true;
    } else if (w == "uv_mapping") {
        // Textures given after it are evaluated at the surface coordinates and stay
        // where the transforms leave the object (POV-Ray's UV_FLAG).
        if (!obj.texture.empty()) error(t, "uv_mapping must be specified before texture");
        obj.uv_mapping = true;
    } else {
        return false;
    }
    return true;
}

void Interpreter::parse_object_modifiers(Object& obj) {
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) {
            // As POV-Ray's Parse_Object_Mods: the inside needs an outside.
            if (obj.texture.empty() && !obj.interior_texture->empty())
                error(t, "interior texture requires an exterior texture");
            return;
        }
        if (!try_object_modifier(obj, t)) expected("an object modifier or '}'", t);
    }
}

bool Interpreter::try_parse_object_or_identifier(const Token& t, Object& out) {
    const Value* v = t.kind == TokenKind::Word ? lookup(t) : nullptr;
    if (auto id = v ? std::get_if<std::shared_ptr<Object>>(v) : nullptr) {
        out = **id;
        out.loc = sources_.location(t);
        return true;
    }
    return try_parse_object(t, out);
}

bool Interpreter::light_block_names_object() {
    Token open = next();
    bool named = false;
    if (is_punct(open, '{')) {
        const Token& first = peek();
        const Value* v = first.kind == TokenKind::Word ? lookup(first) : nullptr;
        named = v && std::holds_alternative<std::shared_ptr<Object>>(*v);
    }
    unget(open);
    return named;
}

bool Interpreter::try_parse_object(const Token& t, Object& out) {
    if (t.kind != TokenKind::Word) return false;
    NestingGuard guard(*this, t);
    std::string_view w = t.text;
    out = Object{};
    out.loc = sources_.location(t);
    auto open = [&] { expect_punct('{', "after ", w); };
    std::optional<PendingHeightField> pending_height_field;
    bool own_mesh = false;
    // `sphere { ID ... }`: an object identifier first in the body copies it.
    auto copy_identifier = [&]() -> bool {
        const Token& p = peek();
        if (p.kind != TokenKind::Word) return false;
        const Value* v = lookup(p);
        auto o = v ? std::get_if<std::shared_ptr<Object>>(v) : nullptr;
        if (!o) return false;
        next();
        SourceLoc loc = out.loc;
        out = **o;
        out.loc = loc;
        mark_copy(out);
        return true;
    };
    if (w == "sphere") {
        open();
        if (!copy_identifier()) {
            Sphere s;
            require_operand("the sphere's centre");
            s.centre = parse_vector();
            accept_punct(',');
            require_operand("the sphere's radius");
            s.radius = parse_float();
            out.shape = s;
        }
    } else if (w == "box") {
        open();
        if (!copy_identifier()) {
            Box b;
            require_operand("the box's first corner");
            b.corner1 = parse_vector();
            accept_punct(',');
            require_operand("the box's second corner");
            b.corner2 = parse_vector();
            // POV-Ray orders the corners (Parse_Box): corner1 is the low one.
            for (int a = 0; a < 3; ++a)
                if (b.corner1[a] > b.corner2[a]) std::swap(b.corner1[a], b.corner2[a]);
            out.shape = b;
        }
    } else if (w == "plane") {
        open();
        if (!copy_identifier()) {
            Plane p;
            Token at = peek();
            Vector3 n = parse_vector();
            if (length(n) < 1e-10) error(at, "degenerate plane normal");
            p.normal = normalize(n);
            accept_punct(',');
            require_operand("the plane's distance");
            p.distance = parse_float();
            out.shape = p;
        }
    } else if (w == "cylinder") {
        open();
        if (!copy_identifier()) {
            Cylinder c;
            c.base = parse_vector();
            accept_punct(',');
            c.cap = parse_vector();
            accept_punct(',');
            require_operand("the cylinder's radius");
            c.radius = parse_float();
            // POV-Ray stops here too: the axis has no direction.
            // POV-Ray reads the first point as its apex and the second as its base.
            const Vector3 axis = c.base - c.cap;
            const Real len = length(axis);
            if (len < 1e-10) error(t, "degenerate cylinder, base point = cap point");
            // As POV-Ray holds it (Compute_Cylinder_Data): the unit cylinder in its
            // frame from the second point towards the first, which the object's
            // transforms then compose onto, so rays meet it with POV-Ray's bits
            // (coincident cylinders tie as in POV-Ray). A zero radius stays as written:
            // a line, never hit.
            if (c.radius != 0 && std::isfinite(c.radius)) {
                out.transform =
                    pov_coordinate_transform(c.cap, axis * (1.0 / len), c.radius, len);
                c = Cylinder{{0, 0, 0}, {0, 0, 1}, 1, false};
            }
            out.shape = c;
        }
    } else if (w == "cone") {
        open();
        if (!copy_identifier()) {
            Cone c;
            c.base = parse_vector();
            accept_punct(',');
            c.base_radius = parse_float();
            accept_punct(',');
            c.cap = parse_vector();
            accept_punct(',');
            c.cap_radius = parse_float();
            if (length(c.cap - c.base) < 1e-10)
                error(t, "degenerate cone, base point = cap point");
            pov_cone_frame(c, out);
        }
    } else if (w == "text") {
        open();
        if (!copy_identifier()) parse_text(out);
    } else if (w == "torus") {
        open();
        if (!copy_identifier()) {
            Torus tor;
            tor.major = parse_float();
            accept_punct(',');
            tor.minor = parse_float();
            out.shape = tor;
        }
    } else if (w == "cubic" || w == "quartic" || w == "poly") {
        open();
        if (!copy_identifier())
            parse_poly(out, w == "cubic" ? 3 : w == "quartic" ? 4 : 0);
    } else if (w == "polynomial") {
        open();
        if (!copy_identifier()) parse_polynomial(out);
    } else if (w == "quadric") {
        open();
        if (!copy_identifier()) parse_quadric(out);
    } else if (w == "blob") {
        open();
        if (!copy_identifier()) parse_blob(out);
    } else if (w == "isosurface") {
        open();
        if (!copy_identifier()) parse_isosurface(out, t);
    } else if (w == "parametric") {
        open();
        if (!copy_identifier()) parse_parametric(out, t);
    } else if (w == "superellipsoid") {
        open();
        if (!copy_identifier()) parse_superellipsoid(out);
    } else if (w == "ovus") {
        open();
        if (!copy_identifier()) parse_ovus(t, out);
    } else if (w == "sor") {
        open();
        if (!copy_identifier()) parse_sor(t, out);
    } else if (w == "lathe") {
        open();
        if (!copy_identifier()) parse_lathe(out);
    } else if (w == "sphere_sweep") {
        open();
        if (!copy_identifier()) parse_sphere_sweep(out);
    } else if (w == "disc") {
        open();
        if (!copy_identifier()) {
            Disc d;
            d.centre = parse_vector();
            accept_punct(',');
            d.normal = parse_vector();
            accept_punct(',');
            d.radius = parse_float();
            // disc { c[,] n[,] r[,] [hole] }: POV-Ray reads floats while they come, the
            // last one is the hole radius.
            accept_punct(',');
            while (starts_float(peek())) d.hole_radius = parse_float();
            out.shape = d;
        }
    } else if (w == "triangle") {
        open();
        if (!copy_identifier()) {
            Triangle tri;
            for (int i = 0; i < 3; ++i) {
                if (i) accept_punct(',');
                tri.p[i] = parse_vector();
            }
            if (degenerate_corners(tri.p))
                warn(t, "degenerate triangle, never hit; please remove");
            out.shape = tri;
        }
    } else if (w == "smooth_triangle") {
        open();
        if (!copy_identifier()) {
            SmoothTriangle tri;
            for (int i = 0; i < 3; ++i) {
                if (i) accept_punct(',');
                tri.p[i] = parse_vector();
                accept_punct(',');
                tri.n.edit()[i] = parse_vector();
            }
            // POV-Ray (Parse_Smooth_Triangle, Compute_Smooth_Triangle) normalises the
            // vertex normals; a zero one, or normals not all on one side of the face,
            // make the triangle degenerate: never hit. A zero first normal marks that.
            auto& n = tri.n.edit();
            bool degenerate = degenerate_corners(tri.p);
            for (Vector3& v : n) {
                const Real len = length(v);
                if (len == 0)
                    degenerate = true;
                else
                    v = v / len;
            }
            if (!normals_on_one_side(tri.p, n)) degenerate = true;
            if (degenerate) {
                warn(t, "degenerate triangle, never hit; please remove");
                n[0] = Vector3{0, 0, 0};
            }
            out.shape = tri;
        }
    } else if (w == "polygon") {
        open();
        if (!copy_identifier()) {
            Polygon poly;
            int n = parse_int();
            for (int i = 0; i < n; ++i) {
                accept_punct(',');
                poly.points.push_back(parse_vector());
            }
            out.shape = poly;
        }
    } else if (w == "julia_fractal") {
        open();
        if (!copy_identifier()) parse_julia_fractal(out, t);
    } else if (w == "bicubic_patch") {
        open();
        if (!copy_identifier()) parse_bicubic_patch(out, t);
    } else if (w == "prism") {
        open();
        if (!copy_identifier()) parse_prism(out, t);
    } else if (w == "height_field") {
        open();
        if (!copy_identifier()) pending_height_field = parse_height_field(out);
    } else if (w == "mesh" || w == "mesh2") {
        open();
        if (!copy_identifier()) {
            if (w == "mesh")
                parse_mesh(out);
            else
                parse_mesh2(out);
            own_mesh = true;
        }
    } else if (w == "union" || w == "merge" || w == "intersection" || w == "difference" ||
               w == "composite") {
        open();
        // POV-Ray 3.7 reads the old `composite` as a union.
        if (w == "composite") warn(t, "use union instead of composite");
        // POV-Ray's Parse_Object_Id: a declared object first in the braces is the result
        // itself, copied whatever its kind (not a child of a new CSG), and only object
        // modifiers may follow it.
        if (!copy_identifier()) {
            Csg csg;
            csg.kind = w == "union" || w == "composite" ? CsgKind::Union
                       : w == "merge"                   ? CsgKind::Merge
                       : w == "intersection"            ? CsgKind::Intersection
                                                        : CsgKind::Difference;
            out.shape = Csg{};
            for (;;) {
                Token c = peek();
                Object child;
                if (c.kind == TokenKind::Word && is_word(c, "light_source")) {
                    next();
                    if (!light_block_names_object()) {
                        csg.lights.push_back(parse_light_block());
                        continue;
                    }
                    unget(c);  // an object, read below
                }
                if (c.kind == TokenKind::Word && !is_word(c, "texture") &&
                    !is_word(c, "pigment") && !is_word(c, "finish") &&
                    !is_word(c, "normal") && !is_word(c, "interior") &&
                    !is_word(c, "material")) {
                    next();
                    // A declared object named bare is a child, as object { Id } without
                    // modifiers.
                    if (try_parse_object_or_identifier(c, child)) {
                        if (holds_parametric(child)) {
                            // A patch object: POV-Ray warns, and keeps it.
                            if (csg.kind == CsgKind::Intersection ||
                                csg.kind == CsgKind::Difference)
                                warn(c, "Patch objects not allowed in intersection.");
                        }
                        csg.children.push_back(std::move(child));
                        continue;
                    }
                    unget(c);
                }
                break;
            }
            if (csg.kind == CsgKind::Intersection || csg.kind == CsgKind::Difference) {
                // POV-Ray sees every child of a difference but the first inverted.
                auto inverted = [&](size_t i) {
                    return csg.children[i].inverse !=
                           (csg.kind == CsgKind::Difference && i > 0);
                };
                bool bounds_quadric = false;
                for (size_t i = 0; i < csg.children.size(); ++i)
                    bounds_quadric =
                        bounds_quadric ||
                        (std::holds_alternative<Quadric>(csg.children[i].shape) &&
                         !inverted(i));
                std::vector<bool> flags(csg.children.size());
                for (size_t i = 0; i < csg.children.size(); ++i) flags[i] = inverted(i);
                if (bounds_quadric &&
                    !quadric_csg_bounds_impl(csg.children, flags, pov_box_of(options_)))
                    unsupported(t,
                                "a quadric in an intersection or difference with shapes "
                                "other than planes and quadrics");
            }
            out.shape = std::move(csg);
            close_csg_box(out);
        }
    } else if (w == "object") {
        open();
        Token id = next();
        const Value* v = id.kind == TokenKind::Word ? lookup(id) : nullptr;
        const bool inline_light = is_word(id, "light_source");
        if (inline_light || (v && std::holds_alternative<std::shared_ptr<Light>>(*v))) {
            // object { LightId } or object { light_source { } } (as POV-Ray, whose
            // lights are objects): a light source, carried by an empty CSG so that
            // later transforms (its own and those of enclosing objects) move it.
            Csg holder;
            holder.lights.push_back(inline_light ? parse_light_block()
                                                 : *std::get<std::shared_ptr<Light>>(*v));
            out = Object{};
            out.shape = std::move(holder);
            for (;;) {
                Token m = next();
                if (is_punct(m, '}')) break;
                Transform tr;
                TransformStep step;
                if (!try_transform(m, tr, &step)) expected("a transformation or '}'", m);
                apply_transform(out, tr, step);
            }
            return true;
        }
        auto o = v ? std::get_if<std::shared_ptr<Object>>(v) : nullptr;
        if (!o) {
            if (!try_parse_object(id, out)) {
                expected("an object identifier", id);
            }
        } else {
            SourceLoc loc = out.loc;
            out = **o;
            out.loc = loc;
            mark_copy(out);
        }
    } else if (w == "light_group") {
        parse_light_group(t, out);  // takes its own few modifiers
        return true;
    } else if (w == "light_source" && light_block_names_object()) {
        // POV-Ray's Parse_Light_Source starts with Parse_Object_Id: a declared object
        // first in its braces makes it `object { Id ... }`, whatever the object.
        Token as_object = t;
        as_object.text = "object";
        return try_parse_object(as_object, out);
    } else {
        // Checked last: the shapes povwall has are the common case.
        if (is_unsupported_shape(w)) unsupported(t, w);
        return false;
    }
    {
        const Object* outer = mesh_in_own_braces_;
        mesh_in_own_braces_ = own_mesh ? &out : nullptr;
        parse_object_modifiers(out);
        mesh_in_own_braces_ = outer;
    }
    check_algebraic_bounds(out, t);
    if (pending_height_field) finish_height_field(out, std::move(*pending_height_field));
    // A julia_fractal's set-up after its modifiers clears the inverse flag (as a
    // transform does); `object { Julia inverse }` has no set-up and keeps it.
    if (w == "julia_fractal" && std::holds_alternative<JuliaFractal>(out.shape))
        out.inverse = false;
    return true;
}

void Interpreter::collect_lights(Object& obj) {
    if (auto csg = std::get_if<Csg>(&obj.shape)) {
        for (Light& l : csg->lights) {
            scene_.lights.push_back(std::move(l));
            scene_.lights.back().objects_before =
                uint32_t(scene_.objects.size() + scene_.objects_left_out);
        }
        csg->lights.clear();
        for (Object& child : csg->children) collect_lights(child);
    }
}

void Interpreter::finish_object(Object& obj) {
    settle_inverted_unions(obj, 0);
    std::unordered_map<uint32_t, Interior> shared;
    place_object(obj, nullptr, shared);
    // Every sharer of an interior gets its final state (a later sharer may have changed
    // it, as POV-Ray's shared pointer lets it).
    auto settle = [&](auto& self, Object& o) -> void {
        *o.interior = shared.at(o.interior->id);
        if (auto csg = std::get_if<Csg>(&o.shape))
            for (Object& child : csg->children) self(self, child);
    };
    settle(settle, obj);
}

// POV-Ray's post-processing of a placed object, top down: a child without a texture or
// interior takes its parent's (the same interior: children then enter and leave it
// together); an object with none gets the default texture (not in a cutaway_textures
// CSG: stays_untextured) and an interior of its own;
// a plain top texture's old finish ior/caustics/refraction go into the interior, which
// every sharer sees (the last one placed wins, as in POV-Ray).
void Interpreter::place_object(Object& obj, const Object* parent,
                               std::unordered_map<uint32_t, Interior>& shared) {
    if (const Csg* up = parent ? std::get_if<Csg>(&parent->shape) : nullptr;
        up && up->cutaway_textures)
        if (Csg* csg = std::get_if<Csg>(&obj.shape)) csg->cutaway_textures = true;
    if (parent) {
        // uv_mapping comes down with the textures it applies to (POV-Ray's
        // Post_Process).
        if (obj.texture.empty()) {
            obj.texture = parent->texture;
            obj.uv_mapping |= parent->uv_mapping;
        }
        // The interior texture comes down on its own, whether the child has a texture
        // of its own or not (POV-Ray's Post_Process).
        if (obj.interior_texture->empty()) {
            if (!parent->interior_texture->empty())
                obj.interior_texture = parent->interior_texture;
            // (POV-Ray passes the flag on here whether the parent has an interior
            // texture or not: a child with a texture of its own gets it too.)
            obj.uv_mapping |= parent->uv_mapping;
        }
        if (!obj.interior) obj.interior = *parent->interior;
        // The ray flags come down (never off); where POV-Ray tests them, ray_use.h.
        obj.no_shadow |= parent->no_shadow;
        obj.no_image |= parent->no_image;
        obj.no_reflection |= parent->no_reflection;
        obj.no_radiosity |= parent->no_radiosity;
        if (obj.radiosity_importance <= 0)
            obj.radiosity_importance = parent->radiosity_importance;
        inherit_photons(obj.photons, parent->photons);
    }
    if (obj.texture.empty() && !stays_untextured(obj, parent))
        obj.texture.push_back(default_texture_);
    if (!obj.interior) obj.interior = Interior{};
    if (obj.interior->id == 0) {
        obj.interior->id = ++interiors_numbered_;
        shared.emplace(obj.interior->id, *obj.interior);
    }
    Interior& in = shared.at(obj.interior->id);
    in.hollow = obj.hollow;
    if (const Texture* top = obj.texture.empty() ? nullptr : &obj.texture.back();
        top && !top->map_pattern && top->map->entries.empty()) {
        const Finish& f = *top->finish;
        if (f.legacy_ior >= 0) {
            in.ior = f.legacy_ior;
            in.ior_set = true;
            in.dispersion = 1;
        }
        if (f.legacy_caustics >= 0) in.caustics = f.legacy_caustics;
        in.old_refract = f.legacy_refraction;
    }
    if (!in.ior_set) in.dispersion = 1;
    if (auto csg = std::get_if<Csg>(&obj.shape)) {
        for (Object& child : csg->children) place_object(child, &obj, shared);
    }
}

void Interpreter::add_scene_object(Object&& obj) {
    count_mesh_copies(obj);
    // The first growth reserves room for 16,384 objects at once: capacity never written
    // costs address space, not memory, and a scene made in a loop no longer moves its
    // objects through four or five ever larger lists. Beyond that the list doubles. The
    // list's pages are written in order, each first touch a fault (microseconds on a VM):
    // they are mapped 256 KB ahead at once, and a grown list is mapped (in 2 MB pages
    // where it is large) before the objects move into it.
    constexpr size_t kAhead = (size_t(256) << 10) / sizeof(Object);
    std::vector<Object>& list = scene_.objects;
    if (list.size() == list.capacity()) {
        constexpr size_t kFirstCapacity = 16384;
        std::vector<Object> grown;
        grown.reserve(std::max(2 * list.capacity(), kFirstCapacity));
        advise_huge_pages(grown.data(), grown.capacity() * sizeof(Object));
        objects_populated_ = std::min(list.size() + kAhead, grown.capacity());
        populate_for_write(grown.data(), objects_populated_ * sizeof(Object));
        std::move(list.begin(), list.end(), std::back_inserter(grown));
        list.swap(grown);
    }
    if (list.size() >= objects_populated_) {
        const size_t upto = std::min(list.size() + kAhead, list.capacity());
        populate_for_write(list.data() + list.size(),
                           (upto - list.size()) * sizeof(Object));
        objects_populated_ = upto;
    }
    if (!options_.keep_object) {
        scene_.objects.push_back(std::move(obj));
        return;
    }
    const auto nodes = uint32_t(object_node_count(obj));
    if (options_.keep_object(obj)) {
        scene_.object_first_node.push_back(scene_.object_nodes_total);
        scene_.objects.push_back(std::move(obj));
    } else {
        scene_.leave_out(obj, scene_.object_nodes_total);
        ++scene_.objects_left_out;
    }
    scene_.object_nodes_total += nodes;
}

void Interpreter::parse_top_level_item(const Token& t) {
    if (is_punct(t, ';')) return;
    if (t.kind == TokenKind::Word) {
        std::string_view w = t.text;
        if (w == "camera") {
            CameraSpec spec = parse_camera_block();
            scene_.camera = finish_camera(spec);
            return;
        }
        if (w == "light_source" && !light_block_names_object()) {
            scene_.lights.push_back(parse_light_block());
            scene_.lights.back().objects_before =
                uint32_t(scene_.objects.size() + scene_.objects_left_out);
            return;
        }
        if (w == "background") {
            expect_punct('{', "after 'background'");
            Numeric c = parse_colour();
            expect_punct('}', "after the background colour");
            scene_.background = Colour(Rgb(float(c.c[0]), float(c.c[1]), float(c.c[2])),
                                       float(c.c[3]), float(c.c[4]));
            scene_.background_legacy = effective_version() < 370;
            return;
        }
        if (w == "global_settings") {
            parse_global_settings();
            return;
        }
        if (w == "sky_sphere") {
            scene_.sky_sphere = parse_sky_sphere();
            return;
        }
        if (w == "fog") {
            scene_.fogs.push_back(parse_fog());
            return;
        }
        if (w == "default") {  // pre-3.0 spelling of #default
            directive_default();
            return;
        }
        if (w == "declare" || w == "include") {
            // Old scenes write these without '#' between objects; POV-Ray's frame takes
            // them as the directives, with its warning.
            warn(t, "Should have '#' before '" + std::string(w) + "'.");
            Token directive = t;
            directive.kind = TokenKind::Directive;
            run_directive(directive);
            return;
        }
        if (w == "media") {
            if (area_light_attenuated_by_media_)
                unsupported(t,
                            "atmospheric media with an area light's media_attenuation");
            scene_.atmosphere_media.push_back(parse_media());
            return;
        }
        if (w == "rainbow") {
            scene_.rainbows.push_back(parse_rainbow(t));
            return;
        }
        if (w == "atmosphere" || w == "photons" || w == "radiosity") {
            unsupported(t, w);
        }
        // POV-Ray's Link_To_Frame removes the bound of a shape placed in the scene (as
        // unnecessary) and says so; the render leaves it out (pov_keeps_bound()).
        auto warn_removed_bounds = [&](auto& self, const Object& o) -> void {
            if (pov_splits_union(o)) {
                for (const Object& c : std::get<Csg>(o.shape).children) self(self, c);
            } else if (!o.bounded_by.empty() && !pov_keeps_bound(o)) {
                warn(t, "unnecessary bounding object removed");
            }
        };
        Object obj;
        if (try_parse_object(t, obj)) {
            finish_object(obj);
            warn_removed_bounds(warn_removed_bounds, obj);
            assign_light_groups(obj);
            collect_lights(obj);
            add_scene_object(std::move(obj));
            return;
        }
        const Value* v = lookup(t);
        if (!v) error(t, "undeclared identifier '" + std::string(w) + "'");
        // Exporters write bare object and light identifiers as statements; POV-Ray takes
        // them.
        if (auto o = std::get_if<std::shared_ptr<Object>>(v)) {
            Object copy = **o;
            copy.loc = sources_.location(t);
            finish_object(copy);
            warn_removed_bounds(warn_removed_bounds, copy);
            assign_light_groups(copy);
            collect_lights(copy);
            add_scene_object(std::move(copy));
            return;
        }
        if (auto l = std::get_if<std::shared_ptr<Light>>(v)) {
            scene_.lights.push_back(**l);
            scene_.lights.back().objects_before =
                uint32_t(scene_.objects.size() + scene_.objects_left_out);
            return;
        }
        error(t, "a " + std::string(type_name(*v)) + " identifier '" + std::string(w) +
                     "' cannot stand alone here (use object { " + std::string(w) + " })");
    }
    expected("an object, camera, light_source or directive", t);
}

}  // namespace povwall::parser
