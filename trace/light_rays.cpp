#include "trace/light_rays.h"

#include <cmath>
#include <limits>

namespace povwall::trace {
namespace {

float cubic_spline(Real low, Real high, Real pos) {
    if (pos < low) return 0;
    if (pos >= high) return 1;
    Real x = (pos - low) / (high - low);
    return float(x * x * (3 - 2 * x));
}

// cos of an angle in degrees, remembering the last one asked for: scenes light a point
// with hundreds of copies of one spotlight, each asking for the same two angles.
struct CosDegrees {
    Real degrees = std::numeric_limits<Real>::quiet_NaN(), cosine = 0;
    Real operator()(Real d) {
        if (d != degrees) {
            degrees = d;
            cosine = std::cos(d * kPi / 180);
        }
        return cosine;
    }
};

}  // namespace

bool lights_material(const Light& light, const Material& m) {
    return light.light_group == 0 ? m.global_lights : light.light_group == m.light_group;
}

bool light_at(const Light& l, const Point3& p, LightSample& s) {
    if (l.kind == Light::Kind::Parallel) {
        // The depth to the light is the distance to its plane, negative behind it
        // (POV-Ray's ComputeOneWhiteLightRay): nothing blocks a point there, and it is
        // lit from the light's side like any other.
        s.dir = normalize(l.location - l.point_at);
        s.distance = dot(l.location - p, s.dir);
    } else {
        Vector3 v = l.location - p;
        s.distance = length(v);
        if (s.distance == 0) return false;
        // Times the reciprocal, as POV-Ray's VInverseScaleEq: dividing is an ulp off at
        // times, which decides shadows of chaotic shapes (julia_fractal dust).
        s.dir = v * (1 / s.distance);
    }
    float att = 1;
    if (l.parallel) {
        // POV-Ray measures the spot's cone along the parallel direction itself: full
        // strength in front of the light, none behind it.
        s.dir = normalize(l.location - l.point_at);
        s.distance = dot(l.location - p, s.dir);
        if (s.distance <= 0) return false;
    } else if (l.kind == Light::Kind::Spot || l.kind == Light::Kind::Cylinder) {
        Vector3 axis = normalize(l.point_at - l.location);
        thread_local CosDegrees radius_cosine, falloff_cosine;
        const Real radius_cos = radius_cosine(l.radius);
        const Real falloff_cos = falloff_cosine(l.falloff);
        if (l.kind == Light::Kind::Spot) {
            Real c = dot(-s.dir, axis);
            if (c <= 0) return false;
            att = float(l.tightness != 0 ? std::pow(c, l.tightness) : 1.0);
            if (c < radius_cos) att *= cubic_spline(falloff_cos, radius_cos, c);
        } else {
            // Cylinder light: distance from the axis instead of an angle.
            Vector3 rel = p - l.location;
            Real along = dot(rel, axis);
            if (along <= 0) return false;
            Real dist = length(rel - axis * along);
            if (dist > l.falloff) return false;
            att = float(l.tightness != 0 ? std::pow(1 - dist / l.falloff, l.tightness)
                                         : 1.0);
            if (dist > l.radius) att *= 1 - cubic_spline(l.radius, l.falloff, dist);
            s.dir = -axis;
            s.distance = along;
        }
        if (att <= 0) return false;
    }
    if (l.fade_power > 0 && std::fabs(l.fade_distance) > kPovEpsilon && att > 0 &&
        s.distance < kInfinity) {
        // POV-Ray 3.7's Attenuate_Light: no fade without a fade_distance.
        att *= float(2 / (1 + std::pow(s.distance / l.fade_distance, l.fade_power)));
    }
    s.colour = l.colour * att;
    return !s.colour.is_black();
}

bool full_area_lighting(const Light& l, Quality quality, const TraceRay& ray) {
    return l.area && l.area->illumination && quality.area_lights() &&
           ray.radiosity_depth == 0;
}

bool light_ray_toward(const Light& l, const Point3& p, const Point3& towards,
                      LightSample& s) {
    if (l.kind == Light::Kind::Cylinder) {
        s.dir = normalize(towards - l.point_at);
        s.distance = dot(towards - p, s.dir);
        return true;
    }
    const Vector3 v = towards - p;
    s.distance = length(v);
    if (s.distance == 0) return false;
    s.dir = v * (1 / s.distance);
    if (l.kind == Light::Kind::Parallel || l.parallel) {
        const Vector3 along = normalize(towards - l.point_at);
        s.distance *= dot(along, s.dir);
        s.dir = along;
    }
    return true;
}

float light_attenuation(const Light& l, const Point3& p, const LightSample& s) {
    float att = 1;
    if (l.kind == Light::Kind::Spot) {
        const Vector3 axis = normalize(l.point_at - l.location);
        // The light comes from the side the depth says (behind a parallel light's
        // plane, from the other).
        const Real c = s.distance > 0 ? -dot(s.dir, axis) : dot(s.dir, axis);
        if (c <= 0) return 0;
        att = float(l.tightness != 0 ? std::pow(c, l.tightness) : 1.0);
        thread_local CosDegrees radius_cosine, falloff_cosine;
        const Real radius_cos = radius_cosine(l.radius);
        if (c < radius_cos) att *= cubic_spline(falloff_cosine(l.falloff), radius_cos, c);
    } else if (l.kind == Light::Kind::Cylinder) {
        const Vector3 axis = normalize(l.point_at - l.location);
        const Vector3 rel = p - l.location;
        const Real along = dot(rel, axis);
        if (along <= 0) return 0;
        const Real dist = length(rel - axis * along);
        if (dist > l.falloff) return 0;
        att = float(l.tightness != 0 ? std::pow(1 - dist / l.falloff, l.tightness) : 1.0);
        if (dist > l.radius) att *= 1 - cubic_spline(l.radius, l.falloff, dist);
    }
    if (l.fade_power > 0 && std::fabs(l.fade_distance) > kPovEpsilon && att > 0 &&
        s.distance < kInfinity)
        att *= float(2 / (1 + std::pow(s.distance / l.fade_distance, l.fade_power)));
    return att;
}

ChildRay shadow_child(const TraceRay& from, const Point3& at, const LightSample& s,
                      size_t l) {
    ChildRay child;
    child.kind = ChildRay::Kind::Shadow;
    child.trace.ray = {at, s.dir};
    child.trace.interiors = from.interiors;
    child.trace.depth = from.depth;
    child.trace.use = RayUse::Shadow;
    child.t_max = s.distance;
    child.light = int(l);
    // A parallel light's depth is negative behind its plane: a test over it finds
    // nothing.
    child.unoccluded = !(s.distance > 0);
    return child;
}

}  // namespace povwall::trace
