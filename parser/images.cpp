// image_map { }, bump_map { }, image_pattern { } and material_map { }: the file
// reference, POV-Ray 3.7's input gamma rules and the mapping attributes. Pixels come from
// ParseOptions::image_reader (the parser itself has no image library); without one, only
// the reference is recorded.
#include <cmath>
#include <filesystem>

#include "core/memory.h"
#include "parser/image_file_types.h"
#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

namespace fs = std::filesystem;

// A transfer curve an image's values are encoded with.
struct Curve {
    enum class Kind { Neutral, Srgb, Power } kind = Kind::Neutral;
    float decoding_exponent = 1;  // Power: linear = encoded^exponent
    float decode(float v) const {
        switch (kind) {
            case Kind::Srgb:
                return v <= 0.04045f ? v / 12.92f
                                     : float(std::pow((v + 0.055) / 1.055, 2.4));
            case Kind::Power:
                return v <= 0 ? v : float(std::pow(double(v), double(decoding_exponent)));
            default:
                return v;
        }
    }
};

Curve power(float exponent) { return {Curve::Kind::Power, exponent}; }
Curve curve_of(const GammaCurve& g) {
    return g.kind == GammaCurve::Kind::Srgb ? Curve{Curve::Kind::Srgb, 1}
                                            : power(g.decoding_exponent);
}

}  // namespace

GammaCurve Interpreter::parse_gamma() {
    if (accept_word("srgb")) return GammaCurve::srgb();
    const Token at = peek();
    const float g = float(parse_float());
    if (!(g > 0)) error(at, "gamma value must be positive.");
    // Below 1 it is likely an encoding gamma where the decoding one is asked for (not
    // said in a scene without gamma handling, where such values make sense).
    if (g < 1 && gamma_mode_ != GammaMode::None) {
        char text[96];
        std::snprintf(text, sizeof text,
                      "Suspicious value %g specified for gamma. Did you mean %g?",
                      double(g), 1.0 / double(g));
        warn(at, text);
    }
    return GammaCurve::power(g);
}

Interpreter::ImageFileRef Interpreter::parse_image_file_ref(bool height_field) {
    ImageFileRef ref;
    ref.type_token = peek();
    ref.type = image_type_for_keyword(ref.type_token.kind == TokenKind::Word
                                          ? ref.type_token.text
                                          : std::string_view());
    if (ref.type) next();
    ref.name_token = peek();
    if (!ref.type) ref.type_token = ref.name_token;
    const std::string name = parse_string();
    if (!ref.type) {
        const std::string extension = fs::path(name).extension().string();
        if (!extension.empty()) {
            ref.type = image_type_for_extension(extension);
            if (!ref.type)
                error(ref.name_token,
                      "Could not determine valid image file type from extension.");
        } else {
            ref.type = image_type_for_output_letter(options_.output_file_type);
            if (!ref.type)
                error(ref.name_token,
                      "Could not determine valid input file type from output type.");
        }
    }
    // POV-Ray's masks of legal types: height fields take `pot` but not `iff`, images the
    // other way round.
    const std::string_view kind = ref.type->keyword;
    if (kind == (height_field ? "iff" : "pot"))
        error(ref.type_token, "File type not supported here.");
    for (const std::string& candidate : image_file_candidates(name, *ref.type)) {
        ref.path = resolve_include(candidate, frames_.back().file, false);
        if (!ref.path.empty()) break;
    }
    if (ref.path.empty())
        error(ref.name_token, "cannot find image file \"" + name + "\"");
    // Unix builds of POV-Ray 3.7 define no system image format.
    if (kind == "sys")
        error(ref.type_token, "This platform has not defined a SYS file type");
    // POV-Ray 3.7's IFF reader reads chunks until the file ends, and fails there: no IFF
    // file loads (iff.cpp's Read; an ILBM of 8 colours fails as any other file).
    if (kind == "iff")
        error(ref.name_token,
              "Unexpected EOF while reading IFF file (POV-Ray 3.7 reads no IFF image)");
    return ref;
}

std::shared_ptr<const ImageMapping> Interpreter::parse_image_block(const Token& keyword,
                                                                   Normal* bump,
                                                                   ImageBlock block) {
    if (bump) block = ImageBlock::BumpMap;
    expect_punct('{', "after '" + std::string(keyword.text) + "'");
    // Only image_map decodes the file's gamma by default: the others read heights,
    // grey values or indices (POV-Ray's Parse_Image without GammaCorrect).
    const bool raw = block != ImageBlock::ImageMap;
    if (accept_word("function")) {
        auto mapping = std::make_shared<ImageMapping>();
        const FunctionImage image = parse_function_image(keyword.text);
        mapping->width = image.width;
        mapping->height = image.height;
        auto pixels = function_image_pixels(image);
        mapping->pixels = pixels;
        parse_image_options(keyword, block, bump, *mapping, pixels, image.channels == 4,
                            false);
        return mapping;
    }
    // POV-Ray 1.0's orientation vector before the file type: warned and dropped
    // (Parse_Image of image maps, bump maps, image patterns and material maps).
    if (const Token v = peek();
        is_punct(v, '<') || (v.kind != TokenKind::String && starts_float(v))) {
        warn(v,
             "Old style orientation vector or map type not supported. Ignoring value.");
        parse_vector();
    }
    const ImageFileRef ref = parse_image_file_ref(false);
    const std::string& path = ref.path;
    const Token& name_token = ref.name_token;

    // Optional decoding gamma and premultiplication right after the name.
    std::optional<Curve> explicit_gamma;
    std::optional<bool> premultiplied;
    for (;;) {
        if (accept_word("gamma")) {
            explicit_gamma = curve_of(parse_gamma());
        } else if (accept_word("premultiplied")) {
            premultiplied = int(parse_float()) != 0;  // POV-Ray's (int)Parse_Float()
        } else {
            break;
        }
    }

    auto mapping = std::make_shared<ImageMapping>();
    mapping->path = path;
    image_files_.push_back(path);
    bool colour_mapped = false;
    bool has_alpha = false;  // the file has an alpha channel (or palette transparency)
    std::shared_ptr<ImagePixels> pixels;  // editable while the block is read
    if (options_.image_reader) {
        StoredImage stored;
        try {
            stored = options_.image_reader(path);
        } catch (const std::exception& e) {
            error(name_token, e.what());
        }
        if (!image_format_matches(*ref.type, stored.format))
            error(name_token, "Cannot read image: not a " +
                                  std::string(ref.type->keyword) + " file (it reads as " +
                                  stored.format + ")");
        // POV-Ray 3.7's gamma modes, as the parse has them when the file is read:
        // legacy scenes (no assumed_gamma, effective version < 3.7) read images raw; 3.6
        // scenes with assumed_gamma take files to be in the working gamma; 3.7 scenes
        // decode with the file type's gamma. bump_map reads raw unless a gamma is given
        // (POV-Ray treats its data as heights, not colours).
        const GammaCurve working = scene_.settings.assumed_gamma.value_or(GammaCurve{});
        bool correct = gamma_mode_ != GammaMode::None && !raw;
        std::optional<Curve> fallback;  // POV-Ray's options.defaultGamma
        if (correct && gamma_mode_ == GammaMode::Assumed36) fallback = curve_of(working);
        if (explicit_gamma) {
            correct = true;
            fallback = explicit_gamma;
        }
        Curve file;
        if (correct) {
            const std::string& f = stored.format;
            if (f == "pnm" || f == "tiff") {
                // Netpbm and TIFF files are decoded only with a gamma assumed (3.6 mode)
                // or given; otherwise their values are working-space values as they are.
                if (fallback)
                    file = *fallback;
                else
                    correct = false;
            } else if (f == "openexr" || f == "hdr") {
                // HDR formats are linear unless a gamma is given.
                if (explicit_gamma) file = *fallback;
            } else if (f == "png" && !explicit_gamma && stored.declared_gamma > 0) {
                file = power(stored.declared_gamma);
            } else {
                file = fallback ? *fallback : Curve{Curve::Kind::Srgb, 1};
            }
        }
        // Decoded values are re-encoded in the working gamma (image_map only); a file
        // encoded with the working curve itself is read as it is (POV-Ray's transcoding
        // between matching curves is the identity).
        const bool srgb_working = working.kind == GammaCurve::Kind::Srgb;
        bool encode_working = correct && !raw && !working.is_linear();
        if (encode_working && file.kind != Curve::Kind::Neutral &&
            working.matches(file.kind == Curve::Kind::Srgb
                                ? GammaCurve::srgb()
                                : GammaCurve::power(file.decoding_exponent))) {
            correct = false;
            encode_working = false;
        }
        auto decode = [&](float v) {
            v = correct ? file.decode(v) : v;
            if (encode_working)
                v = srgb_working ? working.encode(v)
                    : v > 0 ? float(std::pow(double(v), 1.0 / working.decoding_exponent))
                            : v;
            return v;
        };
        const size_t count = size_t(stored.pixels.width) * size_t(stored.pixels.height);
        // The samples of an 8- or 16-bit file are k * (1 / (2^bits - 1)): each value is
        // decoded once (a 4096x2048 texture made 25 M calls of pow), for a 16-bit file
        // when it has more samples than values; a sample not of that form is decoded
        // itself.
        std::vector<float> decoded;
        const int top =
            stored.bits == 8 || stored.bits == 16 ? (1 << stored.bits) - 1 : 0;
        const float step = top ? 1.0f / float(top) : 0.0f;
        if (top && !stored.float_data && (top == 255 || count * 3 > size_t(top))) {
            decoded.resize(size_t(top) + 1);
            for (int k = 0; k <= top; ++k) decoded[size_t(k)] = decode(float(k) * step);
        }
        // The k of a sample k * step; -1 when it is none.
        auto code_of = [&](float v) {
            const int k = v >= 0 && v <= 1 ? int(v * float(top) + 0.5f) : -1;
            return k >= 0 && float(k) * step == v ? k : -1;
        };
        auto decode_sample = [&](float v) {
            const int k = decoded.empty() ? -1 : code_of(v);
            return k >= 0 ? decoded[size_t(k)] : decode(v);
        };
        auto px = std::make_shared<ImagePixels>();
        px->width = stored.pixels.width;
        px->height = stored.pixels.height;
        // An 8-bit file's pixels as codes (ImagePixels): every sample must be a code's
        // value exactly; a palette file keeps floats (filter and transmit per entry).
        if (decoded.size() == 256 && !stored.colour_mapped) {
            resize_on_huge_pages(px->codes, count * 4);
            for (size_t i = 0; i < count * 4 && !px->codes.empty(); ++i) {
                const int k = code_of(stored.pixels.rgba[i]);
                if (k < 0)
                    px->codes.clear();
                else
                    px->codes[i] = uint8_t(k);
            }
            std::copy(decoded.begin(), decoded.end(), px->decoded.begin());
            px->codes_alpha = stored.has_alpha;
        }
        if (px->codes.empty()) {
            resize_on_huge_pages(px->rgbft, count * 5);
            for (size_t i = 0; i < count; ++i) {
                const float* s = &stored.pixels.rgba[i * 4];
                float* d = &px->rgbft[i * 5];
                for (int c = 0; c < 3; ++c) d[c] = decode_sample(s[c]);
                d[3] = 0;
                d[4] = stored.has_alpha ? 1.0f - s[3] : 0.0f;
            }
        }
        stored.pixels = Image();  // the parse's copy of the file is done with
        colour_mapped = stored.colour_mapped;
        has_alpha = stored.has_alpha;
        // POV-Ray's TIFF and OpenEXR readers keep the colours premultiplied (so does any
        // reader told `premultiplied on`), and its image_map divides them back.
        mapping->premultiplied =
            premultiplied.value_or(stored.format == "tiff" || stored.format == "openexr");
        px->indices = std::move(stored.indices);
        px->palette_size = stored.palette_size;
        pixels = px;
        mapping->pixels = std::move(px);
        mapping->width = mapping->pixels->width;
        mapping->height = mapping->pixels->height;
    }

    parse_image_options(keyword, block, bump, *mapping, pixels, has_alpha, colour_mapped);
    return mapping;
}

void Interpreter::parse_image_options(const Token& keyword, ImageBlock block,
                                      Normal* bump, ImageMapping& mapping,
                                      const std::shared_ptr<ImagePixels>& pixels,
                                      bool has_alpha, bool colour_mapped) {
    const bool is_bump = bump != nullptr;
    const bool is_pattern = block == ImageBlock::ImagePattern;
    const bool is_material = block == ImageBlock::MaterialMap;
    std::optional<Token> use_index_at;
    auto uv = [&]() {
        Numeric n = parse_express();
        return n.size == 1 ? std::pair{n.c[0], n.c[0]} : std::pair{n.c[0], n.c[1]};
    };
    for (;;) {
        Token t = next();
        if (is_punct(t, '}')) break;
        std::string_view w = t.kind == TokenKind::Word ? t.text : std::string_view();
        if (is_material && w == "texture") {  // the textures follow
            unget(t);
            break;
        }
        if (w == "once") {
            mapping.once = true;
        } else if (w == "interpolate") {
            Token at = peek();
            mapping.interpolate = parse_int();
            if (block == ImageBlock::ImageMap && mapping.interpolate != 2 &&
                mapping.interpolate != 3 && mapping.interpolate != 4)
                error(at, "invalid interpolate value (2, 3 or 4)");
        } else if (w == "map_type") {
            Token at = peek();
            mapping.map_type = parse_int();
            // POV-Ray 3.7.0's map types: 0 planar, 1 spherical, 2 cylindrical, 5 torus
            // (7, angular, came later). Only image_map checks it (Parse_Image_Map): a
            // bump_map, image_pattern or material_map keeps any value, and maps one it
            // does not know as planar (image_coordinates' default, as map_pos's).
            int mt = mapping.map_type;
            if (block == ImageBlock::ImageMap && mt != 0 && mt != 1 && mt != 2 && mt != 5)
                error(at, "invalid map_type value");
        } else if (!is_material && (w == "use_color" || w == "use_colour")) {
            mapping.use_index = false;
            mapping.image_value = 0;
        } else if (is_pattern && w == "use_alpha") {
            // The transmit of an image with an alpha channel, else its red.
            mapping.image_value = has_alpha ? 1 : 2;
        } else if (is_pattern && w == "use_index") {
            // image_pattern reads the grey whatever it is told (POV-Ray's image_pattern
            // takes an index only with no `use` at all, which it never has).
            mapping.image_value = 0;
        } else if (!is_material && w == "use_index") {
            // A bump map of palette indices takes each index itself as the height; of
            // other images, the colours' grey (POV-Ray 3.7's bump_map).
            if (is_bump && colour_mapped && pixels && pixels->indices.empty())
                unsupported(
                    t, "bump_map use_index on a palette image that repeats a colour");
            use_index_at = t;
            mapping.use_index = true;
        } else if (w == "repeat") {
            Token at = peek();
            auto [ru, rv] = uv();
            if (ru <= 0 || rv <= 0) error(at, "zero or negative image repeat vector");
            mapping.width = mapping.width * ru;
            mapping.height = mapping.height * rv;
        } else if (w == "offset") {
            auto [ou, ov] = uv();
            mapping.offset_u = -ou * (mapping.pixels ? mapping.pixels->width : 0);
            mapping.offset_v = -ov * (mapping.pixels ? mapping.pixels->height : 0);
        } else if (is_bump && w == "bump_size") {
            bump->amount = parse_single();
        } else if (block == ImageBlock::ImageMap &&
                   (w == "filter" || w == "transmit" || w == "alpha")) {
            if (w == "alpha")
                warn(t, "keyword 'alpha' discontinued; use 'filter' instead");
            // A palette image keeps filter and transmit per palette entry, which these
            // set; other images add `all`'s value to every pixel.
            const int channel = w == "transmit" ? 4 : 3;
            const bool indexed = pixels && !pixels->indices.empty();
            if (accept_word("all")) {
                const float v = float(parse_float());
                if (indexed) {
                    for (size_t i = 0; i < pixels->indices.size(); ++i)
                        pixels->rgbft[i * 5 + size_t(channel)] = v;
                } else {
                    (channel == 4 ? mapping.all_transmit : mapping.all_filter) = v;
                }
            } else if (indexed || !pixels) {
                const Token at = peek();
                const int reg = int(parse_float() + 0.01);
                if (pixels && (reg < 0 || reg >= pixels->palette_size))
                    error(at, std::string(w) + " colour register " + std::to_string(reg) +
                                  " out of range (the palette has " +
                                  std::to_string(pixels->palette_size) + " colours)");
                accept_punct(',');
                const float v = float(parse_float());
                if (pixels) {
                    for (size_t i = 0; i < pixels->indices.size(); ++i)
                        if (pixels->indices[i] == reg)
                            pixels->rgbft[i * 5 + size_t(channel)] = v;
                }
            } else if (colour_mapped) {
                unsupported(t, std::string(w) +
                                   " <index> on a palette image that repeats a colour");
            } else {
                // POV-Ray: per-index values need a colour-mapped (palette) image.
                error(t, std::string(w) + " <index> needs a colour-mapped image; use " +
                             std::string(w) + " all");
            }
        } else {
            expected("a " + std::string(keyword.text) + " item or '}'", t);
        }
    }
    if (is_material) {
        // POV-Ray picks by the palette index (of other images, by red * 255).
        if (colour_mapped && pixels && pixels->indices.empty())
            unsupported(keyword, "material_map of a palette image that repeats a colour");
    }
    // POV-Ray averages the corners' indices when it interpolates them.
    if (is_bump && use_index_at && mapping.use_index && colour_mapped &&
        mapping.interpolate != 0)
        unsupported(*use_index_at, "bump_map use_index with interpolate");
    if (pixels) pixels->note_see_through();
}

}  // namespace povwall::parser
