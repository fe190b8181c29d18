// Pigments: colour maps (with POV-Ray's default maps), colour lists of
// checker/hexagon/brick and pigment maps, blended as POV-Ray 3.7's Compute_Pigment does.
#include <algorithm>
#include <array>

#include "trace/pattern.h"
#include "trace/pattern_internal.h"

namespace povwall::trace {
namespace {

struct DefaultMap {
    int count;
    std::array<float, 6> values;
    std::array<Rgb, 6> colours;
};

constexpr Rgb kBlack{0, 0, 0}, kWhite{1, 1, 1}, kRed{1, 0, 0}, kGreen{0, 1, 0},
    kBlue{0, 0, 1}, kCyan{0, 1, 1}, kYellow{1, 1, 0}, kMagenta{1, 0, 1};

// POV-Ray's built-in maps for pigments given without a colour_map (pigment.cpp).
const DefaultMap& default_map(const PatternSpec& spec) {
    const PatternKind k = spec.kind;
    static const DefaultMap kGray{2, {0, 1}, {kBlack, kWhite}};
    static const DefaultMap kBozo{6,
                                  {0.4f, 0.4f, 0.6f, 0.6f, 0.8f, 0.8f},
                                  {kWhite, kGreen, kGreen, kBlue, kBlue, kRed}};
    static const DefaultMap kWood{
        2, {0.6f, 0.6f}, {Rgb{0.666f, 0.312f, 0.2f}, Rgb{0.4f, 0.1333f, 0.066f}}};
    static const DefaultMap kMandel{5,
                                    {0.001f, 0.001f, 0.012f, 0.015f, 0.1f},
                                    {kBlack, kCyan, kYellow, kMagenta, kCyan}};
    static const DefaultMap kAgate{
        6,
        {0.0f, 0.5f, 0.5f, 0.6f, 0.6f, 1.0f},
        {kWhite, Rgb{0.95f, 0.75f, 0.5f}, Rgb{0.9f, 0.7f, 0.5f}, Rgb{0.9f, 0.7f, 0.4f},
         Rgb{1.0f, 0.7f, 0.4f}, Rgb{0.6f, 0.3f, 0.0f}}};
    static const DefaultMap kRadial{
        4, {0.0f, 0.333f, 0.666f, 1.0f}, {kCyan, kYellow, kMagenta, kCyan}};
    static const DefaultMap kMarble{
        3, {0.0f, 0.9f, 0.9f}, {Rgb{0.9f, 0.8f, 0.8f}, Rgb{0.9f, 0.08f, 0.08f}, kBlack}};
    static const DefaultMap kBrick{
        2, {0.0f, 1.0f}, {Rgb{0.5f, 0.5f, 0.5f}, Rgb{0.6f, 0.15f, 0.15f}}};
    // Checker reuses the hexagon entries (first two), as POV-Ray does.
    static const DefaultMap kHex{3, {0.0f, 1.0f, 2.0f}, {kBlue, kGreen, kRed}};
    static const DefaultMap kChecker{2, {0.0f, 1.0f}, {kBlue, kGreen}};
    // Square and triangular take the first four or all six cubic colours, as POV-Ray
    // does (entry lists select by index).
    static const DefaultMap kCubic{6,
                                   {0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f},
                                   {kRed, kGreen, kBlue, kYellow, kCyan, kMagenta}};
    static const DefaultMap kSquareMap{
        4, {0.0f, 1.0f, 2.0f, 3.0f}, {kRed, kGreen, kBlue, kYellow}};
    switch (k) {
        case PatternKind::Bozo:
            return kBozo;
        case PatternKind::Brick:
            return kBrick;
        case PatternKind::Wood:
            return kWood;
        case PatternKind::Mandel:  // the other exponents read as another pattern
            return spec.fractal.exponent == 2 ? kMandel : kGray;
        case PatternKind::Radial:
            return kRadial;
        case PatternKind::Agate:
            return kAgate;
        case PatternKind::Marble:
            return kMarble;
        case PatternKind::Hexagon:
            return kHex;
        case PatternKind::Checker:
        case PatternKind::ObjectInside:  // POV-Ray gives it checker's default list
            return kChecker;
        case PatternKind::Square:
            return kSquareMap;
        case PatternKind::Triangular:
        case PatternKind::Cubic:
            return kCubic;
        default:
            return kGray;
    }
}

// prev + f * (cur - prev), per channel, as POV-Ray blends (single-precision colours).
Colour blend(const Colour& prev, const Colour& cur, Real f) {
    float ff = float(f);
    auto mix = [ff](float a, float b) { return a + ff * (b - a); };
    return Colour{Rgb{mix(prev.rgb.r, cur.rgb.r), mix(prev.rgb.g, cur.rgb.g),
                      mix(prev.rgb.b, cur.rgb.b)},
                  mix(prev.filter, cur.filter), mix(prev.transmit, cur.transmit)};
}

}  // namespace

Colour evaluate_pigment(const Pigment& pigment, const Point3& world,
                        const PatternEnv& env, bool* found) {
    if (env.quick_colours && pigment.maps->quick_colour)
        return *pigment.maps->quick_colour;
    const PatternSpec& spec = *pigment.pattern;
    if (spec.kind == PatternKind::Solid) return pigment.colour;
    if (spec.kind == PatternKind::UvMapping) {
        // Its one entry at the surface coordinates; its own transforms (those after the
        // keyword) apply there, the object's do not.
        if (pigment.maps->list.empty()) return pigment.colour;
        return evaluate_pigment(pigment.maps->list.front(), detail::uv_of(env), env);
    }
    Point3 p = detail::warp_point(spec, world);
    if (spec.kind == PatternKind::ImageMap) {
        return spec.image ? detail::image_map_colour(*spec.image, p, found)
                          : Colour{Rgb{1.0f}, 0.0f, 1.0f};
    }
    if (spec.kind == PatternKind::Average) {
        // Weighted mean of the pigment_map entries, weights being the entry values.
        Colour sum{Rgb{0.0f}};
        float total = 0;
        size_t n = std::min(pigment.maps->map_values.size(), pigment.maps->list.size());
        for (size_t i = 0; i < n; ++i) {
            float w = pigment.maps->map_values[i];
            Colour c = evaluate_pigment(pigment.maps->list[i], p, env);
            sum = sum + c * w;
            total += w;
        }
        return total != 0 ? sum * (1.0f / total) : sum;
    }
    Real value = detail::value_at(spec, p, env);

    // checker/hexagon/brick/square/triangular/cubic/object: the value is the entry
    // number in their list (blended between two where a frequency, phase or wave moved
    // it), the default colours standing for the entries not given.
    if (detail::is_discrete(spec.kind) && pigment.maps->map_values.empty() &&
        pigment.maps->colour_map.empty()) {
        auto entry = [&](int index, bool* entry_found) {
            if (index < int(pigment.maps->list.size()))
                return evaluate_pigment(pigment.maps->list[size_t(index)], p, env,
                                        entry_found);
            const DefaultMap& d = default_map(spec);
            return Colour{d.colours[size_t(std::min(index, d.count - 1))]};
        };
        const MapLookup m = search_list(detail::list_size(spec.kind), value);
        const Colour cur = entry(m.cur, found);
        if (m.prev == m.cur) return cur;
        bool prev_found = true;
        const Colour prev = entry(m.prev, found ? &prev_found : nullptr);
        if (found) *found = *found || prev_found;
        return blend(prev, cur, m.fraction);
    }

    // pigment_map: blend the two neighbouring pigments, each evaluated at this pattern's
    // warped point (POV-Ray nests pattern spaces this way).
    if (!pigment.maps->map_values.empty() && !pigment.maps->list.empty()) {
        int n = int(std::min(pigment.maps->map_values.size(), pigment.maps->list.size()));
        MapLookup m = search_map(pigment.maps->map_values.data(), n, value);
        Colour cur = evaluate_pigment(pigment.maps->list[size_t(m.cur)], p, env, found);
        if (m.prev == m.cur) return cur;
        // Found when either entry finds a colour.
        bool prev_found = true;
        Colour prev = evaluate_pigment(pigment.maps->list[size_t(m.prev)], p, env,
                                       found ? &prev_found : nullptr);
        if (found) *found = *found || prev_found;
        return blend(prev, cur, m.fraction);
    }

    if (!pigment.maps->colour_map.empty()) {
        const ColourMap& map = pigment.maps->colour_map;
        int n = int(map.size());
        // Search over the entry values (kept small; maps have a handful of entries).
        float values[256];
        n = std::min(n, 256);
        for (int i = 0; i < n; ++i) values[i] = map[size_t(i)].value;
        MapLookup m = search_map(values, n, value);
        const Colour& cur = map[size_t(m.cur)].colour;
        if (m.prev == m.cur) return cur;
        return blend(map[size_t(m.prev)].colour, cur, m.fraction);
    }

    const DefaultMap& d = default_map(spec);
    MapLookup m = search_map(d.values.data(), d.count, value);
    Colour cur{d.colours[size_t(m.cur)]};
    if (m.prev == m.cur) return cur;
    return blend(Colour{d.colours[size_t(m.prev)]}, cur, m.fraction);
}

}  // namespace povwall::trace
