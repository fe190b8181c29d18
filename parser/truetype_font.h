// A TrueType font read as POV-Ray 3.7 reads it for `text` (its truetype.cpp, described in
// docs: cmap by platform only, kerning from format-0 `kern` subtables, glyph outlines
// from `glyf` with POV-Ray's composite rules and box widening). Only the tables POV-Ray
// uses are decoded; every read is bounds-checked, a corrupt font is a FontError.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/scene.h"

namespace povwall::parser {

struct FontError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class TrueTypeFont {
  public:
    // `unicode_first`: the cmap platform preference of the utf8 charset (Unicode, then
    // Microsoft, then Macintosh); otherwise ascii's (Macintosh first).
    TrueTypeFont(std::vector<uint8_t> bytes, bool unicode_first);

    struct Metrics {
        uint16_t advance = 0;
        int16_t lsb = 0;
    };
    // One loaded glyph as POV-Ray caches it.
    struct Glyph {
        uint32_t code = 0;     // the character it was first loaded for
        uint16_t index = 0;    // its cmap glyph index
        uint16_t metrics = 0;  // the hmtx entry it uses (USE_MY_METRICS)
        int16_t xmin = 0, ymin = 0, xmax = 0, ymax = 0;  // effective header box, FUnits
        std::shared_ptr<const GlyphOutline> outline;
    };

    int units_per_em() const { return units_per_em_; }
    int glyph_count() const { return num_glyphs_; }
    // The cmap's glyph index for a character code.
    uint16_t glyph_index(uint32_t code);
    // The glyph for a character: cached by code, then by glyph index (POV-Ray's order).
    const Glyph& glyph(uint32_t code);
    Metrics metrics(uint16_t index) const;
    // POV-Ray's kerning between the previous character's cmap index and the current one's
    // metrics index, in FUnits (x, y).
    void kerning(uint16_t prev, uint16_t cur, int& kx, int& ky) const;

  private:
    struct Outline {
        std::vector<uint16_t> end_points;
        std::vector<uint8_t> flags;
        std::vector<double> x, y;  // em units
        int16_t xmin = 0, ymin = 0, xmax = 0, ymax = 0;
        int contours = 0;
        uint16_t metrics = 0;
    };
    struct KernPair {
        uint16_t left, right;
        int16_t value;
    };
    struct KernTable {
        uint16_t coverage = 0;
        std::vector<KernPair> pairs;
    };

    uint16_t cmap_lookup(uint32_t code);
    uint16_t format4_lookup(uint32_t offset, uint32_t code);
    Outline read_outline(uint16_t index, uint32_t code, int depth);
    std::shared_ptr<const GlyphOutline> to_segments(const Outline& o) const;

    std::vector<uint8_t> bytes_;
    bool unicode_first_;
    int units_per_em_ = 0;
    int index_to_loc_format_ = 0;
    int num_glyphs_ = 0;
    uint32_t cmap_ = 0, glyf_ = 0;
    std::vector<uint32_t> loca_;
    std::vector<Metrics> hmtx_;
    std::vector<KernTable> kern_;
    // The first format-4 subtable used (POV-Ray keeps its segment arrays).
    bool format4_read_ = false;
    std::vector<uint16_t> end_code_, start_code_, id_delta_, id_range_offset_;
    uint32_t id_range_offset_at_ = 0;
    std::vector<Glyph> glyphs_;  // newest first, as POV-Ray's list
};

}  // namespace povwall::parser
