// text { ttf "font" | internal N, "string", thickness, offset }: POV-Ray's TrueType text,
// a union of one extruded glyph per character laid out as its Parse_TrueType and
// ProcessNewTTF do (metrics, kerning, the offset rule and the 0.001-degree rotation).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "parser/interpreter.h"
#include "parser/truetype_font.h"

namespace povwall::parser {
namespace fs = std::filesystem;
namespace {

// `internal N`: the fonts POV-Ray 3.7 has built in, byte for byte the ones it installs.
const char* internal_font_file(int id) {
    switch (id) {
        case 1:
            return "timrom.ttf";
        case 2:
            return "cyrvetic.ttf";
        case 3:
            return "crystal.ttf";
        default:
            return "povlogo.ttf";
    }
}

bool ends_with_ttf(const std::string& s) {
    return s.size() >= 4 && (s.compare(s.size() - 4, 4, ".ttf") == 0 ||
                             s.compare(s.size() - 4, 4, ".TTF") == 0);
}

// Decodes UTF-8 as POV-Ray's table does: no validation, code points past 16 bits become
// U+FFFD.
std::vector<uint32_t> decode_utf8(const std::string& s) {
    std::vector<uint32_t> out;
    for (size_t i = 0; i < s.size();) {
        const uint8_t b = uint8_t(s[i]);
        int extra = b < 0xC0   ? 0
                    : b < 0xE0 ? 1
                    : b < 0xF0 ? 2
                    : b < 0xF8 ? 3
                    : b < 0xFC ? 4
                               : 5;
        uint32_t c = extra == 0 ? b : b & (0x3Fu >> extra);
        ++i;
        for (; extra > 0 && i < s.size(); --extra, ++i)
            c = c << 6 | (uint8_t(s[i]) & 0x3Fu);
        out.push_back(c > 0xFFFF ? 0xFFFD : c);
    }
    return out;
}

// POV-Ray's BOUND_HUGE and CRITICAL_LENGTH: the infinite box and the longest side a CSG
// box may have before it counts as infinite.
constexpr double kBoundHuge = 2e10, kCriticalLength = 1e6;

Csg::PovBox infinite_pov_box() {
    Csg::PovBox b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = float(-kBoundHuge / 2);
        b.len[a] = float(kBoundHuge);
    }
    return b;
}

// Make_BBox_from_min_max: the corner and the lengths (in double) rounded to float.
Csg::PovBox pov_box(const double (&lo)[3], const double (&hi)[3]) {
    Csg::PovBox b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = float(lo[a]);
        b.len[a] = float(hi[a] - lo[a]);
    }
    return b;
}

// Recompute_BBox with the corners mapped by `place`.
template <class Place>
void move_box_corners(Csg::PovBox& box, const Place& place) {
    double lo[3] = {INFINITY, INFINITY, INFINITY},
           hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < 8; ++i) {
        Point3 c;
        for (int a = 0; a < 3; ++a)
            c[a] = double(box.lo[a]) + ((i >> a) & 1 ? double(box.len[a]) : 0.0);
        const Point3 p = place(c);
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], p[a]);
            hi[a] = std::max(hi[a], p[a]);
        }
    }
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::max(lo[a], -kBoundHuge / 2);
        hi[a] = std::min(hi[a], kBoundHuge / 2);
    }
    box = pov_box(lo, hi);
}

// The text's box as Parse_TrueType leaves it before the 0.001-degree turn: each glyph's
// header box (TTF_Tolerance around z) through its translation, joined as
// CSG::Compute_BBox joins a union's children; no glyph leaves the constructor's infinite
// box.
Csg::PovBox laid_out_text_box(const Csg& text) {
    constexpr double kTolerance = 1e-6;
    double lo[3] = {kBoundHuge, kBoundHuge, kBoundHuge};
    double hi[3] = {-kBoundHuge, -kBoundHuge, -kBoundHuge};
    for (const Object& child : text.children) {
        const Glyph& g = std::get<Glyph>(child.shape);
        const GlyphOutline& o = *g.outline;
        const double zmin = -kTolerance, zmax = g.depth + kTolerance;
        const double glo[3] = {o.xmin, o.ymin, zmin}, ghi[3] = {o.xmax, o.ymax, zmax};
        Csg::PovBox box = pov_box(glo, ghi);
        move_box_corners(box, [&](const Point3& p) { return child.transform.point(p); });
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], double(box.lo[a]));
            hi[a] = std::max(hi[a], double(box.lo[a]) + double(box.len[a]));
        }
    }
    if (lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]) return infinite_pov_box();
    const Csg::PovBox box = pov_box(lo, hi);
    for (int a = 0; a < 3; ++a)
        if (box.len[a] > kCriticalLength) return infinite_pov_box();
    return box;
}

}  // namespace

void move_pov_box(Csg::PovBox& box, const Transform& t) {
    move_box_corners(box, [&](const Point3& p) { return t.point(p); });
}

std::string Interpreter::resolve_font(const std::string& name, int from_file,
                                      std::string& searched) const {
    std::vector<fs::path> dirs;  // as resolve_include: the working folder first
    dirs.emplace_back();
    dirs.push_back(fs::path(sources_.file(from_file).path).parent_path());
    dirs.push_back(scene_dir_);
    for (const auto& l : options_.library_paths) dirs.emplace_back(l);
    dirs.emplace_back(options_.standard_include_dir);
    for (size_t i = 1; i < dirs.size();) {  // each folder once
        if (std::find(dirs.begin(), dirs.begin() + long(i), dirs[i]) !=
            dirs.begin() + long(i))
            dirs.erase(dirs.begin() + long(i));
        else
            ++i;
    }
    // POV-Ray's candidates: the name as written when it ends in .ttf, then with .ttf and
    // .TTF appended, then as written; each in every folder before the next.
    std::vector<std::string> names;
    if (ends_with_ttf(name)) names.push_back(name);
    names.push_back(name + ".ttf");
    names.push_back(name + ".TTF");
    if (!ends_with_ttf(name)) names.push_back(name);
    for (const fs::path& d : dirs) {
        if (!searched.empty()) searched += ", ";
        searched += d.empty() ? "." : d.string();
    }
    for (const std::string& n : names) {
        const fs::path p(n);
        for (const fs::path& d : dirs) {
            const fs::path c = p.is_absolute() || d.empty() ? p : d / p;
            std::error_code ec;
            if (fs::is_regular_file(c, ec)) return c.string();
            if (p.is_absolute()) break;
        }
    }
    return {};
}

std::shared_ptr<TrueTypeFont> Interpreter::load_font(const Token& at,
                                                     const std::string& path,
                                                     const std::string& shown) {
    std::ifstream in(path, std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) error(at, "cannot read font file \"" + path + "\"");
    try {
        return std::make_shared<TrueTypeFont>(std::move(bytes),
                                              charset_ != Charset::Ascii);
    } catch (const FontError& e) {
        error(at, "cannot read TrueType font \"" + shown + "\": " + e.what());
    }
}

std::vector<uint16_t> Interpreter::text_codes(const Token& at, const std::string& s) {
    std::vector<uint32_t> units;
    switch (charset_) {
        case Charset::Sys:
            error(at, "Cannot convert system specific text format to Unicode.");
        case Charset::Utf8:
            units = decode_utf8(s);
            break;
        case Charset::Ascii:
            for (char ch : s) {
                uint32_t c = uint8_t(ch);
                if (c > 127 && effective_version() >= 350) {
                    warn(at, "Non-ASCII character has been replaced by space character.");
                    c = ' ';
                }
                units.push_back(c);
            }
            break;
    }
    // The lexer has turned the other escapes into their characters already; \uXXXX is
    // read here, after the charset, as POV-Ray does.
    std::vector<uint16_t> codes;
    for (size_t i = 0; i < units.size(); ++i) {
        if (units[i] == '\\' && i + 1 < units.size() && units[i + 1] == 'u') {
            if (i + 6 > units.size())
                error(at, "Unexpected end of escape sequence in text string.");
            std::string hex;
            for (size_t k = i + 2; k < i + 6; ++k) hex.push_back(char(units[k] & 0x7F));
            codes.push_back(uint16_t(std::strtoul(hex.c_str(), nullptr, 16)));
            i += 5;
            continue;
        }
        codes.push_back(uint16_t(units[i]));
    }
    return codes;
}

void Interpreter::parse_text(Object& out) {
    Token kind = next();
    std::shared_ptr<TrueTypeFont> font;
    if (is_word(kind, "ttf")) {
        const Token at = peek();
        std::string name = parse_string();
        if (effective_version() >= 350)
            for (char& c : name)
                if (uint8_t(c) > 127) c = ' ';
        auto cached = fonts_.find(name);
        if (cached != fonts_.end()) {
            font = cached->second;
        } else {
            std::string searched;
            const std::string path = resolve_font(
                name, at.file >= 0 ? at.file : frames_.back().file, searched);
            if (path.empty())
                error(at, "cannot find font file \"" + name + "\" (also tried \"" + name +
                              ".ttf\" and \"" + name + ".TTF\"; searched " + searched +
                              ")");
            font = load_font(at, path, name);
            fonts_.emplace(name, font);
        }
    } else if (is_word(kind, "internal")) {
        const Token at = peek();
        const char* file = internal_font_file(parse_int());
        const std::string path =
            (fs::path(options_.standard_include_dir) / file).string();
        std::error_code ec;
        if (!fs::is_regular_file(path, ec))
            error(at,
                  std::string("cannot find the internal font's file \"") + path + "\"");
        font = load_font(at, path, file);  // never shared, as POV-Ray's
    } else {
        expected("'ttf' or 'internal'", kind);
    }
    accept_punct(',');
    const Token string_at = peek();
    const std::vector<uint16_t> codes = text_codes(string_at, parse_string());
    accept_punct(',');
    const double depth = parse_float();
    accept_punct(',');
    const Vector3 offset = parse_vector();

    Csg text;
    text.kind = CsgKind::Union;
    try {
        const double f = 1.0 / double(font->units_per_em());
        Vector3 pen{0, 0, 0};
        uint16_t previous = 0;
        for (size_t i = 0; i < codes.size(); ++i) {
            const TrueTypeFont::Glyph g = font->glyph(codes[i]);
            const TrueTypeFont::Metrics m = font->metrics(g.metrics);
            Vector3 place{0, 0, 0};
            if (i == 0) {
                // The first glyph's ink starts at x = 0; no kerning before it.
                place.x = -double(g.xmin) * f;
                pen = {double(m.advance - m.lsb) * f, 0, 0};
            } else {
                int kx, ky;
                font->kerning(previous, g.metrics, kx, ky);
                place.x = pen.x + double(m.lsb - g.xmin + kx) * f;
                place.y = pen.y + double(ky) * f;
                pen.x += double(m.advance + kx) * f;
            }
            // The offset moves the pen after every character; its z never reaches a
            // glyph.
            pen = pen + offset;
            Object child;
            child.loc = out.loc;
            child.shape = Glyph{g.outline, depth};
            child.transform = CompactTransform(Transform::translate(place));
            text.children.push_back(std::move(child));
            previous = g.index;
        }
    } catch (const FontError& e) {
        error(string_at, std::string("cannot read TrueType font: ") + e.what());
    }
    text.pov_box = laid_out_text_box(text);
    out.shape = std::move(text);
    // POV-Ray turns every text a little "to fix cracks in text that lies along an axis",
    // before any modifier.
    apply_transform(out, Transform::rotate({0.001, 0.001, 0.001}));
}

}  // namespace povwall::parser
