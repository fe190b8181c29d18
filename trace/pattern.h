// Pattern evaluation: pigments, normals and texture-map selection at a world-space point,
// reproducing POV-Ray 3.7 (values, colour maps, warps, turbulence, normal perturbation).
//
// Point mapping (POV-Ray's warp list, see docs in pattern.cpp):
//   p = spec.transform^-1(world)
//   for the warps from last to first (POV-Ray prepends each parsed warp), skipping the
//   classic turbulence: p = warp(p), then p = warp.transform^-1(p)  [the transforms
//   written *before* that warp in the scene, i.e. applied after it on the way into
//   pattern space] finally the classic turbulence (Warp::classic, the last one wins),
//   applied last as POV-Ray does, except for marble and wood which read it inside the
//   pattern.
//
// Nested entries (pigment_map / normal_map / checker, hexagon and brick lists,
// texture_map entries via pick_map_entries) are evaluated at the OUTER pattern's warped
// point, as POV-Ray does, so their own transforms are relative to the outer pattern
// space: an object transform belongs in the outer spec only, not copied into the entries.
#pragma once

#include "core/scene.h"

namespace povwall::trace {

struct Hit;

// A hit as the surface patterns see it (POV-Ray's Intersection for slope, aoi and
// uv_mapping).
struct SurfaceAtHit {
    Vector3 normal;  // faces the ray; a layer's normal pattern perturbs it (PNormal)
    Point3 point;    // world
    Vector3 ray_direction;
    const Hit* hit = nullptr;  // the hit itself (its surface coordinates); may be null
};

struct PatternEnv {
    // global_settings noise_generator, used when a pattern says 0.
    int noise_generator = 2;
    // global_settings number_of_waves (ripples, waves).
    int number_of_waves = 10;
    // +Q5 and below: a pigment's quick_color stands for it (POV-Ray's Compute_Pigment).
    bool quick_colours = false;
    // The surface being shaded, for the patterns that read it (slope, aoi); none in
    // media, functions and the sky, where those patterns are 0 (as POV-Ray's).
    const SurfaceAtHit* surface = nullptr;
    // A copy of this environment that sees `at` (or no surface).
    PatternEnv at_surface(const SurfaceAtHit* at) const {
        PatternEnv e = *this;
        e.surface = at;
        return e;
    }
};

// What user functions (core/function.h) call to evaluate `pattern { }` and `pigment { }`
// functions with `env`'s settings; `env` must outlive their use.
FunctionHooks function_hooks(const PatternEnv& env);
// The same with the default settings (noise_generator 2), for SDL calls while parsing.
FunctionHooks parse_time_function_hooks();

// The pattern's value at `world` (after warps, wave type, frequency and phase).
// Continuous patterns give [0,1]; checker/brick give 0 or 1, hexagon 0, 1 or 2.
Real evaluate_pattern(const PatternSpec& spec, const Point3& world,
                      const PatternEnv& env);

// The pigment's colour (rgbft) at `world`. `found`, when given (and true on entry), is
// set false where POV-Ray's Compute_Pigment finds no colour: an image_map off its image
// (`once`), or a pigment_map whose entries there all are (the off-image colour still
// comes back).
Colour evaluate_pigment(const Pigment& pigment, const Point3& world,
                        const PatternEnv& env, bool* found = nullptr);

// `geometric` (unit, world space) perturbed by the normal pattern at `world`; unit
// length.
Vector3 perturb_normal(const Normal& normal, const Point3& world,
                       const Vector3& geometric, const PatternEnv& env);
// The same before its last normalisation, as POV-Ray's Perturb_Normal leaves it (the
// PNormal the slope pattern reads): not unit length when the pattern has no_bump_scale.
Vector3 perturb_normal_unnormalised(const Normal& normal, const Point3& world,
                                    const Vector3& geometric, const PatternEnv& env);

// The index of the map entry pair for `value` (POV-Ray's Search_Blend_Map): `prev` and
// `cur` are equal outside the map's range; otherwise `fraction` blends prev -> cur.
struct MapLookup {
    int prev = 0, cur = 0;
    Real fraction = 0;
};
MapLookup search_map(const float* values, int count, Real value);
// The same over a block or object pattern's list, whose entries POV-Ray's blend map
// holds at 0, 1, ..., count - 1: the pattern's entry number picks one; a number a
// frequency, phase or wave moved between two blends them.
MapLookup search_list(int count, Real value);

// texture_map / checker-of-textures selection at `world`: the entries to blend and the
// pattern-space point POV-Ray evaluates the nested entries at. With no `values` (checker,
// hexagon, brick lists) the entries are the list's (search_list).
struct MapPick {
    MapLookup lookup;
    Point3 point;
};
MapPick pick_map_entries(const PatternSpec& spec, const float* values, int count,
                         const Point3& world, const PatternEnv& env);
// The point in `spec`'s pattern space (its transforms and warps applied to `world`).
Point3 pattern_point(const PatternSpec& spec, const Point3& world);
// A normal into `spec`'s pattern space and back (POV-Ray's Warp_Normal, UnWarp_Normal),
// for normals perturbed inside texture maps.
Vector3 normal_into_pattern(const PatternSpec& spec, const Vector3& n);
Vector3 normal_out_of_pattern(const PatternSpec& spec, const Vector3& n);

}  // namespace povwall::trace
