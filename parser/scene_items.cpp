// Camera, lights, global settings, sky and fog, meshes, and declared non-numeric values.
#include <algorithm>
#include <cmath>
#include <optional>

#include "core/mesh_camera.h"
#include "core/pov_angles.h"
#include "parser/interpreter.h"

namespace povwall::parser {

namespace {

// The length of a perspective camera's direction for a field of view of `angle` degrees
// across `right_length`, rounded as POV-Ray's camera set-up rounds it
// (core/pov_angles.h).
double perspective_direction_length(double right_length, double angle) {
    return right_length / std::tan(angle * kPovRadiansPerHalfDegree) / 2;
}

}  // namespace

CameraSpec Interpreter::parse_camera_block() {
    Token open = next();
    if (!is_punct(open, '{')) expected("'{' after 'camera'", open);
    CameraSpec c;
    c.loc = sources_.location(open);
    c.offset = open.offset;
    const Token& first = peek();
    if (first.kind == TokenKind::Word) {
        const Value* v = lookup(first);
        if (v && std::holds_alternative<std::shared_ptr<CameraSpec>>(*v)) {
            next();
            c = *std::get<std::shared_ptr<CameraSpec>>(*v);
        }
    }
    // POV-Ray tests the language version as set (its languageVersion), not the
    // effective one: a scene without #version reads a 3.5+ camera.
    if (version_ < 350) return parse_legacy_camera(c);
    if (c.legacy) {
        // A camera declared in an older part of the scene: its final vectors.
        const Camera cam = finish_camera(c);
        c.kind = cam.kind, c.location = cam.location, c.direction = cam.direction;
        c.right = cam.right, c.up = cam.up, c.angle = cam.angle;
        c.focal_distance = cam.focal_distance;
        c.has_look_at = c.has_angle = c.has_focal_point = false;
        c.has_up = c.has_right = true;
        c.legacy = false;
    }
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) {
            // POV-Ray's focal blur takes no account of a mesh camera's rays.
            if (c.kind == Camera::Kind::Mesh && c.aperture != 0 && c.blur_samples > 0)
                unsupported(t, "focal blur with a mesh_camera");
            c.parsed = true;
            return c;
        }
        Transform tr;
        if (try_transform(t, tr)) {
            c.transform = c.transform.then(tr);
            continue;
        }
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        if (w == "perspective")
            c.kind = Camera::Kind::Perspective;
        else if (w == "orthographic")
            c.kind = Camera::Kind::Orthographic;
        else if (w == "fisheye")
            c.kind = Camera::Kind::Fisheye;
        else if (w == "ultra_wide_angle")
            c.kind = Camera::Kind::UltraWideAngle;
        else if (w == "panoramic")
            c.kind = Camera::Kind::Panoramic;
        else if (w == "omnimax")
            c.kind = Camera::Kind::Omnimax;
        else if (w == "spherical")
            c.kind = Camera::Kind::Spherical;
        else if (w == "cylinder") {
            const Token at = peek();
            const double n = parse_float();
            if (n < 1 || n > 4 || n != std::floor(n))
                error(at, "cylinder camera type must be 1, 2, 3 or 4");
            static constexpr Camera::Kind kCylinders[] = {
                Camera::Kind::Cylinder1, Camera::Kind::Cylinder2, Camera::Kind::Cylinder3,
                Camera::Kind::Cylinder4};
            c.kind = kCylinders[int(n) - 1];
        } else if (w == "location")
            c.location = parse_vector();
        else if (w == "direction")
            c.direction = parse_vector();
        else if (w == "right") {
            c.right = parse_vector();
            c.has_right = true;
        } else if (w == "up") {
            c.up = parse_vector();
            c.has_up = true;
        } else if (w == "sky")
            c.sky = parse_vector();
        else if (w == "look_at") {
            c.look_at = parse_vector();
            c.has_look_at = true;
        } else if (w == "angle" && c.kind == Camera::Kind::Spherical) {
            // `angle h[,] [v]`: the fields of view across and up (v: h / 2 if absent).
            const Token at = peek();
            c.h_angle = parse_float();
            if (c.h_angle < 0) error(at, "negative horizontal angle");
            accept_punct(',');
            const Token vat = peek();
            c.v_angle = starts_expression(vat) ? parse_float() : c.h_angle * 0.5;
            if (c.v_angle < 0) error(vat, "negative vertical angle");
        } else if (w == "angle") {
            // One float: POV-Ray 3.7 reads `angle h[,] v` only for the spherical camera.
            const Token at = peek();
            c.angle = parse_float();
            c.has_angle = true;
            if (c.angle < 0) error(at, "negative viewing angle");
        } else if (w == "normal") {
            parse_normal_into(c.normal);
        } else if (parse_focal_blur_item(t, c)) {
        } else if (w == "bokeh") {
            expect_punct('{', "after 'bokeh'");
            while (is_word(peek(), "pigment")) {
                next();
                c.bokeh = parse_pigment_block();
            }
            expect_punct('}', "to end 'bokeh'");
        } else if (w == "blur_samples") {
            // `blur_samples [min,] max`: one number is the maximum (no minimum).
            const Token at = peek();
            const int given = int(parse_float());
            if (given <= 0) error(at, "illegal number of focal blur samples");
            accept_punct(',');
            const int most = starts_expression(peek()) ? int(parse_float()) : 0;
            if (most == 0) {
                c.blur_samples = given, c.blur_samples_min = 0;
            } else {
                if (given > most)
                    error(at,
                          "focal blur samples minimum must not be larger than maximum");
                c.blur_samples = most, c.blur_samples_min = given;
            }
        } else if (w == "focal_point") {
            c.focal_point = parse_vector();
            c.has_focal_point = true;
        } else if (w == "mesh_camera") {
            c.kind = Camera::Kind::Mesh;
            c.mesh = parse_mesh_camera(t);
        } else if (w == "user_defined") {
            unsupported(t, "camera " + std::string(w));
        } else {
            expected("a camera item or '}'", t);
        }
    }
}

// Before 3.5 POV-Ray applied each camera item where it stood (Parse_Camera's old-style
// branch): look_at turns the vectors it finds, angle scales the direction it finds,
// transforms move the location and turn direction, up and right (not sky) at once.
CameraSpec Interpreter::parse_legacy_camera(CameraSpec c) {
    constexpr double kEpsilon = 1e-10;
    if (!c.legacy) {  // a camera declared in a 3.5+ part of the scene
        const Camera cam = finish_camera(c);
        c.kind = cam.kind, c.location = cam.location, c.direction = cam.direction;
        c.right = cam.right, c.up = cam.up, c.angle = cam.angle;
        // A camera parsed before has its focal distance; a fresh one gets it here.
        c.focal_distance = c.parsed ? cam.focal_distance : -1;
        c.has_focal_point = false;
        c.transform = Transform{};
        c.legacy = true;
    }
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) {
            c.parsed = true;
            return c;
        }
        Transform tr;
        if (try_transform(t, tr)) {
            c.location = tr.point(c.location);
            c.direction = tr.vector(c.direction);
            c.up = tr.vector(c.up);
            c.right = tr.vector(c.right);
            continue;
        }
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        if (w == "perspective") {
            c.kind = Camera::Kind::Perspective;
        } else if (w == "orthographic") {
            c.kind = Camera::Kind::Orthographic;
            // The same image area as the perspective camera, from where it stands now.
            const double k1 = length(c.look_at - c.location), k2 = length(c.direction);
            if (k1 > kEpsilon && k2 > kEpsilon) {
                c.right = c.right * (k1 / k2);
                c.up = c.up * (k1 / k2);
            }
        } else if (w == "fisheye") {
            c.kind = Camera::Kind::Fisheye;
        } else if (w == "ultra_wide_angle") {
            c.kind = Camera::Kind::UltraWideAngle;
        } else if (w == "panoramic") {
            c.kind = Camera::Kind::Panoramic;
        } else if (w == "omnimax") {
            c.kind = Camera::Kind::Omnimax;
        } else if (w == "mesh_camera") {
            error(t, "this camera type is not supported for language version < 3.5");
        } else if (w == "cylinder") {
            const double n = parse_float();  // POV-Ray ignores other values here
            static constexpr Camera::Kind kCylinders[] = {
                Camera::Kind::Cylinder1, Camera::Kind::Cylinder2, Camera::Kind::Cylinder3,
                Camera::Kind::Cylinder4};
            if (int(n) >= 1 && int(n) <= 4) c.kind = kCylinders[int(n) - 1];
        } else if (w == "angle") {
            const Token at = peek();
            c.angle = parse_float();
            c.has_angle = true;
            if (c.angle < 0) error(at, "negative viewing angle");
            if (c.kind == Camera::Kind::Perspective) {
                if (c.angle >= 180) error(at, "camera angle must be below 180 degrees");
                const double len = perspective_direction_length(length(c.right), c.angle);
                c.direction = normalize(c.direction) * len;
                c.legacy_direction_length = len;
            }
        } else if (w == "normal") {
            parse_normal_into(c.normal);
        } else if (w == "location") {
            c.location = parse_vector();
        } else if (w == "direction") {
            c.direction = parse_vector();
        } else if (w == "up") {
            c.up = parse_vector();
        } else if (w == "right") {
            c.right = parse_vector();
        } else if (w == "sky") {
            c.sky = parse_vector();
        } else if (w == "look_at") {
            const double dl = length(c.direction), ul = length(c.up),
                         rl = length(c.right);
            const double handed = dot(cross(c.up, c.direction), c.right);
            const Token at = peek();
            c.look_at = parse_vector();
            c.has_look_at = true;
            Vector3 d = c.look_at - c.location;
            if (dot(d, d) < kEpsilon)
                error(at, "camera location and look_at point must be different");
            d = normalize(d);
            Vector3 r = cross(c.sky, d);
            if (std::fabs(r.x) < kEpsilon && std::fabs(r.y) < kEpsilon &&
                std::fabs(r.z) < kEpsilon)
                r = c.right;
            r = normalize(r);
            c.up = cross(d, r) * ul;
            c.direction = d * dl;
            c.right = r * (handed > 0 ? rl : -rl);
            c.legacy_direction_length = dl;
        } else if (parse_focal_blur_item(t, c)) {
        } else if (w == "blur_samples") {
            const Token at = peek();
            c.blur_samples = int(parse_float());
            if (c.blur_samples <= 0) error(at, "illegal number of focal blur samples");
        } else if (w == "focal_point") {
            // The distance from the location as it stands now.
            c.focal_point = parse_vector();
            c.focal_distance = length(c.focal_point - c.location);
        } else {
            expected("a camera item or '}'", t);
        }
    }
}

// The focal-blur items both camera syntaxes read alike: aperture, confidence, variance
// (out-of-range values warn and keep the default, as POV-Ray). False if `t` is none.
bool Interpreter::parse_focal_blur_item(const Token& t, CameraSpec& c) {
    if (is_word(t, "aperture")) {
        c.aperture = parse_float();
    } else if (is_word(t, "confidence")) {
        const Token at = peek();
        const double k = parse_float();
        if (k > 0 && k < 1)
            c.confidence = k;
        else
            warn(at, "illegal confidence value; the default is used");
    } else if (is_word(t, "variance")) {
        const Token at = peek();
        const double k = parse_float();
        if (k >= 0 && k <= 1)
            c.variance = k;
        else
            warn(at, "illegal variance value; the default is used");
    } else {
        return false;
    }
    return true;
}

// POV-Ray 3.5+ applies the camera items in a fixed order whatever the order in the file:
// right, direction, angle, up, sky, location, look_at, then transforms (Parse_Camera).
Camera Interpreter::finish_camera(const CameraSpec& s) {
    constexpr double kEpsilon = 1e-10;
    Camera cam;
    cam.kind = s.kind;
    cam.loc = s.loc;
    cam.h_angle = s.h_angle;
    cam.v_angle = s.v_angle;
    cam.normal = s.normal;
    cam.aperture = s.aperture;
    cam.blur_samples = s.blur_samples;
    cam.blur_samples_min = s.blur_samples_min;
    cam.confidence = s.confidence;
    cam.variance = s.variance;
    cam.bokeh = s.bokeh;
    cam.mesh = s.mesh;
    // No focal point: POV-Ray's Direction_Length (1, or the direction's length as angle
    // and look_at set it); 0 means 1.
    auto focal = [](double given, double direction_length) {
        const double d = given < 0 ? direction_length : given;
        return d == 0 ? 1.0 : d;
    };
    if (s.legacy) {
        cam.location = s.location;
        cam.direction = s.direction;
        cam.right = s.right;
        cam.up = s.up;
        cam.angle = s.angle;
        cam.focal_distance = focal(s.focal_distance, s.legacy_direction_length);
        return cam;
    }
    double direction_length = 1;
    Vector3 right = s.right, direction = s.direction, up = s.up;
    bool projective =
        s.kind == Camera::Kind::Perspective || s.kind == Camera::Kind::Orthographic;
    if (s.has_angle && projective) {
        if (s.angle >= 180) {
            std::string msg = "camera angle must be below 180 degrees";
            throw ParseError(
                ParseError::Kind::Syntax,
                format_diagnostic_at(sources_, s.loc.file, s.offset, 1, "error", msg),
                msg, s.loc);
        }
        if (s.angle > 0) {
            double len = perspective_direction_length(length(right), s.angle);
            direction = normalize(direction) * len;
            direction_length = len;
        }
    }
    Point3 location = s.location;
    if (s.has_look_at) {
        double dl = length(direction), rl = length(right), ul = length(up);
        direction_length = dl;
        // The handedness of the frame before look_at decides the sign of `right`; `up` is
        // always direction x right (not flipped), as in POV-Ray.
        double handed = dot(cross(up, direction), right);
        Vector3 d = s.look_at - location;
        if (dot(d, d) < kEpsilon) {
            std::string msg = "camera location and look_at point must be different";
            throw ParseError(
                ParseError::Kind::Syntax,
                format_diagnostic_at(sources_, s.loc.file, s.offset, 1, "error", msg),
                msg, s.loc);
        }
        d = normalize(d);
        Vector3 r = cross(s.sky, d);
        // Sky parallel to the view: POV-Ray keeps the given right vector.
        if (std::fabs(r.x) < kEpsilon && std::fabs(r.y) < kEpsilon &&
            std::fabs(r.z) < kEpsilon) {
            r = right;
        }
        r = normalize(r);
        up = cross(d, r) * ul;
        direction = d * dl;
        right = r * (handed > 0 ? rl : -rl);
    }
    if (s.kind == Camera::Kind::Orthographic &&
        (s.has_angle || (!s.has_up && !s.has_right))) {
        Point3 target = s.has_look_at ? s.look_at : Point3(0, 0, 1);
        double k1 = length(target - location), k2 = length(direction);
        if (k1 > kEpsilon && k2 > kEpsilon) {
            right = right * (k1 / k2);
            up = up * (k1 / k2);
        }
    }
    double focal_distance = s.focal_distance;
    if (s.has_focal_point) focal_distance = length(s.focal_point - location);
    cam.focal_distance = focal(focal_distance, direction_length);
    cam.location = s.transform.point(location);
    cam.direction = s.transform.vector(direction);
    cam.right = s.transform.vector(right);
    cam.up = s.transform.vector(up);
    cam.angle = s.angle;
    return cam;
}

Light Interpreter::parse_light_block() {
    Token open = next();
    if (!is_punct(open, '{')) expected("'{' after 'light_source'", open);
    Light l;
    l.loc = sources_.location(open);
    const Token& first = peek();
    bool copied = false;
    if (first.kind == TokenKind::Word) {
        const Value* v = lookup(first);
        if (v && std::holds_alternative<std::shared_ptr<Light>>(*v)) {
            next();
            l = *std::get<std::shared_ptr<Light>>(*v);
            copied = true;
        }
    }
    if (!copied) {
        l.location = parse_vector();
        accept_punct(',');
        Colour c = parse_colour_value();
        l.colour = c.rgb;
    }
    // POV-Ray's parallel flag, apart from the light's one type (a copied light keeps it).
    bool parallel = l.kind == Light::Kind::Parallel || l.parallel;
    if (l.kind == Light::Kind::Parallel) l.kind = Light::Kind::Point;
    bool jitter = false, circular = false, orient = false;
    std::optional<int> adaptive;
    std::optional<bool> illumination;      // area_illumination, when named
    std::optional<Token> illumination_at;  // where it was last turned on
    std::optional<Token> attenuation_at;   // where media_attenuation was turned on
    std::optional<Token> projected_through_at;
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) break;
        Transform tr;
        TransformStep step;
        if (try_transform(t, tr, &step)) {
            transform_light(l, tr, step);
            continue;
        }
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        // As POV-Ray: the light type keyword resets its cone; `parallel` is a flag of its
        // own (cylinder lights have it); the cone items need a spot or cylinder light.
        const bool coned = l.kind == Light::Kind::Spot || l.kind == Light::Kind::Cylinder;
        // A light has one type (POV-Ray's Light_Type): point, shadowless (a fill light),
        // spotlight or cylinder, the last one written; shadowless after a spotlight
        // turns it into a shadowless point light, a spotlight after shadowless casts
        // shadows.
        if (w == "spotlight") {
            l.kind = Light::Kind::Spot;
            l.shadowless = false;
            l.radius = 30, l.falloff = 45, l.tightness = 0;
        } else if (w == "cylinder") {
            l.kind = Light::Kind::Cylinder;
            l.shadowless = false;
            l.radius = 0.75, l.falloff = 1, l.tightness = 0;
            parallel = true;
        } else if (w == "parallel") {
            parallel = true;
        } else if (w == "point_at" && !coned && !parallel) {
            error(t, "'point_at' cannot be used with a standard light source");
        } else if ((w == "radius" || w == "falloff" || w == "tightness") && !coned) {
            error(t,
                  "'" + std::string(w) + "' cannot be used with a standard light source");
        } else if (w == "point_at")
            l.point_at = parse_vector();
        else if (w == "radius")
            l.radius = parse_float();
        else if (w == "falloff")
            l.falloff = parse_float();
        else if (w == "tightness")
            l.tightness = parse_float();
        else if (w == "fade_distance")
            l.fade_distance = parse_float();
        else if (w == "fade_power")
            l.fade_power = parse_float();
        else if (w == "shadowless") {
            l.kind = Light::Kind::Point;
            l.shadowless = true;
        } else if (w == "media_interaction")
            l.media_interaction = parse_bool_opt();
        else if (w == "media_attenuation") {
            l.media_attenuation = parse_bool_opt();
            if (l.media_attenuation) attenuation_at = t;
        } else if (w == "color" || w == "colour" || w == "rgb") {
            unget(t);
            l.colour = parse_colour_value().rgb;
        } else if (w == "area_light") {
            // A copied light's area items stay; only the grid is set (POV-Ray).
            AreaLight a = l.area.value_or(AreaLight{});
            a.axis1 = parse_vector();
            accept_punct(',');
            a.axis2 = parse_vector();
            accept_punct(',');
            a.size1 = parse_int();
            accept_punct(',');
            a.size2 = parse_int();
            l.area = a;
        }
        // These may come before area_light, or on a light that has none (POV-Ray keeps
        // them unused; exporters write them there); applied at the end.
        else if (w == "adaptive")
            adaptive = int(parse_float());
        else if (w == "jitter")
            jitter = true;
        else if (w == "circular")
            circular = true;
        else if (w == "orient")
            orient = true;
        else if (w == "area_illumination") {
            illumination = parse_bool_opt();
            if (*illumination) illumination_at = t;
        } else if (w == "looks_like" || w == "projected_through") {
            expect_punct('{');
            Token o = next();
            Object obj;
            // `looks_like { Shape }`: an object identifier stands for its object.
            if (!try_parse_object_or_identifier(o, obj)) expected("an object", o);
            expect_punct('}');
            finish_object(obj);
            if (w == "projected_through") {
                // POV-Ray 3.7's Parse_Light_Source and Post_Process: one object, left
                // where it is written, only ever intersected (no texture, no interior).
                if (l.projected_through)
                    error(t, "Only one projected through allowed per light_source.");
                if (!obj.texture.empty() || obj.interior) {
                    warn(t, "Projected through objects can not have texture/interior");
                    obj.texture = {};
                    obj.interior = HeapOptional<Interior>();
                }
                l.projected_through = std::make_shared<const Object>(std::move(obj));
                projected_through_at = t;
                continue;
            }
            obj.no_shadow = true;
            obj.photons.pass_through =
                true;  // POV-Ray: photons leave the light through it
            obj.transform = obj.transform;
            apply_transform(obj, Transform::translate(l.location),
                            {TransformStep::Kind::Translate, l.location});
            l.looks_like.push_back(std::move(obj));
        } else if (w == "photons") {
            parse_light_photons(l);
        } else {
            expected("a light_source item or '}'", t);
        }
    }
    // A parallel point or spot light: every point gets the light from point_at's
    // direction at full strength (POV-Ray's spot cone then sees the axis itself).
    if (parallel && l.kind == Light::Kind::Point) l.kind = Light::Kind::Parallel;
    l.parallel = parallel && l.kind == Light::Kind::Spot;
    // The atmosphere's media on an area light's shadow rays: POV-Ray applies them per
    // sample and once more over a leftover stretch of its last sample; not yet.
    if (l.media_attenuation && l.area && attenuation_at) {
        if (!scene_.atmosphere_media.empty())
            unsupported(*attenuation_at,
                        "media_attenuation of an area light with "
                        "atmospheric media");
        area_light_attenuated_by_media_ = true;
    }
    // projected_through is tested once per light ray; POV-Ray also tests it per
    // area-light sample, runs the atmosphere's media past it to the light and shoots
    // photons only through it: not yet.
    if (l.projected_through) {
        const Token& at = projected_through_at ? *projected_through_at : open;
        if (l.area) unsupported(at, "projected_through on an area_light");
        if (l.media_attenuation)
            unsupported(at, "projected_through with media_attenuation");
        if (!projected_through_at_) projected_through_at_ = at;
    }
    // POV-Ray 3.7 turns area_illumination on for any light, but only an area light uses
    // it as such; on another light it drops the test that leaves a surface facing away
    // from the light unlit. Not that.
    if (illumination && *illumination && !l.area)
        unsupported(*illumination_at, "area_illumination without area_light");
    if (l.area) {
        if (illumination) l.area->illumination = *illumination;
        if (adaptive) l.area->adaptive = *adaptive;
        l.area->jitter = l.area->jitter || jitter;
        l.area->circular = l.area->circular || circular;
        l.area->orient = l.area->orient || orient;
    }
    return l;
}

void Interpreter::parse_global_settings() {
    expect_punct('{', "after 'global_settings'");
    GlobalSettings& g = scene_.settings;
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) return;
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        if (w == "assumed_gamma") {
            if (gamma_mode_ == GammaMode::Assumed36 ||
                gamma_mode_ == GammaMode::Assumed37) {
                warn(t, "new instance of assumed_gamma ignored");  // as POV-Ray
                parse_gamma();
            } else {
                // The mode first: the gamma's own checks see a scene with gamma handling.
                gamma_mode_ = effective_version() < 370 ? GammaMode::Assumed36
                                                        : GammaMode::Assumed37;
                g.assumed_gamma = parse_gamma();
            }
        } else if (w == "max_trace_level") {
            int n = parse_int();
            g.max_trace_level = std::min(256, std::max(1, n));
        } else if (w == "adc_bailout") {
            g.adc_bailout = float(parse_float());
        } else if (w == "ambient_light") {
            g.ambient_light = parse_colour_value().rgb;
        } else if (w == "noise_generator") {
            g.noise_generator = parse_int();
            noise_generator_given_ = true;
        } else if (w == "max_intersections") {
            g.max_intersections = parse_int();
        } else if (w == "number_of_waves") {
            g.number_of_waves = parse_int();
        } else if (w == "irid_wavelength") {
            g.irid_wavelength = parse_colour_value().rgb;
        } else if (w == "charset") {
            Token c = next();
            if (is_word(c, "ascii"))
                charset_ = Charset::Ascii;
            else if (is_word(c, "utf8"))
                charset_ = Charset::Utf8;
            else if (is_word(c, "sys"))
                charset_ = Charset::Sys;
            else
                expected("ascii, utf8 or sys", c);
        } else if (w == "hf_gray_16") {
            parse_bool_opt();
        } else if (w == "photons") {
            parse_photon_settings(t);
        } else if (w == "radiosity") {
            parse_radiosity_settings(t);
        } else if (w == "mm_per_unit") {
            const Token at = peek();
            g.mm_per_unit = parse_float();
            // (POV-Ray takes any number: 0 or less divides by zero when it renders.)
            if (!(g.mm_per_unit > 0)) error(at, "mm_per_unit must be positive");
        } else if (w == "subsurface") {
            parse_subsurface_settings(t);
        } else {
            expected("a global setting or '}'", t);
        }
    }
}

// POV-Ray 3.7's global subsurface block: samples (diffuse, single; the comma optional)
// and radiosity, in any order, each repeatable.
void Interpreter::parse_subsurface_settings(const Token& keyword) {
    SubsurfaceSettings& s = scene_.settings.subsurface
                                ? *scene_.settings.subsurface
                                : scene_.settings.subsurface.emplace();
    s.loc = sources_.location(keyword);
    expect_punct('{', "after 'subsurface'");
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) return;
        if (is_word(t, "samples")) {
            const Token first = peek();
            const int diffuse = int(parse_float());
            if (is_punct(peek(), ',')) next();
            const Token second = peek();
            const int single = int(parse_float());
            if (diffuse < 0) error(first, "subsurface samples must not be negative");
            if (single < 0) error(second, "subsurface samples must not be negative");
            s.samples_diffuse = diffuse;
            s.samples_single = single;
        } else if (is_word(t, "radiosity")) {
            s.radiosity = int(parse_float()) != 0;
        } else {
            expected("samples, radiosity or '}'", t);
        }
    }
}

SkySphere Interpreter::parse_sky_sphere() {
    expect_punct('{', "after 'sky_sphere'");
    SkySphere sky;
    const Token& first = peek();
    if (first.kind == TokenKind::Word) {
        const Value* v = lookup(first);
        if (v && std::holds_alternative<std::shared_ptr<SkySphere>>(*v)) {
            next();
            sky = *std::get<std::shared_ptr<SkySphere>>(*v);
        }
    }
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) break;
        Transform tr;
        if (try_transform(t, tr)) {
            sky.transform = sky.transform.then(tr);
            continue;
        }
        if (is_word(t, "pigment")) {
            sky.pigments.push_back(parse_pigment_block());
        } else if (is_word(t, "emission")) {
            sky.emission = parse_colour_value().rgb;
        } else {
            expected("a pigment or '}' in sky_sphere", t);
        }
    }
    return sky;
}

Fog Interpreter::parse_fog() {
    expect_punct('{', "after 'fog'");
    Fog f;
    const Token& first = peek();
    if (first.kind == TokenKind::Word) {
        const Value* v = lookup(first);
        if (v && std::holds_alternative<std::shared_ptr<Fog>>(*v)) {
            next();
            f = *std::get<std::shared_ptr<Fog>>(*v);
        }
    }
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) break;
        Transform tr;
        if (try_transform(t, tr)) {
            f.transform = f.transform.then(tr);
            continue;
        }
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        if (w == "fog_type")
            f.type = parse_int();
        else if (w == "distance")
            f.distance = parse_float();
        else if (w == "color" || w == "colour" || w == "rgb" || w == "rgbf" ||
                 w == "rgbt" || w == "rgbft") {
            unget(t);
            f.colour = parse_colour_value();
        } else if (w == "fog_offset")
            f.offset = parse_float();
        else if (w == "fog_alt")
            f.alt = parse_float();
        else if (w == "up")
            f.up = parse_vector();
        else if (w == "turbulence") {
            f.turbulent = true;
            f.turbulence = parse_vector();
        } else if (w == "turb_depth")
            f.turb_depth = parse_float();
        else if (w == "octaves") {
            f.turbulent = true;
            f.octaves = std::clamp(parse_int(), 1, 10);
        } else if (w == "omega") {
            f.turbulent = true;
            f.omega = parse_single();  // POV-Ray's TURB keeps them in single precision
        } else if (w == "lambda") {
            f.turbulent = true;
            f.lambda = parse_single();
        } else if (t.kind == TokenKind::Word && lookup(t) &&
                   std::holds_alternative<Numeric>(*lookup(t))) {
            unget(t);  // fog { Blue+Gray70 ... }: a colour expression without keyword
            f.colour = parse_colour_value();
        } else
            expected("a fog item or '}'", t);
    }
    return f;
}

namespace {

// POV-Ray makes a mesh face flat when its three vertex normals, normalised, are equal
// (|n1 - n2|^2 and |n1 - n3|^2 at most 1e-10: Parse_Mesh, Parse_Mesh2): the face's own
// normal is used, not the one given (exporters write every corner of a flat face with
// one shared normal that need not be the face's).
void flatten_faces_with_equal_normals(MeshData& mesh) {
    for (MeshFace& f : mesh.faces) {
        if (f.n[0] < 0 || f.n[1] < 0 || f.n[2] < 0) continue;
        Vector3 n[3];
        bool usable = true;
        for (int k = 0; k < 3; ++k) {
            const Vector3 v = mesh.normals[size_t(f.n[k])];
            const Real len = length(v);
            usable = usable && len > 0;
            n[k] = len > 0 ? v / len : v;
        }
        if (!usable) continue;
        const Vector3 d1 = n[0] - n[1], d2 = n[0] - n[2];
        if (dot(d1, d1) <= 1e-10 && dot(d2, d2) <= 1e-10) f.n[0] = f.n[1] = f.n[2] = -1;
    }
}

}  // namespace

void Interpreter::parse_mesh(Object& out) {
    auto data = std::make_shared<MeshData>();
    MeshData& mesh = *data;
    std::vector<LayeredTexture> textures;
    bool any_uv = false;
    for (;;) {
        const Token& p = peek();
        bool smooth = is_word(p, "smooth_triangle");
        if (!is_word(p, "triangle") && !smooth) break;
        next();
        expect_punct('{');
        uint32_t base = uint32_t(mesh.vertices.size());
        MeshFace face;
        for (int i = 0; i < 3; ++i) {
            if (i) accept_punct(',');
            mesh.vertices.push_back(parse_vector());
            face.v[i] = base + i;
            if (smooth) {
                accept_punct(',');
                face.n[i] = int32_t(mesh.normals.size());
                mesh.normals.push_back(parse_vector());
            }
        }
        // `uv_vectors A, B, C`: the corners' texture coordinates; (0, 0) without.
        std::array<std::array<Real, 2>, 3> corner_uvs{};
        if (accept_word("uv_vectors")) {
            for (int k = 0; k < 3; ++k) {
                if (k) accept_punct(',');
                const ProfilePoint q = parse_uv_vector();
                corner_uvs[size_t(k)] = {q.x, q.y};
            }
            any_uv = true;
        }
        for (;;) {
            Token m = next();
            if (is_punct(m, '}')) break;
            if (is_word(m, "texture")) {
                textures.push_back(parse_texture_block());
                face.texture = int32_t(textures.size()) - 1;
            } else if (is_word(m, "texture_list")) {
                // Three texture identifiers, one per corner, blended (POV-Ray's
                // Parse_Mesh_Texture); this ends the triangle's items.
                expect_punct('{', "after 'texture_list'");
                std::array<int32_t, 3> triple;
                for (int k = 0; k < 3; ++k) {
                    if (k) accept_punct(',');
                    Token id = next();
                    const Value* v = id.kind == TokenKind::Word ? lookup(id) : nullptr;
                    auto tex =
                        v ? std::get_if<std::shared_ptr<LayeredTexture>>(v) : nullptr;
                    if (!tex) expected("a texture identifier", id);
                    textures.push_back(**tex);
                    triple[size_t(k)] = int32_t(textures.size()) - 1;
                }
                expect_punct('}', "after the three textures");
                mesh.texture_triples.push_back(triple);
                face.texture = -2 - int32_t(mesh.texture_triples.size() - 1);
                expect_punct('}', "to close the mesh triangle");
                break;
            } else {
                expected("texture, texture_list or '}' in a mesh triangle", m);
            }
        }
        // Degenerate triangles are dropped silently, as POV-Ray does in meshes.
        const Point3 corners[3] = {mesh.vertices[face.v[0]], mesh.vertices[face.v[1]],
                                   mesh.vertices[face.v[2]]};
        if (!degenerate_corners(corners)) {
            mesh.faces.push_back(face);
            const auto first = uint32_t(mesh.uvs.size());
            mesh.uv_faces.push_back({first, first + 1, first + 2});
            for (const auto& uv : corner_uvs) mesh.uvs.push_back(uv);
        }
    }
    if (!any_uv) {  // all (0, 0): no coordinates kept
        mesh.uvs.clear();
        mesh.uv_faces.clear();
    }
    if (accept_word("inside_vector")) {
        mesh.inside_vector = parse_vector();
    }
    flatten_faces_with_equal_normals(mesh);
    out.shape = Mesh{std::move(data), std::move(textures)};
}

Token Interpreter::raw_ahead(size_t k) const {
    if (!pushback_.empty() || frames_.empty()) return Token{};
    const Frame& f = frames_.back();
    if (f.pos + k >= f.end) return Token{};
    return (*f.toks)[f.pos + k];
}

// Machine-written meshes are millions of `<n, n, n>`: when the raw tokens are exactly
// that (commas required, optional minus signs, no operator after '>'), read them directly
// instead of through the expression parser. Anything else is left for parse_vector().
bool Interpreter::try_plain_vector(Vector3& out, Token* at) {
    // On the packed tokens: building a Token for each of a vector's 7 to 10 tokens was
    // the bulk of this path.
    if (!pushback_.empty() || frames_.empty()) return false;
    const Frame& f = frames_.back();
    const TokenArray& toks = *f.toks;
    auto punct = [&](size_t k, char c) {
        return f.pos + k < f.end && toks.packed[f.pos + k].is_punct(c);
    };
    if (!punct(0, '<')) return false;
    size_t k = 1;
    double v[3];
    for (int c = 0; c < 3; ++c) {
        const bool negative = punct(k, '-');
        if (negative) ++k;
        if (f.pos + k >= f.end) return false;
        const PackedToken& n = toks.packed[f.pos + k];
        if (n.kind() != TokenKind::Number) return false;
        v[c] = negative ? -toks.numbers[n.aux] : toks.numbers[n.aux];
        if (!punct(++k, c < 2 ? ',' : '>')) return false;
        ++k;
    }
    if (f.pos + k < f.end) {
        const PackedToken& after = toks.packed[f.pos + k];
        if (after.kind() == TokenKind::Punct && !punct(k, ',') && !punct(k, '}') &&
            !punct(k, '<')) {
            return false;
        }
    }
    if (at) *at = toks[f.pos];
    frames_.back().pos += k;
    out = {v[0], v[1], v[2]};
    return true;
}

// A mesh2 list length: bounded so that a corrupt count fails cleanly instead of
// overflowing.
int Interpreter::parse_count() {
    Token at = peek();
    double n = parse_float();
    if (!(n >= 0 && n <= 1e9)) {
        error(at, "list length " + std::to_string(n) + " out of range");
    }
    return int(n);
}

// Room for a list that says it holds `count` entries, each taking at least one token:
// reserved once instead of grown by doubling (each growth copies and pages in the list
// again), and capped by the tokens left, so a file that claims 10^9 entries reserves
// no more than it could hold. Large lists get huge pages, as token arrays do.
template <class T>
void Interpreter::reserve_list(std::vector<T>& list, int count) {
    const Frame& f = frames_.back();
    const size_t room =
        std::min(size_t(count), f.end > f.pos ? f.end - f.pos : size_t(0));
    if (room <= list.capacity()) return;
    list.reserve(room);
    advise_huge_pages(list.data(), list.capacity() * sizeof(T));
}

void Interpreter::parse_mesh2(Object& out) {
    auto data = std::make_shared<MeshData>();
    MeshData& mesh = *data;
    std::vector<LayeredTexture> textures;
    auto read_vectors = [&](std::vector<Vector3>& into) {
        expect_punct('{');
        int n = parse_count();
        reserve_list(into, n);
        for (int i = 0; i < n; ++i) {
            accept_punct(',');
            Vector3 v;
            if (!try_plain_vector(v, nullptr)) v = parse_vector();
            into.push_back(v);
        }
        accept_punct(',');  // trailing comma
        expect_punct('}');
    };
    std::vector<std::array<int, 3>> normal_idx;
    std::optional<Token> uv_indices_at;
    std::optional<Token> normal_indices_at;
    std::optional<Token> face_indices_at;
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) {
            unget(t);
            break;
        }
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        const bool list_section = w == "vertex_vectors" || w == "normal_vectors" ||
                                  w == "uv_vectors" || w == "texture_list";
        if (list_section && face_indices_at)
            expected("uv_indices, normal_indices or the end of mesh2", t);
        if (w == "vertex_vectors" || w == "normal_vectors") {
            // A second block replaces the first (POV-Ray warns).
            std::vector<Vector3>& list =
                w == "vertex_vectors" ? mesh.vertices : mesh.normals;
            if (!list.empty())
                warn(t,
                     "duplicate " + std::string(w) + " block; ignoring previous block");
            list.clear();
            read_vectors(list);
        } else if (w == "uv_vectors") {
            // A second block replaces the first (POV-Ray warns).
            if (!mesh.uvs.empty())
                warn(t, "duplicate uv_vectors block; ignoring previous block");
            mesh.uvs.clear();
            expect_punct('{');
            int n = parse_count();
            reserve_list(mesh.uvs, n);
            for (int i = 0; i < n; ++i) {
                accept_punct(',');
                const ProfilePoint q = parse_uv_vector();
                mesh.uvs.push_back({q.x, q.y});
            }
            accept_punct(',');  // trailing comma
            expect_punct('}');
        } else if (w == "texture_list") {
            expect_punct('{');
            int n = parse_count();
            for (int i = 0; i < n; ++i) {
                accept_punct(',');
                Token k = next();
                if (!is_word(k, "texture")) expected("texture in texture_list", k);
                textures.push_back(parse_texture_block());
            }
            accept_punct(',');  // trailing comma
            expect_punct('}');
        } else if (w == "face_indices") {
            // One section, before its uv_indices and normal_indices (POV-Ray's fixed
            // order; indices checked against a face count that then changes would not
            // hold).
            if (face_indices_at)
                error(t, "only one face_indices section is allowed in mesh2");
            face_indices_at = t;
            expect_punct('{');
            int n = parse_count();
            reserve_list(mesh.faces, n);
            for (int i = 0; i < n; ++i) {
                accept_punct(',');
                Token at;
                Vector3 v;
                if (!try_plain_vector(v, &at)) {
                    at = peek();
                    v = parse_vector();
                }
                MeshFace f;
                for (int k = 0; k < 3; ++k) {
                    if (!(v[k] >= 0 && v[k] < double(mesh.vertices.size()))) {
                        error(at, "mesh2 face index out of range");
                    }
                    f.v[k] = uint32_t(v[k]);
                }
                std::array<int32_t, 3> indices;
                int given = 0;
                Token second_at;
                // Up to three texture indices may follow (`<a,b,c>[,] t0[,] t1[,] t2`),
                // each a float. Plain numbers are read on the raw stream so that the fast
                // path for the next face stays available.
                for (int k = 0; k < 3; ++k) {
                    double index;
                    Token index_at;
                    if (pushback_.empty()) {
                        const Token first = raw_ahead(0);
                        if (first.kind == TokenKind::End) break;
                        const size_t skip = is_punct(first, ',') ? 1 : 0;
                        const Token value = raw_ahead(skip);
                        if (value.kind == TokenKind::Number) {
                            frames_.back().pos += skip + 1;
                            index = value.number;
                            index_at = value;
                        } else if (value.kind == TokenKind::End || !starts_float(value)) {
                            break;
                        } else {
                            if (skip) next();
                            index_at = peek();
                            index = parse_float();
                        }
                    } else {
                        accept_punct(',');
                        if (!starts_float(peek())) break;
                        index_at = peek();
                        index = parse_float();
                    }
                    if (!(index >= 0 && index < double(textures.size())))
                        error(index_at, "mesh2 texture index out of range");
                    indices[size_t(given++)] = int32_t(index);
                    if (given == 2) second_at = index_at;
                }
                // POV-Ray blends a face with a second index as one with three, and then
                // reads a texture before its list for the missing third.
                if (given == 2)
                    unsupported(second_at, "mesh2 face with two texture indices");
                if (given == 1) f.texture = indices[0];
                if (given == 3) {
                    mesh.texture_triples.push_back(indices);
                    f.texture = -2 - int32_t(mesh.texture_triples.size() - 1);
                }
                mesh.faces.push_back(f);  // degenerate ones are dropped at the end
            }
            accept_punct(',');  // trailing comma
            expect_punct('}');
        } else if (w == "normal_indices") {
            if (!face_indices_at) expected("face_indices", t);
            if (normal_indices_at)
                error(t, "only one normal_indices section is allowed in mesh2");
            normal_indices_at = t;
            expect_punct('{');
            const Token count_at = peek();
            int n = parse_count();
            if (size_t(n) > mesh.faces.size())
                error(count_at,
                      "number of normal indices cannot be more than the number of faces");
            for (int i = 0; i < n; ++i) {
                accept_punct(',');
                Token at = peek();
                Vector3 v = parse_vector();
                for (int k = 0; k < 3; ++k) {
                    if (!(v[k] >= 0 && v[k] < double(mesh.normals.size())))
                        error(at, "mesh2 normal index out of range");
                }
                normal_idx.push_back({int(v.x), int(v.y), int(v.z)});
            }
            accept_punct(',');  // trailing comma
            expect_punct('}');
        } else if (w == "uv_indices") {
            if (!face_indices_at) expected("face_indices", t);
            if (uv_indices_at)
                error(t, "only one uv_indices section is allowed in mesh2");
            uv_indices_at = t;
            expect_punct('{');
            const Token count_at = peek();
            int n = parse_count();
            if (size_t(n) != mesh.faces.size())
                error(count_at, "number of uv indices must equal number of faces");
            reserve_list(mesh.uv_faces, n);
            for (int i = 0; i < n; ++i) {
                accept_punct(',');
                Token at;
                Vector3 v;
                if (!try_plain_vector(v, &at)) {
                    at = peek();
                    v = parse_vector();
                }
                std::array<uint32_t, 3> idx;
                for (int k = 0; k < 3; ++k) {
                    // POV-Ray keeps one (0, 0) coordinate when none were given.
                    const size_t count = std::max<size_t>(mesh.uvs.size(), 1);
                    if (!(v[k] >= 0 && v[k] < double(count)))
                        error(at, "mesh2 uv index out of range");
                    idx[size_t(k)] = uint32_t(v[k]);
                }
                mesh.uv_faces.push_back(idx);
            }
            accept_punct(',');  // trailing comma
            expect_punct('}');
        } else if (w == "inside_vector") {
            mesh.inside_vector = parse_vector();
        } else {
            unget(t);
            break;
        }
    }
    if (!face_indices_at) expected("face_indices", peek());
    // Faces past the normal_indices are flat; without that section, as many normals as
    // vertices are indexed like the vertices, and any other count is an error
    // (Parse_Mesh2).
    if (!normal_indices_at && !mesh.normals.empty()) {
        if (mesh.normals.size() != mesh.vertices.size())
            error(peek(), "missing normal_indices section in mesh2");
        for (MeshFace& f : mesh.faces)
            for (int k = 0; k < 3; ++k) f.n[k] = int32_t(f.v[k]);
    }
    for (size_t i = 0; i < normal_idx.size(); ++i)
        for (int k = 0; k < 3; ++k) mesh.faces[i].n[k] = normal_idx[i][k];
    // Texture coordinates without uv_indices: indexed like the vertices, or the one
    // coordinate for every corner (POV-Ray's rules).
    if (!uv_indices_at && !mesh.uvs.empty()) {
        if (mesh.uvs.size() == mesh.vertices.size()) {
            mesh.uv_faces.reserve(mesh.faces.size());
            for (const MeshFace& f : mesh.faces)
                mesh.uv_faces.push_back({f.v[0], f.v[1], f.v[2]});
        } else if (mesh.uvs.size() == 1) {
            mesh.uv_faces.assign(mesh.faces.size(), {0, 0, 0});
        } else {
            error(peek(), "missing uv_indices section in mesh2");
        }
    }
    if (mesh.uvs.empty()) mesh.uv_faces.clear();  // every corner (0, 0)
    // Degenerate faces are dropped (with their coordinates).
    size_t kept = 0;
    for (size_t i = 0; i < mesh.faces.size(); ++i) {
        const MeshFace& f = mesh.faces[i];
        const Point3 p[3] = {mesh.vertices[f.v[0]], mesh.vertices[f.v[1]],
                             mesh.vertices[f.v[2]]};
        if (degenerate_corners(p)) continue;
        mesh.faces[kept] = f;
        if (!mesh.uv_faces.empty()) mesh.uv_faces[kept] = mesh.uv_faces[i];
        ++kept;
    }
    mesh.faces.resize(kept);
    if (!mesh.uv_faces.empty()) mesh.uv_faces.resize(kept);
    flatten_faces_with_equal_normals(mesh);
    out.shape = Mesh{std::move(data), std::move(textures)};
}

int Interpreter::new_random_stream(int seed) {
    streams_.push_back(std::make_unique<RandomStream>(seed));
    return int(streams_.size()) - 1;
}

double Interpreter::draw_random(int stream, const Token& at) {
    if (stream < 0 || stream >= int(streams_.size()))
        error(at, "illegal random number generator");
    return streams_[stream]->next();
}

// `{ ... }` of `array[n]...`, as POV-Ray 3.7 reads it: one block per dimension holding
// exactly its size of blocks (outer dimensions) or elements (the last one), each element
// and each inner block followed by an optional comma.
void Interpreter::parse_array_initializer(ArrayValue& a, size_t dim, size_t base) {
    NestingGuard guard(*this, peek());
    expect_punct('{', "to begin the array initializer");
    const size_t n = size_t(a.dims[dim]);
    for (size_t i = 0; i < n; ++i) {
        if (dim + 1 < a.dims.size()) {
            if (is_punct(peek(), '}'))
                error(peek(), "too few elements in array initializer");
            parse_array_initializer(a, dim + 1, (base + i) * size_t(a.dims[dim + 1]));
            accept_punct(',');
            continue;
        }
        const Token& e = peek();
        if (is_punct(e, '}')) error(e, "too few elements in array initializer");
        if (is_punct(e, ',')) expected("an array element", e);
        a.items[base + i] = parse_value_additive();
        accept_punct(',');
    }
    if (!is_punct(peek(), '}')) error(peek(), "too many elements in array initializer");
    next();
}

// Keyword-introduced values in expressions: objects, textures, pigments, arrays, ...
Value Interpreter::parse_item_value(const Token& t) {
    if (t.kind == TokenKind::Word) {
        std::string_view w = t.text;
        Object obj;
        if (try_parse_object(t, obj)) return std::make_shared<Object>(std::move(obj));
        if (w == "texture") {
            // `#declare T = texture {...} texture {...}` declares a layered texture.
            LayeredTexture layers = parse_texture_block();
            while (accept_raw_word("texture"))
                link_textures(layers, parse_texture_block(), t);
            return std::make_shared<LayeredTexture>(std::move(layers));
        }
        if (w == "spline") return parse_spline_block();
        if (w == "function") return parse_function_block();
        if (w == "sky_sphere") return std::make_shared<SkySphere>(parse_sky_sphere());
        if (w == "fog") return std::make_shared<Fog>(parse_fog());
        if (w == "media") return std::make_shared<Media>(parse_media());
        // A density is a pigment (POV-Ray parses it as one); `density { D }` reads it.
        if (w == "density") return std::make_shared<Pigment>(parse_density_block());
        if (w == "pigment") return std::make_shared<Pigment>(parse_pigment_block());
        if (w == "finish") return std::make_shared<Finish>(parse_finish_block());
        if (w == "normal") return std::make_shared<Normal>(parse_normal_block());
        if (w == "interior") return std::make_shared<Interior>(parse_interior_block());
        if (w == "camera") return std::make_shared<CameraSpec>(parse_camera_block());
        if (w == "light_source") return std::make_shared<Light>(parse_light_block());
        if (w == "color_map" || w == "colour_map") {
            return std::make_shared<ColourMap>(parse_colour_map_block());
        }
        if (w == "transform") {
            Transform tr;
            try_transform(t, tr);
            return std::make_shared<Transform>(tr);
        }
        if (w == "material") {
            auto m = std::make_shared<Material>();
            Object holder;
            unget(t);
            Token k = next();
            try_object_modifier(holder, k);
            m->texture = holder.texture;
            m->interior_texture = *holder.interior_texture;
            m->interior = holder.interior;
            return m;
        }
        if (w == "array") {
            auto a = std::make_shared<ArrayValue>();
            size_t total = 1;
            while (accept_raw_punct('[')) {
                Token at = peek();
                int n = parse_int();
                if (n <= 0) error(at, "array size must be positive");
                expect_punct(']');
                a->dims.push_back(n);
                total *= size_t(n);
                if (total > kMaxArrayItems) error(at, "array too large");
            }
            if (a->dims.empty()) expected("'[' and the array size", peek());
            a->items.resize(total);
            if (raw_next_is_punct('{')) {
                parse_array_initializer(*a, 0, 0);
                // POV-Ray reads an optional comma after each block, the outermost one
                // too; raw, so that a directive after the array runs after it is
                // stored.
                accept_raw_punct(',');
            }
            return a;
        }
        static constexpr std::string_view kUnsupportedItems[] = {
            "rainbow",     "photons",     "radiosity", "pigment_map",  "normal_map",
            "texture_map", "density_map", "slope_map", "material_map", "lemon"};
        for (std::string_view item : kUnsupportedItems) {
            if (w == item) unsupported(t, w);
        }
        error(t, "undeclared identifier '" + std::string(w) + "'");
    }
    expected("an expression", t);
}

namespace {

bool spline_kind(const Token& t, Spline::Kind& kind) {
    if (t.kind != TokenKind::Word) return false;
    if (t.text == "linear_spline")
        kind = Spline::Kind::Linear;
    else if (t.text == "quadratic_spline")
        kind = Spline::Kind::Quadratic;
    else if (t.text == "cubic_spline")
        kind = Spline::Kind::Cubic;
    else if (t.text == "natural_spline")
        kind = Spline::Kind::Natural;
    else
        return false;
    return true;
}

}  // namespace

// spline { [SPLINE_ID] [kind...] { t [,] value [,] } }, as POV-Ray 3.7 reads it: t is a
// sum-level float, the value a full expression of 2 to 5 components (a float f is
// <f, f>); entries go on while the next token can start a float. A value with fewer
// components than an earlier one keeps that one's higher components (3.7 fills one
// buffer), so the spline has as many components as its widest point.
std::shared_ptr<const Spline> Interpreter::parse_spline_block() {
    expect_punct('{', "after spline");
    auto s = std::make_shared<Spline>();
    if (Token t = peek(); t.kind == TokenKind::Word) {
        if (const Value* v = lookup(t)) {
            if (auto from = std::get_if<std::shared_ptr<const Spline>>(v)) {
                *s = **from;
                next();
            }
        }
    }
    while (spline_kind(peek(), s->kind)) next();
    std::array<double, 5> buffer{};
    while (starts_float(peek())) {
        const double t = parse_float();
        accept_punct(',');
        Numeric n = parse_express();
        if (n.size == 1) n.size = 2, n.c[1] = n.c[0];
        for (int i = 0; i < n.size; ++i) buffer[size_t(i)] = n.c[i];
        s->terms = std::max(s->terms, n.size);
        spline_insert(*s, t, buffer);
        accept_punct(',');
    }
    if (s->points.empty()) error(peek(), "a spline needs at least one point");
    expect_punct('}', "to close the spline");
    return s;
}

// S(p) or S(p, kind): the spline's `terms` components (5: a colour).
Numeric Interpreter::call_spline(const Spline& s) {
    expect_punct('(');
    const double p = parse_float();
    Spline::Kind kind = s.kind;
    if (accept_punct(',')) {
        const Token k = next();
        if (!spline_kind(k, kind))
            expected("linear_spline, quadratic_spline, cubic_spline or natural_spline",
                     k);
    }
    expect_punct(')', "to close the spline call");
    const std::array<double, 5> v = spline_evaluate(s, p, kind);
    Numeric n;
    n.size = s.terms;
    n.colour = s.terms == 5;
    for (int i = 0; i < 5; ++i) n.c[i] = v[size_t(i)];
    return n;
}

// POV-Ray's Parse_RValue: a value that starts as a string is that string alone (a
// comparison after it is an error there); other values are read with directives held
// (see peek_after_operand), as POV-Ray reads a declared float, vector or colour.
Value Interpreter::parse_declared_value(const Token& first) {
    unget(first);
    if (starts_string(first)) return parse_string();
    return parse_expression_value(true);
}

bool Interpreter::starts_string(const Token& t) const {
    if (t.kind == TokenKind::String) return true;
    if (t.kind != TokenKind::Word) return false;
    if (const Value* v = lookup(t)) return std::holds_alternative<std::string>(*v);
    static constexpr std::string_view kStringFunctions[] = {
        "str", "vstr", "concat", "chr", "datetime", "substr", "strupr", "strlwr"};
    for (std::string_view f : kStringFunctions) {
        if (t.text == f) return true;
    }
    return false;
}

}  // namespace povwall::parser
