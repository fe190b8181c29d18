// POV-Ray 3.7's `tiling 25`, `26` and `27`: Penrose's P1 (pentagons, stars, boats,
// diamonds: six kinds), P2 (kites and darts) and P3 (thick and thin rhombs), with edges
// of length 1 around the origin, which they are symmetric about (five-fold, and mirrored
// about every 36 degree line). A point is folded into the wedge 0..36 degrees, scaled
// down to the level whose first tile holds it, then followed down the golden subdivision
// (each step scales by phi) to a tile; its kind picks the value's band [k/N, (k+1)/N],
// its distance to the tile's edges the place in the band (POV-Ray's bevel). Written from
// a description of POV-Ray 3.7.0's pattern.cpp (the same constants and the same order of
// operations, so that boundaries fall on the same side), not from its code.
#include <algorithm>
#include <cmath>

#include "trace/pattern_internal.h"

namespace povwall::trace::detail {
namespace {

constexpr Real kPhi = 1.6180339887498948482;
constexpr Real kInvPhi = 0.61803398874989484820;
constexpr Real kPhi2 = 2.6180339887498948482;
constexpr Real kInvPhi2 = 0.38196601125010515180;
// sin and cos of multiples of 18 degrees (cos 18 = sin 72, and so on).
constexpr Real kSin18 = 0.30901699437494742410, kSin36 = 0.58778525229247312917,
               kSin54 = 0.80901699437494742410, kSin72 = 0.95105651629515357212;
constexpr Real kCos18 = kSin72, kCos36 = kSin54, kCos72 = kSin18;
constexpr Real kTan18 = 0.32491969623290632616, kTan36 = 0.72654252800536088590,
               kTan54 = 1.3763819204711735382, kTan72 = 3.0776835371752534026;
constexpr Real kBandGuard = 1e-6;  // keeps a value inside its kind's band
constexpr Real kOrigin = 1e-10;    // the origin itself gives 1

// A rotation by a multiple of 36 degrees, counter-clockwise in (x, z).
struct Turn {
    Real c, s;
};
constexpr Turn kTurnM144{-kCos36, -kSin36}, kTurnM72{kCos72, -kSin72},
    kTurnM36{kCos36, -kSin36}, kTurn36{kCos36, kSin36}, kTurn72{kCos72, kSin72},
    kTurn108{-kCos72, kSin72};

void turn(const Turn& t, Real& x, Real& z) {
    const Real nx = x * t.c - z * t.s, nz = z * t.c + x * t.s;
    x = nx;
    z = nz;
}

// Into the wedge 0 <= angle <= 36 degrees, r being the point's distance from the origin
// (a point at exactly 36 degrees stays, one at exactly 108 turns by -72).
void fold_to_wedge(Real& x, Real& z, Real r) {
    z = std::fabs(z);
    if (x < r * kCos36) {
        turn(x < -r * kCos72 ? kTurnM144 : kTurnM72, x, z);
        z = std::fabs(z);
    }
}
void fold_to_wedge(Real& x, Real& z) { fold_to_wedge(x, z, std::sqrt(x * x + z * z)); }

Real clamp_band(Real v, Real lo, Real hi) { return std::min(std::max(v, lo), hi); }

// The starting level for a size measure d (the first tile's edge at d = 1) and the
// golden scale per level; at most a few thousand levels (coordinates near the largest
// doubles), none for non-finite ones.
int start_level(Real d, Real scale_per_level) {
    const Real k = std::ceil(std::log(d) / std::log(scale_per_level));
    if (!(k > 0)) return 0;
    return int(std::min(k, Real(2000)));
}

// ---- P2 and P3: golden triangles ----------------------------------------------------
// K: the acute triangle O, A = (1, 0), Q = (cos 36, sin 36), with its mirror a kite;
// D: the obtuse triangle O, A, P = (1/2, sin 36 / phi), with its mirror half a dart.

Real kite_dart_tiles(Real x, Real z, bool rhombs) {
    const Real r = std::sqrt(x * x + z * z);
    if (r <= kOrigin) return 1.0;
    fold_to_wedge(x, z, r);
    if (rhombs) {  // P3's edges are 1 where the triangles' are 1/phi
        x *= kInvPhi;
        z *= kInvPhi;
    }
    const int k = start_level(std::fabs(kSin72 * x + kCos72 * z) / kCos18, kPhi2);
    const Real shrink = std::pow(kInvPhi2, Real(k));
    x *= shrink;
    z *= shrink;
    if (k % 2 == 1) {  // two steps mirror a kite across the wedge's bisector
        turn(kTurnM36, x, z);
        z = std::fabs(z);
    }
    bool kite = true;
    for (int n = 2 * k; n > 0; --n) {
        z = std::fabs(z);
        if (kite) {
            if (z < -kTan36 * (x - kInvPhi)) {
                kite = false;  // the small half dart at O
            } else {
                x -= kCos36;
                z -= kSin36;
                turn(kTurn108, x, z);
            }
        } else if (z < -kTan72 * (x - kInvPhi)) {
            turn(kTurnM36, x, z);
            kite = true;
        } else {
            x -= 1;
            turn(kTurnM144, x, z);
        }
        x *= kPhi;
        z *= kPhi;
    }
    z = std::fabs(z);
    const Real low_lo = 0.0, low_hi = 0.5 - kBandGuard, high_lo = 0.5 + kBandGuard;
    if (!rhombs) {
        constexpr Real kBevel = 4.46;
        if (kite) {
            const Real e1 = std::fabs(kSin36 * x - kCos36 * z) * kBevel;
            const Real e2 = std::fabs(kSin72 * (x - 1) + kCos72 * z) * kBevel;
            return clamp_band(std::max(0.5 - e1 / 2, 0.5 - e2 / 2), low_lo, low_hi);
        }
        const Real e1 = std::fabs(z) * kBevel;
        const Real e2 = std::fabs(kSin36 * (x - 1) + kCos36 * z) * kBevel;
        return std::max(std::max(1 - e1 / 2, 1 - e2 / 2), high_lo);  // no upper bound
    }
    constexpr Real kBevel = 5.55;
    if (kite && z < kTan72 * (x - kInvPhi)) {  // half a thin rhomb
        const Real e1 = std::fabs(kSin72 * (x - kInvPhi) - kCos72 * z) * kBevel;
        const Real e2 = std::fabs(kSin72 * (x - 1) + kCos72 * z) * kBevel;
        return std::max(std::max(1 - e1 / 2, 1 - e2 / 2), high_lo);
    }
    Real e1, e2;
    if (kite) {  // half a thick rhomb: edges on z = 0 and across the kite
        e1 = std::fabs(z) * kBevel;
        e2 = std::fabs(kSin72 * (x - kInvPhi) - kCos72 * z) * kBevel;
    } else {  // a thick rhomb with its mirror
        e1 = std::fabs(kSin36 * x - kCos36 * z) * kBevel;
        e2 = std::fabs(kSin36 * (x - 1) + kCos36 * z) * kBevel;
    }
    return clamp_band(std::max(0.5 - e1 / 2, 0.5 - e2 / 2), low_lo, low_hi);
}

// ---- P1: pentagons of three classes, pentagrams, boats and diamonds ------------------

// A regular pentagon of edge 1 around the origin: circumradius and apothem, and the
// offsets the subdivision uses (each formed in POV-Ray's order of operations).
const Real kCircum = 0.5 / kSin36;
const Real kApothem = 0.5 / kTan36;
const Real kInvPhiCircumCos72 = ((kInvPhi * 0.5) * kCos72) / kSin36;
const Real kInvPhi2Circum = (kInvPhi2 * 0.5) / kSin36;
const Real kInvPhi2CircumCos72 = ((kInvPhi2 * 0.5) * kCos72) / kSin36;
const Real kInvPhiApothem = (kInvPhi * 0.5) / kTan36;
const Real kInvPhiCircum = (kInvPhi * 0.5) / kSin36;
const Real kCircumCos72 = (0.5 * kCos72) / kSin36;
const Real kCircumSin72 = (0.5 * kSin72) / kSin36;
const Real kPhiCircumCos72 = ((kPhi * 0.5) * kCos72) / kSin36;
const Real kPhiCircum = (kPhi * 0.5) / kSin36;
const Real kTwoInvPhiApothem = kInvPhi / kTan36;

enum class P1Tile : uint8_t { Pentagon1, Pentagon2, Pentagon3, Star, Boat, Diamond };

// The bevel: a distance to an edge in the band's units.
Real p1_bevel(Real d) { return (d * 5.55) * kInvPhi; }

Real p1_value(P1Tile tile, Real x, Real z) {
    switch (tile) {
        case P1Tile::Pentagon1:
        case P1Tile::Pentagon2:
        case P1Tile::Pentagon3: {
            if (tile != P1Tile::Pentagon1)
                fold_to_wedge(x, z);  // the first folded already
            const Real e = p1_bevel(std::fabs(x - kApothem));
            const int c = tile == P1Tile::Pentagon1   ? 1
                          : tile == P1Tile::Pentagon2 ? 2
                                                      : 3;
            const Real lo = c == 1 ? 0.0 : Real(c - 1) / 6 + kBandGuard;
            return clamp_band(Real(c) / 6 - e / 6, lo, Real(c) / 6 - kBandGuard);
        }
        case P1Tile::Star: {
            const Real e = p1_bevel(std::fabs(kSin18 * (x - kPhiCircum) + kCos18 * z));
            return clamp_band(4.0 / 6 - e / 6, 3.0 / 6 + kBandGuard,
                              4.0 / 6 - kBandGuard);
        }
        case P1Tile::Boat: {
            const Real e1 = p1_bevel(std::fabs(x - kInvPhiCircumCos72));
            Real fx = -x, fz = z;
            fold_to_wedge(fx, fz);
            const Real e2 = p1_bevel(std::fabs(kSin18 * (fx - kPhiCircum) + kCos18 * fz));
            return std::min(std::max(std::max(5.0 / 6 - e1 / 6, 5.0 / 6 - e2 / 6),
                                     4.0 / 6 + kBandGuard),
                            5.0 / 6 - kBandGuard);
        }
        case P1Tile::Diamond: {
            const Real e = p1_bevel(std::fabs(kSin18 * (x + kInvPhiCircum) - kCos18 * z));
            return clamp_band(6.0 / 6 - e / 6, 5.0 / 6 + kBandGuard, 1 - kBandGuard);
        }
    }
    return 0;
}

Real pentagon_tiles(Real x, Real z) {
    const Real r = std::sqrt(x * x + z * z);
    if (r <= kOrigin) return 1.0;
    fold_to_wedge(x, z, r);
    const int k = start_level((x * 2) * kTan36, kPhi2 * kPhi2);
    const Real shrink = std::pow(kInvPhi2 * kInvPhi2, Real(k));
    x *= shrink;
    z *= shrink;
    P1Tile tile = P1Tile::Pentagon1;
    bool flag = false;  // Pentagon2's q, Pentagon3's and Boat's w, Diamond's A
    for (int n = 4 * k;; --n) {
        z = std::fabs(z);
        if (tile == P1Tile::Pentagon1) fold_to_wedge(x, z);
        if (n == 0) return p1_value(tile, x, z);
        switch (tile) {
            case P1Tile::Pentagon1:
                if (z < kTan54 * (x - kApothem) + 0.5) {
                    x = x - kApothem - kInvPhiCircumCos72;
                    tile = P1Tile::Pentagon2;
                    flag = false;
                } else {
                    turn(kTurnM36, x, z);
                    tile = P1Tile::Star;
                }
                break;
            case P1Tile::Pentagon2:
                if (flag) {
                    if (z < kTan54 * (x - kInvPhi2Circum)) {
                        x -= kCircum;
                        tile = P1Tile::Pentagon1;
                    } else if (z < -kTan18 * (x - kInvPhi2Circum)) {
                        x = -x;
                        tile = P1Tile::Diamond;
                        flag = true;
                    } else {
                        turn(kTurn108, x, z);
                        x += kInvPhiCircum;
                    }
                } else if (z < kTan18 * (x + kCircum)) {
                    x = x + kCircum - kInvPhi2Circum;
                    tile = P1Tile::Diamond;
                    flag = false;
                } else {
                    turn(kTurnM36, x, z);
                    x = -x - kCircumCos72;
                    z = z - kCircumSin72;
                    tile = P1Tile::Pentagon3;
                    flag = false;
                }
                break;
            case P1Tile::Pentagon3:
                if (flag && x > kInvPhi2CircumCos72) {
                    x = -(x - kInvPhi2CircumCos72 - kInvPhiApothem);
                    tile = P1Tile::Pentagon2;
                    flag = true;
                } else if (!flag && x < -kCircumCos72) {
                    turn(kTurnM144, x, z);
                    x -= kCircum;
                    tile = P1Tile::Pentagon2;
                    flag = false;
                } else if (!flag && z > -kTan54 * (x - kInvPhi2Circum)) {
                    turn(kTurn36, x, z);
                    x = -x - kCircumCos72;
                    z = z - kCircumSin72;
                } else {
                    tile = P1Tile::Boat;  // with the same w
                }
                break;
            case P1Tile::Star:
                if (x < kInvPhiApothem) {
                    tile = P1Tile::Pentagon1;
                } else {
                    x = -(x - kTwoInvPhiApothem);
                    tile = P1Tile::Pentagon3;
                    flag = true;
                }
                break;
            case P1Tile::Boat:
                if (flag && x > -kPhiCircumCos72) {
                    x = -x;
                    tile = P1Tile::Pentagon1;
                } else {
                    if (flag) {
                        x += kCircum;
                    } else {
                        turn(kTurn72, x, z);
                        x += kCircum;
                    }
                    tile = P1Tile::Pentagon3;
                    flag = true;
                }
                break;
            case P1Tile::Diamond:
                if (flag) {
                    tile = P1Tile::Pentagon1;
                } else {
                    tile = P1Tile::Pentagon3;
                    flag = true;
                }
                break;
        }
        x *= kPhi;
        z *= kPhi;
    }
}

}  // namespace

Real penrose_tiles(Real x, Real z, PenroseKind kind) {
    switch (kind) {
        case PenroseKind::Pentagons:
            return pentagon_tiles(x, z);
        case PenroseKind::KitesAndDarts:
            return kite_dart_tiles(x, z, false);
        case PenroseKind::Rhombs:
            return kite_dart_tiles(x, z, true);
    }
    return 0;
}

}  // namespace povwall::trace::detail
