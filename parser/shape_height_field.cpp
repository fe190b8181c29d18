// height_field { [TYPE] "file" | function W, H { ... }  [water_level L | smooth]*
// modifiers }: the grid of heights POV-Ray 3.7 takes from the image (Parse_HField,
// Parse_Image, image_height_at in 3.7:source/backend/support/imageutil.cpp), in the
// unit square through the scale POV-Ray starts the object's transform with.
#include <cmath>
#include <filesystem>

#include "parser/image_file_types.h"
#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

namespace fs = std::filesystem;

// A grey container's height: its value as a float in [0, 1] times 65535 in single
// precision, truncated (an 8-bit v gives v * 257, a 16-bit one itself).
uint16_t grey_height(uint32_t v, uint32_t max) {
    return uint16_t(float(v) / float(max) * 65535.0f);
}

// A stored sample back as the integer the file holds.
uint32_t sample(float f, uint32_t max) { return uint32_t(std::lround(double(f) * max)); }

// POV-Ray reads a grey PNG of up to 8 bits through a grey palette, converting each
// entry to a byte with its grey weights in single precision: 84 of the 256 8-bit values
// come out one lower.
uint8_t png_palette_grey(uint32_t v, uint32_t max) {
    const float e = float(v) / float(max);
    return uint8_t((e * 0.297f + e * 0.589f + e * 0.114f) * 255.0f);
}

// A float as POV-Ray stores it in a 16-bit channel: times 65535 in single precision,
// through a 32-bit int (wrapping, not clamped). False when that int overflows.
bool stored_16(double value, uint16_t& out) {
    const float scaled = float(value) * 65535.0f;
    if (!(std::fabs(scaled) < 2147483648.0f)) return false;
    out = uint16_t(int32_t(scaled));
    return true;
}

}  // namespace

Interpreter::PendingHeightField Interpreter::parse_height_field(Object& out) {
    HeightField hf;
    std::vector<uint16_t> heights;  // image rows top first, as read
    int width = 0, depth = 0;
    const Token first = peek();
    if (is_word(first, "function")) {
        next();
        const Token size_at = peek();
        width = int(parse_float() + 0.5);
        accept_punct(',');
        depth = int(parse_float() + 0.5);
        if (!is_punct(peek(), '{'))
            expected("'{' after the function image's size", peek());
        if (width < 2 || depth < 2)
            unsupported(size_at, "height_field function smaller than 2 x 2");
        const Token body_at = peek();
        const auto f = parse_function_block(false);
        if (f->spline || f->transform)
            error(body_at, "Unsupported function type in function image.");
        const FunctionHooks& hooks = options_.function_hooks;
        if (f->pigment && !hooks.pigment)
            unsupported(body_at, "height_field function pigment without the renderer");
        heights.resize(size_t(width) * size_t(depth));
        uint64_t left = options_.max_loop_iterations;
        FunctionHooks run = hooks;
        run.iterations_left = &left;
        for (int i = 0; i < depth; ++i) {
            for (int j = 0; j < width; ++j) {
                const double p[3] = {double(j) / double(float(width) - 1),
                                     double(i) / double(float(depth) - 1), 0};
                uint16_t& h = heights[size_t(i) * size_t(width) + size_t(j)];
                if (f->pigment) {
                    // An RGBA 16-bit image: the height is the grey of its channels, read
                    // back as floats (the weights' sum below 1 loses one for half the
                    // values).
                    float c[5] = {0, 0, 0, 0, 0};
                    hooks.pigment(*f->pigment, Point3(p[0], p[1], p[2]), hooks.context,
                                  c);
                    double rgb[3];
                    for (int k = 0; k < 3; ++k) {
                        uint16_t s;
                        if (!stored_16(c[k], s))
                            unsupported(body_at,
                                        "height_field function value out of range");
                        rgb[k] = double(float(s) / 65535.0f);
                    }
                    h = uint16_t((0.297 * rgb[0] + 0.589 * rgb[1] + 0.114 * rgb[2]) *
                                 double(65535.0f));
                } else {
                    uint16_t s;
                    if (!stored_16(evaluate_function(*f, p, run), s))
                        unsupported(body_at, "height_field function value out of range");
                    h = grey_height(s, 65535);
                }
            }
        }
    } else {
        const ImageFileType* type = nullptr;
        for (const ImageFileType& ft : kImageFileTypes) {
            if (is_word(first, ft.keyword)) type = &ft;
        }
        if (type) {
            const std::string_view k = type->keyword;
            if (k == "iff") error(first, "File type not supported here.");
            if (k == "sys" || k == "pot" || k == "tiff" || k == "exr" || k == "hdr")
                unsupported(first, "height_field " + std::string(k) + " file");
            next();
        }
        const Token name_token = peek();
        const std::string name = parse_string();
        if (!type) {
            const std::string ext = fs::path(name).extension().string();
            bool known = false;
            for (const ImageFileType& ft : kImageFileTypes)
                known = known || (*ft.extension && ext == ft.extension);
            if (ext.empty())
                unsupported(name_token, "height_field file without an extension");
            if (!known && ext != ".jpeg" && ext != ".tiff")
                error(name_token,
                      "Could not determine valid image file type from extension.");
            if (ext == ".iff") error(name_token, "File type not supported here.");
            if (ext == ".pot" || ext == ".tif" || ext == ".tiff" || ext == ".exr" ||
                ext == ".hdr")
                unsupported(name_token, "height_field " + ext.substr(1) + " file");
        }
        std::string path = resolve_include(name, frames_.back().file);
        if ((path.empty() || fs::path(path).extension() == ".inc") && type &&
            fs::path(name).extension().empty() && *type->extension) {
            path = resolve_include(name + type->extension, frames_.back().file);
        }
        if (path.empty() || fs::path(path).extension() == ".inc")
            error(name_token, "cannot find image file \"" + name + "\"");
        if (const Token& t = peek(); is_word(t, "gamma"))
            unsupported(t, "height_field image gamma");
        if (const Token& t = peek(); is_word(t, "premultiplied"))
            unsupported(t, "height_field premultiplied");
        image_files_.push_back(path);
        if (!options_.image_reader) {
            // Parsing only (which files a scene reads, as image_map records just the
            // reference): a flat grid stands in.
            width = depth = 2;
            heights.assign(4, 0);
        } else {
            StoredImage stored;
            try {
                stored = options_.image_reader(path);
            } catch (const std::exception& e) {
                error(name_token, e.what());
            }
            width = stored.pixels.width;
            depth = stored.pixels.height;
            if (width < 2 || depth < 2)
                unsupported(name_token, "height_field image smaller than 2 x 2");
            if (stored.float_data)
                unsupported(name_token, "height_field from a floating-point image");
            if (stored.has_alpha && !stored.colour_mapped)
                unsupported(name_token, "height_field image with an alpha channel");
            if (stored.colour_mapped && stored.indices.empty())
                unsupported(name_token,
                            "height_field on a palette image that repeats a colour");
            const int bits = stored.bits;
            const bool pnm = stored.format == "pnm";
            if (pnm && stored.pnm_maxval != 255 && stored.pnm_maxval != 65535)
                unsupported(name_token, "height_field Netpbm file of maxval " +
                                            std::to_string(stored.pnm_maxval));
            const bool grey = stored.channels <= 2;
            const bool png_palette_path = grey && stored.format == "png" && bits <= 8;
            if (!stored.colour_mapped && !png_palette_path && bits != 8 && bits != 16)
                unsupported(name_token, "height_field image of " + std::to_string(bits) +
                                            " bits per sample");
            heights.resize(size_t(width) * size_t(depth));
            for (size_t i = 0; i < heights.size(); ++i) {
                const float* px = &stored.pixels.rgba[i * 4];
                uint16_t& h = heights[i];
                if (stored.colour_mapped) {
                    h = uint16_t(stored.indices[i] * 256);  // POV-Ray's index * 256
                } else if (png_palette_path) {
                    const uint32_t max = (1u << bits) - 1;
                    h = grey_height(png_palette_grey(sample(px[0], max), max), 255);
                } else if (grey) {
                    const uint32_t max = bits == 16 ? 65535 : 255;
                    h = grey_height(sample(px[0], max), max);
                } else if (bits == 16) {
                    double c[3];
                    for (int k = 0; k < 3; ++k)
                        c[k] = double(float(sample(px[k], 65535)) / 65535.0f);
                    h = uint16_t((0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2]) *
                                 double(65535.0f));
                } else {
                    // Red the high byte, green the low one (blue unused).
                    const double r = double(float(sample(px[0], 255)) / 255.0f);
                    const double g = double(float(sample(px[1], 255)) / 255.0f);
                    h = uint16_t((r * 256.0 + g) * 255.0);
                }
            }
        }
    }
    // Image rows run top down; the grid's z = 0 is the image's bottom row.
    std::vector<uint16_t> grid(heights.size());
    for (int z = 0; z < depth; ++z) {
        for (int x = 0; x < width; ++x) {
            grid[size_t(z) * size_t(width) + size_t(x)] =
                heights[size_t(depth - 1 - z) * size_t(width) + size_t(x)];
        }
    }
    Real water = 0;
    for (;;) {
        if (accept_word("water_level")) {
            Real level = parse_float();
            if (effective_version() < 200) level /= 256.0;
            water = 65536.0 * level;
        } else if (accept_word("smooth")) {
            hf.smooth = true;
        } else {
            break;
        }
    }
    out.shape = hf;
    out.transform = CompactTransform(
        Transform::scale({1.0 / Real(width - 1), 1.0 / 65536.0, 1.0 / Real(depth - 1)}));
    return {width, depth, std::move(grid), water};
}

void Interpreter::finish_height_field(Object& out, PendingHeightField p) {
    HeightField& hf = std::get<HeightField>(out.shape);
    hf.data = std::make_shared<const HeightFieldData>(make_height_field(
        p.width, p.depth, std::move(p.heights), p.water, hf.smooth, hf.hierarchy));
}

}  // namespace povwall::parser
