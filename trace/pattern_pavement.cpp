// POV-Ray 3.7's `pavement` pattern in the x-z plane: tilings by polyominoes (squares),
// polyiamonds (triangles) and polyhexes (hexagons, drawn on the triangle grid), written
// from a clean-room description of POV-Ray 3.7.0's pattern.cpp (its rules in prose and
// its tables in another layout; no code copied) and compared with POV-Ray's renders value
// for value (tests/trace/pattern_parsed_test.cpp).
// The plane is cut into cells, unit squares or unit equilateral triangles; each cell
// gets a code word from its tiling's table saying which of its sides are tile outline
// and which of its corners are concave corners or bends of the outline, and the value
// is computed inside the cell from that word alone: 0 in the middle of a tile, rising to
// 1 on the outline. Every expression keeps POV-Ray's order of operations, so that values
// agree to the last bit and boundaries fall on the same side.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "core/math_constants.h"
#include "core/pattern_lists.h"
#include "trace/pattern_internal.h"

namespace povwall::trace::detail {
namespace pavement {

// How a cell's indices (a, b) pick the position k of its code word in a tiling's list
// (mod is the non-negative remainder, idiv the floor of a quotient of non-negatives):
//   Grid (m, n)            k = mod(a, m) + m mod(b, n)                   (m n words)
//   Shift (m, c, n)        k = mod(a + c mod(b, n), m)                   (m words)
//   RowBlocks (m, c, p, n) q = mod(b, p); k = mod(a + c idiv(q, n), m) + m mod(q, n)
//   ColumnBlocks (m, c, p, n)  r = mod(a, p); k = mod(a, m) + m mod(b + c idiv(r, m), n)
//   Turn                   k = mod(a + mod(b, 4), 4) + 4 mod(b, 2)       (8 words)
// A tiling whose every cell has the same word is a 1 x 1 grid.
enum class Rule : uint8_t { Grid, Shift, RowBlocks, ColumnBlocks, Turn };

struct TilingText {
    uint8_t sides, tiles, pattern;
    Rule rule;
    int8_t m, c, p, n;
    std::string_view words;  // hex code words, in the order of k
};

// Square words: 01 top side outline (z = b + 1), 02 right (x = a + 1), 04 bottom, 08
// left; 10, 20, 40, 80 the corners top-left, top-right, bottom-right, bottom-left.
// Triangle words (in the cell turned onto the reference triangle L (0,0), R (1,0),
// T (1/2, sqrt3/2)): 001 side L-T, 002 side R-T, 004 side L-R; 080 no concave corners;
// 010/020/040 with 100/200/400 the bends of the outline (in pairs); 1000, 2000, 4000 a
// concave corner at R, L, T (hexagons).
// One line a tiling: sides, tiles, pattern; the rule and its m, c, p, n (0 where it has
// none; Turn's 8 words counted as 4 x 2); the words.
// clang-format off
constexpr TilingText kTilings[] = {
    {3, 1, 1, Rule::Grid, 1, 0, 0, 1, "0007"},
    {3, 2, 1, Rule::Grid, 1, 0, 0, 1, "0166"},
    {3, 3, 1, Rule::Shift, 6, 3, 0, 2, "0215 0344 0126 0126 0344 0215"},
    {3, 4, 1, Rule::Turn, 4, 0, 0, 2, "0126 0126 0144 0144 0126 0126 0144 0144"},
    {3, 4, 2, Rule::Turn, 4, 0, 0, 2, "0611 0344 0126 0423 0611 0344 0126 0423"},
    {3, 4, 3, Rule::Turn, 4, 0, 0, 2, "0005 0000 0006 0003 0000 0005 0003 0006"},
    {3, 5, 1, Rule::Shift, 10, 5, 0, 2, "0215 0244 0004 0144 0126 0126 0144 0004 0244 0215"},
    {3, 5, 2, Rule::Shift, 10, 5, 0, 2, "0215 0244 0244 0611 0611 0244 0244 0215 0423 0423"},
    {3, 5, 3, Rule::Shift, 10, 5, 0, 2, "0146 0126 0344 0611 0611 0344 0126 0146 0522 0522"},
    {3, 5, 4, Rule::Shift, 10, 3, 0, 10, "0005 0000 0244 0215 0003 0003 0215 0244 0000 0005"},
    {3, 6, 1, Rule::Shift, 6, 5, 0, 6, "0215 0244 0004 0004 0244 0215"},
    {3, 6, 2, Rule::Shift, 6, 5, 0, 6, "0413 0522 0144 0004 0244 0215"},
    {3, 6, 3, Rule::Shift, 6, 3, 0, 2, "0003 0126 0144 0000 0244 0215"},
    {3, 6, 4, Rule::RowBlocks, 6, 14, 6, 2, "0215 0244 0004 0000 0006 0003 0004 0244 0215 0003 0006 0000"},
    {3, 6, 5, Rule::RowBlocks, 6, 8, 6, 2, "0005 0000 0244 0215 0245 0211 0005 0211 0245 0215 0244 0000"},
    {3, 6, 6, Rule::Grid, 6, 0, 0, 2, "0245 0211 0215 0244 0244 0211 0245 0211 0244 0244 0215 0211"},
    {3, 6, 7, Rule::RowBlocks, 4, -1, 12, 3, "0215 0244 0244 0611 0522 0146 0146 0522 0611 0244 0244 0215"},
    {3, 6, 8, Rule::RowBlocks, 4, -1, 12, 3, "0005 0000 0244 0215 0146 0122 0122 0146 0215 0244 0000 0005"},
    {3, 6, 9, Rule::RowBlocks, 6, 8, 6, 2, "0005 0000 0006 0126 0344 0211 0005 0211 0344 0126 0006 0000"},
    {3, 6, 10, Rule::Shift, 6, 5, 0, 6, "0215 0344 0122 0122 0344 0215"},
    {3, 6, 11, Rule::Shift, 6, 3, 0, 2, "0005 0000 0006 0006 0000 0005"},
    {3, 6, 12, Rule::Shift, 6, 3, 0, 2, "0691 03C4 05A2 05A2 03C4 0691"},
    {4, 1, 1, Rule::Grid, 1, 0, 0, 1, "0F"},
    {4, 2, 1, Rule::Grid, 1, 0, 0, 2, "0E 0B"},
    {4, 3, 1, Rule::Grid, 3, 0, 0, 2, "0D 05 07 0D 05 07"},
    {4, 3, 2, Rule::Grid, 3, 0, 0, 2, "0E 0D 16 49 07 0B"},
    {4, 4, 1, Rule::Grid, 4, 0, 0, 4, "0D 05 05 07 0D 05 05 07 0D 05 05 07 0D 05 05 07"},
    {4, 4, 2, Rule::Grid, 4, 0, 0, 4, "0E 0D 05 16 49 05 07 0B 0E 0D 05 16 49 05 07 0B"},
    {4, 4, 3, Rule::Grid, 4, 0, 0, 4, "0D 34 07 0B 07 0B 0D 34 0D 34 07 0B 07 0B 0D 34"},
    {4, 4, 4, Rule::Grid, 4, 0, 0, 4, "0C 06 0C 06 09 03 09 03 0C 06 0C 06 09 03 09 03"},
    {4, 4, 5, Rule::Grid, 4, 0, 0, 4, "07 2C 07 2C 0D 83 0D 83 2C 07 2C 07 83 0D 83 0D"},
    {4, 5, 1, Rule::Grid, 5, 0, 0, 2, "0D 05 05 05 07 0D 05 05 05 07"},
    {4, 5, 2, Rule::Grid, 5, 0, 0, 2, "0E 0D 05 05 16 49 05 05 07 0B"},
    {4, 5, 3, Rule::RowBlocks, 5, 3, 10, 2, "07 0C 06 0C 24 0D 81 03 09 03"},
    {4, 5, 4, Rule::Shift, 5, 2, 0, 5, "0D 05 34 07 0B"},
    {4, 5, 5, Rule::Shift, 5, 2, 0, 5, "0D F0 07 0B 0E"},
    {4, 5, 6, Rule::Shift, 10, 1, 0, 10, "0E 0A 49 05 07 0D 05 16 0A 0B"},
    {4, 5, 7, Rule::Shift, 10, 1, 0, 10, "0B 0E 49 16 49 07 0D 16 49 16"},
    {4, 5, 8, Rule::Shift, 10, 3, 0, 10, "2C 05 16 0B 0E 0B 0E 49 05 83"},
    {4, 5, 9, Rule::Shift, 10, 1, 0, 10, "0E 49 05 16 0B 0E 49 05 16 0B"},
    {4, 5, 10, Rule::RowBlocks, 5, 3, 10, 2, "0E 0D C1 16 0B 49 34 07 0B 0E"},
    {4, 5, 11, Rule::RowBlocks, 5, 4, 10, 2, "07 2C 05 07 2C 0D 83 0D 05 83"},
    {4, 5, 12, Rule::Shift, 10, 8, 0, 10, "0D 34 07 0D C1 07 0A 0B 0E 0A"},
    {4, 6, 1, Rule::Grid, 6, 0, 0, 2, "0D 05 05 05 05 07 0D 05 05 05 05 07"},
    {4, 6, 2, Rule::Grid, 6, 0, 0, 2, "2C 05 05 05 07 0E 0B 0D 05 05 05 83"},
    {4, 6, 3, Rule::Grid, 6, 0, 0, 2, "0D 34 05 05 07 0E 07 0B 0D 05 05 C1"},
    {4, 6, 4, Rule::Grid, 6, 0, 0, 2, "0D 05 34 05 07 0E 05 07 0B 0D 05 C1"},
    {4, 6, 5, Rule::Shift, 6, 5, 0, 6, "0D 83 2C 05 05 07"},
    {4, 6, 6, Rule::Grid, 6, 0, 0, 2, "0C 24 05 07 0C 06 09 03 0D 05 81 03"},
    {4, 6, 7, Rule::Grid, 6, 0, 0, 2, "07 0C 06 0D 14 24 0D 81 41 07 09 03"},
    {4, 6, 8, Rule::Shift, 6, 5, 0, 6, "0D 05 83 2C 05 07"},
    {4, 6, 9, Rule::Grid, 6, 0, 0, 2, "07 0C 24 07 0C 24 0D 81 03 0D 81 03"},
    {4, 6, 10, Rule::Grid, 6, 0, 0, 2, "0C 04 06 0C 04 06 09 01 03 09 01 03"},
    {4, 6, 11, Rule::Grid, 4, 0, 0, 3, "0E 0D 14 06 48 06 09 12 09 41 07 0B"},
    {4, 6, 12, Rule::Shift, 6, 1, 0, 6, "0D 05 16 49 16 0B"},
    {4, 6, 13, Rule::Grid, 4, 0, 0, 3, "0D 34 05 16 0E 0B 0E 0B 49 05 C1 07"},
    {4, 6, 14, Rule::Grid, 3, 0, 0, 4, "0D 34 07 16 0A 0D 0A 49 07 C1 07 0D"},
    {4, 6, 15, Rule::RowBlocks, 3, 2, 6, 2, "0D 14 82 0E 09 03"},
    {4, 6, 16, Rule::ColumnBlocks, 2, 1, 6, 3, "0E 0D D0 06 09 03"},
    {4, 6, 17, Rule::RowBlocks, 6, 1, 12, 2, "0D F0 05 07 0E 0B 0E 0B 0D 05 F0 07"},
    {4, 6, 18, Rule::RowBlocks, 6, 1, 12, 2, "0E 0B 0D 05 05 92 68 05 05 07 0E 0B"},
    {4, 6, 19, Rule::Shift, 6, 1, 0, 6, "0E 49 05 16 0A 0B"},
    {4, 6, 20, Rule::Shift, 6, 5, 0, 6, "0B 2C 05 05 83 0E"},
    {4, 6, 21, Rule::Shift, 6, 5, 0, 6, "0B 0A 2C 05 05 07"},
    {4, 6, 22, Rule::Grid, 4, 0, 0, 3, "2C 05 05 16 0B 0E 0E 0B 05 83 49 05"},
    {4, 6, 23, Rule::Grid, 4, 0, 0, 3, "0A 0D C1 16 49 34 07 0A 0E 0B 0E 0B"},
    {4, 6, 24, Rule::RowBlocks, 6, 4, 12, 2, "0D 16 0D 05 92 0B 0E 68 05 07 49 07"},
    {4, 6, 25, Rule::Grid, 4, 0, 0, 3, "0D 16 0D 16 16 49 16 49 49 07 49 07"},
    {4, 6, 26, Rule::Grid, 4, 0, 0, 3, "0C 06 0C 06 09 12 09 12 07 49 07 49"},
    {4, 6, 27, Rule::Grid, 4, 0, 0, 3, "2C 07 2C 07 92 0D 92 0D 49 07 49 07"},
    {4, 6, 28, Rule::Shift, 6, 1, 0, 6, "0E 49 05 16 49 07"},
    {4, 6, 29, Rule::RowBlocks, 6, 4, 12, 2, "0D 16 0B 0E 49 07 16 49 05 83 2C 05"},
    {4, 6, 30, Rule::RowBlocks, 6, 3, 4, 2, "07 0E 49 34 07 49 0D C1 16 0B 0D 16"},
    {4, 6, 31, Rule::RowBlocks, 6, 3, 4, 2, "2C 05 C1 07 0E 0B 0B 0D 34 05 83 0E"},
    {4, 6, 32, Rule::Shift, 6, 4, 0, 3, "0E 0B 0D 34 C1 07"},
    {4, 6, 33, Rule::Grid, 3, 0, 0, 4, "0D 05 16 2C 07 0A 0A 0D 83 49 05 07"},
    {4, 6, 34, Rule::Shift, 12, 7, 0, 12, "2C C1 05 07 0E 0B 0E 0B 0D 05 34 83"},
    {4, 6, 35, Rule::RowBlocks, 4, 2, 6, 3, "0A 0D 05 92 68 05 07 0A 0B 0E 0E 0B"},
    {6, 1, 1, Rule::Shift, 6, 3, 0, 2, "0691 03C4 05A2 05A2 03C4 0691"},
    {6, 2, 1, Rule::Grid, 6, 0, 0, 2, "0691 03C4 01A2 01A2 03C4 0691 05A2 01C4 6080 6080 01C4 05A2"},
    {6, 3, 1, Rule::Grid, 6, 0, 0, 6, "0691 03C4 05A2 05A2 03C4 0691 05A2 03C4 0691 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0691 03C4 05A2"},
    {6, 3, 2, Rule::ColumnBlocks, 6, 2, 18, 6, "0691 03C4 01A2 01A2 03C4 0691 05A2 01C4 4080 2080 2080 04A2 0691 02C4 4080 1080 1080 0491 05A2 03C4 0291 0291 03C4 05A2 0491 1080 1080 4080 02C4 0691 04A2 2080 2080 4080 01C4 05A2"},
    {6, 3, 3, Rule::Grid, 18, 0, 0, 2, "0691 03C4 01A2 01A2 03C4 0291 0291 03C4 05A2 05A2 01C4 6080 6080 00C4 5080 5080 02C4 0691 05A2 01C4 6080 6080 00C4 5080 5080 02C4 0691 0691 03C4 01A2 01A2 03C4 0291 0291 03C4 05A2"},
    {6, 4, 1, Rule::Grid, 6, 0, 0, 8, "0691 03C4 05A2 05A2 03C4 0691 05A2 03C4 0691 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0691 03C4 05A2"},
    {6, 4, 2, Rule::ColumnBlocks, 6, 2, 12, 8, "0691 02C4 4080 1080 0080 2080 4080 02C4 0691 0291 03C4 01A2 4080 01C4 05A2 01A2 03C4 0291 05A2 01C4 4080 2080 0080 1080 0691 02C4 4080 1080 0080 2080 4080 02C4 0691 0291 03C4 01A2 4080 01C4 05A2 01A2 03C4 0291 05A2 01C4 4080 2080 0080 1080"},
    {6, 4, 3, Rule::Grid, 12, 0, 0, 2, "0691 02C4 5080 5080 00C4 6080 6080 00C4 5080 5080 02C4 0691 05A2 03C4 0291 0291 03C4 01A2 01A2 03C4 0291 0291 03C4 05A2"},
    {6, 4, 4, Rule::ColumnBlocks, 6, -2, 24, 8, "0691 03C4 05A2 04A2 3080 0491 01A2 03C4 0691 0691 03C4 05A2 6080 01C4 05A2 01A2 03C4 0691 05A2 01C4 6080 6080 01C4 05A2 0491 3080 00A2 05A2 01C4 6080 04A2 3080 0491 0491 3080 00A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2"},
    {6, 4, 5, Rule::ColumnBlocks, 6, -2, 24, 8, "0691 03C4 01A2 05A2 01C4 6080 5080 02C4 0691 0491 3080 00A2 0291 03C4 05A2 04A2 3080 0091 05A2 03C4 0291 0691 02C4 5080 0691 02C4 5080 5080 02C4 0691 01A2 03C4 0691 0091 3080 04A2 6080 01C4 05A2 00A2 3080 0491 05A2 01C4 6080 6080 01C4 05A2"},
    {6, 4, 6, Rule::ColumnBlocks, 6, -2, 24, 8, "0691 03C4 05A2 00A2 3080 0491 05A2 01C4 4080 2080 2080 04A2 0691 02C4 4080 1080 1080 0491 05A2 03C4 0291 0291 03C4 05A2 0491 1080 1080 4080 02C4 0691 04A2 2080 2080 4080 01C4 05A2 0491 3080 00A2 05A2 03C4 0691 04A2 3080 0491 0491 3080 04A2"},
    {6, 4, 7, Rule::Grid, 12, 0, 0, 4, "0691 03C4 05A2 01A2 03C4 0691 0091 3080 00A2 05A2 03C4 0291 5080 00C4 6080 6080 01C4 05A2 04A2 3080 0491 0691 02C4 5080 0091 3080 00A2 05A2 03C4 0291 0691 03C4 05A2 01A2 03C4 0691 04A2 3080 0491 0691 02C4 5080 5080 00C4 6080 6080 01C4 05A2"},
    {6, 5, 1, Rule::Grid, 6, 0, 0, 10, "0691 03C4 05A2 05A2 03C4 0691 05A2 03C4 0691 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0691 03C4 05A2"},
    {6, 5, 2, Rule::ColumnBlocks, 6, -2, 30, 10, "6080 01C4 05A2 01A2 03C4 0691 05A2 01C4 6080 6080 01C4 05A2 0491 3080 00A2 05A2 01C4 6080 04A2 3080 0491 0491 3080 00A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0691 03C4 05A2 04A2 3080 0491 01A2 03C4 0691 0691 03C4 05A2"},
    {6, 5, 3, Rule::Grid, 6, 0, 0, 10, "0691 03C4 01A2 01A2 03C4 0691 05A2 01C4 4080 2080 2080 04A2 0691 02C4 4080 1080 1080 0491 05A2 03C4 0691 0091 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0091 0691 03C4 05A2 0491 1080 1080 4080 02C4 0691 04A2 2080 2080 4080 01C4 05A2"},
    {6, 5, 4, Rule::Grid, 6, 0, 0, 10, "0691 03C4 05A2 00A2 3080 0491 05A2 01C4 4080 2080 2080 04A2 0691 02C4 4080 1080 1080 0491 05A2 03C4 0691 0091 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0091 0691 03C4 05A2 0491 1080 1080 4080 02C4 0691 04A2 2080 2080 4080 01C4 05A2 0491 3080 00A2 05A2 03C4 0691 04A2 3080 0491 0491 3080 04A2"},
    {6, 5, 5, Rule::ColumnBlocks, 6, -2, 30, 10, "6080 01C4 05A2 00A2 3080 0491 05A2 01C4 6080 6080 01C4 05A2 0491 3080 00A2 05A2 01C4 6080 04A2 3080 0491 0491 3080 00A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0691 03C4 05A2 04A2 3080 0491 05A2 03C4 0691 0691 03C4 05A2 0491 3080 04A2 05A2 03C4 0691 00A2 3080 0491 0491 3080 04A2"},
    {6, 5, 6, Rule::Grid, 6, 0, 0, 10, "0691 03C4 01A2 01A2 03C4 0691 05A2 01C4 4080 2080 2080 04A2 0491 1080 0080 0080 1080 0491 04A2 2080 2080 4080 01C4 05A2 0491 3080 00A2 05A2 03C4 0691 04A2 3080 0491 0491 3080 04A2 0691 03C4 05A2 00A2 3080 0491 05A2 01C4 4080 2080 2080 04A2 0491 1080 0080 0080 1080 0491 04A2 2080 2080 4080 01C4 05A2"},
    {6, 5, 7, Rule::Grid, 6, 0, 0, 10, "0691 02C4 4080 1080 1080 0491 05A2 03C4 0291 0291 03C4 05A2 0491 1080 1080 4080 02C4 0691 04A2 2080 0080 0080 2080 04A2 0491 1080 0080 0080 1080 0491 04A2 2080 2080 4080 01C4 05A2 0691 03C4 01A2 01A2 03C4 0691 05A2 01C4 4080 2080 2080 04A2 0491 1080 0080 0080 1080 0491 04A2 2080 0080 0080 2080 04A2"},
    {6, 5, 8, Rule::ColumnBlocks, 3, -7, 60, 20, "6080 01C4 05A2 05A2 01C4 4080 0691 02C4 4080 4080 02C4 0691 4080 01C4 05A2 05A2 01C4 6080 0691 03C4 01A2 05A2 01C4 6080 0491 3080 00A2 04A2 3080 0091 0491 1080 1080 04A2 2080 2080 0691 03C4 01A2 01A2 03C4 0691 2080 2080 04A2 1080 1080 0491 0091 3080 04A2 00A2 3080 0491 6080 01C4 05A2 01A2 03C4 0691"},
    {6, 5, 9, Rule::ColumnBlocks, 6, 2, 30, 10, "6080 00C4 5080 5080 02C4 0291 05A2 03C4 0291 0291 02C4 5080 0691 02C4 5080 5080 02C4 0691 5080 02C4 0691 0091 3080 04A2 0091 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0691 03C4 05A2 00A2 3080 0491 05A2 01C4 6080 6080 01C4 05A2 0691 03C4 01A2 05A2 01C4 6080 01A2 03C4 0291 0691 03C4 01A2"},
    {6, 5, 10, Rule::ColumnBlocks, 6, -2, 30, 10, "0691 03C4 01A2 01A2 03C4 0691 5080 00C4 6080 6080 01C4 05A2 0291 03C4 01A2 01A2 03C4 0291 05A2 01C4 6080 6080 00C4 5080 0491 3080 00A2 05A2 03C4 0691 06A2 3080 0491 0491 3080 04A2 0691 03C4 05A2 00A2 3080 0491 5080 00C4 6080 6080 01C4 05A2 0291 03C4 01A2 01A2 03C4 0291 05A2 01C4 6080 6080 00C4 5080"},
    {6, 5, 11, Rule::ColumnBlocks, 6, 2, 30, 10, "0691 03C4 01A2 01A2 03C4 0691 05A2 01C4 4080 2080 2080 04A2 0491 1080 0080 0080 1080 0091 04A2 2080 2080 4080 00C4 5080 0691 03C4 01A2 05A2 03C4 0291 5080 02C4 0691 0691 02C4 5080 0291 03C4 05A2 01A2 03C4 0691 5080 00C4 4080 2080 2080 04A2 0091 1080 0080 0080 1080 0491 04A2 2080 2080 4080 01C4 05A2"},
    {6, 5, 12, Rule::ColumnBlocks, 6, -6, 30, 10, "0291 03C4 05A2 01A2 03C4 0691 4080 00C4 4080 2080 2080 04A2 4080 00C4 4080 1080 1080 0491 05A2 03C4 0291 0291 03C4 05A2 0491 1080 1080 4080 00C4 4080 04A2 2080 2080 4080 00C4 4080 0691 03C4 01A2 05A2 03C4 0291 01A2 03C4 0691 0491 1080 1080 2080 2080 04A2 04A2 2080 2080 1080 1080 0491 0691 03C4 01A2"},
    {6, 5, 13, Rule::ColumnBlocks, 6, 6, 30, 10, "0691 02C4 5080 5080 02C4 0691 5080 02C4 0691 0091 3080 04A2 0291 03C4 05A2 00A2 3080 0491 5080 00C4 6080 6080 01C4 05A2 0291 03C4 01A2 01A2 03C4 0291 05A2 01C4 6080 6080 00C4 5080 0491 3080 00A2 05A2 03C4 0291 04A2 3080 0091 0691 02C4 5080 0691 02C4 5080 5080 02C4 0691 05A2 03C4 0291 0291 03C4 05A2"},
    {6, 5, 14, Rule::ColumnBlocks, 6, 2, 30, 10, "0691 03C4 05A2 05A2 03C4 0691 05A2 03C4 0691 0491 3080 04A2 0491 3080 04A2 04A2 3080 0091 04A2 3080 0091 0691 02C4 5080 0691 02C4 5080 5080 02C4 0291 5080 02C4 0291 0291 02C4 5080 0291 02C4 5080 5080 02C4 0691 5080 02C4 0691 0091 3080 04A2 0091 3080 04A2 04A2 3080 0491 04A2 3080 0491 0691 03C4 05A2"},
    {6, 5, 15, Rule::ColumnBlocks, 6, 2, 30, 10, "0291 03C4 05A2 05A2 03C4 0691 05A2 03C4 0691 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0491 3080 04A2 04A2 3080 0091 04A2 3080 0091 0691 02C4 5080 0691 02C4 5080 5080 02C4 0291 5080 02C4 0291 0291 02C4 5080 0291 02C4 5080 5080 02C4 0691 5080 02C4 0691 0291 03C4 05A2"},
    {6, 5, 16, Rule::ColumnBlocks, 6, 2, 30, 10, "0691 02C4 5080 5080 00C4 4080 01A2 03C4 0691 0291 02C4 4080 2080 2080 04A2 05A2 03C4 0691 1080 1080 0491 0491 3080 04A2 0091 3080 04A2 04A2 3080 0091 04A2 3080 0491 0491 1080 1080 0691 03C4 05A2 04A2 2080 2080 4080 02C4 0291 0691 03C4 01A2 4080 00C4 5080 5080 02C4 0691 05A2 03C4 0291 0291 03C4 05A2"},
    {6, 5, 17, Rule::ColumnBlocks, 6, -6, 30, 10, "4080 01C4 01A2 01A2 01C4 4080 05A2 01C4 6080 6080 00C4 4080 0691 03C4 01A2 05A2 03C4 0691 01A2 03C4 0691 0491 3080 04A2 2080 2080 04A2 04A2 3080 0091 1080 1080 0491 0491 1080 1080 0091 3080 04A2 04A2 2080 2080 04A2 3080 0491 0691 03C4 01A2 0691 03C4 05A2 01A2 03C4 0691 4080 00C4 6080 6080 01C4 05A2"},
    {6, 5, 18, Rule::ColumnBlocks, 6, 2, 30, 10, "0291 03C4 01A2 01A2 03C4 0291 05A2 01C4 6080 6080 00C4 5080 0691 03C4 01A2 05A2 03C4 0691 5080 02C4 0691 0491 3080 04A2 0091 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0491 3080 04A2 04A2 3080 0091 04A2 3080 0491 0691 02C4 5080 0691 03C4 05A2 01A2 03C4 0691 5080 00C4 6080 6080 01C4 05A2"},
    {6, 5, 19, Rule::ColumnBlocks, 6, 6, 30, 10, "0091 3080 04A2 05A2 03C4 0691 04A2 3080 0491 0491 3080 04A2 0691 03C4 05A2 00A2 3080 0091 05A2 01C4 6080 6080 00C4 5080 0691 03C4 01A2 01A2 03C4 0691 5080 00C4 6080 6080 01C4 05A2 0091 3080 00A2 05A2 03C4 0691 04A2 3080 0491 0491 3080 04A2 0691 03C4 05A2 04A2 3080 0091 5080 02C4 0691 0691 02C4 5080"},
    {6, 5, 20, Rule::Grid, 6, 0, 0, 10, "0691 03C4 01A2 01A2 03C4 0691 05A2 01C4 4080 2080 2080 04A2 0691 02C4 4080 1080 1080 0091 5080 02C4 0691 0291 02C4 5080 0091 3080 04A2 05A2 03C4 0691 04A2 3080 0491 0491 3080 04A2 0691 03C4 05A2 04A2 3080 0091 5080 02C4 0291 0691 02C4 5080 0091 1080 1080 4080 02C4 0691 04A2 2080 2080 4080 01C4 05A2"},
    {6, 5, 21, Rule::ColumnBlocks, 6, 2, 30, 10, "0291 03C4 05A2 05A2 03C4 0691 05A2 03C4 0691 0491 3080 04A2 0491 3080 04A2 04A2 3080 0091 04A2 3080 0091 0691 02C4 5080 0691 02C4 5080 5080 02C4 0691 5080 02C4 0691 0091 3080 04A2 0091 3080 04A2 04A2 3080 0091 04A2 3080 0091 0691 02C4 5080 0691 02C4 5080 5080 02C4 0691 5080 02C4 0691 0291 03C4 05A2"},
    {6, 5, 22, Rule::ColumnBlocks, 6, 2, 30, 10, "0691 03C4 01A2 05A2 03C4 0291 5080 02C4 0691 0691 02C4 5080 0291 03C4 05A2 01A2 03C4 0691 5080 00C4 6080 6080 01C4 05A2 0091 3080 00A2 05A2 03C4 0691 04A2 3080 0491 0491 3080 04A2 0491 3080 04A2 04A2 3080 0491 04A2 3080 0491 0491 3080 04A2 0691 03C4 05A2 00A2 3080 0091 05A2 01C4 6080 6080 00C4 5080"},
};
// clang-format on

constexpr int kTilingCount = int(std::size(kTilings));

constexpr int words_in(const TilingText& t) {
    switch (t.rule) {
        case Rule::Shift:
            return t.m;
        case Rule::Turn:
            return 8;
        default:
            return t.m * t.n;
    }
}

constexpr int count_words(std::string_view s) {
    int n = 0;
    bool in_word = false;
    for (char ch : s) {
        if (ch != ' ' && !in_word) ++n;
        in_word = ch != ' ';
    }
    return n;
}

constexpr int hex_digit(char ch) {
    return ch >= '0' && ch <= '9'   ? ch - '0'
           : ch >= 'A' && ch <= 'F' ? ch - 'A' + 10
                                    : -1;
}

constexpr int total_words() {
    int n = 0;
    for (const TilingText& t : kTilings) n += count_words(t.words);
    return n;
}

struct Tiling {
    Rule rule;
    int8_t m, c, p, n;
    uint16_t first;  // its first word in kWords
};

constexpr std::array<uint16_t, total_words()> kWords = [] {
    std::array<uint16_t, total_words()> out{};
    int at = 0;
    for (const TilingText& t : kTilings) {
        int word = -1;
        for (char ch : t.words) {
            if (ch == ' ') {
                if (word >= 0) out[size_t(at++)] = uint16_t(word);
                word = -1;
            } else {
                word = (word < 0 ? 0 : word * 16) + hex_digit(ch);
            }
        }
        if (word >= 0) out[size_t(at++)] = uint16_t(word);
    }
    return out;
}();

constexpr std::array<Tiling, kTilingCount> kCompiled = [] {
    std::array<Tiling, kTilingCount> out{};
    int first = 0;
    for (int i = 0; i < kTilingCount; ++i) {
        const TilingText& t = kTilings[i];
        out[size_t(i)] = {t.rule, t.m, t.c, t.p, t.n, uint16_t(first)};
        first += count_words(t.words);
    }
    return out;
}();

// The index in kTilings of (sides, tiles, 1): the lines are sorted by sides, tiles and
// pattern, with pavement_patterns(sides, tiles) lines for each.
constexpr int first_of(int sides, int tiles) {
    int i = 0;
    for (int s : {3, 4, 6}) {
        for (int t = 1; t <= 6; ++t) {
            if (s == sides && t == tiles) return i;
            i += pavement_patterns(s, t);
        }
    }
    return -1;
}

constexpr bool tables_consistent() {
    for (int s : {3, 4, 6}) {
        for (int t = 1; t <= 6; ++t) {
            for (int p = 1; p <= pavement_patterns(s, t); ++p) {
                const TilingText& l = kTilings[first_of(s, t) + p - 1];
                if (l.sides != s || l.tiles != t || l.pattern != p) return false;
                if (count_words(l.words) != words_in(l)) return false;
                for (char ch : l.words)
                    if (ch != ' ' && hex_digit(ch) < 0) return false;
            }
        }
    }
    return first_of(6, 6) == kTilingCount;
}
static_assert(tables_consistent(), "pavement tables: one line per tiling, in order");

// first_of for the sides and tiles a byte can say up to 6, -1 where pavement has none.
constexpr auto kFirst = [] {
    std::array<std::array<int16_t, 7>, 7> out{};
    for (int s = 0; s < 7; ++s)
        for (int t = 0; t < 7; ++t)
            out[size_t(s)][size_t(t)] =
                int16_t(pavement_patterns(s, t) ? first_of(s, t) : -1);
    return out;
}();

// Non-negative remainder and floor quotient (b > 0).
constexpr int64_t mod(int64_t a, int64_t b) {
    const int64_t r = a % b;
    return r < 0 ? r + b : r;
}
constexpr int64_t idiv(int64_t a, int64_t b) { return (a - mod(a, b)) / b; }

unsigned word_at(const Tiling& t, int64_t a, int64_t b) {
    int64_t k = 0;
    switch (t.rule) {
        case Rule::Grid:
            k = mod(a, t.m) + t.m * mod(b, t.n);
            break;
        case Rule::Shift:
            k = mod(a + t.c * mod(b, t.n), t.m);
            break;
        case Rule::RowBlocks: {
            const int64_t q = mod(b, t.p);
            k = mod(a + t.c * idiv(q, t.n), t.m) + t.m * mod(q, t.n);
            break;
        }
        case Rule::ColumnBlocks: {
            const int64_t r = mod(a, t.p);
            k = mod(a, t.m) + t.m * mod(b + t.c * idiv(r, t.m), t.n);
            break;
        }
        case Rule::Turn:
            k = mod(a + mod(b, 4), 4) + 4 * mod(b, 2);
            break;
    }
    return kWords[t.first + size_t(k)];
}

// A cell index from a floored coordinate (far outside int64, the edge of it).
int64_t cell(Real floored) {
    constexpr Real kLimit = 4.6e18;
    return int64_t(std::clamp(floored, -kLimit, kLimit));
}

// ---------------------------------------------------------------- squares

// The corners of a unit square cell as the bits 10, 20, 40, 80 name them.
struct Corner {
    unsigned bit;
    bool right, top;  // x = 1 (else 0), z = 1 (else 0)
};
constexpr Corner kCorners[4] = {
    {0x10, false, true}, {0x20, true, true}, {0x40, true, false}, {0x80, false, false}};

Real squares(const Tiling& tiling, Real x, Real z, int exterior, int interior, int form) {
    const Real fx = std::floor(x), fz = std::floor(z);
    const unsigned w = word_at(tiling, cell(fx), cell(fz));
    // The cell doubled: [0,2) x [0,2), its centre at (1, 1).
    const Real A = 2 * (x - fx), B = 2 * (z - fz);
    // The doubled offsets from a corner (both >= 0).
    auto offsets = [&](const Corner& k, Real& P, Real& Q) {
        P = k.right ? 2 - A : A;
        Q = k.top ? 2 - B : B;
    };
    // A bend of the outline around a corner: the corner's bit with the two sides that do
    // not meet there. The first that matches decides the whole cell.
    if (form != 3) {
        for (const Corner& k : kCorners) {
            const unsigned sides = (k.top ? 0x04u : 0x01u) | (k.right ? 0x08u : 0x02u);
            if ((w & (k.bit | sides)) != (k.bit | sides)) continue;
            if (form == 2) {
                Real P, Q;
                offsets(k, P, Q);
                return std::min(std::fabs(std::sqrt(P * P + Q * Q) - 1), 1.0);
            }
            if (form == 1) {
                Real v;
                if (k.bit == 0x10)
                    v = A - B + 1;
                else if (k.bit == 0x20)
                    v = (2 - B) - A + 1;
                else if (k.bit == 0x40)
                    v = B - A + 1;
                else
                    v = A - (2 - B) + 1;
                return std::min(std::fabs(v), 1.0);
            }
            // Sharp: the outline ramps of the two far sides, and the corner's own.
            const Real along_x = k.right ? 1 - A : A - 1;
            const Real along_z = k.top ? 1 - B : B - 1;
            return std::max(std::max(along_x, along_z), std::min(-along_x, -along_z));
        }
    }
    // The outline sides: 1 on the side, 0 on the cell's middle line.
    Real r = 0;
    if (w & 0x01) r = std::max(r, B - 1);
    if (w & 0x02) r = std::max(r, A - 1);
    if (w & 0x04) r = std::max(r, 1 - B);
    if (w & 0x08) r = std::max(r, 1 - A);
    // Concave corners.
    for (const Corner& k : kCorners) {
        if (!(w & k.bit)) continue;
        Real P, Q;
        offsets(k, P, Q);
        Real term;
        if (interior == 2)
            term = 1 - std::sqrt(P * P + Q * Q);
        else if (interior == 1)
            term = 1 - (P + Q);
        else
            term = std::min(k.right ? A - 1 : 1 - A, k.top ? B - 1 : 1 - B);
        r = std::max(r, term);
    }
    // Convex corners: the two outline sides meeting at a corner.
    if (exterior != 0) {
        const Real U = A - 1, V = B - 1;
        bool round = false;
        for (const Corner& k : kCorners) {
            const unsigned sides = (k.top ? 0x01u : 0x04u) | (k.right ? 0x02u : 0x08u);
            if ((w & sides) != sides) continue;
            if (exterior == 2) {
                round =
                    round || ((k.right ? U >= 0 : U <= 0) && (k.top ? V >= 0 : V <= 0));
            } else {
                Real P, Q;
                offsets(k, P, Q);
                r = std::max(r, std::min(2 - (P + Q), 1.0));
            }
        }
        if (round) r = std::max(r, std::min(std::sqrt(U * U + V * V), 1.0));
    }
    return r;
}

// ---------------------------------------------------------------- the triangle grid

// The point folded onto the reference triangle L (0,0), R (1,0), T (1/2, h), and its
// cell's indices: b the row (b h <= z < (b + 1) h), a twice the x of the cell's leftmost
// vertex. A downward cell comes onto it by a half turn about one of its slanted sides'
// middles.
struct TriangleCell {
    Real x, z;
    int64_t a, b;
};

TriangleCell fold_to_triangle(Real x, Real z) {
    const Real a0 = std::floor(x), b0 = std::floor(z / kSqrt3);
    x = x - a0;
    z = z - kSqrt3 * b0;
    int64_t a = 2 * cell(a0), b = 2 * cell(b0);
    if (z > kSqrt3Half) {
        z = z - kSqrt3Half;
        if (x > 0.5) {
            x = x - 0.5;
            a += 1;
        } else {
            x = x + 0.5;
            a -= 1;
        }
        b += 1;
    }
    if (x == 0 || z / x > kSqrt3) {
        z = kSqrt3Half - z;
        x = 0.5 - x;
        a -= 1;
    }
    if (x == 1 || z / (1 - x) > kSqrt3) {
        z = kSqrt3Half - z;
        x = 1.5 - x;
        a += 1;
    }
    return {x, z, a, b};
}

Real triangles(const Tiling& tiling, bool hexagons, Real px, Real pz, int exterior,
               int interior, int form) {
    const TriangleCell f = fold_to_triangle(px, pz);
    const Real x = f.x, z = f.z;
    const unsigned w = word_at(tiling, f.a, f.b);
    // Concave corners at the apex T, at L and at R: neither side there is outline (and
    // the cell does not say otherwise), or a hexagon's word forces one.
    const bool at_T = (w & 0x083) == 0 || (hexagons && (w & 0x4000));
    const bool at_L = (w & 0x085) == 0 || (hexagons && (w & 0x2000));
    const bool at_R = (w & 0x086) == 0 || (hexagons && (w & 0x1000));
    // The medians cut the triangle into a kite around each vertex.
    const Real m1 = 1 - std::fabs(kSqrt3 * z + x);
    const Real m2 = 1 - std::fabs(kSqrt3 * z - x + 1);
    const Real m3 = 1 - x * 2;
    const bool kite_T = m1 < 0 && m2 < 0;
    const bool kite_L = m1 > 0 && m3 > 0;
    const bool kite_R = m3 < 0 && m2 > 0;
    // The outline sides: 1 on the side, 0 at the inradius from it.
    const Real ramp_LT = 1 - std::fabs(kSqrt3 * x - z) * kSqrt3;
    const Real ramp_RT = 1 - std::fabs(kSqrt3 * (1 - x) - z) * kSqrt3;
    const Real ramp_LR = 1 - z * 2 * kSqrt3;
    Real r = 0;
    if (w & 0x001) r = std::max(r, ramp_LT);
    if (w & 0x002) r = std::max(r, ramp_RT);
    if (w & 0x004) r = std::max(r, ramp_LR);
    if (interior == 0) {
        // The ramps of the lines through the vertex parallel to the opposite side.
        if (at_T) r = std::max(r, 1 - (kSqrt3Half - z) * 2 * kSqrt3);
        if (at_L) r = std::max(r, 1 - std::fabs(kSqrt3 * x + z) * kSqrt3);
        if (at_R) r = std::max(r, 1 - std::fabs(kSqrt3 * (x - 1) - z) * kSqrt3);
    } else if (interior == 1) {
        if (at_T && kite_T)
            r = std::max(r, std::min(1.5 * std::fabs(kSqrt3 * z + x) - 2,
                                     1.5 * std::fabs(kSqrt3 * z - x + 1) - 2));
        if (at_L && kite_L)
            r = std::max(r, std::min(1 - 1.5 * std::fabs(kSqrt3 * z + x), 1 - x * 3));
        if (at_R && kite_R)
            r = std::max(r, std::min(1 - 1.5 * std::fabs(kSqrt3 * z - x + 1), x * 3 - 2));
    } else {
        if (at_T) {
            const Real dx = x - 0.5, dz = z - kSqrt3Half;
            r = std::max(r, 1 - std::sqrt(dx * dx + dz * dz) * 3);
        }
        if (at_L) r = std::max(r, 1 - std::sqrt(x * x + z * z) * 3);
        if (at_R) {
            const Real dx = x - 1;
            r = std::max(r, 1 - std::sqrt(dx * dx + z * z) * 3);
        }
    }
    // Pointy corners of the outline (triangles only): they replace the value.
    if (!hexagons && exterior != 0) {
        const Real g1 = x - 0.5, g2 = z - kSqrt3Half / 3;  // from the centroid
        const bool pair_T = (w & 0x003) == 0x003, pair_R = (w & 0x006) == 0x006,
                   pair_L = (w & 0x005) == 0x005;
        if (exterior == 2) {
            if ((pair_T && m1 <= 0 && m2 <= 0) || (pair_R && m2 >= 0 && m3 <= 0) ||
                (pair_L && m1 >= 0 && m3 >= 0))
                r = std::min(1.0, 2 * kSqrt3 * std::sqrt(g1 * g1 + g2 * g2));
        } else {
            // Ramps across the bisector from the corner through the centroid.
            if (pair_T && ramp_LT >= 0 && ramp_RT >= 0)
                r = std::min(1.0, std::fabs(g2 * 2 * kSqrt3));
            if (pair_R && ramp_RT >= 0 && ramp_LR >= 0)
                r = std::min(1.0, std::fabs(kSqrt3 * g1 - g2) * kSqrt3);
            if (pair_L && ramp_LT >= 0 && ramp_LR >= 0)
                r = std::min(1.0, std::fabs(kSqrt3 * g1 + g2) * kSqrt3);
        }
    }
    // Bends of the outline: the first pair of marks whose kite holds the point decides,
    // an arc about the far vertex C (form 2) or a straight cut (form 1).
    if (form != 0) {
        struct Bend {
            unsigned bits;
            bool in_kite;
            Real cx, cz, cut;
        };
        const Bend bends[6] = {
            {0x120, kite_T, 0, 0, -m1 * 2}, {0x140, kite_L, 0.5, kSqrt3Half, m1 * 2},
            {0x210, kite_T, 1, 0, -m2 * 2}, {0x240, kite_R, 0.5, kSqrt3Half, m2 * 2},
            {0x410, kite_L, 1, 0, m3 * 2},  {0x420, kite_R, 0, 0, -m3 * 2}};
        for (const Bend& b : bends) {
            if ((w & b.bits) != b.bits || !b.in_kite) continue;
            if (form == 1) return std::min(b.cut, 1.0);
            const Real dx = x - b.cx, dz = z - b.cz;
            const Real v = 2 * kSqrt3 * (std::sqrt(dx * dx + dz * dz) - kSqrt3 / 3);
            return std::min(std::max(v, 0.0), 1.0);
        }
    }
    return r;
}

}  // namespace pavement

Real pavement_value(const PatternSpec::Pavement& pv, const Point3& p) {
    using namespace pavement;
    const int first = pv.sides <= 6 && pv.tiles <= 6 ? kFirst[pv.sides][pv.tiles] : -1;
    if (first < 0 || pv.pattern < 1 || pv.pattern > pavement_patterns(pv.sides, pv.tiles))
        return 0;  // the parser lets no other through
    const Tiling& t = kCompiled[size_t(first + pv.pattern - 1)];
    if (pv.sides == 4) return squares(t, p.x, p.z, pv.exterior, pv.interior, pv.form);
    return triangles(t, pv.sides == 6, p.x, p.z, pv.exterior, pv.interior, pv.form);
}

}  // namespace povwall::trace::detail
