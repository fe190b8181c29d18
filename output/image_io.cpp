#include "output/image_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

namespace povwall::output {
namespace {

namespace fs = std::filesystem;

float srgb_encode(float x) {
    if (x <= 0.0031308f) return x * 12.92f;
    return 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

// A temporary name in the destination folder (same file system, so rename is atomic).
fs::path temporary_name(const fs::path& target) {
    std::random_device rd;
    fs::path dir = target.parent_path();
    std::string name =
        "." + target.filename().string() + ".tmp" + std::to_string(rd() % 1000000);
    name += target.extension().string();
    return dir / name;
}

}  // namespace

float encode_channel(float v, const OutputEncoding& enc) {
    if (!enc.gamma_handling) return std::clamp(v, 0.0f, 1.0f);
    // Working space (assumed_gamma) to linear, then to the file's encoding.
    float lin =
        enc.working_gamma == 1.0f ? v : std::pow(std::max(v, 0.0f), enc.working_gamma);
    lin = std::clamp(lin, 0.0f, 1.0f);
    return enc.file_srgb ? srgb_encode(lin) : std::pow(lin, 1.0f / enc.file_gamma);
}

void write_image(const Image& image, const std::string& path, const OutputEncoding& enc) {
    write_image(image, path, enc, "");
}

void write_image(const Image& image, const std::string& path, const OutputEncoding& enc,
                 const std::string& format) {
    fs::path target(path);
    if (target.parent_path().empty()) target = fs::path(".") / target;
    std::string ext = format.empty() ? target.extension().string() : "." + format;
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext == ".tga") ext = ".targa";  // OIIO's plugin names
    if (ext == ".ppm") ext = ".pnm";
    const bool linear_format = ext == ".exr" || ext == ".hdr";
    const int channels = enc.alpha ? 4 : 3;
    const int W = image.width, H = image.height;
    const bool sixteen = enc.bits > 8 && !linear_format;
    OIIO::ImageSpec spec(
        W, H, channels,
        linear_format ? OIIO::TypeDesc::FLOAT
                      : (sixteen ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8));
    // POV-Ray writes straight (non-premultiplied) alpha; without this OIIO would divide
    // the colours by alpha on the way out.
    if (!linear_format) spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!linear_format && enc.gamma_handling && enc.file_srgb) {
        spec.attribute("oiio:ColorSpace", "sRGB");
    }
    std::vector<float> floats;
    std::vector<uint16_t> words;
    std::vector<uint8_t> bytes;
    const size_t n = size_t(W) * H;
    const float maxv = sixteen ? 65535.0f : 255.0f;
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < channels; ++c) {
            float v = image.rgba[i * 4 + c];
            if (linear_format) {
                // EXR/HDR hold linear light, as POV-Ray writes them (working -> linear).
                if (c < 3 && enc.gamma_handling && enc.working_gamma != 1.0f) {
                    v = std::pow(std::max(v, 0.0f), enc.working_gamma);
                }
                floats.push_back(v);
                continue;
            }
            // The renderer's colours are premultiplied (a transparent background adds
            // black); POV-Ray's integer formats store straight alpha.
            const float a = image.rgba[i * 4 + 3];
            if (enc.alpha && c < 3) v = a > 0.0f ? v / a : 0.0f;
            float e = c == 3 ? std::clamp(v, 0.0f, 1.0f) : encode_channel(v, enc);
            // POV-Ray quantises with floor(x * max + 0.5).
            float q = std::floor(e * maxv + 0.5f);
            if (sixteen)
                words.push_back(uint16_t(q));
            else
                bytes.push_back(uint8_t(q));
        }
    }
    fs::path tmp = temporary_name(target);
    auto out =
        OIIO::ImageOutput::create(format.empty() ? target.string() : ext.substr(1));
    if (!out) throw ImageIoError("cannot write '" + path + "': unsupported image format");
    // OIIO picks the format from the file name: give the temporary the same extension.
    std::error_code ec;
    if (!out->open(tmp.string(), spec)) {
        std::string err = out->geterror();
        fs::remove(tmp, ec);
        throw ImageIoError("cannot write '" + path + "': " + err);
    }
    const void* data = linear_format ? static_cast<const void*>(floats.data())
                       : sixteen     ? static_cast<const void*>(words.data())
                                     : static_cast<const void*>(bytes.data());
    bool ok = out->write_image(spec.format, data);
    ok = out->close() && ok;
    if (!ok) {
        fs::remove(tmp, ec);
        throw ImageIoError("cannot write '" + path + "': " + out->geterror());
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw ImageIoError("cannot write '" + path + "': " + ec.message());
    }
}

Image read_image(const std::string& path) {
    // Values as stored: no premultiplication by alpha on the way in.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) throw ImageIoError("cannot read '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> pixels(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) {
        throw ImageIoError("cannot read '" + path + "': " + in->geterror());
    }
    Image img(spec.width, spec.height);
    const int nc = spec.nchannels;
    for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i) {
        // Grey (1 channel) and grey+alpha (2) files spread their grey over RGB.
        const bool grey = nc <= 2;
        for (int c = 0; c < 3; ++c) img.rgba[i * 4 + c] = pixels[i * nc + (grey ? 0 : c)];
        img.rgba[i * 4 + 3] = nc == 2   ? pixels[i * nc + 1]
                              : nc >= 4 ? pixels[i * nc + 3]
                                        : 1.0f;
    }
    in->close();
    return img;
}

}  // namespace povwall::output
