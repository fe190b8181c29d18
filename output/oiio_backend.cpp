// The module behind output/image_backend.h: every OpenImageIO call of povwall.
#include <OpenImageIO/imageio.h>
#include <sys/mman.h>

#include <cstdint>

#include "output/image_backend.h"

namespace povwall::output {
namespace {

std::string write_oiio(const std::string& path, const std::string& format, int width,
                       int height, int channels, PixelType type, const void* pixels,
                       bool straight_alpha, bool srgb) {
    const OIIO::TypeDesc td = type == PixelType::Float    ? OIIO::TypeDesc::FLOAT
                              : type == PixelType::UInt16 ? OIIO::TypeDesc::UINT16
                                                          : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(width, height, channels, td);
    // POV-Ray writes straight (non-premultiplied) alpha; without this OIIO would divide
    // the colours by alpha on the way out.
    if (straight_alpha) spec.attribute("oiio:UnassociatedAlpha", 1);
    if (srgb) spec.attribute("oiio:ColorSpace", "sRGB");
    auto out = OIIO::ImageOutput::create(format.empty() ? path : format);
    if (!out) return "unsupported image format";
    // POV-Ray's JPEG quality when the scene gives no Compression (its jpeg.cpp).
    if (std::string(out->format_name()) == "jpeg")
        spec.attribute("Compression", "jpeg:85");
    if (!out->open(path, spec)) return out->geterror();
    bool ok = out->write_image(td, pixels);
    ok = out->close() && ok;
    return ok ? std::string() : out->geterror();
}

std::string read_oiio(const std::string& path, int& width, int& height, int& channels,
                      std::vector<float>& pixels, ImageFileInfo& info) {
    // Values as stored: no premultiplication by alpha on the way in.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) return OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    width = spec.width;
    height = spec.height;
    channels = spec.nchannels;
    info.format = in->format_name();
    info.has_alpha = spec.alpha_channel >= 0 || channels == 2 || channels >= 4;
    info.channels = channels;
    info.float_data = spec.format.is_floating_point();
    info.tiff_palette = info.format == "tiff" &&
                        spec.get_int_attribute("tiff:PhotometricInterpretation", -1) == 3;
    info.bits = spec.get_int_attribute("oiio:BitsPerSample", int(spec.format.size() * 8));
    // OIIO reports a PNG gAMA chunk as oiio:Gamma (the decoding exponent); an sRGB chunk,
    // or none, as the sRGB colour space, which is what POV-Ray assumes then too.
    if (info.format == "png" && spec.get_string_attribute("oiio:ColorSpace") != "sRGB")
        info.declared_gamma = spec.get_float_attribute("oiio:Gamma", 0.0f);
    // Large images on huge pages where the kernel has them (madvise mode): first touches
    // of fresh 4 KB pages cost more than decoding a big texture. (This module links no
    // povwall library: core/memory.h's resize_on_huge_pages, written out.)
    const size_t count = size_t(width) * size_t(height) * size_t(channels);
    constexpr uintptr_t kHuge = uintptr_t(2) << 20;
    if (count * sizeof(float) >= 4 * kHuge && pixels.capacity() < count) {
        pixels.reserve(count);
        const auto start = reinterpret_cast<uintptr_t>(pixels.data());
        const uintptr_t begin = (start + kHuge - 1) & ~(kHuge - 1);
        const uintptr_t end = (start + count * sizeof(float)) & ~(kHuge - 1);
        if (end > begin)
            madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
    }
    pixels.resize(count);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        return in->geterror();
    in->close();
    return {};
}

const ImageBackend kBackend{write_oiio, read_oiio};

}  // namespace
}  // namespace povwall::output

extern "C" const povwall::output::ImageBackend* povwall_image_backend() {
    return &povwall::output::kBackend;
}
