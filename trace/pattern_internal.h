// Pieces shared by the pattern, pigment and normal evaluators (not a public interface).
#pragma once

#include "core/noise.h"
#include "core/pattern_lists.h"
#include "core/scene.h"
#include "trace/pattern.h"

namespace povwall::trace::detail {

// The classic turbulence of a pattern, or null.
const Warp* classic_turbulence(const PatternSpec& spec);

// World point -> pattern-space point: transforms and warps, classic turbulence included
// where POV-Ray applies it (everything but marble and wood).
Point3 warp_point(const PatternSpec& spec, const Point3& world);

// World-space normal -> pattern space (only the transforms act, as in POV-Ray), unit.
Vector3 warp_normal(const PatternSpec& spec, const Vector3& n);
// Pattern-space normal -> world space, unit.
Vector3 unwarp_normal(const PatternSpec& spec, const Vector3& n);

// The pattern value at an already warped point (POV-Ray's Evaluate_TPat).
Real value_at(const PatternSpec& spec, const Point3& p, const PatternEnv& env);

// POV-Ray's quilted profile (Bezier with controls p1, p2).
Real quilt_cubic(Real t, Real p1, Real p2);

// image_map: the image's colour at pattern-space point p (clear white off the image;
// then *on_image, when given, is set false).
Colour image_map_colour(const ImageMapping& m, const Point3& p, bool* on_image = nullptr);
// bump_map: bends pattern-space normal n (unit) by the image's heights around p.
void bump_map_normal(const ImageMapping& m, Real amount, const Point3& p, Vector3& n);

// density_file: the df3 grid's value at pattern-space point p (POV-Ray's
// density_pattern; `interpolation` as the scene wrote it).
Real density_file_value(const DensityFile& file, int interpolation, const Point3& p);

// mandel, julia and magnet (pattern_fractal.cpp).
Real fractal_value(const PatternSpec& spec, const Point3& p);

// The block patterns and the cubic warp (pattern_blocks.cpp).
Real square_value(const Point3& p);
Real triangular_value(const Point3& p);
Real cubic_value(const Point3& p);
Point3 cubic_warp(const Point3& p);

// `tiling n` (pattern_tiling.cpp), 1 to 27 (others: square).
Real tiling_value(int n, const Point3& p);
// Tilings 25 to 27 (pattern_penrose.cpp): Penrose's P1, P2 and P3 around the origin.
enum class PenroseKind : uint8_t { Pentagons, KitesAndDarts, Rhombs };
Real penrose_tiles(Real x, Real z, PenroseKind kind);

// `pavement` (pattern_pavement.cpp): the value at p of a parsed pavement (its values
// reduced as the parser does).
Real pavement_value(const PatternSpec::Pavement& pavement, const Point3& p);

// facets: replaces (or with `coords`, perturbs) pattern-space normal n at point p
// (pattern_facets.cpp).
void facets_normal(const PatternSpec::Facets& facets, const Point3& p, Vector3& n);

inline int resolve_generator(const PatternSpec& spec, const PatternEnv& env) {
    return spec.noise_generator != 0 ? spec.noise_generator : env.noise_generator;
}

// The patterns whose value is an entry index, and their lists' sizes (2 for the others,
// whose lists are maps).
inline bool is_discrete(PatternKind k) { return pattern_list_size(k) != 0; }
inline int list_size(PatternKind k) {
    const int n = pattern_list_size(k);
    return n ? n : 2;
}

// The surface coordinates (u, v, 0) of the hit `env` sees (trace/uv_mapping.h); the
// origin where there is none (the parser refuses uv_mapping where no hit can be).
Point3 uv_of(const PatternEnv& env);

// image_pattern: the image's value at pattern-space point p (0 off the image).
Real image_pattern_value(const ImageMapping& m, const Point3& p);
// material_map: the index of the texture the image's pixel at p picks among `count`.
int material_map_index(const ImageMapping& m, const Point3& p, int count);

// Whether world point p is inside `object` (the object pattern; trace/prepared_scene.h).
bool inside_pattern_object(const Object& object, const Point3& p);

}  // namespace povwall::trace::detail
