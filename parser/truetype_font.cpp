#include "parser/truetype_font.h"

#include <algorithm>

namespace povwall::parser {
namespace {

const char* const kShortRead = "the file ends inside a table (corrupt font)";

// Big-endian reads at an offset, checked against the file's size.
struct Bytes {
    const std::vector<uint8_t>& b;
    uint32_t need(uint64_t at, uint64_t n) const {
        if (at + n > b.size()) throw FontError(kShortRead);
        return uint32_t(at);
    }
    uint8_t u8(uint64_t at) const { return b[need(at, 1)]; }
    uint16_t u16(uint64_t at) const {
        const uint32_t i = need(at, 2);
        return uint16_t(b[i] << 8 | b[i + 1]);
    }
    int16_t s16(uint64_t at) const { return int16_t(u16(at)); }
    uint32_t u32(uint64_t at) const {
        const uint32_t i = need(at, 4);
        return uint32_t(b[i]) << 24 | uint32_t(b[i + 1]) << 16 | uint32_t(b[i + 2]) << 8 |
               b[i + 3];
    }
};

// Simple-glyph flag bits.
constexpr uint8_t kOnCurve = 1, kXShort = 2, kYShort = 4, kRepeat = 8, kXSame = 16,
                  kYSame = 32;
// Composite component flag bits.
constexpr uint16_t kArgsAreWords = 1, kArgsAreXY = 2, kHaveScale = 8,
                   kMoreComponents = 32, kHaveXYScale = 64, kHaveTwoByTwo = 128,
                   kUseMyMetrics = 512;
// Composite glyphs nest this deep at most (fonts use 2 or 3 levels; a loop is corrupt).
constexpr int kMaxCompositeDepth = 16;
// POV-Ray scans this many table-directory entries.
constexpr uint32_t kMaxTables = 40;

}  // namespace

TrueTypeFont::TrueTypeFont(std::vector<uint8_t> bytes, bool unicode_first)
    : bytes_(std::move(bytes)), unicode_first_(unicode_first) {
    const Bytes in{bytes_};
    uint64_t dir = 0;
    if (bytes_.size() >= 4 && std::equal(bytes_.begin(), bytes_.begin() + 4, "ttcf"))
        dir = in.u32(12);  // a collection: its first font
    const uint32_t num_tables = in.u16(dir + 4);
    uint32_t head = 0, loca = 0, maxp = 0, kern = 0, hhea = 0, hmtx = 0;
    bool has_cff = false;
    for (uint32_t i = 0; i < num_tables && i < kMaxTables; ++i) {
        const uint64_t e = dir + 12 + 16 * uint64_t(i);
        in.need(e, 16);
        const std::string tag(reinterpret_cast<const char*>(&bytes_[e]), 4);
        const uint32_t offset = in.u32(e + 8);
        if (tag == "cmap")
            cmap_ = offset;
        else if (tag == "glyf")
            glyf_ = offset;
        else if (tag == "head")
            head = offset;
        else if (tag == "loca")
            loca = offset;
        else if (tag == "maxp")
            maxp = offset;
        else if (tag == "kern")
            kern = offset;
        else if (tag == "hhea")
            hhea = offset;
        else if (tag == "hmtx")
            hmtx = offset;
        else if (tag == "CFF " || tag == "CFF2")
            has_cff = true;
    }
    if (in.u32(uint64_t(head) + 12) != 0x5F0F3CF5u)
        throw FontError("not a TrueType font (no 'head' table with its magic number)");
    if (glyf_ == 0 || loca == 0)
        throw FontError(has_cff
                            ? "an OpenType font with CFF outlines: POV-Ray reads only "
                              "TrueType ('glyf') outlines"
                            : "no 'glyf' and 'loca' tables: POV-Ray reads only "
                              "TrueType outlines");
    if (cmap_ == 0 || maxp == 0 || hhea == 0 || hmtx == 0)
        throw FontError("a required table (cmap, maxp, hhea or hmtx) is missing");
    units_per_em_ = in.u16(uint64_t(head) + 18);
    if (units_per_em_ == 0) throw FontError("unitsPerEm is 0");
    index_to_loc_format_ = in.s16(uint64_t(head) + 50);
    num_glyphs_ = in.u16(uint64_t(maxp) + 4);
    loca_.resize(size_t(num_glyphs_));
    for (int i = 0; i < num_glyphs_; ++i)
        loca_[size_t(i)] = index_to_loc_format_ == 0
                               ? uint32_t(in.u16(uint64_t(loca) + 2 * uint64_t(i))) << 1
                               : in.u32(uint64_t(loca) + 4 * uint64_t(i));
    const int long_metrics = std::min<int>(in.u16(uint64_t(hhea) + 34), num_glyphs_);
    hmtx_.resize(size_t(num_glyphs_));
    uint16_t last_advance = 0;
    for (int i = 0; i < num_glyphs_; ++i) {
        Metrics& m = hmtx_[size_t(i)];
        if (i < long_metrics) {
            last_advance = m.advance = in.u16(uint64_t(hmtx) + 4 * uint64_t(i));
            m.lsb = in.s16(uint64_t(hmtx) + 4 * uint64_t(i) + 2);
        } else {
            m.advance = last_advance;
            m.lsb = in.s16(uint64_t(hmtx) + 4 * uint64_t(long_metrics) +
                           2 * uint64_t(i - long_metrics));
        }
    }
    if (kern != 0) {
        // The Microsoft layout: 16-bit version and count, then subtables of version,
        // length, coverage; only format 0 (coverage >> 8 == 0) holds pairs.
        const uint32_t count = in.u16(uint64_t(kern) + 2);
        uint64_t at = uint64_t(kern) + 4;
        kern_.resize(count);
        for (uint32_t i = 0; i < count; ++i) {
            const uint16_t length = in.u16(at + 2);
            kern_[i].coverage = in.u16(at + 4);
            if ((kern_[i].coverage >> 8) == 0) {
                const uint32_t pairs = in.u16(at + 6);
                in.need(at + 14, 6 * uint64_t(pairs));
                kern_[i].pairs.resize(pairs);
                for (uint32_t k = 0; k < pairs; ++k) {
                    const uint64_t p = at + 14 + 6 * uint64_t(k);
                    kern_[i].pairs[k] = {in.u16(p), in.u16(p + 2), in.s16(p + 4)};
                }
                at += 14 + 6 * uint64_t(pairs);
            } else {
                at += length;
            }
        }
    }
}

TrueTypeFont::Metrics TrueTypeFont::metrics(uint16_t index) const {
    if (index >= hmtx_.size())
        throw FontError("glyph " + std::to_string(index) + " has no horizontal metrics");
    return hmtx_[index];
}

void TrueTypeFont::kerning(uint16_t prev, uint16_t cur, int& kx, int& ky) const {
    int16_t x = 0, y = 0;
    int16_t min_x = int16_t(-units_per_em_), min_y = int16_t(-units_per_em_);
    // POV-Ray reads the coverage of the first subtable and applies it to all of them.
    const uint16_t coverage = kern_.empty() ? 0 : kern_[0].coverage;
    for (const KernTable& table : kern_) {
        if (!(coverage & 1)) continue;  // not horizontal
        for (const KernPair& p : table.pairs) {
            if (p.left == prev && p.right == cur) {
                if (coverage & 2) {  // minimum
                    ((coverage & 4) ? min_y : min_x) = p.value;
                } else if (coverage & 4) {  // cross-stream
                    if (p.value == int16_t(-32768))
                        y = 0;
                    else
                        y = (coverage & 8) ? p.value : int16_t(y + p.value);
                } else {
                    x = (coverage & 8) ? p.value : int16_t(x + p.value);
                }
                break;
            }
            if (p.left > prev) break;
        }
    }
    kx = std::max(x, min_x);
    ky = std::max(y, min_y);
}

uint16_t TrueTypeFont::glyph_index(uint32_t code) { return cmap_lookup(code); }

uint16_t TrueTypeFont::cmap_lookup(uint32_t code) {
    const Bytes in{bytes_};
    const uint32_t count = in.u16(uint64_t(cmap_) + 2);
    static constexpr int kAscii[4] = {1, 3, 0, 3}, kUnicode[4] = {0, 3, 1, 3};
    const int* order = unicode_first_ ? kUnicode : kAscii;
    for (int j = 0; j < 4; ++j) {
        for (uint32_t i = 0; i < count; ++i) {
            const uint64_t e = uint64_t(cmap_) + 4 + 8 * uint64_t(i);
            if (in.u16(e) != order[j]) continue;  // the platform only, as POV-Ray
            const uint64_t sub = uint64_t(cmap_) + in.u32(e + 4);
            const uint16_t format = in.u16(sub);
            if (format == 0) return in.u8(sub + 6 + code);
            if (format == 4) return format4_lookup(uint32_t(sub), code);
            if (format == 6) {
                const uint32_t first = in.u16(sub + 6), n = in.u16(sub + 8);
                if (code >= first && code < first + n)
                    return in.u16(sub + 10 + 2 * uint64_t(code - first));
                return 0;
            }
        }
    }
    return 0;
}

uint16_t TrueTypeFont::format4_lookup(uint32_t sub, uint32_t code) {
    const Bytes in{bytes_};
    if (!format4_read_) {
        const uint32_t segs = in.u16(uint64_t(sub) + 6) >> 1;
        const uint64_t ends = uint64_t(sub) + 14, starts = ends + 2 * uint64_t(segs) + 2;
        const uint64_t deltas = starts + 2 * uint64_t(segs),
                       ranges = deltas + 2 * uint64_t(segs);
        in.need(ends, 8 * uint64_t(segs) + 2);
        for (uint32_t i = 0; i < segs; ++i) {
            end_code_.push_back(in.u16(ends + 2 * i));
            start_code_.push_back(in.u16(starts + 2 * i));
            id_delta_.push_back(in.u16(deltas + 2 * i));
            id_range_offset_.push_back(in.u16(ranges + 2 * i));
        }
        id_range_offset_at_ = uint32_t(ranges);
        format4_read_ = true;
    }
    uint32_t index = 0;
    for (int attempt = 0; attempt < 2; ++attempt) {
        for (size_t i = 0; i < end_code_.size(); ++i) {
            if (code > end_code_[i]) continue;
            if (code >= start_code_[i]) {
                if (id_range_offset_[i] == 0) {
                    index = code + id_delta_[i];
                } else {
                    index =
                        in.u16(uint64_t(id_range_offset_at_) + 2 * i +
                               id_range_offset_[i] + 2 * uint64_t(code - start_code_[i]));
                    if (index != 0) index += id_delta_[i];
                }
            }
            break;
        }
        // Symbol fonts map their 8-bit codes at 0xF000.
        if (index != 0 || code >= 0x100) break;
        code += 0xF000;
    }
    return uint16_t(index);
}

TrueTypeFont::Outline TrueTypeFont::read_outline(uint16_t index, uint32_t code,
                                                 int depth) {
    if (depth > kMaxCompositeDepth)
        throw FontError("composite glyphs nested deeper than " +
                        std::to_string(kMaxCompositeDepth) + " (corrupt font)");
    const Bytes in{bytes_};
    Outline o;
    o.metrics = index;
    if (code == ' ') return o;  // POV-Ray reads nothing for a space
    if (index >= loca_.size())
        throw FontError("glyph " + std::to_string(index) + " is past the font's " +
                        std::to_string(num_glyphs_) + " glyphs");
    // An empty glyph's offset is the next glyph's: POV-Ray reads that one's data.
    uint64_t at = uint64_t(glyf_) + loca_[index];
    int contours = in.s16(at);
    o.xmin = in.s16(at + 2);
    o.ymin = in.s16(at + 4);
    o.xmax = in.s16(at + 6);
    o.ymax = in.s16(at + 8);
    at += 10;
    const double upem = units_per_em_;
    if (contours > 0) {
        o.contours = contours;
        for (int i = 0; i < contours; ++i) o.end_points.push_back(in.u16(at + 2 * i));
        at += 2 * uint64_t(contours);
        at += 2 + uint64_t(in.u16(at));  // instructions
        const size_t n = size_t(o.end_points.back()) + 1;
        o.flags.assign(n, 0);
        for (size_t i = 0; i < n; ++i) {
            o.flags[i] = in.u8(at++);
            if (o.flags[i] & kRepeat) {
                for (int r = in.u8(at++); r > 0; --r, ++i)
                    if (i + 1 < n) o.flags[i + 1] = o.flags[i];
            }
        }
        for (int axis = 0; axis < 2; ++axis) {
            const uint8_t short_bit = axis ? kYShort : kXShort;
            const uint8_t same_bit = axis ? kYSame : kXSame;
            std::vector<double>& v = axis ? o.y : o.x;
            int16_t& lo = axis ? o.ymin : o.xmin;
            int16_t& hi = axis ? o.ymax : o.xmax;
            int16_t coord = 0;  // FWord: running sums wrap at 16 bits
            v.resize(n);
            for (size_t i = 0; i < n; ++i) {
                const uint8_t f = o.flags[i];
                if (f & short_bit) {
                    const int d = in.u8(at++);
                    coord = int16_t((f & same_bit) ? coord + d : coord - d);
                } else if (!(f & same_bit)) {
                    coord = int16_t(coord + in.s16(at));
                    at += 2;
                }
                hi = std::max(hi, coord);
                lo = std::min(lo, coord);
                v[i] = double(coord) / upem;
            }
        }
    } else if (contours < 0) {
        uint16_t flags;
        do {
            flags = in.u16(at);
            const uint16_t sub_index = in.u16(at + 2);
            at += 4;
            int arg1, arg2;
            if (flags & kArgsAreWords) {
                arg1 = in.s16(at);
                arg2 = in.s16(at + 2);
                at += 4;
            } else {  // POV-Ray reads the byte offsets unsigned
                arg1 = in.u8(at);
                arg2 = in.u8(at + 1);
                at += 2;
            }
            double a = 1, b = 0, c = 0, d = 1;
            auto f2dot14 = [&](uint64_t p) { return double(in.s16(p)) / 0x4000; };
            if (flags & kHaveScale) {
                a = d = f2dot14(at);
                at += 2;
            } else if (flags & kHaveXYScale) {
                a = f2dot14(at);
                d = f2dot14(at + 2);
                at += 4;
            } else if (flags & kHaveTwoByTwo) {
                a = f2dot14(at);
                b = f2dot14(at + 2);
                c = f2dot14(at + 4);
                d = f2dot14(at + 6);
                at += 8;
            }
            if (!(flags & kArgsAreXY)) continue;  // point matching: POV-Ray drops it
            if (flags & kUseMyMetrics) o.metrics = sub_index;
            const double dx = arg1 / upem, dy = arg2 / upem;
            const Outline sub = read_outline(sub_index, code, depth + 1);
            if (sub.contours == 0) continue;
            const size_t base = o.x.size();
            for (uint16_t e : sub.end_points) o.end_points.push_back(uint16_t(e + base));
            o.contours += sub.contours;
            for (size_t i = 0; i < sub.x.size(); ++i) {
                o.flags.push_back(sub.flags[i]);
                // POV-Ray's mapping is the transpose of the specification's.
                const double x = a * sub.x[i] + b * sub.y[i] + dx;
                const double y = c * sub.x[i] + d * sub.y[i] + dy;
                o.x.push_back(x);
                o.y.push_back(y);
                // It widens the FUnit header by em coordinates, truncating to integers.
                if (x < o.xmin) o.xmin = int16_t(x);
                if (x > o.xmax) o.xmax = int16_t(x);
                if (y < o.ymin) o.ymin = int16_t(y);
                if (y > o.ymax) o.ymax = int16_t(y);
            }
        } while (flags & kMoreComponents);
    }
    return o;
}

std::shared_ptr<const GlyphOutline> TrueTypeFont::to_segments(const Outline& o) const {
    auto g = std::make_shared<GlyphOutline>();
    const double f = 1.0 / double(units_per_em_);
    g->xmin = double(o.xmin) * f;
    g->ymin = double(o.ymin) * f;
    g->xmax = double(o.xmax) * f;
    g->ymax = double(o.ymax) * f;
    size_t first = 0;
    for (int c = 0; c < o.contours; ++c) {
        const size_t end = size_t(o.end_points[size_t(c)]) + 1;
        if (end < first || end > o.x.size())
            throw FontError("contour end points out of order (corrupt font)");
        const size_t n = end - first;
        if (n == 0) continue;
        // The contour closes on a copy of its first point; that point starts it, taken
        // as on-curve whatever its flag.
        auto px = [&](size_t j) { return o.x[first + (j == n ? 0 : j)]; };
        auto py = [&](size_t j) { return o.y[first + (j == n ? 0 : j)]; };
        auto on = [&](size_t j) {
            return (o.flags[first + (j == n ? 0 : j)] & kOnCurve) != 0;
        };
        double sx = px(0), sy = py(0);
        for (size_t j = 1; j <= n; ++j) {
            if (on(j)) {
                g->segments.push_back({{sx, px(j), 0}, {sy, py(j), 0}, false});
                sx = px(j);
                sy = py(j);
                continue;
            }
            double ex, ey;
            if (j == n) {
                ex = px(0);
                ey = py(0);
            } else {
                ex = px(j + 1);
                ey = py(j + 1);
                if (!on(j + 1)) {
                    ex = 0.5 * (px(j) + ex);
                    ey = 0.5 * (py(j) + ey);
                }
            }
            g->segments.push_back({{sx, px(j), ex}, {sy, py(j), ey}, true});
            sx = ex;
            sy = ey;
        }
        first = end;
    }
    g->index();
    return g;
}

const TrueTypeFont::Glyph& TrueTypeFont::glyph(uint32_t code) {
    for (const Glyph& g : glyphs_)
        if (g.code == code) return g;
    const uint16_t index = cmap_lookup(code);
    for (const Glyph& g : glyphs_)
        if (g.index == index) return g;
    const Outline o = read_outline(index, code, 0);
    Glyph g;
    g.code = code;
    g.index = index;
    g.metrics = o.metrics;
    g.xmin = o.xmin;
    g.ymin = o.ymin;
    g.xmax = o.xmax;
    g.ymax = o.ymax;
    g.outline = to_segments(o);
    glyphs_.push_back(std::move(g));
    return glyphs_.back();
}

}  // namespace povwall::parser
