// The scene language's questions about objects: trace(), inside(), min_extent() and
// max_extent(), answered by the renderer's shapes (ParseOptions::object_queries), and
// the box a CSG keeps from the moment it is closed.
#include <cmath>

#include "parser/interpreter.h"

namespace povwall::parser {

namespace {

// POV-Ray's PATCH_OBJECT: a bicubic patch, a parametric or a mesh without inside_vector,
// and any CSG holding one (CHILDREN_FLAGS); such objects have no inside.
bool is_patch(const Object& o) {
    if (std::holds_alternative<BicubicPatch>(o.shape) ||
        std::holds_alternative<Parametric>(o.shape))
        return true;
    if (const Mesh* m = std::get_if<Mesh>(&o.shape)) return !m->data->inside_vector;
    if (const Csg* csg = std::get_if<Csg>(&o.shape)) {
        for (const Object& c : csg->children)
            if (is_patch(c)) return true;
    }
    return false;
}

}  // namespace

void Interpreter::close_csg_box(Object& obj) {
    Csg& csg = std::get<Csg>(obj.shape);
    if (!options_.object_queries || csg.pov_box) return;
    csg.pov_box = options_.object_queries->box(obj);
}

std::shared_ptr<Object> Interpreter::object_argument(const Token& id) {
    const Value* v = id.kind == TokenKind::Word ? lookup(id) : nullptr;
    auto object = v ? std::get_if<std::shared_ptr<Object>>(v) : nullptr;
    if (!object) expected("an object identifier", id);
    return *object;
}

Vector3 Interpreter::object_extent(const Token& at, const Object& o, bool max) {
    std::optional<Csg::PovBox> box;
    if (options_.object_queries) {
        box = options_.object_queries->box(o);
    } else if (const Csg* csg = std::get_if<Csg>(&o.shape);
               csg && csg->pov_box && !o.inverse && o.clipped_by.empty() &&
               o.bounded_by.empty()) {
        box = csg->pov_box;  // without the renderer only a text's own box is known
    } else {
        unsupported(at, max ? "max_extent" : "min_extent");
    }
    const Csg::PovBox& b = *box;
    // POV-Ray adds corner and lengths in single precision.
    Vector3 v;
    for (int a = 0; a < 3; ++a) v[a] = max ? double(b.lo[a] + b.len[a]) : double(b.lo[a]);
    return v;
}

Vector3 Interpreter::trace_object(const Token& at, const std::shared_ptr<Object>& object,
                                  const Point3& origin, const Vector3& direction,
                                  Vector3& normal) {
    // trace() also writes its normal argument: without the shapes the scene would go
    // on with that variable unchanged, so it stops here even inside a #declare.
    if (!options_.object_queries) unsupported(at, "trace", false);
    normal = Vector3{0, 0, 0};
    const Real len = length(direction);
    // POV-Ray normalises the direction; a zero one meets nothing.
    if (!(len > 0) || !std::isfinite(len)) return Vector3{0, 0, 0};
    // As VNormalizeEq: times the reciprocal (scenes feed hits back as new origins, so the
    // last bits carry on).
    const auto hit =
        options_.object_queries->trace(object, origin, direction * (1.0 / len));
    if (!hit) return Vector3{0, 0, 0};
    normal = hit->normal;
    return Vector3{hit->point.x, hit->point.y, hit->point.z};
}

bool Interpreter::inside_object(const Token& at, const Token& id,
                                const std::shared_ptr<Object>& object, const Point3& p) {
    if (!options_.object_queries) unsupported(at, "inside");
    if (is_patch(*object)) error(id, "solid object identifier expected");
    return options_.object_queries->inside(object, p);
}

}  // namespace povwall::parser
