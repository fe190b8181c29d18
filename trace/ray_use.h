// What kind of ray a ray is, for the object flags no_image, no_reflection, no_shadow and
// no_radiosity,
// and where POV-Ray 3.7 tests those flags: on the objects it links to the scene (its
// frame objects: top-level objects, a plain union's children), and inside a union or a
// merge on their children, each by its own rule.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/scene.h"

namespace povwall::trace {

enum class RayUse : uint8_t {
    Camera,      // a camera ray (POV-Ray's primary ray)
    Reflection,  // reflected, or passed on after any reflection
    Refraction,  // transmitted or refracted, never reflected
    Shadow,
    // Transmitted or refracted after a reflection: counted as refracted, but POV-Ray's
    // reflection flag stays on (Ray::SetFlags(type, other)), so it is no image ray.
    ReflectedRefraction,
    // A parse-time trace(): a primary ray, and no test of the object's own flags.
    Query,
    Photon,            // a photon from its light, or refracted, never reflected
    PhotonReflection,  // a photon reflected at some point
    // A radiosity sample ray (trace/radiosity/): POV-Ray's "other" ray with the
    // radiosity flag. The rays it spawns keep that flag (the `radiosity_ray` argument
    // of PreparedScene::closest_hit).
    Radiosity,
};
constexpr RayUse kLastRayUse = RayUse::Radiosity;
constexpr size_t kRayUses = size_t(kLastRayUse) + 1;

// POV-Ray's flags of such a ray (Ray::IsPrimaryRay, IsImageRay, IsReflectionRay,
// IsShadowTestRay, IsPhotonRay, IsRadiosityRay), and whether its frame objects' own
// flags are tested.
struct RayFlags {
    bool primary = false, image = false, reflection = false, shadow = false,
         photon = false, radiosity = false;
    bool frame_test = true;
    // Where POV-Ray's ray starts, as a distance along the ray traced: a shadow ray is
    // restarted at each see-through surface it crosses. A mesh without inside_vector
    // reports only what it meets first from there.
    Real restart = 0;
};

constexpr RayFlags ray_flags(RayUse u) {
    RayFlags f;
    switch (u) {
        case RayUse::Camera:
            f.primary = f.image = true;
            break;
        case RayUse::Reflection:
        case RayUse::ReflectedRefraction:
            f.reflection = true;
            break;
        case RayUse::Refraction:
            f.image = true;
            break;
        case RayUse::Shadow:
            f.shadow = true;
            break;
        case RayUse::Query:
            f.primary = f.image = true;
            f.frame_test = false;
            break;
        case RayUse::Photon:
            // A photon leaves its light as a primary ray.
            f.primary = f.image = f.photon = true;
            break;
        case RayUse::PhotonReflection:
            f.reflection = f.photon = true;
            break;
        case RayUse::Radiosity:
            f.radiosity = true;
            break;
    }
    return f;
}

// The use of a ray reflected from, or transmitted through a surface by, a ray of use
// `u` (total internal reflection is a reflection). The reflection flag stays on.
constexpr RayUse reflected_use(RayUse u) {
    return u == RayUse::Photon || u == RayUse::PhotonReflection ? RayUse::PhotonReflection
                                                                : RayUse::Reflection;
}
constexpr RayUse transmitted_use(RayUse u) {
    switch (u) {
        case RayUse::Photon:
        case RayUse::PhotonReflection:
            return u;
        case RayUse::Reflection:
        case RayUse::ReflectedRefraction:
            return RayUse::ReflectedRefraction;
        default:
            return RayUse::Refraction;
    }
}

// A frame object's flags as POV-Ray tests them on the objects it links to the scene (a
// light's looks_like object: the light's, no_shadow alone).
struct FrameFlags {
    bool no_shadow = false, no_image = false, no_reflection = false, no_radiosity = false;
};

// Whether a ray of these flags passes by a frame object with these flags (POV-Ray's
// NoSomethingFlagRayObjectCondition for traced rays, NoShadowFlagRayObjectCondition for
// shadow rays).
constexpr bool frame_hides(const FrameFlags& o, const RayFlags& f) {
    return f.frame_test &&
           ((f.image && o.no_image) || (f.reflection && o.no_reflection) ||
            ((f.shadow || f.photon) && o.no_shadow) || (f.radiosity && o.no_radiosity));
}

// The flags of frame object `o` (flags given to its CSG ancestors have come down to it):
// its own, and, for a union (not a merge, not inverse: POV-Ray's inverse union is an
// intersection) whose children all have no_shadow, no_shadow (Link_To_Frame).
inline FrameFlags frame_flags(const Object& o) {
    FrameFlags f{o.no_shadow, o.no_image, o.no_reflection, o.no_radiosity};
    const Csg* csg = std::get_if<Csg>(&o.shape);
    if (csg && csg->kind == CsgKind::Union && !o.inverse) {
        bool all = true;
        for (const Object& c : csg->children) all = all && c.no_shadow;
        f.no_shadow = f.no_shadow || all;
    }
    return f;
}

// How POV-Ray sees a CSG node when it tests its children's flags: after an odd number of
// inversions (its own `inverse` and its CSG ancestors', `inverted`) its union or merge
// is an intersection and its intersection or difference a merge (CSG::Invert and
// Morph); povwall's parser already turned unions under an inverse into merges.
enum class PovCsg : uint8_t { Union, Merge, Intersection };
constexpr PovCsg pov_csg(CsgKind kind, bool inverted) {
    const bool intersection =
        kind == CsgKind::Intersection || kind == CsgKind::Difference;
    if (inverted) return intersection ? PovCsg::Merge : PovCsg::Intersection;
    if (intersection) return PovCsg::Intersection;
    return kind == CsgKind::Union ? PovCsg::Union : PovCsg::Merge;
}

// Whether a CSG node leaves out child `c` for a ray: POV-Ray's union tests its children
// with Test_Ray_Flags (no_image only for image rays that are not primary rays, so a
// camera ray sees a no_image child), its merge with Test_Ray_Flags_Shadow (a shadow ray
// passes every child, no_shadow or not; a child left out is also left out of the merge's
// inside tests), its intersection and difference with nothing. Photons are stopped by
// no_shadow alone.
constexpr bool csg_skips(PovCsg csg, const Object& c, const RayFlags& f) {
    if (csg == PovCsg::Intersection) return false;
    if (f.photon) return c.no_shadow;
    if (f.shadow) return false;
    const bool image = f.image && (csg == PovCsg::Merge || !f.primary);
    return (image && c.no_image) || (f.reflection && c.no_reflection) ||
           (f.radiosity && c.no_radiosity);
}

}  // namespace povwall::trace
