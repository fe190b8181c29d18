// The object pattern, `object { OBJECT [transforms] ENTRY, ENTRY }` (POV-Ray 3.7's
// Parse_Pattern with Parse_Bound_Clip): one object, moved by the transforms that follow
// it; the pattern is 1 inside it, 0 outside.
#include "parser/interpreter.h"

namespace povwall::parser {

void Interpreter::parse_object_pattern(const Token& keyword, PatternSpec& spec) {
    expect_punct('{', "after 'object'");
    Object obj;
    Token first = next();
    const Value* v = first.kind == TokenKind::Word ? lookup(first) : nullptr;
    if (auto id = v ? std::get_if<std::shared_ptr<Object>>(v) : nullptr) {
        obj = **id;
    } else if (!try_parse_object(first, obj)) {
        expected("an object or object identifier", first);
    }
    // POV-Ray takes any number of objects here and then refuses all but one.
    const Token n = next();
    if (Object more; try_parse_object(n, more))
        error(keyword, "object or object identifier expected");
    unget(n);
    for (;;) {
        Transform tr;
        TransformStep step;
        const Token t = next();
        if (!try_transform(t, tr, &step)) {
            unget(t);
            break;
        }
        apply_transform(obj, tr, step);
    }
    spec.kind = PatternKind::ObjectInside;
    spec.scalar = 0;
    spec.vector = {0, 0, 0};
    spec.vector2 = {0, 0, 0};
    spec.object = std::make_shared<const Object>(std::move(obj));
}

}  // namespace povwall::parser
