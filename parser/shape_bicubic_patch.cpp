// bicubic_patch { [type N | flatness F | u_steps N | v_steps N | accuracy F]...
//                 [uv_vectors UV00, UV10, UV11, UV01] P00, ..., P33 }, as POV-Ray 3.7's
//                 Parse_Bicubic_Patch.
#include <memory>

#include "core/bicubic_patch.h"
#include "parser/interpreter.h"

namespace povwall::parser {

void Interpreter::parse_bicubic_patch(Object& out, const Token& keyword) {
    auto data = std::make_shared<BicubicPatchData>();
    int type = -1;
    if (starts_float(peek())) {
        // The old form: type [flatness] u_steps v_steps, without keywords.
        if (effective_version() > 150)
            warn(peek(), "Should use keywords for bicubic parameters.");
        // No commas between them: POV-Ray reads four floats in a row.
        type = int(parse_float());
        data->flatness = type == 2 || type == 3 ? parse_float() : 0.1;
        data->u_steps = int(parse_float());
        data->v_steps = int(parse_float());
    } else {
        for (;;) {
            const Token t = peek();
            if (is_word(t, "type")) {
                next();
                type = int(parse_float());
            } else if (is_word(t, "flatness")) {
                next();
                data->flatness = parse_float();
            } else if (is_word(t, "u_steps")) {
                next();
                data->u_steps = int(parse_float());
            } else if (is_word(t, "v_steps")) {
                next();
                data->v_steps = int(parse_float());
            } else if (is_word(t, "accuracy")) {
                next();
                parse_float();  // read and never used, as in POV-Ray
            } else if (is_word(t, "uv_vectors")) {
                // The corners' texture coordinates (uv_mapping); they end the keywords,
                // as in POV-Ray.
                next();
                for (int i = 0; i < 4; ++i) {
                    if (i) accept_punct(',');
                    const ProfilePoint q = parse_uv_vector();
                    data->uv_vectors[size_t(i)] = {q.x, q.y};
                }
                break;
            } else {
                break;
            }
        }
    }
    if (type > 1) {
        warn(keyword, "Patch type no longer supported. Using type 1.");
        type = 1;
    }
    if (type < 0) error(keyword, "Undefined bicubic patch type.");
    data->type = type;
    // Deeper than this the pieces (4^steps) could not be held; POV-Ray has no limit and
    // runs out of memory.
    constexpr int kMaxSteps = 10;
    if (data->u_steps > kMaxSteps || data->v_steps > kMaxSteps)
        error(keyword, "bicubic_patch u_steps and v_steps above " +
                           std::to_string(kMaxSteps) + " are not supported");
    accept_punct(',');
    for (size_t i = 0; i < 16; ++i) {
        if (i) accept_punct(',');
        data->control[i] = parse_vector();
    }
    build_patch_pieces(*data);
    out.shape = BicubicPatch{std::move(data)};
}

}  // namespace povwall::parser
