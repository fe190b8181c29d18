// height_field { [TYPE] "file" | function W, H { ... }  [water_level L | smooth]*
// modifiers }: the grid of heights POV-Ray 3.7 takes from the image (Parse_HField,
// Parse_Image, image_height_at in 3.7:source/backend/support/imageutil.cpp), in the
// unit square through the scale POV-Ray starts the object's transform with.
#include <cmath>

#include "parser/image_file_types.h"
#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

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

// POV-Ray's cast of a double to its 16-bit height as x86 code makes it: through a 32-bit
// int (wrapping; out of that range, or NaN, the int is its minimum, whose low half is 0).
uint16_t height_cast(double v) {
    if (!(std::fabs(v) < 2147483648.0)) return 0;
    return uint16_t(int32_t(v));
}

// A container of 8-bit colour (or float colour, which reports the same maximum): red is
// the high byte, green the low one, blue unused.
uint16_t red_green_height(double r, double g) {
    return height_cast((r * 256.0 + g) * 255.0);
}

// An 8-bit sample as POV-Ray's 8-bit containers give it back.
double byte_value(uint32_t v) { return double(float(v) / 255.0f); }

}  // namespace

std::vector<uint16_t> Interpreter::height_field_image_heights(const StoredImage& stored,
                                                              std::string_view kind,
                                                              const Token& at, int& width,
                                                              int& depth) {
    width = stored.pixels.width;
    depth = stored.pixels.height;
    const auto index = [&](int x, int y) {
        return stored.indices[size_t(y) * size_t(stored.pixels.width) + size_t(x)];
    };
    if (kind == "pot") {
        // A GIF twice as wide as the grid: the left half's indices are the heights' high
        // bytes, the right half's their low bytes (the palette unused).
        if (stored.indices.empty())
            unsupported(at, "height_field pot file whose palette repeats a colour");
        if (width % 2 != 0) error(at, "Invalid width for POT file");
        width /= 2;
    }
    if (width < 2 || depth < 2) unsupported(at, "height_field image smaller than 2 x 2");
    std::vector<uint16_t> heights(size_t(width) * size_t(depth));
    if (kind == "pot") {
        for (int y = 0; y < depth; ++y) {
            for (int x = 0; x < width; ++x)
                heights[size_t(y) * size_t(width) + size_t(x)] =
                    uint16_t(index(x, y) << 8 | index(x + width, y));
        }
        return heights;
    }
    // POV-Ray's heights ignore alpha where its readers keep colours as stored (PNG,
    // Targa, BMP); its TIFF path premultiplies them in 8 bits, its EXR keeps them
    // premultiplied: those are not reproduced.
    if (stored.has_alpha && !stored.colour_mapped && stored.format != "png" &&
        stored.format != "targa" && stored.format != "bmp")
        unsupported(at, "height_field image with an alpha channel");
    if (stored.colour_mapped && stored.indices.empty())
        unsupported(at, stored.format == "tiff"
                            ? "height_field on a palette TIFF"
                            : "height_field on a palette image that repeats a colour");
    const int bits = stored.bits;
    const bool tiff = stored.format == "tiff";
    const bool pnm = stored.format == "pnm";
    if (pnm && stored.pnm_maxval != 255 && stored.pnm_maxval != 65535)
        unsupported(at, "height_field Netpbm file of maxval " +
                            std::to_string(stored.pnm_maxval));
    const bool grey = stored.channels <= 2;
    // (Grey with alpha has a grey container of its own, no palette.)
    const bool png_palette_path =
        stored.channels == 1 && stored.format == "png" && bits <= 8;
    if (!stored.float_data && !stored.colour_mapped && !png_palette_path && bits != 8 &&
        bits != 16)
        unsupported(at,
                    "height_field image of " + std::to_string(bits) + " bits per sample");
    for (size_t i = 0; i < heights.size(); ++i) {
        const float* px = &stored.pixels.rgba[i * 4];
        uint16_t& h = heights[i];
        if (stored.colour_mapped) {
            h = uint16_t(stored.indices[i] * 256);  // POV-Ray's index * 256
        } else if (stored.float_data) {
            // HDR and EXR: float colour, taken as if 8-bit (values above 1 wrap).
            h = red_green_height(double(px[0]), double(px[1]));
        } else if (tiff) {
            // Read through libtiff's 8-bit RGBA interface: a 16-bit grey keeps its high
            // byte, 16-bit colour rounds to the nearest byte.
            uint32_t r = sample(px[0], 255), g = sample(px[1], 255);
            if (bits == 16) {
                r = sample(px[0], 65535);
                g = sample(px[1], 65535);
                r = grey ? r >> 8 : (r + 128) / 257;
                g = grey ? g >> 8 : (g + 128) / 257;
            }
            h = red_green_height(byte_value(r), byte_value(g));
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
            h = uint16_t((0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2]) * double(65535.0f));
        } else {
            h = red_green_height(byte_value(sample(px[0], 255)),
                                 byte_value(sample(px[1], 255)));
        }
    }
    return heights;
}

Interpreter::PendingHeightField Interpreter::parse_height_field(Object& out) {
    HeightField hf;
    std::vector<uint16_t> heights;  // image rows top first, as read
    int width = 0, depth = 0;
    const Token first = peek();
    if (is_word(first, "function")) {
        next();
        const FunctionImage image = parse_function_image("height_field");
        width = image.width;
        depth = image.height;
        heights.resize(size_t(width) * size_t(depth));
        for (size_t i = 0; i < heights.size(); ++i) {
            if (image.channels == 1) {
                heights[i] = grey_height(image.samples[i], 65535);
                continue;
            }
            // An RGBA 16-bit image: the height is the grey of its channels, read back as
            // floats (the weights' sum below 1 loses one for half the values).
            double rgb[3];
            for (int k = 0; k < 3; ++k)
                rgb[k] = double(float(image.samples[i * 4 + size_t(k)]) / 65535.0f);
            heights[i] = uint16_t((0.297 * rgb[0] + 0.589 * rgb[1] + 0.114 * rgb[2]) *
                                  double(65535.0f));
        }
    } else {
        const ImageFileRef file = parse_image_file_ref(true);
        const std::string_view kind = file.type->keyword;
        const Token& name_token = file.name_token;
        for (;;) {
            if (const Token& t = peek(); is_word(t, "gamma")) {
                unsupported(t, "height_field image gamma");
            } else if (accept_word("premultiplied")) {
                // Changes only how alpha is kept, and images with alpha are refused
                // below: without alpha, no effect on the heights.
                parse_float();
            } else {
                break;
            }
        }
        image_files_.push_back(file.path);
        if (!options_.image_reader) {
            // Parsing only (which files a scene reads, as image_map records just the
            // reference): a flat grid stands in.
            width = depth = 2;
            heights.assign(4, 0);
        } else {
            StoredImage stored;
            try {
                stored = options_.image_reader(file.path);
            } catch (const std::exception& e) {
                error(name_token, e.what());
            }
            if (!image_format_matches(*file.type, stored.format))
                error(name_token, "Cannot read image: not a " + std::string(kind) +
                                      " file (it reads as " + stored.format + ")");
            heights = height_field_image_heights(stored, kind, name_token, width, depth);
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
