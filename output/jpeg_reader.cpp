#include "output/jpeg_reader.h"

#include <csetjmp>
#include <cstdio>
#include <memory>
// jpeglib.h needs size_t and FILE declared first.
#include <jpeglib.h>

#include "core/memory.h"

namespace povwall::output {
namespace {

// libjpeg's error manager with a way back: error_exit jumps to the read's setjmp.
struct JumpingErrors {
    jpeg_error_mgr manager;
    std::jmp_buf back;
    char message[JMSG_LENGTH_MAX];
};

void on_jpeg_error(j_common_ptr cinfo) {
    auto* errors = reinterpret_cast<JumpingErrors*>(cinfo->err);
    (*cinfo->err->format_message)(cinfo, errors->message);
    std::longjmp(errors->back, 1);
}
// Warnings (corrupt data libjpeg recovers from) are not printed: OpenImageIO's reader
// ignores them too.
void on_jpeg_message(j_common_ptr) {}

}  // namespace

DirectRead read_jpeg(const std::string& path, DecodedImage& image, std::string& error) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                         &std::fclose);
    if (!file) {
        error = "cannot open the file";
        return DirectRead::Failed;
    }
    // A JPEG starts with its start-of-image marker and another marker.
    unsigned char head[3];
    if (std::fread(head, 1, 3, file.get()) != 3 || head[0] != 0xFF || head[1] != 0xD8 ||
        head[2] != 0xFF)
        return DirectRead::NotMine;
    std::rewind(file.get());
    // As in png_reader.cpp: what changes between setjmp and a longjmp is on the heap.
    auto errors = std::make_unique<JumpingErrors>();
    auto cinfo = std::make_unique<jpeg_decompress_struct>();
    auto bytes = std::make_unique<std::vector<unsigned char>>();
    auto status = std::make_unique<DirectRead>(DirectRead::Failed);
    cinfo->err = jpeg_std_error(&errors->manager);
    errors->manager.error_exit = on_jpeg_error;
    errors->manager.output_message = on_jpeg_message;
    errors->message[0] = 0;
    if (!setjmp(errors->back)) {
        jpeg_create_decompress(cinfo.get());
        jpeg_stdio_src(cinfo.get(), file.get());
        jpeg_read_header(cinfo.get(), TRUE);
        if (cinfo->jpeg_color_space == JCS_CMYK || cinfo->jpeg_color_space == JCS_YCCK) {
            *status = DirectRead::NotMine;
        } else {
            jpeg_start_decompress(cinfo.get());
            const size_t width = cinfo->output_width, height = cinfo->output_height;
            const size_t channels = size_t(cinfo->output_components);
            bytes->resize(width * height * channels);
            while (cinfo->output_scanline < cinfo->output_height) {
                JSAMPROW row =
                    bytes->data() + size_t(cinfo->output_scanline) * width * channels;
                jpeg_read_scanlines(cinfo.get(), &row, 1);
            }
            jpeg_finish_decompress(cinfo.get());
            image.width = int(width);
            image.height = int(height);
            image.channels = int(channels);
            *status = DirectRead::Done;
        }
    }
    jpeg_destroy_decompress(cinfo.get());  // a no-op when creating it failed (zeroed)
    if (*status == DirectRead::Failed) {
        error = errors->message[0] ? errors->message : "not a readable JPEG file";
        return DirectRead::Failed;
    }
    if (*status == DirectRead::NotMine) return DirectRead::NotMine;
    image.info = ImageFileInfo{};
    image.info.format = "jpeg";
    image.info.channels = image.channels;
    image.info.bits = 8;
    resize_on_huge_pages(image.samples, bytes->size());
    const float scale = 1.0f / 255.0f;
    for (size_t i = 0; i < bytes->size(); ++i)
        image.samples[i] = float((*bytes)[i]) * scale;
    return DirectRead::Done;
}

}  // namespace povwall::output
