// The radiosity blocks (POV-Ray 3.7): global_settings' settings with its parser's range
// checks, an object's `radiosity { importance }` and `no_radiosity` (and how a CSG's
// come down to its children). trace/radiosity/ renders them.
#include "parser/interpreter.h"

namespace povwall::parser {

// global_settings { radiosity { } }: the block turns radiosity on (from +Q9), then its
// items (POV-Ray's Parse_Global_Settings, RADIOSITY_TOKEN).
void Interpreter::parse_radiosity_settings(const Token& at) {
    expect_punct('{', "after 'radiosity'");
    RadiositySettings r = scene_.settings.radiosity.value_or(RadiositySettings{});
    r.loc = sources_.location(at);
    bool minimum_reuse_set = false, maximum_reuse_set = false;
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) break;
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        auto on_off = [&] { return int(parse_float()) != 0; };
        if (w == "load_file" || w == "save_file") {
            warn(t, "in POV-Ray 3.7 and later '" + std::string(w) +
                        "' has to be given as a command-line or INI option; the '" +
                        std::string(w) + "' setting here is ignored");
            parse_string();
        } else if (w == "always_sample") {
            r.always_sample = on_off();
        } else if (w == "pretrace_start") {
            r.pretrace_start = parse_float();
            if (r.pretrace_start <= 0 || r.pretrace_start > 1)
                error(t,
                      "radiosity pretrace start must be greater than 0 and no higher "
                      "than 1");
        } else if (w == "pretrace_end") {
            r.pretrace_end = parse_float();
            if (r.pretrace_end <= 0 || r.pretrace_end > 1)
                error(t,
                      "radiosity pretrace end must be greater than 0 and no higher "
                      "than 1");
        } else if (w == "brightness") {
            r.brightness = parse_float();
            if (r.brightness <= 0)
                error(t, "radiosity brightness must be a positive number");
        } else if (w == "count") {
            r.count = int(parse_float());
            if (r.count <= 0) error(t, "radiosity count must be a positive number");
            accept_punct(',');
            r.direction_pool =
                starts_float(peek()) ? int(parse_float()) : std::max(1600, r.count);
            if (r.direction_pool < r.count)
                error(t,
                      "radiosity count can not be more than direction pool size "
                      "(count 2nd value)");
        } else if (w == "error_bound") {
            r.error_bound = parse_float();
            if (r.error_bound <= 0)
                error(t, "radiosity error bound must be a positive number");
        } else if (w == "gray_threshold") {
            r.gray_threshold = parse_float();
            if (r.gray_threshold < 0 || r.gray_threshold > 1)
                error(t, "radiosity gray threshold must be from 0.0 to 1.0");
        } else if (w == "low_error_factor") {
            r.low_error_factor = parse_float();
            if (r.low_error_factor <= 0)
                error(t, "radiosity low error factor must be a positive number");
        } else if (w == "maximum_reuse") {
            maximum_reuse_set = true;
            r.maximum_reuse = parse_float();
            if (r.maximum_reuse <= 0)
                error(t, "radiosity maximum reuse must be a positive number");
        } else if (w == "minimum_reuse") {
            minimum_reuse_set = true;
            r.minimum_reuse = parse_float();
            if (r.minimum_reuse < 0)
                error(t, "radiosity minimum reuse can not be a negative number");
        } else if (w == "nearest_count") {
            r.nearest_count = int(parse_float());
            if (r.nearest_count < 1 || r.nearest_count > 20)
                error(t, "radiosity nearest count must be a value from 1 to 20");
            accept_punct(',');
            r.nearest_count_pretrace = starts_float(peek()) ? int(parse_float()) : 0;
            if (r.nearest_count_pretrace < 0 ||
                r.nearest_count_pretrace >= r.nearest_count)
                error(t,
                      "radiosity nearest count for adaptive pretrace must be "
                      "non-negative and smaller than general nearest count");
            if (r.nearest_count_pretrace > 0)
                unsupported(t,
                            "radiosity adaptive pretrace (nearest_count's second value)");
        } else if (w == "recursion_limit") {
            r.recursion_limit = int(parse_float());
            if (r.recursion_limit < 1 || r.recursion_limit > 20)
                error(t, "radiosity recursion limit must be in the range 1 to 20");
        } else if (w == "max_sample") {
            r.max_sample = parse_float();
        } else if (w == "adc_bailout") {
            r.adc_bailout = parse_float();
            if (r.adc_bailout <= 0) error(t, "ADC bailout must be a positive number");
        } else if (w == "normal") {
            r.normal = on_off();
        } else if (w == "media") {
            r.media = on_off();
        } else if (w == "subsurface") {
            r.subsurface = on_off();
        } else {
            expected("a radiosity item or '}'", t);
        }
    }
    // POV-Ray's checks once the scene is parsed (Parse_Frame's end), made here: the
    // block is the only place these settings come from.
    if (r.minimum_reuse > r.maximum_reuse * 0.5) {
        if (!minimum_reuse_set) {
            r.minimum_reuse = r.maximum_reuse * 0.5;
            warn(at,
                 "radiosity maximum_reuse should be significantly larger than "
                 "minimum_reuse; decreasing minimum_reuse");
        } else if (!maximum_reuse_set) {
            r.maximum_reuse = r.minimum_reuse * 2;
            warn(at,
                 "radiosity maximum_reuse should be significantly larger than "
                 "minimum_reuse; increasing maximum_reuse");
        } else if (r.minimum_reuse >= r.maximum_reuse) {
            error(at, "radiosity maximum_reuse must be larger than minimum_reuse");
        }
    }
    scene_.settings.radiosity = r;
    radiosity_at_ = at;
}

// An object's radiosity { importance }.
void Interpreter::parse_object_radiosity(Object& obj) {
    expect_punct('{', "after 'radiosity'");
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) return;
        if (is_word(t, "importance")) {
            obj.radiosity_importance = float(parse_float());
            if (obj.radiosity_importance <= 0 || obj.radiosity_importance > 1)
                error(t, "radiosity importance must be greater than 0.0 and at most 1.0");
        } else {
            expected("importance or '}'", t);
        }
    }
}

// The radiosity block's checks that need the whole scene.
void Interpreter::check_radiosity() {
    if (!scene_.settings.radiosity) return;
    if (scene_.settings.radiosity->pretrace_end >
        scene_.settings.radiosity->pretrace_start)
        error(*radiosity_at_,
              "radiosity pretrace end must be smaller than or equal to pretrace start");
}

}  // namespace povwall::parser
