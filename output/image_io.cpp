#include "output/image_io.h"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <random>

#include "core/memory.h"
#include "core/self_exe.h"
#include "output/decoded_image.h"
#include "output/image_backend.h"
#include "output/jpeg_reader.h"
#include "output/palette.h"
#include "output/png_reader.h"
#include "output/png_writer.h"
#include "output/ppm_writer.h"
#include "output/radiance_rgbe.h"

namespace povwall::output {
namespace {

namespace fs = std::filesystem;

// A temporary name in the destination folder (same file system, so rename is atomic).
fs::path temporary_name(const fs::path& target) {
    std::random_device rd;
    fs::path dir = target.parent_path();
    std::string name =
        "." + target.filename().string() + ".tmp" + std::to_string(rd() % 1000000);
    name += target.extension().string();
    return dir / name;
}

// The temporary file being written, for remove_partial_output() in a signal handler:
// a plain buffer and a lock-free flag, nothing a handler could find half-updated.
char g_partial_path[4096];
std::atomic<bool> g_partial_active{false};

void set_partial(const fs::path& tmp) {
    const std::string p = tmp.string();
    if (p.size() >= sizeof g_partial_path) return;
    std::memcpy(g_partial_path, p.c_str(), p.size() + 1);
    g_partial_active.store(true);
}

// The OpenImageIO module: next to the binary (the build tree's layout), else where CMake
// built it.
const ImageBackend* load_backend(std::string& error) {
    std::vector<std::string> candidates;
    if (const std::string exe = self_exe(); !exe.empty())
        candidates.push_back(
            (fs::path(exe).parent_path() / POVWALL_IMAGE_BACKEND_NAME).string());
    candidates.push_back(POVWALL_IMAGE_BACKEND_PATH);
    for (const std::string& path : candidates) {
        // Lazy: most of OpenImageIO's ~260 libraries' functions are never called, and
        // binding them all up front cost ~0.17 s per process (of ~0.45 s for the load).
        void* handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
        if (!handle) {
            error = dlerror();
            continue;
        }
        using Entry = const ImageBackend* (*)();
        auto entry = reinterpret_cast<Entry>(dlsym(handle, "povwall_image_backend"));
        if (entry) return entry();
        error = path + ": no povwall_image_backend()";
    }
    return nullptr;
}

std::once_flag g_backend_once;
const ImageBackend* g_backend = nullptr;
std::string g_backend_error;

// The maxval of a Netpbm grey map or pixmap (P2, P3, P5, P6): the image library scales
// samples by it without saying what it was. 0 for bitmaps and unreadable headers.
int pnm_maxval(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return 0;
    char head[512];
    const size_t n = std::fread(head, 1, sizeof head, f);
    std::fclose(f);
    if (n < 2 || head[0] != 'P' || !std::strchr("2356", head[1])) return 0;
    size_t i = 2;
    long values[3];
    for (long& v : values) {
        // Whitespace and comments up to the next number.
        for (;;) {
            while (i < n && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
            if (i < n && head[i] == '#') {
                while (i < n && head[i] != '\n') ++i;
            } else {
                break;
            }
        }
        if (i >= n || !std::isdigit(static_cast<unsigned char>(head[i]))) return 0;
        v = 0;
        while (i < n && std::isdigit(static_cast<unsigned char>(head[i])) && v < 1000000)
            v = v * 10 + (head[i++] - '0');
    }
    return int(values[2]);
}

const ImageBackend& backend() {
    std::call_once(g_backend_once, [] { g_backend = load_backend(g_backend_error); });
    if (!g_backend)
        throw ImageIoError("cannot load the OpenImageIO module: " + g_backend_error);
    return *g_backend;
}

}  // namespace

bool remove_partial_output() noexcept {
    if (!g_partial_active.exchange(false)) return false;
    ::unlink(g_partial_path);
    return true;
}

float encode_channel(float v, const OutputEncoding& enc) {
    if (!enc.gamma_handling) return std::clamp(v, 0.0f, 1.0f);
    const GammaCurve& working = enc.working_gamma;
    // sRGB working space written to an sRGB file: POV-Ray's transcoding is the identity.
    if (working.kind == GammaCurve::Kind::Srgb && enc.file_srgb)
        return std::clamp(v, 0.0f, 1.0f);
    // Working space (assumed_gamma) to linear, then to the file's encoding.
    float lin = working.is_linear() ? v : working.decode(v);
    lin = std::clamp(lin, 0.0f, 1.0f);
    return enc.file_srgb ? GammaCurve::srgb().encode(lin)
                         : std::pow(lin, 1.0f / enc.file_gamma);
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
    if (ext == ".jpeg") ext = ".jpg";
    const bool linear_format = ext == ".exr" || ext == ".hdr";
    const bool png = ext == ".png", ppm = ext == ".pnm";
    // PPM, JPEG and Radiance RGBE have no alpha channel (POV-Ray's +FP, +FJ and +FH
    // ignore +UA).
    const int channels = enc.alpha && ext != ".hdr" && ext != ".jpg" && !ppm ? 4 : 3;
    const int W = image.width, H = image.height;
    // POV-Ray's colour depth (+FN12: 12 bits; it takes 5..16): PNG and PPM quantise to
    // it, PNG then fills its 8- or 16-bit samples by left bit replication (12-bit v is
    // stored as v << 4 | v >> 8); its other formats are 8 bits.
    const int depth = png || ppm ? std::clamp(enc.bits == 0 ? 8 : enc.bits, 5, 16) : 8;
    const int container = ppm ? depth : depth > 8 ? 16 : 8;
    const bool sixteen = container > 8 && !linear_format;
    const int replicate_up = ppm ? 0 : container - depth,
              replicate_down = depth - replicate_up;
    std::vector<float> floats;
    std::vector<uint16_t> words;
    std::vector<uint8_t> bytes;
    const size_t n = size_t(W) * H;
    const float maxv = float((1 << depth) - 1);
    for (size_t i = 0; i < n; ++i) {
        // The renderer's colours are premultiplied (a transparent background adds black);
        // POV-Ray's integer formats with alpha store straight alpha, and a pixel brighter
        // than its opacity (a highlight on glass) gets its brightness as its alpha, so
        // that dividing keeps its colour (GetEncodedRGBAValue). Without an alpha channel
        // (PPM) the premultiplied colour is written: the image over black.
        float a = image.rgba[i * 4 + 3];
        if (channels == 4 && !linear_format) {
            const float bright = 0.297f * image.rgba[i * 4] +
                                 0.589f * image.rgba[i * 4 + 1] +
                                 0.114f * image.rgba[i * 4 + 2];
            if (bright > a) a = std::min(1.0f, bright);
        }
        for (int c = 0; c < channels; ++c) {
            float v = c == 3 ? a : image.rgba[i * 4 + c];
            if (linear_format) {
                // EXR/HDR hold linear light, as POV-Ray writes them (working -> linear).
                const GammaCurve& working = enc.working_gamma;
                if (c < 3 && enc.gamma_handling && !working.is_linear())
                    v = working.decode(v);
                floats.push_back(v);
                continue;
            }
            if (channels == 4 && c < 3) v = a > 0.0f ? v / a : 0.0f;
            float e = c == 3 ? std::clamp(v, 0.0f, 1.0f) : encode_channel(v, enc);
            // POV-Ray quantises with floor(x * max + 0.5), and writes a NaN channel (a
            // reflection exponent over negative light) as 0.
            unsigned q = std::isnan(e) ? 0u : unsigned(std::floor(e * maxv + 0.5f));
            if (replicate_up > 0) q = q << replicate_up | q >> replicate_down;
            if (sixteen)
                words.push_back(uint16_t(q));
            else
                bytes.push_back(uint8_t(q));
        }
    }
    fs::path tmp = temporary_name(target);
    set_partial(tmp);
    struct ClearPartial {
        ~ClearPartial() { g_partial_active.store(false); }
    } clear_partial;
    const void* data = linear_format ? static_cast<const void*>(floats.data())
                       : sixteen     ? static_cast<const void*>(words.data())
                                     : static_cast<const void*>(bytes.data());
    const PixelType type = linear_format ? PixelType::Float
                           : sixteen     ? PixelType::UInt16
                                         : PixelType::UInt8;
    std::string err;
    if (ext == ".png") {
        PngEncoding declared;
        declared.kind = !enc.gamma_handling ? PngEncoding::Kind::None
                        : enc.file_srgb     ? PngEncoding::Kind::Srgb
                                            : PngEncoding::Kind::Gamma;
        declared.gamma = enc.file_gamma;
        err = write_png(tmp.string(), W, H, channels, container, data, declared);
    } else if (ppm) {
        err = write_ppm(tmp.string(), W, H, depth, data);
    } else {
        // OIIO picks the format from the file name unless told: the temporary keeps the
        // extension.
        err =
            backend().write(tmp.string(), format.empty() ? std::string() : ext.substr(1),
                            W, H, channels, type, data, !linear_format,
                            !linear_format && enc.gamma_handling && enc.file_srgb);
    }
    std::error_code ec;
    if (!err.empty()) {
        fs::remove(tmp, ec);
        throw ImageIoError("cannot write '" + path + "': " + err);
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw ImageIoError("cannot write '" + path + "': " + ec.message());
    }
}

namespace {

// The nearest half-precision value (ties to even, as OpenEXR's conversion; beyond the
// largest half, infinity).
float round_to_half(float f) {
    if (!std::isfinite(f)) return f;
    const float a = std::fabs(f);
    if (a >= 65520.0f) return std::copysign(INFINITY, f);
    int e = 0;
    std::frexp(a, &e);  // a = m * 2^e, m in [0.5, 1)
    // 10 mantissa bits below the leading one; subnormal below 2^-14.
    const double step = std::ldexp(1.0, std::max(e - 1, -14) - 10);
    return std::copysign(float(std::nearbyint(double(a) / step) * step), f);
}

}  // namespace

DecodedImage decode_with_open_image_io(const std::string& path) {
    DecodedImage decoded;
    const std::string err =
        backend().read(path, decoded.width, decoded.height, decoded.channels,
                       decoded.samples, decoded.info);
    if (!err.empty()) throw ImageIoError("cannot read '" + path + "': " + err);
    return decoded;
}

DecodedImage decode_image_file(const std::string& path) {
    DecodedImage decoded;
    std::string err;
    DirectRead direct = read_png(path, decoded, err);
    if (direct == DirectRead::NotMine) direct = read_jpeg(path, decoded, err);
    if (direct == DirectRead::Failed)
        throw ImageIoError("cannot read '" + path + "': " + err);
    if (direct == DirectRead::Done) return decoded;  // (a conditional would copy it)
    return decode_with_open_image_io(path);
}

namespace {

// The file's pixels as RGBA and what it says about itself, as its reader gives them.
StoredImage stored_as_read(const std::string& path) {
    DecodedImage decoded = decode_image_file(path);
    const int width = decoded.width, height = decoded.height, nc = decoded.channels;
    const std::vector<float>& pixels = decoded.samples;
    const ImageFileInfo& info = decoded.info;
    Image img;
    img.width = width;
    img.height = height;
    if (nc == 4) {  // RGBA already: taken as it is (large textures: no second copy)
        img.rgba = std::move(decoded.samples);
    } else {
        resize_on_huge_pages(img.rgba, size_t(width) * size_t(height) * 4);
        for (size_t i = 0; i < size_t(width) * height; ++i) {
            // Grey (1 channel) and grey+alpha (2) files spread their grey over RGB.
            const bool grey = nc <= 2;
            for (int c = 0; c < 3; ++c)
                img.rgba[i * 4 + c] = pixels[i * nc + (grey ? 0 : c)];
            img.rgba[i * 4 + 3] = nc == 2   ? pixels[i * nc + 1]
                                  : nc >= 4 ? pixels[i * nc + 3]
                                            : 1.0f;
        }
    }
    StoredImage stored;
    stored.pixels = std::move(img);
    stored.format = info.format;
    stored.declared_gamma = info.declared_gamma;
    stored.has_alpha = info.has_alpha;
    stored.channels = info.channels;
    stored.bits = info.bits;
    stored.float_data = info.float_data;
    if (info.format == "pnm") stored.pnm_maxval = pnm_maxval(path);
    stored.colour_mapped = info.tiff_palette;  // its indices are not recovered
    return stored;
}

}  // namespace

Image read_image(const std::string& path) { return stored_as_read(path).pixels; }

StoredImage read_stored_image(const std::string& path) {
    StoredImage stored = stored_as_read(path);
    if (stored.format == "hdr") {
        // A scene's RGBE file as POV-Ray decodes it (OpenImageIO's values are lower by
        // half a mantissa step).
        int w = 0, h = 0;
        std::vector<float> rgb;
        const std::string err = read_rgbe_as_povray(path, w, h, rgb);
        if (!err.empty()) throw ImageIoError("cannot read '" + path + "': " + err);
        stored.pixels = Image(w, h);
        for (size_t i = 0; i < size_t(w) * size_t(h); ++i) {
            for (int c = 0; c < 3; ++c)
                stored.pixels.rgba[i * 4 + size_t(c)] = rgb[i * 3 + size_t(c)];
            stored.pixels.rgba[i * 4 + 3] = 1.0f;
        }
    }
    if (stored.format == "openexr" && stored.bits > 16) {
        // POV-Ray reads EXR files through OpenEXR's RGBA interface, in half precision.
        for (float& v : stored.pixels.rgba) v = round_to_half(v);
    }
    if (!stored.colour_mapped && colour_mapped_file(path, stored.format)) {
        stored.colour_mapped = true;
        const auto palette = read_palette(path, stored.format);
        stored.indices = palette_indices(path, stored.format, stored.pixels, palette);
        stored.palette_size = int(palette.size());
    }
    return stored;
}

}  // namespace povwall::output
