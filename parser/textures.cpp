// Textures: pigments (colours and patterns), normals, finishes, interiors, colour maps.
#include <cmath>

#include "core/pattern_lists.h"
#include "parser/interpreter.h"
#include "parser/no_bump_scale.h"

namespace povwall::parser {
bool is_colour_keyword(std::string_view w) {
    return w == "color" || w == "colour" || w == "rgb" || w == "rgbf" || w == "rgbt" ||
           w == "rgbft" || w == "srgb" || w == "srgbf" || w == "srgbt" || w == "srgbft" ||
           w == "red" || w == "green" || w == "blue" || w == "filter" ||
           w == "transmit" || w == "alpha";
}

namespace {

// An sRGB-encoded value in the working gamma (POV-Ray's workingGammaToSRGB->Decode):
// to linear, then to `working`'s power curve. Negative values mirror. An sRGB working
// space takes it as it is (the transcoding between equal curves is the identity).
float srgb_to_working(double v, const GammaCurve& working) {
    if (working.kind == GammaCurve::Kind::Srgb) return float(v);
    double a = std::fabs(v);
    double r = a <= 0.04045 ? a / 12.92 : std::pow((a + 0.055) / 1.055, 2.4);
    if (working.decoding_exponent != 1.0f)
        r = std::pow(r, 1.0 / working.decoding_exponent);
    return float(v < 0 ? -r : r);
}

struct PatternName {
    std::string_view name;
    PatternKind kind;
};
constexpr PatternName kPatterns[] = {
    {"agate", PatternKind::Agate},
    {"bozo", PatternKind::Bozo},
    {"brick", PatternKind::Brick},
    {"bumps", PatternKind::Bumps},
    {"checker", PatternKind::Checker},
    {"crackle", PatternKind::Crackle},
    {"dents", PatternKind::Dents},
    {"gradient", PatternKind::Gradient},
    {"granite", PatternKind::Granite},
    {"hexagon", PatternKind::Hexagon},
    {"leopard", PatternKind::Leopard},
    {"mandel", PatternKind::Mandel},
    {"marble", PatternKind::Marble},
    {"onion", PatternKind::Onion},
    {"quilted", PatternKind::Quilted},
    {"radial", PatternKind::Radial},
    {"ripples", PatternKind::Ripples},
    {"spiral1", PatternKind::Spiral1},
    {"spiral2", PatternKind::Spiral2},
    {"spotted", PatternKind::Spotted},
    {"waves", PatternKind::Waves},
    {"wood", PatternKind::Wood},
    {"wrinkles", PatternKind::Wrinkles},
    {"boxed", PatternKind::Boxed},
    {"cylindrical", PatternKind::Cylindrical},
    {"spherical", PatternKind::Spherical},
    {"planar", PatternKind::Planar},
    {"cells", PatternKind::Cells},
    {"average", PatternKind::Average},
    {"square", PatternKind::Square},
    {"triangular", PatternKind::Triangular},
    {"cubic", PatternKind::Cubic},
    {"julia", PatternKind::Julia},
    {"magnet", PatternKind::Magnet},
    {"tiling", PatternKind::Tiling},
    {"pavement", PatternKind::Pavement},
};

bool is_unsupported_pattern(std::string_view w) { return w == "material_map"; }

// How many entries the block patterns take right after their keyword (checker
// rgb A, rgb B; ...); 0 for the other patterns.
int entry_list_size(PatternKind k) { return pattern_list_size(k); }

bool is_fractal(PatternKind k) {
    return k == PatternKind::Mandel || k == PatternKind::Julia ||
           k == PatternKind::Magnet;
}

// POV-Ray's `(unsigned char)Parse_Float()` (pavement's values): truncated toward zero,
// then the low 8 bits as x86-64 gcc's conversion through a 32-bit int leaves them (-1 is
// 255, 257 is 1); 0 where no such int holds the value.
uint8_t pavement_byte(double v) {
    if (!(std::fabs(v) < 2147483648.0)) return 0;
    return uint8_t(uint32_t(int32_t(v)) & 0xFFu);
}

}  // namespace

Numeric Interpreter::parse_colour(bool hold_directives, bool any_vector) {
    Numeric c;
    c.size = 5;
    c.colour = true;
    bool any = false;
    if (is_word(peek(), "color") || is_word(peek(), "colour")) next();
    // sRGB forms decode into the working gamma, which only assumed_gamma sets.
    auto decode_srgb = [&](double v) {
        return srgb_to_working(v, *scene_.settings.assumed_gamma);
    };
    auto check_srgb = [&](const Token& form) {
        if (form.text[0] == 's' && !scene_.settings.assumed_gamma)
            error(form, "cannot read sRGB colours before assumed_gamma has been set");
    };
    // POV-Ray's Parse_Colour keeps every term the expression has: `rgb <r, g, b, f>` is
    // rgbf (a declared colour after rgb keeps its filter and transmit), with a warning.
    auto set = [&](const Numeric& v, int count, bool srgb, const Token& keyword) {
        Numeric p = v;
        if (p.size == 1) {
            for (int i = 1; i < 5; ++i) p.c[i] = p.c[0];
        } else if (p.size > count) {
            warn(keyword, "suspicious expression after " + std::string(keyword.text));
            count = p.size;
        }
        for (int i = 0; i < count; ++i) {
            c.c[i] = (srgb && i < 3) ? decode_srgb(p.c[i]) : p.c[i];
        }
    };
    auto express = [&] { return parse_express(hold_directives); };
    // POV-Ray's Parse_Colour takes any vector expression (CASE_VECTOR), promoted to five
    // terms: an identifier, a number, '<', '(', a unary '-', '+' or '!', a float or
    // vector function, x, y, z, u or v (`emission y*2`); its colour keywords are read
    // below, and `t` is no colour.
    auto starts_colour_expression = [&](const Token& tok) {
        if (tok.kind == TokenKind::Word && lookup(tok)) return true;
        if (!any_vector)
            return tok.kind == TokenKind::Number || is_punct(tok, '<') ||
                   is_punct(tok, '(') || is_punct(tok, '-');
        if (tok.kind == TokenKind::Word &&
            (tok.text == "t" || tok.text == "color" || tok.text == "colour" ||
             tok.text == "red" || tok.text == "green" || tok.text == "blue" ||
             tok.text == "filter" || tok.text == "transmit" || tok.text == "gray" ||
             tok.text == "grey" || tok.text.find("rgb") != std::string_view::npos))
            return false;
        return starts_expression(tok);
    };
    for (;;) {
        const Token& t = any ? peek_after_operand(hold_directives) : peek();
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        // A second form keyword starts the next colour (checker rgb A rgb B).
        bool form = w == "rgb" || w == "srgb" || w == "rgbf" || w == "srgbf" ||
                    w == "rgbt" || w == "srgbt" || w == "rgbft" || w == "srgbft";
        if (form && any) break;
        if (form) check_srgb(t);
        if (w == "rgb" || w == "srgb") {
            const Token keyword = next();
            set(express(), 3, w == "srgb", keyword);
        } else if (w == "rgbf" || w == "srgbf") {
            const Token keyword = next();
            set(express(), 4, w == "srgbf", keyword);
        } else if (w == "rgbt" || w == "srgbt") {
            const Token keyword = next();
            Numeric v = express();
            Numeric p = v;
            if (p.size == 1) {
                for (int i = 1; i < 5; ++i) p.c[i] = p.c[0];
            } else if (p.size > 4) {
                warn(keyword, "suspicious expression after " + std::string(keyword.text));
            }
            for (int i = 0; i < 3; ++i)
                c.c[i] = w == "srgbt" ? decode_srgb(p.c[i]) : p.c[i];
            c.c[4] = p.c[3];
        } else if (w == "rgbft" || w == "srgbft") {
            const Token keyword = next();
            set(express(), 5, w == "srgbft", keyword);
        } else if (w == "red" || w == "green" || w == "blue" || w == "filter" ||
                   w == "transmit" || w == "alpha") {
            next();
            if (w == "alpha")
                warn(t, "keyword 'alpha' discontinued; use 'filter' instead");
            int i = w == "red"                      ? 0
                    : w == "green"                  ? 1
                    : w == "blue"                   ? 2
                    : w == "filter" || w == "alpha" ? 3
                                                    : 4;
            c.c[i] = parse_numeric(false, hold_directives).c[0];
        } else if (!any && starts_colour_expression(t)) {
            Numeric v = express();
            if (v.size == 1) {
                for (int i = 0; i < 5; ++i) c.c[i] = v.c[0];
            } else {
                for (int i = 0; i < v.size; ++i) c.c[i] = v.c[i];
            }
        } else {
            break;
        }
        any = true;
    }
    // No colour at all is black, as POV-Ray's Parse_Colour leaves it (a light_source
    // written with its location alone is a black light there).
    return c;
}

Colour Interpreter::parse_colour_value(bool any_vector) {
    Numeric c = parse_colour(false, any_vector);
    return Colour(Rgb(float(c.c[0]), float(c.c[1]), float(c.c[2])), float(c.c[3]),
                  float(c.c[4]));
}

ColourMap Interpreter::parse_colour_map_block() {
    expect_punct('{', "after 'color_map'");
    ColourMap map;
    const Token& first = peek();
    if (first.kind == TokenKind::Word) {
        const Value* v = lookup(first);
        if (v && std::holds_alternative<std::shared_ptr<ColourMap>>(*v)) {
            next();
            map = *std::get<std::shared_ptr<ColourMap>>(*v);
        }
    }
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) break;
        if (!is_punct(t, '[')) expected("'[' or '}' in a color_map", t);
        float v1 = float(parse_float());
        accept_punct(',');
        // After the value, POV-Ray's Parse_Colour_Map reads a whole expression when a
        // float could start one: a float is the old two-value form [v1, v2 color A color
        // B], a colour (`0.6 * White`) the entry's colour.
        if (const Token at = peek(); starts_float(at)) {
            const Numeric n = parse_express();
            if (n.size == 1) {
                const float v2 = float(n.c[0]);
                Colour a = parse_colour_value();
                Colour b = parse_colour_value();
                map.push_back({v1, a});
                map.push_back({v2, b});
            } else if (n.size == 5) {
                map.push_back(
                    {v1, Colour(Rgb(float(n.c[0]), float(n.c[1]), float(n.c[2])),
                                float(n.c[3]), float(n.c[4]))});
            } else {
                error(at, "Illegal expression syntax in color_map.");
            }
        } else {
            map.push_back({v1, parse_colour_value(false)});
        }
        expect_punct(']', "to close the color_map entry");
    }
    return map;
}

// After `slope`: `<direction>`, or `{ [point_at] <vector> [, low [, high]] [altitude
// <vector> [, low [, high]]] }` (POV-Ray's Parse_Pattern).
PatternSpec::Slope Interpreter::parse_slope() {
    PatternSpec::Slope s;
    // An optional `, low [, high]` pair as (low, high - low); equal ends mean none.
    auto parse_range = [&](Real& low, Real& range, const char* what) {
        Real lo = 0, hi = 0;
        accept_punct(',');
        if (starts_float(peek())) lo = parse_float();
        accept_punct(',');
        if (starts_float(peek())) hi = parse_float();
        const Token& at = peek();
        if (hi != 0 && hi == lo) {
            warn(at, std::string("Zero ") + what + " range, ignoring.");
            lo = hi = 0;
        }
        low = lo;
        range = hi - lo;
    };
    if (accept_punct('{')) {
        s.point_at = accept_word("point_at");
        s.direction = parse_vector();
        parse_range(s.low, s.range, "slope");
        const Token t = peek();
        if (is_word(t, "altitude")) {
            if (s.point_at)
                error(t,
                      "Keyword 'altitude' cannot be used with 'point_at' in slope "
                      "pattern.");
            next();
            s.altitude = parse_vector();
            parse_range(s.altitude_low, s.altitude_range, "gradient");
        }
        expect_punct('}', "to close the slope pattern");
    } else {
        s.direction = parse_vector();
    }
    if (s.point_at) {
        s.share = 1;
        s.altitude_share = 0;
        return s;
    }
    const Real slope_len = length(s.direction), altitude_len = length(s.altitude);
    if (slope_len != 0) s.direction = s.direction / slope_len;
    if (altitude_len != 0) s.altitude = s.altitude / altitude_len;
    const Real total = slope_len + altitude_len;
    if (total == 0) error(peek(), "Zero length for both slope and gradient.");
    s.share = slope_len / total;
    s.altitude_share = 1.0 - s.share;
    // An exact unit axis is read as that component (the same value, POV-Ray's shortcut).
    auto axis_of = [](const Vector3& v) -> int8_t {
        for (int i = 0; i < 3; ++i) {
            if (v[i] == 1.0) return int8_t(i + 1);
            if (v[i] == -1.0) return int8_t(-(i + 1));
        }
        return 0;
    };
    s.axis = axis_of(s.direction);
    s.altitude_axis = axis_of(s.altitude);
    return s;
}

bool Interpreter::try_pattern_keyword(const Token& t, PatternSpec& spec) {
    if (!try_pattern_keyword_kind(t, spec)) return false;
    // POV-Ray's parser sets Frequency 0 for these (their value is taken as it is, and
    // `phase` alone does nothing); the others keep the frequency they had.
    if (initial_frequency(spec.kind) == 0) spec.frequency = 0;
    return true;
}

bool Interpreter::try_pattern_keyword_kind(const Token& t, PatternSpec& spec) {
    if (t.kind != TokenKind::Word) return false;
    std::string_view w = t.text;
    if (is_unsupported_pattern(w)) unsupported(t, w);
    if (w == "object") {
        parse_object_pattern(t, spec);  // its entries and '}' are the caller's
        return true;
    }
    if (w == "image_pattern") {
        spec.kind = PatternKind::ImagePattern;
        spec.image = parse_image_block(t, nullptr, ImageBlock::ImagePattern);
        return true;
    }
    // parse_normal_body reads facets before coming here.
    if (w == "facets")
        error(t, "Keyword 'facets' can only be used in a normal statement.");
    if (w == "function") {
        // `function { EXPR }` of x, y, z (a declared function is called inside it:
        // `function { F(x, y, z) }`).
        spec.kind = PatternKind::Function;
        spec.function = parse_function_block(true);
        return true;
    }
    if (w == "slope") {
        spec.kind = PatternKind::Slope;
        spec.slope = std::make_shared<const PatternSpec::Slope>(parse_slope());
        return true;
    }
    if (w == "aoi") {
        spec.kind = PatternKind::Aoi;
        return true;
    }
    if (w == "density_file") {
        spec.kind = PatternKind::DensityFile;
        spec.density_file = parse_density_file();
        spec.density_interpolation = 0;  // a new file starts without interpolation
        return true;
    }
    if (w == "pigment_pattern") {
        // The grey of a pigment (POV-Ray's pigment_pattern; an empty one is black).
        auto inner = std::make_shared<Pigment>();
        inner->colour = Colour{};
        expect_punct('{', "after 'pigment_pattern'");
        parse_pigment_body(*inner, '}');
        spec.kind = PatternKind::PigmentPattern;
        spec.pigment = std::move(inner);
        return true;
    }
    for (const auto& p : kPatterns) {
        if (w != p.name) continue;
        // A pattern keyword in a block that edits an earlier pattern (a second
        // `pigment { }`) replaces the type and the type's own parameters, and keeps the
        // rest (maps, transforms, warps), as POV-Ray's Parse_Pattern. The parameters
        // share the generic fields, so they start over; brick keeps its size and mortar
        // when it was brick already.
        if (p.kind != PatternKind::Brick || spec.kind != PatternKind::Brick) {
            spec.scalar = 0;
            spec.vector = {0, 0, 0};
            spec.vector2 = {0, 0, 0};
        }
        spec.kind = p.kind;
        switch (p.kind) {
            case PatternKind::Gradient:
                spec.vector = parse_vector();
                break;
            case PatternKind::Agate:
                break;
            // POV-Ray's default wave for marble, wood and the spirals is the triangle
            // wave.
            case PatternKind::Marble:
            case PatternKind::Wood:
                spec.wave = WaveType::Triangle;
                break;
            case PatternKind::Spiral1:
            case PatternKind::Spiral2:
                spec.scalar = parse_float();
                spec.wave = WaveType::Triangle;
                break;
            case PatternKind::Mandel:
                spec.fractal = {};  // POV-Ray's default colouring, exponent 2
                spec.scalar = parse_int();
                break;
            case PatternKind::Tiling: {
                const Token at = peek();
                const int n = saturating_int(parse_float());
                if (n < 1 || n > 27) error(at, "Tiling number must be between 1 and 27.");
                spec.scalar = n;
                break;
            }
            case PatternKind::Julia: {
                spec.fractal = {};
                const ProfilePoint c = parse_uv_vector();
                spec.fractal.c_re = c.x;
                spec.fractal.c_im = c.y;
                accept_punct(',');
                spec.scalar = parse_int();
                break;
            }
            case PatternKind::Magnet: {
                // `magnet 1|2 mandel ITERATIONS` or `magnet 1|2 julia <c>, ITERATIONS`.
                spec.fractal = {};
                const Token at = peek();
                const int formula = parse_int();
                const Token form = next();
                const bool julia = is_word(form, "julia");
                if (!julia && !is_word(form, "mandel"))
                    error(form,
                          "Invalid magnet pattern found. Valid types are 'mandel' and "
                          "'julia'.");
                if (formula != 1 && formula != 2)
                    error(at, julia ? "Invalid magnet-julia pattern type found. Valid "
                                      "types are 1 and 2."
                                    : "Invalid magnet-mandel pattern type found. Valid "
                                      "types are 1 and 2.");
                spec.fractal.magnet_formula = uint8_t(formula);
                spec.fractal.magnet_julia = julia;
                if (julia) {
                    const ProfilePoint c = parse_uv_vector();
                    spec.fractal.c_re = c.x;
                    spec.fractal.c_im = c.y;
                    accept_punct(',');
                }
                spec.scalar = parse_int();
                break;
            }
            case PatternKind::Quilted:
                spec.vector = {1, 1, 0};  // control0, control1 defaults
                break;
            case PatternKind::Crackle:
                spec.vector = {-1, 1, 0};  // form
                spec.scalar = 2;           // metric
                break;
            case PatternKind::Pavement:
                spec.pavement = {};  // triangles, every one a tile
                break;
            default:
                break;
        }
        return true;
    }
    return false;
}

// The pattern of a pigment or normal is allocated only when a keyword writes it (see
// HeapValue); a word that is not one leaves it unallocated.
bool Interpreter::try_pattern_keyword(const Token& t, HeapValue<PatternSpec>& spec) {
    if (t.kind != TokenKind::Word) return false;
    const bool had = spec.allocated();
    if (try_pattern_keyword(t, spec.edit())) return true;
    if (!had) spec.clear();
    return false;
}

bool Interpreter::try_pattern_modifier(const Token& t, HeapValue<PatternSpec>& spec) {
    if (t.kind != TokenKind::Word) return false;
    const bool had = spec.allocated();
    if (try_pattern_modifier(t, spec.edit())) return true;
    if (!had) spec.clear();
    return false;
}

bool Interpreter::try_pattern_modifier(const Token& t, PatternSpec& spec) {
    if (t.kind != TokenKind::Word) return false;
    std::string_view w = t.text;
    // POV-Ray reads it on any pattern; only a normal's (or a texture_map's) is used.
    if (w == "no_bump_scale") {
        spec.no_bump_scale = true;
        return true;
    }
    Transform tr;
    if (try_transform(t, tr)) {
        spec.transform = spec.transform.then(tr);
        return true;
    }
    auto turbulence_warp = [&]() -> Warp& {
        // Classic turbulence keywords edit the pattern's turbulence warp (created on
        // demand).
        for (Warp& wp : spec.warps) {
            if (wp.kind == Warp::Kind::Turbulence && wp.classic) return wp;
        }
        spec.warps.push_back(Warp{});
        return spec.warps.back();
    };
    if (w == "turbulence") {
        turbulence_warp().turbulence = parse_vector();
    } else if (w == "octaves") {
        turbulence_warp().octaves = parse_int();
    } else if (w == "omega") {
        turbulence_warp().omega = parse_single();
    } else if (w == "lambda") {
        turbulence_warp().lambda = parse_single();
    } else if (w == "frequency") {
        spec.frequency = parse_single();
    } else if (w == "phase") {
        spec.phase = parse_single();
    } else if (w == "ramp_wave") {
        spec.wave = WaveType::Ramp;
    } else if (w == "triangle_wave") {
        spec.wave = WaveType::Triangle;
    } else if (w == "sine_wave") {
        spec.wave = WaveType::Sine;
    } else if (w == "scallop_wave") {
        spec.wave = WaveType::Scallop;
    } else if (w == "cubic_wave") {
        spec.wave = WaveType::Cubic;
    } else if (w == "poly_wave") {
        spec.wave = WaveType::Poly;
        const Token& n = peek();
        if (starts_float(n)) spec.wave_exponent = parse_single();
    } else if (w == "noise_generator") {
        spec.noise_generator = parse_int();
    } else if (w == "agate_turb") {
        spec.scalar = parse_single();
    } else if (w == "mortar") {
        spec.scalar = parse_float();
    } else if (w == "brick_size") {
        spec.vector2 = parse_vector();
    } else if (w == "metric") {
        // A vector (POV-Ray reads its x); crackle keeps it in scalar.
        const Real metric = parse_vector().x;
        if (spec.kind == PatternKind::Facets)
            spec.facets.metric = metric;
        else if (spec.kind == PatternKind::Crackle)
            spec.scalar = metric;
        else
            error(t,
                  "Keyword 'metric' can only be used in a facets or crackle statement.");
    } else if (w == "size") {
        if (spec.kind != PatternKind::Facets)
            error(t, "Keyword 'size' can only be used in a facets statement.");
        spec.facets.size = parse_float();
    } else if (w == "coords") {
        if (spec.kind != PatternKind::Facets)
            error(t, "Keyword 'coords' can only be used in a facets statement.");
        spec.facets.coords = parse_float();
    } else if (w == "exponent") {
        if (spec.kind != PatternKind::Mandel && spec.kind != PatternKind::Julia)
            error(t,
                  "Keyword 'exponent' can only be used in a mandel or julia statement.");
        const int n = parse_int();
        if (n >= 2 && n <= 33) {
            spec.fractal.exponent = uint8_t(n);
        } else {
            warn(t, std::string("Invalid ") +
                        (spec.kind == PatternKind::Julia ? "julia" : "mandel") +
                        " pattern exponent found. Supported exponents are 2 to 33. Using "
                        "default exponent 2.");
            spec.fractal.exponent = 2;
        }
    } else if (w == "form") {
        if (spec.kind == PatternKind::Pavement)
            spec.pavement.form = pavement_byte(parse_float());
        else if (spec.kind == PatternKind::Crackle)
            spec.vector = parse_vector();
        else
            error(t,
                  "Keyword 'form' can only be used in a crackle or pavement statement.");
    } else if (w == "number_of_sides" || w == "number_of_tiles" || w == "pattern") {
        if (spec.kind != PatternKind::Pavement)
            error(t, "Keyword '" + std::string(w) +
                         "' can only be used in a pavement statement.");
        const uint8_t v = pavement_byte(parse_float());
        (w == "number_of_sides"   ? spec.pavement.sides
         : w == "number_of_tiles" ? spec.pavement.tiles
                                  : spec.pavement.pattern) = v;
    } else if (w == "offset") {
        spec.vector2.x = parse_float();  // crackle: vector2 = <offset, solid, 0>
    } else if (w == "solid") {
        spec.vector2.y = 1;
    } else if (w == "interior" || w == "exterior") {
        // Fractal colouring: `exterior TYPE, FACTOR`, `interior TYPE, FACTOR`; on
        // pavement one value, the look of its convex and concave corners. POV-Ray's
        // message names exterior for both.
        const bool exterior = w == "exterior";
        if (spec.kind == PatternKind::Pavement) {
            (exterior ? spec.pavement.exterior : spec.pavement.interior) =
                pavement_byte(parse_float());
            return true;
        }
        if (!is_fractal(spec.kind))
            error(t,
                  "Keyword 'exterior' can only be used in a mandel, julia, magnet or "
                  "pavement statement.");
        Token at = peek();
        const int type = saturating_int(parse_float());
        if (type < 0 || type > (exterior ? 8 : 6))
            error(at, exterior ? "invalid fractal pattern exterior type (0 to 8)"
                               : "invalid fractal pattern interior type (0 to 6)");
        accept_punct(',');
        const Real factor = parse_float();
        if (exterior) {
            spec.fractal.exterior_type = uint8_t(type);
            spec.fractal.exterior_factor = factor;
        } else {
            spec.fractal.interior_type = uint8_t(type);
            spec.fractal.interior_factor = factor;
        }
    } else if (w == "interpolate") {
        if (spec.kind != PatternKind::DensityFile)
            error(t, "keyword 'interpolate' cannot be used with non-density_file");
        spec.density_interpolation = parse_int();
    } else if (w == "control0") {
        spec.vector.x = parse_single();
    } else if (w == "control1") {
        spec.vector.y = parse_single();
    } else if (w == "warp") {
        expect_punct('{', "after 'warp'");
        Warp wp;
        Token k = next();
        std::string_view kind = k.kind == TokenKind::Word ? k.text : std::string_view();
        if (kind == "turbulence") {
            wp.kind = Warp::Kind::Turbulence;
            wp.classic = false;
            wp.turbulence = parse_vector();
        } else if (kind == "repeat") {
            wp.kind = Warp::Kind::Repeat;
            wp.repeat = parse_vector();
        } else if (kind == "black_hole") {
            wp.kind = Warp::Kind::BlackHole;
            wp.centre = parse_vector();
            accept_punct(',');
            wp.radius = parse_float();
        } else if (kind == "cylindrical" || kind == "spherical" || kind == "toroidal" ||
                   kind == "planar") {
            wp.kind = kind == "cylindrical" ? Warp::Kind::Cylindrical
                      : kind == "spherical" ? Warp::Kind::Spherical
                      : kind == "toroidal"  ? Warp::Kind::Toroidal
                                            : Warp::Kind::Planar;
            const Token& n = peek();
            bool vector_follows = is_punct(n, '<') || is_word(n, "x") ||
                                  is_word(n, "y") || is_word(n, "z") ||
                                  (n.kind == TokenKind::Word && lookup(n) &&
                                   std::holds_alternative<Numeric>(*lookup(n)));
            if (wp.kind == Warp::Kind::Planar &&
                vector_follows) {  // planar <normal>, offset
                wp.orientation = parse_vector();
                accept_punct(',');
                wp.plane_offset = parse_float();
            }
        } else if (kind == "cubic") {
            wp.kind = Warp::Kind::Cubic;
        } else {
            unsupported(k, "warp " + std::string(k.text));
        }
        for (;;) {
            Token m = next();
            if (is_punct(m, '}')) break;
            std::string_view mw = m.kind == TokenKind::Word ? m.text : std::string_view();
            if (mw == "octaves")
                wp.octaves = parse_int();
            else if (mw == "omega")
                wp.omega = parse_single();
            else if (mw == "lambda")
                wp.lambda = parse_single();
            else if (mw == "offset")
                wp.offset = parse_vector();
            else if (mw == "flip")
                wp.flip = parse_vector();
            else if (mw == "strength")
                wp.strength = parse_float();
            else if (mw == "falloff")
                wp.falloff = parse_float();
            else if (mw == "inverse")
                wp.inverse = true;
            else if (mw == "repeat")
                wp.repeat = parse_vector();
            else if (mw == "turbulence")
                wp.turbulence = parse_vector();
            else if (mw == "orientation")
                wp.orientation = parse_vector();
            else if (mw == "dist_exp")
                wp.dist_exp = parse_float();
            else if (mw == "major_radius")
                wp.major_radius = parse_float();
            else
                expected("a warp modifier or '}'", m);
        }
        // POV-Ray keeps transforms and warps in one list, each new one put in front:
        // the transforms written before this warp act after it on the way into pattern
        // space (Warp::transform), the ones written after it before it (spec.transform
        // again, from here on).
        wp.transform = spec.transform;
        spec.transform = Transform{};
        spec.warps.push_back(wp);
    } else {
        return false;
    }
    return true;
}

void Interpreter::finish_pavement(PatternSpec& spec, const Token& at) {
    if (spec.kind != PatternKind::Pavement) return;
    PatternSpec::Pavement& pv = spec.pavement;
    pv.interior %= 3;
    pv.exterior %= 3;
    const char* max_per_tile;
    switch (pv.sides) {
        case 3:
            max_per_tile = "(1,1,1,3,4,12)";
            break;
        case 4:
            max_per_tile = "(1,1,2,5,12,35)";
            break;
        case 6:
            max_per_tile = "(1,1,3,7,22)";
            break;
        default:
            error(at, "number_of_sides of pavement must be 3, 4 or 6.");
    }
    const int most_tiles = pv.sides == 6 ? 5 : 6;
    if (pv.tiles == 0 || pv.tiles > most_tiles)
        error(at, "number_of_tiles of pavement must be between 1 and " +
                      std::to_string(most_tiles) + ".");
    if (pv.pattern == 0 || pv.pattern > pavement_patterns(pv.sides, pv.tiles))
        error(at,
              std::string("pattern value for pavement is out of range. max per tile:") +
                  max_per_tile);
    pv.form %= pv.sides == 4 ? 4 : 3;
}

Pigment Interpreter::parse_pigment_block() {
    Pigment p = default_texture_.pigment;
    parse_pigment_into(p);
    return p;
}

// `pigment { ... }` after the keyword, editing `p` in place: a second pigment block in
// a texture continues from the first (POV-Ray's Parse_Pigment).
void Interpreter::parse_pigment_into(Pigment& p) {
    expect_punct('{', "after 'pigment'");
    parse_pigment_body(p, '}');
}

// The inside of `pigment { ... }`, also the entries of a pigment_map (ending at ']').
void Interpreter::parse_pigment_body(Pigment& p, char terminator) {
    const Token& first = peek();
    NestingGuard guard(*this, first);  // maps of maps of ...
    if (first.kind == TokenKind::Word) {
        const Value* v = lookup(first);
        if (v && std::holds_alternative<std::shared_ptr<Pigment>>(*v)) {
            next();
            p = *std::get<std::shared_ptr<Pigment>>(*v);
        }
    }
    // POV-Ray reads the pattern only as the first item (after the identifier): one after
    // a modifier or another pattern ends the block there (Parse_Pattern, then the
    // caller's closing brace).
    bool first_item = true;
    for (;;) {
        Token t = next();
        if (is_punct(t, terminator)) {
            finish_pavement(p.pattern, t);
            return;
        }
        const bool pattern_allowed = first_item;
        first_item = false;
        // Colours first: no pattern keyword or modifier is one, and solid pigments are
        // the common case (the pattern tables are long).
        const bool colour = t.kind == TokenKind::Word && is_colour_keyword(t.text);
        if (!colour && try_pattern_keyword(t, p.pattern)) {
            if (!pattern_allowed)
                error(t, terminator == '}'
                             ? "No matching } in 'pigment', " + std::string(t.text) +
                                   " found instead"
                             : "Expected ']', " + std::string(t.text) + " found instead");
            // The block patterns (and the object pattern) take their colours or
            // pigments right after the keyword (POV-Ray's Parse_Blend_List).
            const bool object_pattern = p.pattern->kind == PatternKind::ObjectInside;
            if (const int count = entry_list_size(p.pattern->kind)) {
                // The list replaces the map an earlier block gave.
                if (p.maps.allocated()) {
                    PigmentMaps& m = p.maps.edit();
                    m.colour_map.clear();
                    m.map_values.clear();
                    m.list.clear();
                }
                const bool pigments = is_word(peek(), "pigment");
                int given = 0;
                // Each entry takes an optional comma after it, the last one too
                // (POV-Ray's Parse_Blend_List).
                for (; given < count; ++given, accept_punct(',')) {
                    const Token& n = peek();
                    if (pigments) {
                        if (!accept_word("pigment")) break;
                        p.maps.edit().list.push_back(parse_pigment_block());
                    } else if (is_punct(n, '}') ||
                               (n.kind == TokenKind::Word && !lookup(n) &&
                                !is_colour_keyword(n.text))) {
                        break;
                    } else {
                        Pigment sub;
                        sub.colour = parse_colour_value();
                        p.maps.edit().list.push_back(sub);
                    }
                }
                // Missing pigments are the default pigment (missing colours, the
                // pattern's default colours, come from the evaluator).
                for (; pigments && given < count; ++given)
                    p.maps.edit().list.push_back(default_texture_.pigment);
                if (object_pattern) expect_punct('}', "to close the object pattern");
            }
            continue;
        }
        if (!colour && try_pattern_modifier(t, p.pattern)) continue;
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        if (colour) {
            unget(t);
            if (p.pattern->kind != PatternKind::Solid)
                p.pattern.edit().kind = PatternKind::Solid;
            p.colour = parse_colour_value();
        } else if (w == "color_map" || w == "colour_map") {
            if (entry_list_size(p.pattern->kind))
                error(t, "Cannot use color_map with this pattern type.");
            // It replaces a pigment_map the pigment had, as any map replaces the last.
            if (p.maps.allocated()) {
                p.maps.edit().map_values.clear();
                p.maps.edit().list.clear();
            }
            p.maps.edit().colour_map = parse_colour_map_block();
        } else if (w == "pigment_map" || w == "density_map") {
            if (w == "pigment_map" && entry_list_size(p.pattern->kind))
                error(t, "Keyword 'pigment_map' cannot be used with this pigment type.");
            // A density_map blends densities as a pigment_map blends pigments (POV-Ray
            // evaluates both as pigments); its entries start from an empty density.
            const bool density = w == "density_map";
            if (density) {
                switch (p.pattern->kind) {
                    case PatternKind::Checker:
                    case PatternKind::Brick:
                    case PatternKind::Hexagon:
                    case PatternKind::Square:
                    case PatternKind::Triangular:
                    case PatternKind::Cubic:
                    case PatternKind::Solid:
                    case PatternKind::ImageMap:
                        error(t, "a density_map cannot be used with this pattern type");
                    default:
                        break;
                }
            }
            expect_punct('{', density ? "after 'density_map'" : "after 'pigment_map'");
            // The map replaces the one a pigment identifier or an earlier map gave
            // (POV-Ray's Parse_Pigment destroys the old blend map).
            if (p.maps.allocated()) {
                PigmentMaps& m = p.maps.edit();
                m.colour_map.clear();
                m.map_values.clear();
                m.list.clear();
            }
            for (;;) {
                Token e = next();
                if (is_punct(e, '}')) break;
                if (!is_punct(e, '['))
                    expected(density ? "'[' in a density_map" : "'[' in a pigment_map",
                             e);
                float v = parse_map_value(p.pattern->kind == PatternKind::Average);
                accept_punct(',');
                Pigment sub = density ? Pigment{} : default_texture_.pigment;
                if (density) sub.colour = Colour{};
                // POV-Ray: a density entry is an identifier or a pattern, no keyword.
                if (!density && accept_word("pigment")) {
                    sub = parse_pigment_block();
                    expect_punct(']');
                } else {
                    parse_pigment_body(sub, ']');
                }
                p.maps.edit().map_values.push_back(v);
                p.maps.edit().list.push_back(std::move(sub));
            }
        } else if (w == "quick_color" || w == "quick_colour") {
            p.maps.edit().quick_colour = parse_colour_value();
        } else if (t.kind == TokenKind::Word && lookup(t) &&
                   std::holds_alternative<Numeric>(*lookup(t))) {
            // A colour identifier alone: pigment { Red }
            unget(t);
            if (p.pattern->kind != PatternKind::Solid)
                p.pattern.edit().kind = PatternKind::Solid;
            p.colour = parse_colour_value();
        } else if (w == "image_map") {
            p.pattern.edit().kind = PatternKind::ImageMap;
            p.pattern.edit().image = parse_image_block(t, nullptr);
        } else if (w == "uv_mapping") {
            // The rest of the block is one pigment evaluated at the surface coordinates
            // (POV-Ray's Parse_Item_Into_Blend_List): it takes every later item.
            Pigment inner = default_texture_.pigment;
            parse_pigment_body(inner, terminator);
            p.pattern = PatternSpec{};
            p.pattern.edit().kind = PatternKind::UvMapping;
            p.maps = PigmentMaps{};
            p.maps.edit().list.push_back(std::move(inner));
            return;
        } else {
            expected("a pigment item or '}'", t);
        }
    }
}

Normal Interpreter::parse_normal_block() {
    expect_punct('{', "after 'normal'");
    Normal n;
    if (default_texture_.normal) n = *default_texture_.normal;
    parse_normal_body(n, '}');
    return n;
}

// `normal { ... }` after the keyword, editing the texture's normal in place; a texture
// without one starts from the default texture's normal (POV-Ray's Parse_Tnormal).
void Interpreter::parse_normal_into(HeapOptional<Normal>& n) {
    if (!n) {
        n = parse_normal_block();
        return;
    }
    expect_punct('{', "after 'normal'");
    parse_normal_body(*n, '}');
}

// The inside of `normal { ... }`, also a normal_map entry (ending at ']').
void Interpreter::parse_normal_body(Normal& n, char terminator) {
    const Token& first = peek();
    NestingGuard guard(*this, first);  // maps of maps of ...
    if (first.kind == TokenKind::Word) {
        const Value* v = lookup(first);
        if (v && std::holds_alternative<std::shared_ptr<Normal>>(*v)) {
            next();
            n = *std::get<std::shared_ptr<Normal>>(*v);
        }
    }
    // Without a pattern first, POV-Ray still reads `[,] amount`: `normal { N 0.3 }`.
    if (is_punct(peek(), ',') || starts_float(peek())) {
        accept_punct(',');
        if (starts_float(peek())) n.amount = parse_float();
    }
    for (;;) {
        Token t = next();
        if (is_punct(t, terminator)) {
            // POV-Ray has no facets value to look a map up with: it stops rendering
            // ("Problem in Evaluate_TPat").
            if (n.pattern->kind == PatternKind::Facets && !n.map_values.empty())
                error(t, "facets cannot select from a normal_map");
            finish_pavement(n.pattern, t);
            if (n.pattern->no_bump_scale) set_no_bump_scale(n);
            return;
        }
        // facets is a pattern of normals only (try_pattern_keyword refuses it).
        const bool facets = is_word(t, "facets");
        if (facets) {
            PatternSpec& spec = n.pattern.edit();
            spec.kind = PatternKind::Facets;
            spec.facets = {};
        }
        if (facets || try_pattern_keyword(t, n.pattern)) {
            const bool object_pattern = n.pattern->kind == PatternKind::ObjectInside;
            if (const int count = entry_list_size(n.pattern->kind)) {
                // checker normal{..} normal{..}: entries follow the keyword and replace
                // the map an earlier block gave; once one is given, the missing ones are
                // the #default normal (without one POV-Ray crashes on them: refused).
                n.list.clear();
                n.map_values.clear();
                for (int i = 0; i < count; ++i) {
                    if (i == 0 && !is_word(peek(), "normal")) break;
                    if (accept_word("normal")) {
                        n.list.push_back(parse_normal_block());
                        accept_punct(',');  // after each entry, the last one too
                    } else {
                        if (!default_texture_.normal)
                            error(t, "give all " + std::to_string(count) +
                                         " normals of '" + std::string(t.text) +
                                         "' (POV-Ray 3.7 crashes on the missing ones)");
                        n.list.push_back(*default_texture_.normal);
                    }
                    n.map_values.push_back(float(i));
                }
                if (object_pattern) expect_punct('}', "to close the object pattern");
            }
            // `bumps 0.5`, `gradient x, 5.6`: an optional bump size follows the pattern.
            accept_punct(',');
            if (starts_float(peek())) n.amount = parse_single();
            continue;
        }
        if (try_pattern_modifier(t, n.pattern)) continue;
        if (is_word(t, "bump_size")) {
            n.amount = parse_single();
        } else if (is_word(t, "accuracy")) {
            n.accuracy = parse_single();
        } else if (is_word(t, "normal_map")) {
            expect_punct('{', "after 'normal_map'");
            n.list.clear();
            n.map_values.clear();
            for (;;) {
                Token e = next();
                if (is_punct(e, '}')) break;
                if (!is_punct(e, '[')) expected("'[' or '}' in a normal_map", e);
                float value = parse_map_value(n.pattern->kind == PatternKind::Average);
                accept_punct(',');
                Normal sub;
                if (accept_word("normal")) {
                    sub = parse_normal_block();
                    expect_punct(']', "to close the normal_map entry");
                } else {
                    // An entry starts from the #default normal, as a normal { } does.
                    if (default_texture_.normal) sub = *default_texture_.normal;
                    parse_normal_body(sub, ']');
                }
                n.map_values.push_back(value);
                n.list.push_back(std::move(sub));
            }
        } else if (is_word(t, "slope_map")) {
            expect_punct('{', "after 'slope_map'");
            n.slope_map.clear();
            for (;;) {
                Token e = next();
                if (is_punct(e, '}')) break;
                if (!is_punct(e, '[')) expected("'[' or '}' in a slope_map", e);
                SlopeMapEntry entry{parse_map_value(false), 0, 0};
                accept_punct(',');
                Numeric hs = parse_express();
                entry.height = hs.c[0];
                entry.slope = hs.size == 1 ? hs.c[0] : hs.c[1];
                expect_punct(']', "to close the slope_map entry");
                n.slope_map.push_back(entry);
            }
        } else if (is_word(t, "bump_map")) {
            n.pattern.edit().kind = PatternKind::ImageMap;
            n.pattern.edit().image = parse_image_block(t, &n);
        } else if (is_word(t, "uv_mapping")) {
            // The rest of the block is one normal, at the surface coordinates.
            Normal inner;
            if (default_texture_.normal) inner = *default_texture_.normal;
            parse_normal_body(inner, terminator);
            n = Normal{};
            n.pattern.edit().kind = PatternKind::UvMapping;
            n.list.push_back(std::move(inner));
            return;
        } else {
            expected("a normal item or '}'", t);
        }
    }
}

// A finish equal to the last one parsed shares its object: a loop that writes the same
// finish for each of its objects keeps one, not one per object.
SharedValue<Finish> Interpreter::shared_finish(const Finish& f) {
    if (!last_finish_.allocated() || !(*last_finish_ == f)) last_finish_ = f;
    return last_finish_;
}

Finish Interpreter::parse_finish_block() {
    Finish f = *default_texture_.finish;
    parse_finish_into(f);
    return f;
}

void Interpreter::parse_finish_into(SharedValue<Finish>& finish) {
    Finish f = *finish;
    parse_finish_into(f);
    finish = shared_finish(f);
}

// `finish { ... }` after the keyword, editing `f` in place (POV-Ray's Parse_Finish): a
// second finish block continues from the first; a finish identifier is read only as the
// first item and replaces what `f` held. The albedo forms are scaled at the end of the
// block, by the brilliance, phong_size and roughness it ends with.
void Interpreter::parse_finish_into(Finish& f) {
    expect_punct('{', "after 'finish'");
    const Token& first = peek();
    if (first.kind == TokenKind::Word) {
        const Value* v = lookup(first);
        if (v && std::holds_alternative<std::shared_ptr<Finish>>(*v)) {
            next();
            f = *std::get<std::shared_ptr<Finish>>(*v);
        }
    }
    auto rgb_of = [](const Numeric& n) {
        if (n.size == 1) return Rgb(float(n.c[0]));
        return Rgb(float(n.c[0]), float(n.c[1]), float(n.c[2]));
    };
    bool diffuse_albedo = false, phong_albedo = false, specular_albedo = false;
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) break;
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        if (w == "ambient") {
            f.ambient = rgb_of(parse_colour());
        } else if (w == "emission") {
            f.emission = rgb_of(parse_colour());
        } else if (w == "diffuse") {
            diffuse_albedo = accept_word("albedo") || diffuse_albedo;
            f.diffuse = float(parse_float());
            accept_punct(',');  // `diffuse a[,] [back]`
            f.diffuse_back = starts_float(peek()) ? float(parse_float()) : 0.0f;
        } else if (w == "brilliance") {
            f.brilliance = float(parse_float());
        } else if (w == "crand") {
            f.crand = float(parse_float());
        } else if (w == "phong") {
            phong_albedo = accept_word("albedo") || phong_albedo;
            f.phong = float(parse_float());
        } else if (w == "phong_size") {
            f.phong_size = float(parse_float());
        } else if (w == "specular") {
            specular_albedo = accept_word("albedo") || specular_albedo;
            f.specular = float(parse_float());
        } else if (w == "roughness") {
            f.roughness = float(parse_float());
        } else if (w == "metallic") {
            f.metallic = starts_float(peek()) ? float(parse_float()) : 1.0f;
        } else if (w == "reflection") {
            if (accept_punct('{')) {
                Rgb a = rgb_of(parse_colour());
                Rgb b = a;
                bool two = false;
                // reflection { min[,] [max] ...}
                accept_punct(',');
                if (starts_expression(peek())) {
                    b = rgb_of(parse_colour());
                    two = true;
                }
                f.reflection_min = a;
                f.reflection_max = b;
                for (;;) {
                    Token m = next();
                    if (is_punct(m, '}')) break;
                    if (is_word(m, "fresnel")) {
                        f.reflection_fresnel = parse_bool_opt();
                    } else if (is_word(m, "falloff")) {
                        f.reflection_falloff = float(parse_float());
                    } else if (is_word(m, "exponent")) {
                        f.reflection_exponent = float(parse_float());
                    } else if (is_word(m, "metallic")) {
                        f.reflection_metallic =
                            starts_float(peek()) ? float(parse_float()) : 1.0f;
                    } else {
                        expected("a reflection item or '}'", m);
                    }
                }
                if (f.reflection_fresnel && !two) f.reflection_min = Rgb(0.0f);
            } else {
                Rgb c = rgb_of(parse_colour());
                f.reflection_min = c;
                f.reflection_max = c;
            }
        } else if (w == "reflection_exponent") {
            f.reflection_exponent = float(parse_float());
        } else if (w == "conserve_energy") {
            f.conserve_energy = parse_bool_opt();
        } else if (w == "irid") {
            expect_punct('{');
            f.irid = float(parse_float());
            for (;;) {
                Token m = next();
                if (is_punct(m, '}')) break;
                if (is_word(m, "thickness"))
                    f.irid_thickness = float(parse_float());
                else if (is_word(m, "turbulence"))
                    f.irid_turbulence = float(parse_float());
                else
                    expected("an irid item or '}'", m);
            }
        } else if (w == "ior") {
            // POV-Ray 3.7 still reads these old finish items (with a warning) and moves
            // them into the object's interior when it is placed (finish_object).
            f.legacy_ior = float(parse_float());
            warn(t, "the index of refraction belongs in interior { }");
        } else if (w == "caustics") {
            f.legacy_caustics = float(parse_float());
            warn(t, "caustics belong in interior { }");
        } else if (w == "refraction") {
            f.legacy_refraction = float(parse_float());
            warn(t,
                 "refraction is not needed to turn refraction on; it scales what "
                 "passes the surface");
        } else if (w == "subsurface") {
            f.subsurface = true;
            if (!subsurface_finish_at_) subsurface_finish_at_ = t;
            expect_punct('{', "after 'subsurface'");
            for (;;) {
                Token m = next();
                if (is_punct(m, '}')) break;
                if (is_word(m, "translucency")) {
                    f.translucency = parse_colour_value().rgb;
                } else if (is_word(m, "anisotropy")) {
                    f.anisotropy = parse_colour_value().rgb;
                } else {
                    expected("translucency, anisotropy or '}'", m);
                }
            }
            // The free path divides: 0 (the default) or less in a channel is a NaN
            // there, which POV-Ray aborts on.
            if (!(f.translucency.r > 0 && f.translucency.g > 0 && f.translucency.b > 0))
                error(t, "subsurface needs a translucency above 0 in every channel");
        } else {
            expected("a finish item or '}'", t);
        }
    }
    f.raw_diffuse = f.diffuse;
    f.raw_diffuse_back = f.diffuse_back;
    if (diffuse_albedo) {
        f.diffuse *= (f.brilliance + 1) / 2;
        f.diffuse_back *= (f.brilliance + 1) / 2;
    }
    if (phong_albedo) f.phong *= (f.phong_size + 1) / 2;
    if (specular_albedo) {
        // POV-Ray keeps 1/roughness.
        const double r = f.roughness != 0 ? 1.0 / f.roughness : 0.0;
        f.specular = float(f.specular * (r + 2) / (4 * (2 - std::pow(2.0, -r / 2))));
    }
}

Interior Interpreter::parse_interior_block() {
    Interior in;
    parse_interior_into(in);
    return in;
}

// `interior { ... }` on an object or in a material: a second block edits the first
// (POV-Ray's Parse_Interior).
void Interpreter::parse_interior_into(HeapOptional<Interior>& in) {
    if (!in) in = Interior();
    parse_interior_into(*in);
}

void Interpreter::parse_interior_into(Interior& in) {
    expect_punct('{', "after 'interior'");
    const Token& first = peek();
    if (first.kind == TokenKind::Word) {
        const Value* v = lookup(first);
        if (v && std::holds_alternative<std::shared_ptr<Interior>>(*v)) {
            next();
            in = *std::get<std::shared_ptr<Interior>>(*v);
        }
    }
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) return;
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        if (w == "ior") {
            in.ior = float(parse_float());
            in.ior_set = true;
        } else if (w == "caustics")
            in.caustics = float(parse_float() * 45.0);  // as POV-Ray scales it
        else if (w == "dispersion")
            in.dispersion = float(parse_float());
        else if (w == "dispersion_samples") {
            const Token at = peek();
            in.dispersion_samples = parse_int();
            if (in.dispersion_samples < 2) error(at, "dispersion samples minimum is 2");
            // (A band's index travels in 16 bits; POV-Ray has no limit.)
            if (in.dispersion_samples > 65535)
                unsupported(at, "dispersion_samples above 65535");
        } else if (w == "refraction") {
            in.old_refract = float(parse_float());
            warn(t,
                 "refraction is not needed to turn refraction on; it scales what "
                 "passes the surface");
        } else if (w == "fade_distance")
            in.fade_distance = float(parse_float());
        else if (w == "fade_power")
            in.fade_power = float(parse_float());
        else if (w == "fade_color" || w == "fade_colour") {
            Colour c = parse_colour_value();
            in.fade_colour = c.rgb;
        } else if (w == "media") {
            in.media.push_back(parse_media());
        } else {
            expected("an interior item or '}'", t);
        }
    }
}

// `density { ... }` after the keyword: a pigment that starts empty, black (no medium)
// unless a pattern or colour is given, as POV-Ray's.
Pigment Interpreter::parse_density_block() {
    Pigment d;
    d.colour = Colour{};
    const Token at = peek();
    expect_punct('{', "after 'density'");
    parse_pigment_body(d, '}');
    refuse_uv_mapping(d, at, "a media density");
    return d;
}

// `media { ... }` (POV-Ray 3.7's Parse_Media): an interior's or the atmosphere's.
Media Interpreter::parse_media() {
    expect_punct('{', "after 'media'");
    Media m;
    const Token& first = peek();
    const Value* declared = first.kind == TokenKind::Word ? lookup(first) : nullptr;
    if (declared && std::holds_alternative<std::shared_ptr<Media>>(*declared)) {
        // A copy of the declared media, version defaults and all (POV-Ray's).
        next();
        m = *std::get<std::shared_ptr<Media>>(*declared);
    } else if (language_version() < 350) {  // decided per block, as POV-Ray decides it
        m.method = 1;
        m.intervals = 10;
        m.samples_min = m.samples_max = 1;
    }
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) break;
        Transform tr;
        if (try_transform(t, tr)) {
            // Moves the densities given so far only, as POV-Ray's.
            for (Pigment& d : m.density) transform_pigment(d, tr);
            continue;
        }
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        const Token at = peek();
        if (w == "method") {
            m.method = parse_int();
            if (m.method < 1 || m.method > 3) error(at, "media method must be 1, 2 or 3");
        } else if (w == "intervals") {
            m.intervals = parse_int();
            if (m.intervals < 1) error(at, "at least one interval is needed");
            if (m.intervals > 10000) unsupported(at, "media intervals above 10000");
        } else if (w == "samples") {
            m.samples_min = parse_int();
            m.samples_max = m.samples_min;
            if (accept_punct(',')) {
                const Token max_at = peek();
                m.samples_max = parse_int();
                if (m.samples_max < m.samples_min)
                    error(max_at, "maximum samples must not be below the minimum");
            }
            if (m.samples_min < 1) error(at, "at least one sample is needed");
            if (m.samples_max > 10000) unsupported(at, "media samples above 10000");
        } else if (w == "jitter") {
            m.jitter = float(parse_float());
        } else if (w == "aa_threshold") {
            m.aa_threshold = float(parse_float());
            if (!(m.aa_threshold > 0)) error(at, "aa_threshold must be above 0");
        } else if (w == "aa_level") {
            m.aa_level = parse_int();
            if (m.aa_level < 1) error(at, "aa_level must be at least 1");
            if (m.aa_level > 30) unsupported(at, "media aa_level above 30");
        } else if (w == "confidence") {
            m.confidence = float(parse_float());
            if (!(m.confidence >= 0 && m.confidence < 1))
                error(at, "confidence must be at least 0 and below 1");
        } else if (w == "variance") {
            m.variance = float(parse_float());
        } else if (w == "ratio") {
            m.ratio = float(parse_float());
        } else if (w == "collect") {
            m.collect = parse_bool_opt();
        } else if (w == "absorption") {
            m.absorption = parse_colour_value().rgb;
        } else if (w == "emission") {
            m.emission = parse_colour_value().rgb;
        } else if (w == "scattering") {
            // scattering { type, colour [eccentricity e] [extinction x] }
            expect_punct('{', "after 'scattering'");
            m.scattering_loc = sources_.location(t);
            const Token type_at = peek();
            m.scattering_type = parse_int();
            if (m.scattering_type < 1 || m.scattering_type > 5)
                warn(type_at, "unknown atmospheric scattering type");  // as type 1
            accept_punct(',');
            m.scattering = parse_colour_value().rgb;
            for (;;) {
                const Token k = next();
                if (is_punct(k, '}')) break;
                const std::string_view kw =
                    k.kind == TokenKind::Word ? k.text : std::string_view();
                if (kw == "eccentricity") {
                    if (m.scattering_type != 5)
                        error(k, "eccentricity only applies to scattering type 5");
                    m.eccentricity = float(parse_float());
                } else if (kw == "extinction") {
                    m.scattering_extinction = float(parse_float());
                } else {
                    expected("eccentricity, extinction or '}'", k);
                }
            }
        } else if (w == "density") {
            m.density.push_back(parse_density_block());
        } else {
            expected("a media item or '}'", t);
        }
    }
    // POV-Ray's variance test never runs with one sample; with more it needs its
    // chi-square table, which povwall has not yet.
    if (m.method != 3 && m.samples_max > m.samples_min && m.samples_min >= 2)
        unsupported(peek(), "media samples with a maximum above the minimum");
    return m;
}

LayeredTexture Interpreter::parse_texture_block() {
    expect_punct('{', "after 'texture'");
    LayeredTexture layers;
    parse_texture_body(layers, '}');
    return layers;
}

// The inside of `texture { ... }`; also a texture_map entry (ending at ']').
void Interpreter::parse_texture_body(LayeredTexture& layers, char terminator) {
    // Below version 3.0 POV-Ray reads pigment, normal and finish items written straight
    // in the texture (Parse_Vers1_Texture, parser/texture_vers1.cpp).
    if (language_version() < 300) {
        parse_vers1_texture_body(layers, terminator);
        return;
    }
    const Token& first = peek();
    NestingGuard guard(*this, first);  // maps of maps of ...
    if (first.kind == TokenKind::Word) {
        const Value* v = lookup(first);
        if (v && std::holds_alternative<std::shared_ptr<LayeredTexture>>(*v)) {
            next();
            layers = *std::get<std::shared_ptr<LayeredTexture>>(*v);
        }
    }
    if (layers.empty()) layers.push_back(default_texture_);
    // POV-Ray flags the texture statement's first layer (the top one).
    bool no_bump_scale = false;
    for (;;) {
        Token t = next();
        if (is_punct(t, terminator)) {
            if (layers.back().map_pattern) finish_pavement(*layers.back().map_pattern, t);
            if (no_bump_scale) set_no_bump_scale(layers.back());
            return;
        }
        Transform tr;
        if (try_transform(t, tr)) {
            transform_textures(layers, tr);
            continue;
        }
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        Texture& top = layers.back();
        // pigment, normal and finish edit what the texture holds (from its identifier
        // or the default texture), so a second block continues from the first.
        if (w == "pigment") {
            parse_pigment_into(top.pigment);
        } else if (w == "finish") {
            parse_finish_into(top.finish);
        } else if (w == "normal") {
            parse_normal_into(top.normal);
        } else if (const Value* v = t.kind == TokenKind::Word ? lookup(t) : nullptr;
                   v && !top.map_pattern &&
                   (std::holds_alternative<std::shared_ptr<Pigment>>(*v) ||
                    std::holds_alternative<std::shared_ptr<Finish>>(*v) ||
                    std::holds_alternative<std::shared_ptr<Normal>>(*v))) {
            // The old form `texture { P_Id F_Id }` replaces the part.
            if (auto p = std::get_if<std::shared_ptr<Pigment>>(v)) top.pigment = **p;
            if (auto f = std::get_if<std::shared_ptr<Finish>>(v))
                top.finish = shared_finish(**f);
            if (auto n = std::get_if<std::shared_ptr<Normal>>(v)) top.normal = **n;
        } else if (w == "texture_map") {
            if (!top.map_pattern) expected("a pattern before texture_map", t);
            expect_punct('{', "after 'texture_map'");
            top.map.edit().entries.clear();
            top.map.edit().values.clear();
            for (;;) {
                Token e = next();
                if (is_punct(e, '}')) break;
                if (!is_punct(e, '[')) expected("'[' or '}' in a texture_map", e);
                float value =
                    parse_map_value(top.map_pattern->kind == PatternKind::Average);
                accept_punct(',');
                LayeredTexture entry;
                if (accept_word("texture")) {
                    entry = parse_texture_block();
                    expect_punct(']', "to close the texture_map entry");
                } else {
                    parse_texture_body(entry, ']');
                }
                top.map.edit().values.push_back(value);
                top.map.edit().entries.push_back(std::move(entry));
            }
        } else if (w == "uv_mapping") {
            // The rest of the block is one texture, at the surface coordinates; the
            // transforms of its object move nothing but the normals' frame (POV-Ray
            // keeps them on this pattern, which it never warps the point by).
            LayeredTexture inner;
            parse_texture_body(inner, terminator);
            Texture uv;
            uv.map_pattern = PatternSpec{};
            uv.map_pattern->kind = PatternKind::UvMapping;
            uv.map.edit().entries.push_back(std::move(inner));
            if (no_bump_scale) set_no_bump_scale(uv);
            layers.assign(1, std::move(uv));
            return;
        } else if (w == "no_bump_scale") {
            // Handed to the normals when the texture ends, whatever comes after it.
            no_bump_scale = true;
        } else if (w == "material_map") {
            parse_material_map(t, top);
        } else if (w == "tiles") {
            parse_tiles(t, layers);
            if (no_bump_scale) set_no_bump_scale(layers.back());
            parse_texture_transforms(layers, terminator);
            return;
        } else if (top.map_pattern && try_pattern_modifier(t, *top.map_pattern)) {
            continue;
        } else {
            PatternSpec spec;
            if (t.kind == TokenKind::Word && try_pattern_keyword(t, spec)) {
                top.map_pattern = spec;
                const bool object_pattern = spec.kind == PatternKind::ObjectInside;
                if (const int count = entry_list_size(spec.kind)) {
                    // checker texture{..} texture{..}: entries follow the keyword; the
                    // missing ones are the default texture.
                    top.map.edit().entries.clear();
                    top.map.edit().values.clear();
                    for (int i = 0; i < count; ++i) {
                        if (accept_word("texture")) {
                            top.map.edit().entries.push_back(parse_texture_block());
                            accept_punct(',');  // after each entry, the last one too
                        } else {
                            top.map.edit().entries.push_back({default_texture_});
                        }
                        top.map.edit().values.push_back(float(i));
                    }
                    if (object_pattern) expect_punct('}', "to close the object pattern");
                }
                continue;
            }
            expected("a texture item or '" + std::string(1, terminator) + "'", t);
        }
    }
}

// The old checker of textures: `tiles { texture {..}.. tile2 texture {..}.. }`, the
// first ones on the checker's odd squares; it replaces `layers`.
void Interpreter::parse_tiles(const Token& keyword, LayeredTexture& layers) {
    PatternSpec checker;
    checker.kind = PatternKind::Checker;
    checker.frequency = 0;
    TextureMap map;
    map.values = {0, 1};
    map.entries.resize(2);
    expect_punct('{', "after 'tiles'");
    while (accept_word("texture")) {
        LayeredTexture layer = parse_texture_block();
        map.entries[1].insert(map.entries[1].end(), layer.begin(), layer.end());
    }
    const Token tile2 = next();
    if (!is_word(tile2, "tile2")) expected("'tile2'", tile2);
    while (accept_word("texture")) {
        LayeredTexture layer = parse_texture_block();
        map.entries[0].insert(map.entries[0].end(), layer.begin(), layer.end());
    }
    expect_punct('}', "to close 'tiles'");
    if (map.entries[1].empty()) error(keyword, "First texture missing from tiles");
    if (map.entries[0].empty()) map.entries[0].push_back(default_texture_);
    Texture tiles;
    tiles.map_pattern = checker;
    tiles.map = map;
    layers = {std::move(tiles)};
}

// Transforms only, up to the terminator (after tiles; POV-Ray's Parse_Texture_Transform).
void Interpreter::parse_texture_transforms(LayeredTexture& layers, char terminator) {
    for (;;) {
        Token m = next();
        if (is_punct(m, terminator)) return;
        if (is_word(m, "no_bump_scale")) {
            set_no_bump_scale(layers.back());
            continue;
        }
        Transform step;
        if (!try_transform(m, step))
            expected("a transform or '" + std::string(1, terminator) + "'", m);
        transform_textures(layers, step);
    }
}

}  // namespace povwall::parser
