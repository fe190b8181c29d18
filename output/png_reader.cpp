#include "output/png_reader.h"

#include <png.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "core/memory.h"

namespace povwall::output {
namespace {

void keep_png_error_and_jump(png_structp png, png_const_charp message) {
    auto* error = static_cast<std::string*>(png_get_error_ptr(png));
    if (error) *error = message;
    png_longjmp(png, 1);
}
void ignore_png_warning(png_structp, png_const_charp) {}

}  // namespace

DirectRead read_png(const std::string& path, DecodedImage& image, std::string& error) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                         &std::fclose);
    if (!file) {
        error = "cannot open the file";
        return DirectRead::Failed;
    }
    unsigned char signature[8];
    if (std::fread(signature, 1, 8, file.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0)
        return DirectRead::NotMine;
    // Everything written between setjmp and a longjmp lives behind pointers made before
    // it (locals changed there would be indeterminate after the jump).
    auto rows = std::make_unique<std::vector<png_bytep>>();
    auto bytes = std::make_unique<std::vector<unsigned char>>();
    auto message = std::make_unique<std::string>();
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, message.get(),
                                             keep_png_error_and_jump, ignore_png_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_read_struct(png ? &png : nullptr, nullptr, nullptr);
        error = "out of memory";
        return DirectRead::Failed;
    }
    volatile bool ok = false;  // set after setjmp
    if (!setjmp(png_jmpbuf(png))) {
        png_init_io(png, file.get());
        png_set_sig_bytes(png, 8);
        png_read_info(png, info);
        png_set_expand(png);  // 1, 2, 4 bits to 8; palette to RGB; tRNS to alpha
        png_set_interlace_handling(png);
        png_read_update_info(png, info);
        image.width = int(png_get_image_width(png, info));
        image.height = int(png_get_image_height(png, info));
        image.channels = int(png_get_channels(png, info));
        const int depth = png_get_bit_depth(png, info);
        const size_t row_bytes = png_get_rowbytes(png, info);
        bytes->resize(row_bytes * size_t(image.height));
        rows->resize(size_t(image.height));
        for (size_t y = 0; y < rows->size(); ++y)
            (*rows)[y] = bytes->data() + y * row_bytes;
        png_read_image(png, rows->data());
        png_read_end(png, nullptr);

        ImageFileInfo& fi = image.info;
        fi = ImageFileInfo{};
        fi.format = "png";
        fi.channels = image.channels;
        fi.has_alpha = image.channels == 2 || image.channels == 4;
        fi.bits = depth;
        int intent = 0;
        double gamma = 0;
        if (!png_get_sRGB(png, info, &intent) && png_get_gAMA(png, info, &gamma) &&
            gamma > 0) {
            // Rounded to hundredths as OpenImageIO does (2.2, not 2.19998).
            const float exponent = float(1.0 / gamma);
            fi.declared_gamma = std::round(float(100.0 * double(exponent))) / 100.0f;
        }
        ok = true;
    }
    png_destroy_read_struct(&png, &info, nullptr);
    if (!ok) {
        error = message->empty() ? "not a readable PNG file" : *message;
        return DirectRead::Failed;
    }
    const size_t count =
        size_t(image.width) * size_t(image.height) * size_t(image.channels);
    resize_on_huge_pages(image.samples, count);
    if (image.info.bits == 16) {
        const float scale = 1.0f / 65535.0f;
        for (size_t i = 0; i < count; ++i)
            image.samples[i] = float((*bytes)[2 * i] << 8 | (*bytes)[2 * i + 1]) * scale;
    } else {
        const float scale = 1.0f / 255.0f;
        for (size_t i = 0; i < count; ++i) image.samples[i] = float((*bytes)[i]) * scale;
    }
    return DirectRead::Done;
}

}  // namespace povwall::output
