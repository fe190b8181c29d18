#include "trace/photon_map.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <queue>
#include <thread>
#include <unordered_set>

#include "core/math_constants.h"
#include "trace/media.h"
#include "trace/pov_bounds.h"
#include "trace/prepared_scene.h"
#include "trace/shading.h"

namespace povwall::trace {
namespace {

// Our random numbers: a hash of what the number is for, so that the map depends only on
// the scene (splitmix64's finaliser over the combined key).
double hashed_unit(uint64_t a, uint64_t b, uint64_t c, uint64_t d) {
    uint64_t x =
        a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull) * 0xBF58476D1CE4E5B9ull;
    x ^= (c + 0x85EBCA77C2B2AE63ull) * 0x94D049BB133111EBull;
    x ^= (d + 0x27D4EB2F165667C5ull) * 0xD6E8FEB86659FD93ull;
    x ^= x >> 30;
    x *= 0xBF58476D1CE4E5B9ull;
    x ^= x >> 27;
    x *= 0x94D049BB133111EBull;
    x ^= x >> 31;
    return double(x >> 11) * (1.0 / 9007199254740992.0);
}

// The sphere photons are shot at: POV-Ray's about the target's own box (photons.cpp:
// the corner plus half the lengths, the radius to the corner), whatever the surface
// inside it. An infinite box (a plane, CSG of planes without a bounded_by) gives the
// origin and sqrt(3) BOUND_HUGE / 2.
void target_sphere(const Object& target, Point3& ctr, double& rad) {
    const PovBBox box = pov_object_bbox(target);
    const Point3 lo{box.lo[0], box.lo[1], box.lo[2]};
    ctr = Point3{box.lo[0] + box.len[0] / 2.0, box.lo[1] + box.len[1] / 2.0,
                 box.lo[2] + box.len[2] / 2.0};
    rad = length(ctr - lo);
}

bool switch_on(PhotonSwitch object, PhotonSwitch light) {
    return (object == PhotonSwitch::On && light != PhotonSwitch::Off) ||
           (object != PhotonSwitch::Off && light == PhotonSwitch::On);
}

// POV-Ray's frame objects: the top-level objects after plain unions are split into their
// children (recursively), as Link_To_Frame does after the flags came down.
void frame_objects(const Object& o, std::vector<const Object*>& out) {
    if (pov_splits_union(o)) {
        for (const Object& c : std::get<Csg>(o.shape).children) frame_objects(c, out);
        return;
    }
    out.push_back(&o);
}

// POV-Ray's SearchThroughObjects: a target is shot at whole; a CSG that is none is
// searched for targets among its children.
void find_targets(const Object& o, std::vector<const Object*>& out) {
    if (o.photons.target) {
        out.push_back(&o);
        return;
    }
    if (const Csg* csg = std::get_if<Csg>(&o.shape))
        for (const Object& c : csg->children) find_targets(c, out);
}

void leaves_of(const Object& o, std::unordered_set<const Object*>& out) {
    out.insert(&o);
    if (const Csg* csg = std::get_if<Csg>(&o.shape))
        for (const Object& c : csg->children) leaves_of(c, out);
}

// Ward's RGBE with POV-Ray's exponent offset of 250 (colour2photonRgbe).
void encode_rgbe(const Rgb& c, uint8_t out[4]) {
    float v = std::max(c.r, std::max(c.g, c.b));
    if (v < 1e-32f) {
        out[0] = out[1] = out[2] = out[3] = 0;
        return;
    }
    int e = 0;
    v = float(std::frexp(v, &e) * 256.0 / v);
    out[0] = uint8_t(c.r * v);
    out[1] = uint8_t(c.g * v);
    out[2] = uint8_t(c.b * v);
    out[3] = uint8_t(e + 250);
}

// The unit vector from the photon toward where it came from in POV-Ray's two bytes.
void encode_direction(const Vector3& d, Photon& ph) {
    const double dl = std::sqrt(d.x * d.x + d.z * d.z);
    double phi = dl > 0 ? std::acos(std::clamp(d.x / dl, -1.0, 1.0)) : 0;
    if (d.z < 0) phi = -phi;
    double theta = std::acos(std::clamp(dl, -1.0, 1.0));
    if (d.y < 0) theta = -theta;
    ph.theta = int8_t(theta * 127.0 / kPi);
    ph.phi = int8_t(phi * 127.0 / kPi);
}

// POV-Ray's Parallel lights (parallel point and spot lights, and cylinder lights): their
// photons leave a disc across the light's direction, all along it, rather than a point.
bool shoots_parallel(const Light& l) {
    return l.parallel || l.kind == Light::Kind::Parallel ||
           l.kind == Light::Kind::Cylinder;
}

// `v` turned about the unit `axis` by `angle`.
Vector3 turned(const Vector3& v, const Vector3& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
}

// POV-Ray's cubic_spline: 0 below `low`, 1 from `high`, smooth between.
double smooth_step(double low, double high, double pos) {
    if (pos < low) return 0;
    if (pos >= high) return 1;
    const double x = (pos - low) / (high - low);
    return x * x * (3 - 2 * x);
}

// POV-Ray's ShootingDirection from `from` toward the target's centre `ctr`: the unit
// direction, a unit `left` across it (across the light's `parallel` direction for a
// parallel light) and the distance.
struct Aim {
    Vector3 toctr, left;
    double dist = 0;
};
Aim aim_at(const Point3& from, const Point3& ctr, const Vector3* parallel) {
    Aim a;
    const Vector3 t = ctr - from;
    a.dist = length(t);
    a.toctr = a.dist > 0 ? t * (1 / a.dist) : t;
    const Vector3 up =
        std::fabs(std::fabs(a.toctr.z) - 1) < 0.1 ? Vector3{0, 1, 0} : Vector3{0, 0, 1};
    a.left = normalize(cross(parallel ? *parallel : a.toctr, up));
    return a;
}

// POV-Ray's computeAttenuation of a photon leaving along `dir`: a spot light's cone
// about its `axis`; a cylinder light's by the distance `from_axis` of the photon's start
// from the light's location, across the axis.
double photon_attenuation(const Light& l, const Vector3& dir, const Vector3& axis,
                          double from_axis) {
    if (l.kind == Light::Kind::Spot) {
        const double cs = dot(dir, axis);
        if (cs <= 0) return 0;
        double a = std::pow(cs, l.tightness);
        const double radius_cos = std::cos(l.radius * kPi / 180);
        if (radius_cos > 0)
            a *= smooth_step(std::cos(l.falloff * kPi / 180), radius_cos, cs);
        return a;
    }
    if (l.kind == Light::Kind::Cylinder) {
        if (dot(dir, axis) <= 0 || from_axis >= l.falloff) return 0;
        const double d = 1 - from_axis / l.falloff;
        double a = std::pow(d, l.tightness);
        if (l.radius > 0 && from_axis > l.radius)
            a *= smooth_step(0, 1 - l.radius / l.falloff, d);
        return a;
    }
    return 1;
}

struct Target {
    const Object* object;
    std::unordered_set<const Object*> leaves;
};

// One light shooting at one target (POV-Ray's LightTargetCombo and ShootingDirection).
class Shooter final : public MediaPhotonSink {
  public:
    Shooter(const PreparedScene& scene, const PhotonSettings& settings, int max_level,
            float adc, const std::vector<Material>& light_interiors_materials,
            std::vector<Photon>& out, std::vector<Photon>& media_out)
        : scene_(scene),
          settings_(settings),
          max_level_(max_level),
          adc_(adc),
          stand_ins_(light_interiors_materials),
          out_(out),
          media_out_(media_out) {
        scene.init_context(ctx_);
        spacing_factor = settings.media_spacing_factor;
        max_steps = settings.media_steps;
        step_jitter = settings.jitter;
    }

    void shoot(const Light& light, size_t light_index, const Target& target,
               size_t target_index, const std::vector<const Object*>& frames);
    uint64_t shot() const { return shot_; }

    // MediaPhotonSink: the jitter of the media steps, from a running count of this
    // light and target's (each pair is shot in one thread, in the same order in every
    // process).
    Real draw() override { return hashed_unit(media_draws_++, pair_, 0, 5); }
    void set_pair(uint64_t pair) { pair_ = pair; }
    void store(const Point3& at, Real along, const Rgb& colour) override {
        deposit(media_out_, at, media_from_, colour, travelled + along);
    }

  private:
    void trace(const TraceRay& ray, Rgb colour, int level, bool prev_pass, double depth);
    void deposit(std::vector<Photon>& into, const Point3& at, const Point3& from,
                 const Rgb& colour, double depth);

    const PreparedScene& scene_;
    const PhotonSettings& settings_;
    int max_level_;
    float adc_;
    const std::vector<Material>& stand_ins_;
    std::vector<Photon>& out_;
    std::vector<Photon>& media_out_;
    Point3 media_from_;  // the origin of the ray storing media photons
    uint64_t media_draws_ = 0;
    uint64_t pair_ = 0;  // the light and target's index among the pairs shot
    RayContext ctx_;
    const Light* light_ = nullptr;
    const Target* target_ = nullptr;
    double spread_ = 0;
    bool parallel_ = false;  // shoots_parallel(*light_)
    bool hit_target_ = false;
    uint64_t shot_ = 0;
};

void Shooter::shoot(const Light& light, size_t light_index, const Target& target,
                    size_t target_index, const std::vector<const Object*>& frames) {
    const ObjectPhotons& ph = target.object->photons;
    if (!switch_on(ph.refraction, light.photon_refraction) &&
        !switch_on(ph.reflection, light.photon_reflection))
        return;
    light_ = &light;
    target_ = &target;
    parallel_ = shoots_parallel(light);
    parallel = parallel_;
    // An area light with `photons { area_light }` shoots from each point of its grid
    // (not a parallel one), each photon carrying its share.
    const AreaLight* area =
        light.photon_area_light && !parallel_ && light.area ? &*light.area : nullptr;
    const int samples1 = area ? std::max(1, area->size1) : 1;
    const int samples2 = area ? std::max(1, area->size2) : 1;
    Point3 ctr;
    double rad;
    target_sphere(*target.object, ctr, rad);
    // The light's direction (POV-Ray's Direction: unit unless point_at is the location).
    Vector3 axis = light.point_at - light.location;
    if (const double len = length(axis); len > kPovEpsilon) axis = axis * (1 / len);
    Aim aim = aim_at(light.location, ctr, parallel_ ? &axis : nullptr);
    // A parallel light's photons start on the disc about the target's centre seen along
    // the light, in the plane through the light's location.
    const Point3 disc = ctr - axis * (dot(axis, aim.toctr) * aim.dist);
    // The spacing at unit distance (for a parallel light: the spacing itself).
    spread_ = ph.spacing_multiplier * settings_.spacing / (parallel_ ? 1 : aim.dist);
    if (area) spread_ *= std::sqrt(double(samples1 * samples2));
    spread_at_unit = spread_;
    if (spread_ <= 0) return;
    // For a parallel light "theta" is the disc's radius.
    const double dtheta = parallel_ ? spread_ : std::atan(spread_);
    double maxtheta;
    if (parallel_) {
        maxtheta = rad;
    } else if (aim.dist >= rad) {
        maxtheta = std::asin(rad / aim.dist);
    } else {
        maxtheta = kPi;
        if (std::fabs(aim.dist) < kPovEpsilon) {
            aim.left = {0, 1, 0};
            aim.toctr = {0, 0, 1};
        }
    }
    // The interiors around the photon's start (POV-Ray: of the frame objects containing
    // it): the light's, or each photon's own where they start elsewhere.
    auto interiors_at = [&](const Point3& p) {
        InteriorStack inside;
        for (size_t i = 0; i < frames.size(); ++i)
            if (inside_object(*frames[i], p)) inside.push(&stand_ins_[i]);
        return inside;
    };
    const InteriorStack at_light = interiors_at(light.location);
    bool hit_once = false;
    uint64_t ring = 0;
    for (double theta = 0; theta < maxtheta; theta += dtheta, ++ring) {
        hit_target_ = false;
        const double dphi = theta < kPovEpsilon ? 2 * kPi
                            : parallel_         ? dtheta / theta
                                                : dtheta / std::sin(theta);
        const uint64_t key = (uint64_t(light_index) << 32) | uint64_t(target_index);
        const double minphi = -kPi + dphi * hashed_unit(key, ring, ~0ull, 0) * 0.5;
        const double maxphi = kPi - dphi / 2 + (minphi + kPi);
        uint64_t k = 0;
        for (double phi = minphi; phi < maxphi; phi += dphi, ++k) {
            const double jitphi =
                phi + dphi * (hashed_unit(key, ring, k, 1) - 0.5) * settings_.jitter;
            const double jittheta =
                theta + dtheta * (hashed_unit(key, ring, k, 2) - 0.5) * settings_.jitter;
            for (int u = 0; u < samples1; ++u) {
                for (int v = 0; v < samples2; ++v) {
                    Point3 origin = light.location;
                    Vector3 dir;
                    if (parallel_) {
                        dir = axis;
                        origin = disc + turned(aim.left * jittheta, axis, jitphi);
                    } else {
                        Aim from = aim;
                        if (area) {
                            // POV-Ray's grid: the axes' ends and evenly between.
                            if (samples1 > 1)
                                origin +=
                                    area->axis1 * (double(u) / (samples1 - 1) - 0.5);
                            if (samples2 > 1)
                                origin +=
                                    area->axis2 * (double(v) / (samples2 - 1) - 0.5);
                            from = aim_at(origin, ctr, nullptr);
                            if (std::fabs(from.dist) < kPovEpsilon) {
                                from.left = {0, 1, 0};
                                from.toctr = {0, 0, 1};
                            }
                        }
                        // toctr turned by theta toward -left, then about toctr by phi.
                        const Vector3 w = from.toctr * std::cos(jittheta) -
                                          from.left * std::sin(jittheta);
                        dir = normalize(turned(w, from.toctr, jitphi));
                    }
                    const double attenuation =
                        photon_attenuation(
                            light, dir, axis,
                            parallel_ ? length(origin - light.location) : 0) /
                        (samples1 * samples2);
                    if (attenuation < 0.00001) continue;
                    TraceRay ray;
                    ray.ray = {origin, dir};
                    ray.use = RayUse::Photon;
                    ray.interiors = parallel_ || area ? interiors_at(origin) : at_light;
                    ++shot_;
                    trace(ray, light.colour * float(attenuation), 0, false, 0);
                }
            }
        }
        if (hit_target_) hit_once = true;
        if (hit_once && !hit_target_ && theta > settings_.autostop * maxtheta) break;
    }
}

// POV-Ray's PhotonTrace::TraceRay and ComputeLightedTexture for a caustic photon: the
// first surface must be the target (or let photons pass), then each surface stores the
// photon (from the second on) and sends it on by the target's reflection and refraction.
void Shooter::trace(const TraceRay& ray, Rgb colour, int level, bool prev_pass,
                    double depth) {
    if (level >= max_level_ || ray.weight < adc_) return;
    ++level;
    Hit hit;
    if (!scene_.closest_hit(ray.ray, 0, kInfinity, ray.use, hit, ctx_)) return;
    const Material& m = *hit.material;
    static const ObjectPhotons kNone;
    const ObjectPhotons& ph = m.object ? m.object->photons : kNone;
    bool pass = false;
    if (level == 1 || prev_pass) {
        const bool is_target = ph.target && target_->leaves.count(m.object);
        if (ph.target && !is_target) {
            if (!ph.pass_through) return;
            pass = true;
        } else if (is_target) {
            hit_target_ = true;
        } else {
            if (!ph.pass_through) return;
            pass = true;
        }
    }
    // The media it crossed act on the photon first (their glow adds to it, or it
    // stores media photons along them), then the interior's `refraction` and, inside
    // it, its fade dim it.
    const bool store_in_media = settings_.media_steps > 0 && level > 1 && !prev_pass;
    if (store_in_media) {
        travelled = depth;
        media_from_ = ray.ray.origin;
    }
    colour = photon_through_media(scene_, ray, hit.t, {m.global_lights, m.light_group},
                                  colour, store_in_media ? this : nullptr);
    const Rgb arriving = colour;
    Rgb att(m.interior ? m.interior->old_refract : 1.0f);
    if (m.interior && ray.interiors.contains(m.interior_id))
        att *= interior_attenuation(*m.interior, hit.t, true);  // fade_power > 0 only
    colour *= att;
    depth += hit.t;
    if (level > 1 && !prev_pass && ph.collect && m.global_lights)
        deposit(out_, hit.point, ray.ray.origin, colour, depth);
    if (pass) {
        // Straight through, unfiltered, entering or leaving the object.
        TraceRay next = ray;
        next.ray = {hit.point, ray.ray.direction};
        if (!next.interiors.remove(m.interior_id)) next.interiors.push(&m);
        trace(next, colour, level, pass, depth);
        return;
    }
    const bool refract = switch_on(ph.refraction, light_->photon_refraction);
    const bool reflect = switch_on(ph.reflection, light_->photon_reflection);
    if (!refract && !reflect) return;
    ShadingRecord record;
    // The media along the way acted above (photon_through_media): the surface's
    // children only (their fog and media would light nothing the photon carries).
    spawn_surface_children(scene_, ray, hit, record, ctx_);
    for (const ChildRay& child : record.children) {
        if (child.kind == ChildRay::Kind::Shadow) continue;
        if (child.kind == ChildRay::Kind::Transmission || child.internal_reflection) {
            // The child's coefficient holds the interior's dimming already.
            if (refract) trace(child.trace, arriving * child.coeff, level, false, depth);
        } else if (reflect) {
            Rgb c = colour;
            if (child.exponent != 1) {
                const float e = 1 / child.exponent;
                c = Rgb(std::pow(c.r, e), std::pow(c.g, e), std::pow(c.b, e));
            }
            // POV-Ray's photon pass weighs a reflected photon by the reflectivity twice
            // (ComputeReflectivity scales the layer's weight, then the reflection is
            // traced with that weight times the reflectivity again), so adc_bailout
            // ends reflection chains sooner than in the render.
            TraceRay next = child.trace;
            next.weight *=
                std::max(child.coeff.r, std::max(child.coeff.g, child.coeff.b));
            trace(next, c * child.coeff, level, false, depth);
        }
    }
}

// POV-Ray's addSurfacePhoton: the flux a photon of this spread carries to this depth
// (lights do not dim with distance, so the photon's share grows with the square of it).
void Shooter::deposit(std::vector<Photon>& into, const Point3& at, const Point3& from,
                      const Rgb& colour, double depth) {
    const Light& l = *light_;
    double attenuation = 1;
    if (l.fade_power > 0 && std::fabs(l.fade_distance) > kPovEpsilon)
        attenuation = 2 / (1 + std::pow(depth / l.fade_distance, l.fade_power));
    // A parallel light's photons do not spread out with distance.
    const double spread = parallel_ ? 1 : depth * depth;
    const Rgb flux = colour * float(attenuation * spread_ * spread_ * spread);
    Photon ph;
    encode_rgbe(flux, ph.rgbe);
    ph.pos[0] = float(at.x);
    ph.pos[1] = float(at.y);
    ph.pos[2] = float(at.z);
    encode_direction(normalize(from - at), ph);
    into.push_back(ph);
}

// POV-Ray's PhotonEstimationTask: the spacing `count` asks for.
double spacing_for_count(const Scene& sc, const std::vector<Target>& targets,
                         const PhotonSettings& s) {
    double estimate = 0;
    for (const Light& light : sc.lights) {
        if (light.light_group != 0) continue;
        for (const Target& t : targets) {
            const ObjectPhotons& ph = t.object->photons;
            const bool rfr = switch_on(ph.refraction, light.photon_refraction);
            const bool rfl = switch_on(ph.reflection, light.photon_reflection);
            if (!rfr && !rfl) continue;
            Point3 ctr;
            double rad;
            target_sphere(*t.object, ctr, rad);
            double x = rad / (ph.spacing_multiplier * s.spacing);
            x = x * x * kPi;
            if (rfr && rfl) x *= 1.5;
            if (ph.collect) x *= rfr && rfl ? 3 : rfr ? 2 : 1;
            estimate += x * 0.5;
        }
    }
    return s.spacing * std::sqrt(estimate / s.count);
}

}  // namespace

bool refracts_photons(const ObjectPhotons& leaf, const Light& light) {
    return leaf.target && leaf.refraction != PhotonSwitch::Off &&
           light.photon_refraction != PhotonSwitch::Off &&
           (leaf.refraction == PhotonSwitch::On ||
            light.photon_refraction == PhotonSwitch::On);
}

Rgb PhotonMap::flux(const Photon& ph) {
    if (ph.rgbe[3] == 0) return Rgb{};
    const float f = float(std::ldexp(1.0, int(ph.rgbe[3]) - (250 + 8)));
    return Rgb(ph.rgbe[0] * f, ph.rgbe[1] * f, ph.rgbe[2] * f);
}

Vector3 PhotonMap::incoming(const Photon& ph) {
    const double theta = double(ph.theta) * kPi / 127.0;
    const double phi = double(ph.phi) * kPi / 127.0;
    const double ct = std::cos(theta);
    return {ct * std::cos(phi), std::sin(theta), ct * std::sin(phi)};
}

std::shared_ptr<PhotonMap> PhotonMap::assemble(const PhotonSettings& settings,
                                               std::vector<Photon> photons,
                                               double min_radius, double radius_step,
                                               std::shared_ptr<PhotonMap> media) {
    auto map = std::make_shared<PhotonMap>();
    map->settings_ = settings;
    map->photons_ = std::move(photons);
    map->min_radius_ = min_radius;
    map->radius_step_ = radius_step;
    map->media_ = std::move(media);
    return map;
}

void PhotonMap::build_tree(size_t lo, size_t hi) {
    if (hi - lo < 1) return;
    float mn[3] = {1e30f, 1e30f, 1e30f}, mx[3] = {-1e30f, -1e30f, -1e30f};
    for (size_t i = lo; i < hi; ++i)
        for (int a = 0; a < 3; ++a) {
            mn[a] = std::min(mn[a], photons_[i].pos[a]);
            mx[a] = std::max(mx[a], photons_[i].pos[a]);
        }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (mx[a] - mn[a] > mx[axis] - mn[axis]) axis = a;
    const size_t mid = lo + (hi - lo) / 2;
    std::nth_element(
        photons_.begin() + long(lo), photons_.begin() + long(mid),
        photons_.begin() + long(hi),
        [axis](const Photon& a, const Photon& b) { return a.pos[axis] < b.pos[axis]; });
    photons_[mid].axis = uint8_t(axis);
    build_tree(lo, mid);
    build_tree(mid + 1, hi);
}

double PhotonMap::nearest(const Point3& p, const Vector3* n, double radius,
                          std::vector<const Photon*>& out) const {
    out.clear();
    const size_t k = size_t(std::max(1, settings_.gather_max));
    // Max-heap of (flattened squared distance, photon) holding the k nearest so far.
    thread_local std::vector<std::pair<double, const Photon*>> heap;
    heap.clear();
    double dmax = radius * radius;
    bool overflowed = false;
    const double q[3] = {p.x, p.y, p.z};
    auto visit = [&](auto&& self, size_t lo, size_t hi) -> void {
        if (lo >= hi) return;
        const size_t mid = lo + (hi - lo) / 2;
        const Photon& ph = photons_[mid];
        const double v[3] = {ph.pos[0] - q[0], ph.pos[1] - q[1], ph.pos[2] - q[2]};
        double d = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (n) d += std::fabs(n->x * v[0] + n->y * v[1] + n->z * v[2]) * d * 16;
        if (d < dmax) {
            if (heap.size() < k) {
                heap.push_back({d, &ph});
                std::push_heap(heap.begin(), heap.end());
            } else {
                std::pop_heap(heap.begin(), heap.end());
                heap.back() = {d, &ph};
                std::push_heap(heap.begin(), heap.end());
                dmax = heap.front().first;
                overflowed = true;
            }
        }
        const int a = ph.axis;
        const double delta = q[a] - ph.pos[a];
        if (delta < 0) {
            self(self, lo, mid);
            if (delta * delta < dmax) self(self, mid + 1, hi);
        } else {
            self(self, mid + 1, hi);
            if (delta * delta < dmax) self(self, lo, mid);
        }
    };
    visit(visit, 0, photons_.size());
    for (const auto& e : heap) out.push_back(e.second);
    return overflowed ? std::sqrt(dmax) : radius;
}

double PhotonMap::gather(const Point3& p, const Vector3* n,
                         std::vector<const Photon*>& out) const {
    double size = min_radius_;
    double radius = nearest(p, n, size, out);
    size_t num = out.size();
    double prev_density = double(num) / (radius * radius);
    if (prev_density == 0) prev_density = 1e-16;
    // POV-Ray expands at most once (gatherNumSteps 2).
    if (int(num) < settings_.gather_min) {
        thread_local std::vector<const Photon*> wider;
        size += radius_step_;
        const double r2 = nearest(p, n, size, wider);
        const size_t n2 = wider.size();
        const double density = double(n2) / (r2 * r2);
        if ((density - prev_density) / prev_density < settings_.expand_tolerance ||
            (int(n2) < settings_.expand_min && n2 > 0)) {
            out.swap(wider);
            radius = r2;
        }
    }
    return radius;
}

// POV-Ray's setGatherOptions: the radius holding gather_max photons at the average
// density of sampled photons (per area on surfaces, per volume in media), widened where
// many samples are sparse; a media map's is doubled.
void PhotonMap::estimate_gather_radius(double radius, double multiplier, bool media) {
    // POV-Ray's density of n photons within r (the media's with its 0.3333 for 1/3).
    auto density_of = [media](size_t n, double r) {
        return media ? 3.0 * double(n) / (4.0 * kPi * r * r * r)
                     : double(n) / (kPi * r * r);
    };
    double r = radius;
    if (r <= 0) {
        const size_t count = photons_.size();
        size_t samples = std::clamp<size_t>(count / 20, 100, 1000);
        std::vector<const Photon*> found;
        double sum = 0;
        for (size_t i = 0; i < samples; ++i) {
            const Photon& ph = photons_[size_t(hashed_unit(i, 7, 0, 3) * double(count))];
            const Point3 at{ph.pos[0], ph.pos[1], ph.pos[2]};
            const double rr = nearest(at, nullptr, 10000000.0, found);
            const double density =
                rr > 0 ? density_of(found.size(), rr) : (i > 0 ? sum / double(i) : 0);
            sum += density;
        }
        const double average = sum / double(samples);
        r = media ? std::pow(3.0 * settings_.gather_max / (average * kPi * 4.0), 0.3333)
                  : std::sqrt(settings_.gather_max / (average * kPi));
        size_t sparse = 0;
        for (size_t i = 0; i < samples; ++i) {
            const Photon& ph = photons_[size_t(hashed_unit(i, 7, 1, 3) * double(count))];
            const Point3 at{ph.pos[0], ph.pos[1], ph.pos[2]};
            const double rr = nearest(at, nullptr, r, found);
            if (rr > 0) {
                const double density = density_of(found.size(), rr);
                if (density < average * 0.7 && density > average * 0.05) ++sparse;
            }
        }
        r *= 1.0 + 20.0 * (double(sparse) / double(samples));
    }
    min_radius_ = r * multiplier;
    if (media) min_radius_ *= 2;
    radius_step_ = min_radius_ * 2;
}

std::shared_ptr<const PhotonMap> build_photon_map(const PreparedScene& scene) {
    const Scene& sc = scene.scene();
    if (!sc.settings.photons || !scene.plan().quality.atmosphere()) return nullptr;
    auto map = std::make_shared<PhotonMap>();
    PhotonSettings& s = map->settings_;
    s = *sc.settings.photons;
    std::vector<const Object*> frames;
    for (const Object& o : sc.objects) frame_objects(o, frames);
    std::vector<Target> targets;
    for (const Object* f : frames) {
        std::vector<const Object*> found;
        find_targets(*f, found);
        for (const Object* t : found) {
            if (!t->global_lights) continue;  // POV-Ray: no photons without global lights
            Target target{t, {}};
            leaves_of(*t, target.leaves);
            targets.push_back(std::move(target));
        }
    }
    if (s.count > 0 && !targets.empty())
        s.spacing = float(spacing_for_count(sc, targets, s));
    const int max_level =
        s.max_trace_level >= 0 ? s.max_trace_level : sc.settings.max_trace_level;
    const float adc = s.adc_bailout >= 0 ? s.adc_bailout : sc.settings.adc_bailout;
    std::vector<Material> stand_ins;
    stand_ins.reserve(frames.size());
    for (const Object* f : frames) stand_ins.push_back(material_of(*f, f->texture));
    // Each light and target is shot on its own (POV-Ray's LightTargetCombo), in
    // parallel; their photons are joined in the pairs' order, so the map does not depend
    // on the threads.
    struct Pair {
        size_t light, target;
        std::vector<Photon> surface, media;
        uint64_t shot = 0;
    };
    std::vector<Pair> pairs;
    for (size_t l = 0; l < sc.lights.size(); ++l) {
        if (sc.lights[l].light_group != 0) continue;
        for (size_t t = 0; t < targets.size(); ++t) pairs.push_back({l, t, {}, {}, 0});
    }
    std::atomic<size_t> next_pair{0};
    auto shoot_pairs = [&] {
        for (size_t i; (i = next_pair.fetch_add(1)) < pairs.size();) {
            Pair& p = pairs[i];
            Shooter shooter(scene, s, max_level, adc, stand_ins, p.surface, p.media);
            shooter.set_pair(i);
            shooter.shoot(sc.lights[p.light], p.light, targets[p.target], p.target,
                          frames);
            p.shot = shooter.shot();
        }
    };
    const size_t threads =
        std::min(pairs.size(),
                 size_t(scene.threads() > 0 ? scene.threads()
                                            : int(std::thread::hardware_concurrency())));
    std::vector<std::thread> pool;
    for (size_t k = 1; k < threads; ++k) pool.emplace_back(shoot_pairs);
    shoot_pairs();
    for (std::thread& t : pool) t.join();
    std::vector<Photon> media_photons;
    uint64_t shot = 0;
    for (Pair& p : pairs) {
        map->photons_.insert(map->photons_.end(), p.surface.begin(), p.surface.end());
        media_photons.insert(media_photons.end(), p.media.begin(), p.media.end());
        shot += p.shot;
    }
    if (!media_photons.empty()) {
        map->media_ = std::make_shared<PhotonMap>();
        PhotonMap& media = *map->media_;
        media.settings_ = s;
        media.photons_ = std::move(media_photons);
        media.build_tree(0, media.photons_.size());
        media.estimate_gather_radius(s.media_radius, s.media_radius_multiplier, true);
    }
    if (!map->photons_.empty()) {
        map->build_tree(0, map->photons_.size());
        map->estimate_gather_radius(s.radius, s.radius_multiplier, false);
    }
    // POVWALL_PHOTON_STATS=1: what the pass made (to set beside POV-Ray's statistics).
    if (std::getenv("POVWALL_PHOTON_STATS"))
        std::fprintf(stderr,
                     "photons: %zu stored, %zu in media, %llu shot, gather radius %g, "
                     "media %g\n",
                     map->photons_.size(), map->media_ ? map->media_->size() : size_t(0),
                     (unsigned long long)shot, map->min_radius_,
                     map->media_ ? map->media_->min_radius_ : 0.0);
    return map;
}

}  // namespace povwall::trace
