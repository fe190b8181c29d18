// The photons blocks (POV-Ray 3.7): global_settings' settings, an object's flags (and
// how a CSG's flags come down to its children), a light's switches. trace/photon_map.h
// uses them.
#include "parser/interpreter.h"

namespace povwall::parser {

// global_settings { photons { } }: POV-Ray 3.7's values when the block is given, then
// its items (Parse_Global_Settings, PHOTONS_TOKEN).
void Interpreter::parse_photon_settings(const Token& at) {
    expect_punct('{', "after 'photons'");
    PhotonSettings p;
    p.loc = sources_.location(at);
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) break;
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        // POV-Ray's Allow_Float: a float follows, or the item's default stays.
        auto optional_float = [&](float fallback) {
            accept_punct(',');
            return starts_float(peek()) ? float(parse_float()) : fallback;
        };
        if (w == "spacing") {
            p.spacing = float(parse_float());
        } else if (w == "count") {
            p.count = parse_int();
        } else if (w == "gather") {
            p.gather_min = parse_int();
            accept_punct(',');
            p.gather_max = parse_int();
        } else if (w == "jitter") {
            p.jitter = float(parse_float());
        } else if (w == "autostop") {
            p.autostop = float(parse_float());
        } else if (w == "expand_thresholds") {
            p.expand_tolerance = float(parse_float());
            accept_punct(',');
            p.expand_min = parse_int();
            if (p.expand_tolerance < 0) {
                warn(t,
                     "the first parameter of expand_thresholds must be greater than "
                     "or equal to 0; setting it to 0 now");
                p.expand_tolerance = 0;
            }
            if (p.expand_min < 0) {
                warn(t,
                     "the second parameter of expand_thresholds must be greater than "
                     "or equal to 0; setting it to 0 now");
                p.expand_min = 0;
            }
        } else if (w == "max_trace_level") {
            p.max_trace_level = parse_int();
        } else if (w == "adc_bailout") {
            p.adc_bailout = float(parse_float());
        } else if (w == "radius") {
            p.radius = starts_float(peek()) ? float(parse_float()) : -1.0f;
            p.radius_multiplier = optional_float(1);
            p.media_radius = optional_float(-1);
            p.media_radius_multiplier = optional_float(1);
        } else if (w == "media") {
            p.media_steps = parse_int();
            if (p.media_steps < 0) error(t, "max media steps must be non-negative");
            p.media_spacing_factor = optional_float(1);
            if (p.media_spacing_factor <= 0)
                error(t, "media spacing factor must be greater than zero");
        } else if (w == "save_file" || w == "load_file") {
            unsupported(t, std::string("photons ") + std::string(w));
        } else {
            unget(t);
            expected("a photons item or '}'", t);
        }
    }
    // gather_max 0 means no photon maps (POV-Ray).
    if (p.gather_max <= 0) {
        scene_.settings.photons.reset();
        return;
    }
    if (p.gather_min < 0) error(at, "min_gather_count cannot be negative");
    if (p.gather_min > p.gather_max)
        error(at, "min_gather_count must be less than max_gather_count");
    scene_.settings.photons = p;
    photons_at_ = at;
}

// A light's photons { refraction on|off reflection on|off area_light }.
void Interpreter::parse_light_photons(Light& l) {
    expect_punct('{', "after 'photons'");
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) return;
        if (is_word(t, "refraction")) {
            l.photon_refraction = parse_int() ? PhotonSwitch::On : PhotonSwitch::Off;
        } else if (is_word(t, "reflection")) {
            l.photon_reflection = parse_int() ? PhotonSwitch::On : PhotonSwitch::Off;
        } else if (is_word(t, "area_light")) {
            l.photon_area_light = true;
        } else {
            expected("refraction, reflection, area_light or '}'", t);
        }
    }
}

// POV-Ray's CheckPassThru: pass_through, target and refraction do not go together; the
// one given last gives way (with POV-Ray's warning).
void Interpreter::check_photon_pass_through(ObjectPhotons& ph, const Token& at,
                                            PhotonPassThroughCause cause) {
    if (!(ph.pass_through && ph.target && ph.refraction != PhotonSwitch::Off)) return;
    const bool drop_pass_through =
        cause == PhotonPassThroughCause::Refraction ||
        (cause == PhotonPassThroughCause::Target && ph.refraction == PhotonSwitch::On);
    if (drop_pass_through) {
        warn(at,
             "cannot use pass_through with refraction & target; turning off "
             "pass_through");
        ph.pass_through = false;
    } else {
        warn(at,
             "cannot use pass_through with refraction & target; turning off "
             "refraction");
        ph.refraction = PhotonSwitch::Off;
    }
}

// An object's photons { target [spacing_multiplier] refraction reflection collect
// pass_through } (Parse_Object_Mods, PHOTONS_TOKEN).
void Interpreter::parse_object_photons(Object& obj) {
    expect_punct('{', "after 'photons'");
    ObjectPhotons& ph = obj.photons;
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) return;
        if (is_word(t, "target")) {
            const float density = starts_float(peek()) ? float(parse_float()) : 1.0f;
            ph.spacing_multiplier = density;
            ph.target = density > 0;
            if (ph.target)
                check_photon_pass_through(ph, t, PhotonPassThroughCause::Target);
        } else if (is_word(t, "refraction")) {
            ph.refraction = parse_int() ? PhotonSwitch::On : PhotonSwitch::Off;
            if (ph.refraction == PhotonSwitch::On)
                check_photon_pass_through(ph, t, PhotonPassThroughCause::Refraction);
        } else if (is_word(t, "reflection")) {
            ph.reflection = parse_int() ? PhotonSwitch::On : PhotonSwitch::Off;
        } else if (is_word(t, "pass_through")) {
            ph.pass_through = starts_float(peek()) ? parse_int() != 0 : true;
            if (ph.pass_through)
                check_photon_pass_through(ph, t, PhotonPassThroughCause::PassThrough);
        } else if (is_word(t, "collect")) {
            ph.collect = starts_float(peek()) ? parse_float() > 0 : true;
        } else {
            expected("a photons item or '}'", t);
        }
    }
}

// A CSG child placed in its parent (POV-Ray's Post_Process): the parent's target (with
// its spacing multiplier), pass_through, given switches and collect off win.
void Interpreter::inherit_photons(ObjectPhotons& child, const ObjectPhotons& parent) {
    if (parent.target) {
        child.target = true;
        child.spacing_multiplier = parent.spacing_multiplier;
    }
    if (parent.pass_through) child.pass_through = true;
    if (parent.reflection != PhotonSwitch::Unset) child.reflection = parent.reflection;
    if (parent.refraction != PhotonSwitch::Unset) child.refraction = parent.refraction;
    if (!parent.collect) child.collect = false;
    // POV-Ray's CheckPassThru after promoting target, pass_through or refraction on
    // (without a second warning: the parent's was given).
    if (child.pass_through && child.target && child.refraction != PhotonSwitch::Off) {
        if (child.refraction == PhotonSwitch::On)
            child.pass_through = false;
        else
            child.refraction = PhotonSwitch::Off;
    }
}

}  // namespace povwall::parser
