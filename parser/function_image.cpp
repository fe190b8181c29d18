// `function W, H { ... }` in place of an image file (height_field, image_map, bump_map,
// image_pattern, material_map): POV-Ray 3.7.0's Make_Pattern_Image. Sample (i, j) is the
// function at x = j / (W - 1), y = i / (H - 1), z = 0, row 0 first (the top row of an
// image); a float function fills a 16-bit grey image, a pigment function a 16-bit RGBA
// one (alpha 1 - transmit, filter dropped). POV-Ray stores each float as float(v) *
// 65535 converted to a 16-bit channel through a 32-bit int: wrapping, not clamped.
#include "parser/function_image.h"

#include <cmath>

#include "core/function.h"
#include "parser/interpreter.h"

namespace povwall::parser {

bool stored_16(double value, uint16_t& out) {
    const float scaled = float(value) * 65535.0f;
    if (!(std::fabs(scaled) < 2147483648.0f)) return false;
    out = uint16_t(int32_t(scaled));
    return true;
}

FunctionImage Interpreter::parse_function_image(std::string_view keyword) {
    const std::string what = std::string(keyword) + " function";
    FunctionImage image;
    const Token size_at = peek();
    image.width = int(parse_float() + 0.5);
    accept_punct(',');
    image.height = int(parse_float() + 0.5);
    if (!is_punct(peek(), '{')) expected("'{' after the function image's size", peek());
    // One row or column puts its samples at 0 / 0 (NaN).
    if (image.width < 2 || image.height < 2)
        unsupported(size_at, what + " smaller than 2 x 2");
    const Token body_at = peek();
    const auto f = parse_function_block(false);
    if (f->spline || f->transform)
        error(body_at, "Unsupported function type in function image.");
    const FunctionHooks& hooks = parse_time_hooks();
    if (f->pigment && !hooks.pigment)
        unsupported(body_at, what + " pigment without the renderer");
    image.channels = f->pigment ? 4 : 1;
    image.samples.resize(size_t(image.width) * size_t(image.height) *
                         size_t(image.channels));
    uint64_t left = options_.max_loop_iterations;
    FunctionHooks run = hooks;
    run.iterations_left = &left;
    auto store = [&](double v, uint16_t& s) {
        if (!stored_16(v, s)) unsupported(body_at, what + " value out of range");
    };
    uint16_t* s = image.samples.data();
    for (int i = 0; i < image.height; ++i) {
        for (int j = 0; j < image.width; ++j) {
            const double p[3] = {double(j) / double(float(image.width) - 1),
                                 double(i) / double(float(image.height) - 1), 0};
            if (f->pigment) {
                float c[5] = {0, 0, 0, 0, 0};
                hooks.pigment(*f->pigment, Point3(p[0], p[1], p[2]), hooks.context, c);
                for (int k = 0; k < 3; ++k) store(c[k], *s++);
                store(1.0f - c[4], *s++);
            } else {
                store(evaluate_function(*f, p, run), *s++);
            }
        }
    }
    return image;
}

}  // namespace povwall::parser

namespace povwall::parser {

std::shared_ptr<ImagePixels> function_image_pixels(const FunctionImage& image) {
    auto px = std::make_shared<ImagePixels>();
    px->width = image.width;
    px->height = image.height;
    const size_t count = size_t(image.width) * size_t(image.height);
    px->rgbft.resize(count * 5);
    // POV-Ray's 16-bit images give back each sample as float(k) / 65535 (no gamma: a
    // function image has no file); alpha a transmit of 1 - it, filter 0.
    auto value = [](uint16_t k) { return float(k) / 65535.0f; };
    for (size_t i = 0; i < count; ++i) {
        float* d = &px->rgbft[i * 5];
        if (image.channels == 1) {
            d[0] = d[1] = d[2] = value(image.samples[i]);
            d[3] = d[4] = 0;
        } else {
            const uint16_t* s = &image.samples[i * 4];
            for (int c = 0; c < 3; ++c) d[c] = value(s[c]);
            d[3] = 0;
            d[4] = 1.0f - value(s[3]);
        }
    }
    return px;
}

}  // namespace povwall::parser
