// rainbow { } (POV-Ray 3.7's Parse_Rainbow): the band's angles in radians, `up` made
// perpendicular to the direction, the colour map as a gradient x pigment
// (trace/rainbow.h).
#include <cmath>

#include "parser/interpreter.h"

namespace povwall::parser {

Rainbow Interpreter::parse_rainbow(const Token& at) {
    constexpr double kEpsilon = 1e-10;
    expect_punct('{', "after 'rainbow'");
    Rainbow r;
    // POV-Ray's defaults: no distance limit, and an arc and falloff angle of 180 (not
    // converted to radians: no limit around `up`).
    r.distance = 1e7;
    r.arc_angle = 180;
    r.falloff_angle = 180;
    Vector3 direction{0, 0, 0}, up{0, 1, 0};
    Real angle = 0, width = 0;
    bool falloff_given = false, arc_given = false;
    for (;;) {
        const Token t = next();
        if (is_punct(t, '}')) break;
        if (is_word(t, "angle")) {
            angle = parse_float();
        } else if (is_word(t, "direction")) {
            direction = parse_vector();
        } else if (is_word(t, "colour_map") || is_word(t, "color_map")) {
            Pigment p;
            p.pattern.edit().kind = PatternKind::Gradient;
            p.pattern.edit().vector = Vector3{1, 0, 0};
            p.maps.edit().colour_map = parse_colour_map_block();
            r.pigment = std::move(p);
        } else if (is_word(t, "distance")) {
            r.distance = parse_float();
        } else if (is_word(t, "jitter")) {
            r.jitter = parse_float();
        } else if (is_word(t, "width")) {
            width = parse_float();
        } else if (is_word(t, "up")) {
            up = parse_vector();
        } else if (is_word(t, "falloff_angle") || is_word(t, "arc_angle")) {
            const Real a = parse_float();
            if (a < 0 || a > 360)
                error(t, std::string("illegal ") +
                             (is_word(t, "arc_angle") ? "arc" : "falloff") +
                             " angle in rainbow (use a value from 0 to 360 degrees)");
            if (is_word(t, "arc_angle")) {
                r.arc_angle = a * kPi / 360;
                arc_given = true;
            } else {
                r.falloff_angle = a * kPi / 360;
                falloff_given = true;
            }
        } else {
            expected("a rainbow item or '}'", t);
        }
    }
    if (arc_given && !falloff_given) r.falloff_angle = r.arc_angle;
    if (r.arc_angle < r.falloff_angle)
        error(at, "arc angle is smaller than falloff angle in rainbow");
    r.falloff_width = r.arc_angle - r.falloff_angle;
    if (std::fabs(dot(direction, direction)) < kEpsilon)
        error(at, "rainbow's direction vector is zero");
    if (std::fabs(dot(up, up)) < kEpsilon) error(at, "rainbow's up vector is zero");
    r.antisolar = normalize(direction);
    up = normalize(up);
    if (std::fabs(1 - std::fabs(dot(up, r.antisolar))) < kEpsilon)
        error(at, "rainbow's up and direction vector are co-linear");
    r.right = normalize(cross(up, r.antisolar));
    r.up = normalize(cross(r.antisolar, cross(up, r.antisolar)));
    r.angle = (angle - 0.5 * width) * kPi / 180;
    r.width = width * kPi / 180;
    return r;
}

}  // namespace povwall::parser
