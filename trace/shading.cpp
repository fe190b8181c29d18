// POV-Ray 3.7's surface model (ComputeLightedTexture and friends), as spawn + combine.
#include "trace/shading.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>

#include "core/hash_fold.h"
#include "core/noise.h"
#include "trace/light_masks.h"
#include "trace/light_rays.h"
#include "trace/media.h"
#include "trace/photon_map.h"
#include "trace/radiosity/gatherer.h"
#include "trace/rainbow.h"
#include "trace/shapes/shape.h"
#include "trace/subsurface.h"
#include "trace/uv_mapping.h"

namespace povwall::trace {
namespace {

constexpr float kShadowTolerance = 1e-3f;

float max3(const Rgb& c) { return std::max(c.r, std::max(c.g, c.b)); }

// Empirical Fresnel-like factor POV-Ray uses for `metallic`.
float metallic_fresnel(Real cos_angle) {
    Real x = std::acos(std::clamp(cos_angle, -1.0, 1.0)) / (kPi / 2);
    Real f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
    return float(std::clamp(f, 0.0, 1.0));
}

Rgb metallic_tint(float metallic, Real cos_angle, const Rgb& pigment) {
    if (metallic == 0) return Rgb(1.0f);
    float f = metallic_fresnel(cos_angle);
    return Rgb(1.0f) + (pigment - Rgb(1.0f)) * (metallic * (1 - f));
}

float ior_of(const Material* m) {
    if (!m || !m->interior) return 1.0f;
    return m->interior->ior > 0 ? m->interior->ior : 1.0f;
}
float dispersion_of(const Material* m) {
    return m && m->interior ? m->interior->dispersion : 1.0f;
}
int dispersion_samples_of(const Material* m) {
    static const int kDefault = Interior().dispersion_samples;
    return m && m->interior ? m->interior->dispersion_samples : kDefault;
}

// The index ratio (transmitted over incident) POV-Ray's fresnel reflection uses at a
// surface of `m` (its ComputeRelativeIOR), from the interiors the incoming ray is in. It
// keeps POV-Ray's quirk: leaving the innermost of two or more interiors compares the
// object with itself (ratio 1, no fresnel reflection), unlike the refraction there.
Real fresnel_relative_ior(const InteriorStack& inside, const Material& m) {
    if (inside.size == 0) return ior_of(&m);
    // Two objects' indices divide in float, as POV-Ray's (both are floats there); the
    // atmosphere's (a double 1) in double.
    if (!inside.contains(m.interior_id))
        return Real(ior_of(&m) / ior_of(inside.innermost()));
    if (inside.size == 1) return 1 / Real(ior_of(&m));
    return Real(ior_of(inside.innermost()) / ior_of(&m));
}

// POV-Ray's thin-film iridescence (ComputeIridColour): each channel of a light's
// contribution scaled by 1 + irid * cos(phase / wavelength).
Rgb iridescence(const Finish& f, const Scene& sc, const Point3& P, const Vector3& N,
                const Vector3& to_light, const Vector3& eye) {
    Real thickness = f.irid_thickness;
    if (f.irid_turbulence != 0) {
        TurbulenceParams tp;  // POV-Ray's fixed octaves, omega and lambda here
        tp.octaves = 5;
        tp.omega = 0.5;
        tp.lambda = 2.0;
        const Real noise = 2 * turbulence(P, tp, sc.settings.noise_generator) - 1;
        thickness *= 1 + noise * f.irid_turbulence;
    }
    const Real phase =
        2 * kPi * thickness * (std::fabs(dot(N, to_light)) + std::fabs(dot(N, eye)));
    const Rgb& wl = sc.settings.irid_wavelength;
    return {float(1 + f.irid * std::cos(phase / wl.r)),
            float(1 + f.irid * std::cos(phase / wl.g)),
            float(1 + f.irid * std::cos(phase / wl.b))};
}

// POV-Ray's reflected direction (ComputeReflection): D mirrored about the layer's normal
// Nl; when that sends it behind the surface (N faces the ray), mirrored once more about
// N, or, if it also leaves through Nl's back, D mirrored about N instead.
Vector3 reflected_direction(const Vector3& D, const Vector3& Nl, const Vector3& N) {
    Vector3 R = D - Nl * (2 * dot(D, Nl));
    const Real rn = dot(R, N);
    if (rn < 0) R = dot(R, Nl) < 0 ? D - N * (2 * dot(D, N)) : R - N * (2 * rn);
    return normalize(R);
}

// A reflected child's iridescence (POV-Ray tints what a reflected ray brings back, before
// the reflection exponent): folded into its coefficient, which is exact for the
// non-negative colours it scales.
void tint_reflection(ChildRay& child, const Rgb& tint) {
    auto f = [&](float t) {
        return child.exponent == 1 ? t : std::pow(std::max(0.0f, t), 1 / child.exponent);
    };
    child.coeff *= Rgb(f(tint.r), f(tint.g), f(tint.b));
}

// A uniform number in [0, 1) for crand at point P and light l: POV-Ray draws a random
// one there; this one depends only on where (the same in every mode).
Real crand_sample(const Point3& P, size_t l) {
    uint64_t h = 0x9e3779b97f4a7c15ull * (l + 1);
    for (double v : {P.x, P.y, P.z}) h = hash_fold(h, v);
    return Real(h >> 11) / Real(1ull << 53);
}

// Removes the reflection children whose layer normal is `normal` (each component within
// 1e-10), as POV-Ray skips them after a total internal reflection.
void drop_reflections_with_normal(std::vector<ChildRay>& children,
                                  const std::vector<std::pair<size_t, Vector3>>& normals,
                                  const Vector3& normal) {
    auto same = [&](const Vector3& a) {
        return std::fabs(a.x - normal.x) < kPovEpsilon &&
               std::fabs(a.y - normal.y) < kPovEpsilon &&
               std::fabs(a.z - normal.z) < kPovEpsilon;
    };
    // Children after the reflections (shadows) keep their order.
    for (auto it = normals.rbegin(); it != normals.rend(); ++it)
        if (same(it->second)) children.erase(children.begin() + ptrdiff_t(it->first));
}

Point3 area_sample_point(const AreaGrid& grid, int u, int v);

// The samples of area light `l` lighting `p` one by one (full_area_lighting(), POV-Ray's
// ComputeFullAreaDiffuseLight): every point of the grid, adaptive or not, each with its
// own ray and its share of `colour` attenuated along that ray. Appended to `out`. (A
// jittered grid's samples are the shadow samples' points; POV-Ray draws other ones.)
void area_lighting_samples(const Scene& sc, size_t l, const Point3& p, const Rgb& colour,
                           std::vector<LightSample>& out) {
    const Light& light = sc.lights[l];
    ChildRay at;  // the grid as the shadow child from `p` sees it (axes, orient, jitter)
    at.trace.ray.origin = p;
    at.light = int(l);
    const AreaGrid grid(sc, at);
    const float share = 1.0f / float(grid.samples());
    for (int u = 0; u < grid.n1; ++u) {
        for (int v = 0; v < grid.n2; ++v) {
            LightSample s;
            if (!light_ray_toward(light, p, area_sample_point(grid, u, v), s)) continue;
            // (A fade past a parallel light's plane may turn it negative, as POV-Ray's.)
            const float att = light_attenuation(light, p, s);
            if (att == 0) continue;
            s.colour = colour * (att * share);
            out.push_back(s);
        }
    }
}

// POV-Ray's +Q0 and +Q1 (its FULL_AMBIENT): no lighting, no rays; a surface is the
// colour of its layers' pigments as seen through the transparent ones, opaque.
void pigment_only(const PreparedScene& scene, const Material& m, const Point3& P,
                  const PatternEnv& env, ShadingRecord& out);

Colour eval_pigment(const Pigment& p, const Point3& at, const PatternEnv& env,
                    bool* found = nullptr) {
    if (pigment_is_solid(p)) {
        return p.colour;
    }
    return evaluate_pigment(p, at, env, found);
}

// Where the patterns of a material's top level are evaluated: the hit point, or its
// surface coordinates on an object with uv_mapping.
Point3 surface_point(const Material& m, const Hit& hit) {
    return m.uv_mapping ? surface_uv(hit) : hit.point;
}

// Where a material's patterns are evaluated: surface_point(), or for a texture_map entry
// the map pattern's point.
Point3 texture_point(const Material& m, const Hit& hit) {
    return m.nesting ? m.nesting->point : surface_point(m, hit);
}

// A layer's normal perturbed as POV-Ray does inside texture maps: the normal goes into
// each enclosing map pattern's space (outermost first), is perturbed there, and comes
// back out. `pattern_normal`, when given, takes the perturbed normal still in the maps'
// space, which is what POV-Ray leaves for the patterns after it (its PNormal).
Vector3 perturb_nested(const Normal& normal, const Point3& at, Vector3 n,
                       const PatternEnv& env, const TextureNesting* nesting,
                       Vector3* pattern_normal = nullptr) {
    // With no_bump_scale the patterns after this one see the normal before POV-Ray's
    // Trace normalises it.
    auto perturb = [&](const Vector3& into) {
        Vector3 r = perturb_normal_unnormalised(normal, at, into, env);
        if (pattern_normal) *pattern_normal = r;
        return normal.pattern->no_bump_scale ? normalize(r) : r;
    };
    if (!nesting) return perturb(n);
    constexpr int kMaxDepth = 64;
    const TextureNesting* chain[kMaxDepth];
    int depth = 0;
    for (const TextureNesting* p = nesting; p && depth < kMaxDepth; p = p->outer)
        chain[depth++] = p;
    for (int i = depth - 1; i >= 0; --i) n = normal_into_pattern(*chain[i]->pattern, n);
    n = perturb(n);
    for (int i = 0; i < depth; ++i) n = normal_out_of_pattern(*chain[i]->pattern, n);
    return n;
}

// The surface as POV-Ray's patterns see a hit: its normal turned to face `direction`.
SurfaceAtHit surface_facing(const Hit& hit, const Vector3& direction) {
    return {dot(hit.normal, direction) > 0 ? -hit.normal : hit.normal, hit.point,
            direction, &hit};
}

Rgb rgb_transm(const Colour& c) { return c.rgb * c.filter + Rgb(c.transmit); }

const LayeredTexture& texture_of(const Material& m);

// POV-Ray's texture choice (ComputeTextureColour, ComputeShadowColour): a ray meeting a
// surface from inside, along its raw normal (Hit::normal has POV-Ray's sign), sees the
// object's interior_texture when it has one. Decided from the hit alone, so every back
// end and every kind of ray agrees. A blob with component textures blends those from
// either side (POV-Ray's multi-textured objects never take the interior texture).
bool shows_interior_texture(const Material& m, const Hit& hit, const Ray& ray) {
    return m.interior_texture && !m.blob_blend && dot(hit.normal, ray.direction) > 0;
}

void pigment_only(const PreparedScene& scene, const Material& m, const Point3& P,
                  const PatternEnv& env, ShadingRecord& out) {
    const float adc = scene.scene().settings.adc_bailout;
    Rgb fil(1.0f);
    float trans = 1;
    if (m.plain) {
        out.local = m.plain_colour.rgb;
        return;
    }
    const LayeredTexture& layers = texture_of(m);
    for (int li = int(layers.size()) - 1; li >= 0 && trans > adc; --li) {
        const Colour lay = eval_pigment(layers[size_t(li)].pigment, P, env);
        out.local = lay.rgb;  // each layer seen replaces the one above
        fil *= rgb_transm(lay);
        trans = std::min(1.0f, std::fabs(fil.grey()));
    }
}

const LayeredTexture& texture_of(const Material& m) {
    static const LayeredTexture kDefault{Texture{}};
    return (m.texture && !m.texture->empty()) ? *m.texture : kDefault;
}

}  // namespace

Rgb interior_attenuation(const Interior& in, Real distance, bool shadow_ray) {
    // POV-Ray tests fade_power > 0 only on shadow rays (ComputeShadowTexture).
    if (std::fabs(in.fade_distance) <= kPovEpsilon) return Rgb(1.0f);
    if (shadow_ray && in.fade_power <= 0) return Rgb(1.0f);
    Rgb fc = in.fade_colour;
    if (in.fade_power >= 1000) {
        auto e = [&](float c) {
            return float(std::exp(-(1 - c) * distance / in.fade_distance));
        };
        return {e(fc.r), e(fc.g), e(fc.b)};
    }
    float k = float(1 / (1 + std::pow(distance / in.fade_distance, Real(in.fade_power))));
    return fc + (Rgb(1.0f) - fc) * k;
}

namespace {

// spawn_children(), with or without the effect along the ray (`with_fog`: a stand-in
// material of a blend shares the hit's, computed once). `pattern_normal` is the normal
// the hit's patterns read (POV-Ray's PNormal: the normal facing the ray, then each
// layer's perturbed normal as the layers are shaded); POV-Ray keeps one per hit, so
// the stand-ins of a blend or texture_map share their hit's (null: a hit of its own).
void spawn_hit(const PreparedScene& scene, const TraceRay& ray, const Hit& hit,
               ShadingRecord& out, const MediaShadows& shadows, bool with_fog,
               SurfaceAtHit* pattern_normal = nullptr);
FogEffect along_ray(const PreparedScene& scene, const TraceRay& ray, Real depth,
                    MediaEndLights end, const MediaShadows& shadows);
MediaEndLights media_end_lights(const Material& m) {
    return {m.global_lights, m.light_group};
}

// Shades `hit` once with each of `n` stand-in materials and merges the records with
// their weights (POV-Ray sums the weighted colours of the textures it finds for a hit);
// children keep combining linearly, and their interior stacks name the hit's own
// material, not the stand-ins. `out.fog` is kept. The stand-ins share the hit's
// `pattern_normal`, so each one's patterns see the normal the ones shaded before it
// left; `last_first` shades them from the last (POV-Ray shades a texture_map's upper
// entry before the lower) while the record keeps them in order.
void spawn_weighted(const PreparedScene& scene, const TraceRay& ray, const Hit& hit,
                    const Material* const* subs, const float* weights, int n,
                    ShadingRecord& out, RayContext* trace, SurfaceAtHit& pattern_normal,
                    bool last_first = false) {
    FogEffect fog = out.fog;
    Rgb local;
    // A deque keeps references valid while nested texture maps grow it.
    thread_local std::deque<ShadingRecord> scratch_pool;
    thread_local size_t depth = 0;
    if (scratch_pool.size() <= depth) scratch_pool.resize(depth + 1);
    std::vector<ChildRay> children;
    for (int i = 0; i < n; ++i) {
        const int e = last_first ? n - 1 - i : i;
        const float w = weights[e];
        Hit h = hit;
        h.material = subs[e];
        ++depth;
        ShadingRecord& rec = scratch_pool[depth - 1];
        // No effect along the ray per stand-in (the caller's record has it), but the
        // tracer's context: a radiosity gather needs it.
        MediaShadows sub;
        sub.trace = trace;
        spawn_hit(scene, ray, h, rec, sub, false, &pattern_normal);
        --depth;
        local += rec.local * w;
        // Shaded from the last, each stand-in's children go before those of the ones
        // after it.
        size_t at = last_first ? 0 : children.size();
        for (ChildRay c : rec.children) {
            c.coeff *= w;
            c.transmit_factor *= w;
            c.trace.interiors.replace(subs[e], hit.material);
            children.insert(children.begin() + std::ptrdiff_t(at++), c);
        }
    }
    out.clear();
    out.fog = fog;
    out.local = local;
    out.children = std::move(children);
}

// A texture_map (or checker/hexagon/brick of textures) as the object's texture: POV-Ray
// blends the final colours of the two entries around the pattern value.
bool spawn_texture_map(const PreparedScene& scene, const TraceRay& ray, const Hit& hit,
                       ShadingRecord& out, RayContext* trace,
                       SurfaceAtHit& pattern_normal) {
    const Material& m = *hit.material;
    if (m.plain || !m.texture || m.texture->size() != 1) return false;
    const Texture& t = m.texture->front();
    if (!t.map_pattern || t.map->entries.empty()) return false;
    const int count = int(t.map->entries.size());
    const bool has_values = int(t.map->values.size()) == count;
    if (t.map_pattern->kind == PatternKind::Average) {
        // `average`: every entry shaded, weighted by its value over their sum (POV-Ray's
        // ComputeAverageTextureColours). Rare enough for the lists to be allocated here.
        float total = 0;
        for (int i = 0; i < count; ++i)
            total += has_values ? t.map->values[size_t(i)] : 1.0f;
        const size_t entries = size_t(count);
        const TextureNesting nest{&*t.map_pattern,
                                  pattern_point(*t.map_pattern, texture_point(m, hit)),
                                  m.nesting};
        std::vector<Material> subs(entries, m);
        std::vector<const Material*> used(entries);
        std::vector<float> weights(entries);
        for (int i = 0; i < count; ++i) {
            subs[size_t(i)].texture = &t.map->entries[size_t(i)];
            subs[size_t(i)].nesting = &nest;
            used[size_t(i)] = &subs[size_t(i)];
            weights[size_t(i)] = (has_values ? t.map->values[size_t(i)] : 1.0f) / total;
        }
        spawn_weighted(scene, ray, hit, used.data(), weights.data(), count, out, trace,
                       pattern_normal);
        return true;
    }
    MapPick pick = pick_map_entries(
        *t.map_pattern, has_values ? t.map->values.data() : nullptr, count,
        texture_point(m, hit), scene.pattern_env().at_surface(&pattern_normal));
    const TextureNesting nest{&*t.map_pattern, pick.point, m.nesting};
    const int entries[2] = {pick.lookup.prev, pick.lookup.cur};
    const float fraction = float(pick.lookup.fraction);
    Material subs[2] = {m, m};
    const Material* used[2];
    float weights[2];
    int n = 0;
    for (int e = 0; e < 2; ++e) {
        const float w = entries[1] == entries[0]
                            ? 1.0f
                            : (e == 0 ? float(1 - pick.lookup.fraction) : fraction);
        if ((e == 0 ? float(1 - pick.lookup.fraction) : fraction) <= 0) continue;
        if (e == 1 && entries[1] == entries[0]) continue;
        subs[e].texture = &t.map->entries[size_t(std::clamp(entries[e], 0, count - 1))];
        subs[e].nesting = &nest;
        used[n] = &subs[e];
        weights[n++] = w;
    }
    // The upper entry first, as POV-Ray: the lower one's patterns see the normal the
    // upper's layers left.
    spawn_weighted(scene, ray, hit, used, weights, n, out, trace, pattern_normal, true);
    return true;
}

// A mesh face with a texture per corner: the corners' textures, weighted toward the hit
// (textures below adc_bailout left out, as POV-Ray's ComputeTextureColour does).
bool spawn_corner_blend(const PreparedScene& scene, const TraceRay& ray, const Hit& hit,
                        ShadingRecord& out, RayContext* trace,
                        SurfaceAtHit& pattern_normal) {
    const TextureBlend* b = hit.material->blend;
    if (!b) return false;
    float w[3];
    blend_weights(*b, hit.point, w);
    const float adc = scene.scene().settings.adc_bailout;
    const Material* used[3];
    float weights[3];
    int n = 0;
    for (int k = 0; k < 3; ++k) {
        if (w[k] < adc) continue;
        used[n] = b->corners[k];
        weights[n++] = w[k];
    }
    spawn_weighted(scene, ray, hit, used, weights, n, out, trace, pattern_normal);
    return true;
}

// A blob with textures on its components: the touching elements' textures weighted by
// their |field| (POV-Ray's Blob::Determine_Textures), those below adc_bailout left out.
bool spawn_blob_blend(const PreparedScene& scene, const TraceRay& ray, const Hit& hit,
                      ShadingRecord& out, RayContext* trace,
                      SurfaceAtHit& pattern_normal) {
    const BlobTextureBlend* b = hit.material->blob_blend;
    if (!b) return false;
    thread_local std::vector<const Material*> mats;  // no allocation per ray
    thread_local std::vector<float> w;
    const int n =
        blob_texture_weights(*b, hit.point, scene.scene().settings.adc_bailout, mats, w);
    if (!scene.scene().settings.radiosity) {
        spawn_weighted(scene, ray, hit, mats.data(), w.data(), n, out, trace,
                       pattern_normal);
        return true;
    }
    // Under radiosity the entries' shading may come back here for another blob.
    const std::vector<const Material*> own_mats(mats.begin(), mats.begin() + n);
    const std::vector<float> own_w(w.begin(), w.begin() + n);
    spawn_weighted(scene, ray, hit, own_mats.data(), own_w.data(), n, out, trace,
                   pattern_normal);
    return true;
}

}  // namespace

namespace {

// Rays under a radiosity sample ray pass on its limits and recursion depth, and see an
// area light as a point at its centre (POV-Ray's radiosity quality flags).
void pass_on_radiosity(const TraceRay& ray, ShadingRecord& out) {
    if (ray.radiosity_depth == 0) return;
    for (ChildRay& c : out.children) {
        c.trace.radiosity_depth = ray.radiosity_depth;
        c.trace.max_level = ray.max_level;
        c.trace.adc_bailout = ray.adc_bailout;
        c.area = false;
    }
}

// A ray that dispersion split keeps its wavelength band in every descendant (POV-Ray's
// monochromatic rays copy it on).
void pass_on_band(const TraceRay& ray, ShadingRecord& out) {
    if (!ray.band.monochromatic()) return;
    for (ChildRay& c : out.children) c.trace.band = ray.band;
}

}  // namespace

void spawn_children(const PreparedScene& scene, const TraceRay& ray, const Hit& hit,
                    ShadingRecord& out, RayContext* ctx) {
    MediaShadows shadows;
    if (ctx) {
        shadows.trace = ctx;
        spawn_hit(scene, ray, hit, out, shadows, true);
        pass_on_radiosity(ray, out);
        pass_on_band(ray, out);
        return;
    }
    // Black boxes: the media samples' shadow rays become children after the others.
    thread_local ShadingRecord staging;
    staging.clear();
    shadows.collect = &staging;
    spawn_hit(scene, ray, hit, out, shadows, true);
    pass_on_band(ray, out);
    if (!staging.media_replay) return;
    out.media_replay = true;
    out.media_first = out.children.size();
    out.children.insert(out.children.end(), staging.children.begin(),
                        staging.children.end());
    out.media_samples = staging.media_samples;
    out.media_depth = hit.t;
    out.media_lights = media_end_lights(*hit.material);
}

void spawn_surface_children(const PreparedScene& scene, const TraceRay& ray,
                            const Hit& hit, ShadingRecord& out, RayContext& ctx) {
    MediaShadows shadows;
    shadows.trace = &ctx;
    spawn_hit(scene, ray, hit, out, shadows, false);
    pass_on_radiosity(ray, out);
    pass_on_band(ray, out);
}

namespace {

// The lists spawn_hit fills for one hit (kept per thread so that a ray allocates
// nothing), one set per nesting level: under radiosity, spawn_hit runs again for the
// sample rays' hits while the outer hit's lists are in use.
struct ShadingScratch {
    std::vector<Rgb> lit;
    std::vector<LightSample> samples;
    std::vector<uint8_t> sample_ok;
    // Lights with full_area_lighting(): their grid samples, light l's at
    // area_samples[area_range[l].first, area_range[l].second).
    std::vector<LightSample> area_samples;
    std::vector<std::pair<uint32_t, uint32_t>> area_range;
    // projected_through lights: where their shadow rays stop looking for blockers.
    std::vector<Real> blockers_end;
    std::vector<std::pair<size_t, Vector3>> reflection_normals;
    std::vector<const Photon*> found_photons;
};
thread_local std::deque<ShadingScratch> shading_scratch_pool;  // deque: no moves
thread_local size_t shading_nesting = 0;

ShadingScratch& shading_scratch() {
    if (shading_scratch_pool.size() <= shading_nesting)
        shading_scratch_pool.resize(shading_nesting + 1);
    return shading_scratch_pool[shading_nesting];
}

// Holds the current nesting level's scratch while it lives.
struct ScratchLevel {
    ScratchLevel() { ++shading_nesting; }
    ~ScratchLevel() { --shading_nesting; }
    ScratchLevel(const ScratchLevel&) = delete;
    ScratchLevel& operator=(const ScratchLevel&) = delete;
};

void spawn_hit(const PreparedScene& scene, const TraceRay& ray, const Hit& hit,
               ShadingRecord& out, const MediaShadows& shadows, bool with_fog,
               SurfaceAtHit* pattern_normal) {
    if (shows_interior_texture(*hit.material, hit, ray.ray)) {
        // Shaded with the interior texture; the children's interior stacks name the
        // object's own material, not this stand-in.
        const Material inside = interior_side(*hit.material);
        Hit h = hit;
        h.material = &inside;
        spawn_hit(scene, ray, h, out, shadows, with_fog, pattern_normal);
        for (ChildRay& c : out.children) {
            c.trace.interiors.replace(&inside, hit.material);
        }
        return;
    }
    out.clear();
    const Quality quality = scene.plan().quality;
    if (with_fog && quality.atmosphere())
        out.fog = along_ray(scene, ray, hit.t, media_end_lights(*hit.material), shadows);
    // Normals face the incoming ray, as POV-Ray flips them.
    SurfaceAtHit own_surface;
    if (!pattern_normal) {
        own_surface = surface_facing(hit, ray.ray.direction);
        pattern_normal = &own_surface;
    }
    if (spawn_corner_blend(scene, ray, hit, out, shadows.trace, *pattern_normal)) return;
    if (spawn_blob_blend(scene, ray, hit, out, shadows.trace, *pattern_normal)) return;
    if (spawn_texture_map(scene, ray, hit, out, shadows.trace, *pattern_normal)) return;
    const Scene& sc = scene.scene();
    const Material& m = *hit.material;
    const Vector3 D = ray.ray.direction;
    const Point3 P = hit.point;
    const Point3 Ptex = texture_point(m, hit);  // where the patterns are evaluated
    // The surface patterns see the normal as the layers shaded so far have perturbed it
    // (POV-Ray's PNormal), the layers themselves perturb the normal facing the ray.
    SurfaceAtHit& surface = *pattern_normal;
    const Vector3 N = surface_facing(hit, D).normal;
    const PatternEnv env = scene.pattern_env().at_surface(&surface);
    if (!quality.lighting()) return pigment_only(scene, m, Ptex, env, out);
    const bool legacy = sc.language_version < 370;
    const float adc = ray.adc_bailout >= 0 ? ray.adc_bailout : sc.settings.adc_bailout;
    // Radiosity (from +Q9): the ambient light is gathered (trace/radiosity/), and
    // `ambient` counts only in scenes before #version 3.7.
    const bool radiosity_on = sc.settings.radiosity && quality.level >= 9;
    RadiosityGatherer* gatherer = radiosity_on && shadows.trace &&
                                          shadows.trace->radiosity &&
                                          shadows.trace->radiosity->active_for(ray)
                                      ? shadows.trace->radiosity
                                      : nullptr;
    // Subsurface light transport (from +Q9) replaces the diffuse term of the finishes
    // that have it. Radiosity sample rays evaluate it with `radiosity { subsurface on }`,
    // else see such a finish without its diffuse (POV-Ray's quality flags there lack
    // subsurface).
    const bool subsurface_on = sc.settings.subsurface && quality.level >= 9;
    const bool subsurface_here =
        subsurface_on && shadows.trace && shadows.trace->subsurface &&
        (ray.radiosity_depth == 0 || sc.settings.radiosity->subsurface);
    bool radiosity_done = false, radiosity_back_done = false;
    Rgb radiosity_front, radiosity_back;
    // A plain material (see Material::plain) is one layer read from the material itself.
    const LayeredTexture* layers = m.plain ? nullptr : &texture_of(m);
    const int nlayers = m.plain ? 1 : int(layers->size());
    const size_t nlights = sc.lights.size();

    // Per nesting level: a radiosity gather in the layer loop shades its sample rays'
    // hits with this same function before this hit's lights are added up.
    ShadingScratch& scratch = shading_scratch();
    const ScratchLevel level_guard;
    std::vector<Rgb>& lit = scratch.lit;
    std::vector<LightSample>& samples = scratch.samples;
    std::vector<uint8_t>& sample_ok = scratch.sample_ok;
    lit.assign(nlights, Rgb{});
    samples.resize(nlights);
    sample_ok.assign(nlights, 2);  // 2: not computed yet
    std::vector<LightSample>& area_samples = scratch.area_samples;
    std::vector<std::pair<uint32_t, uint32_t>>& area_range = scratch.area_range;
    area_samples.clear();
    area_range.assign(nlights, {0, 0});
    const LightMasks* masks = scene.light_masks();
    std::vector<Real>& blockers_end = scratch.blockers_end;
    if (masks) blockers_end.assign(nlights, kInfinity);

    Rgb fil(1.0f);
    float trans = 1;
    Vector3 top_normal = N;
    const Finish* top_finish = nullptr;  // the top layer's (total internal reflection)
    // Each reflection child with its layer's normal: total internal reflection drops
    // those of the layers whose normal is the top layer's (POV-Ray 3.7).
    std::vector<std::pair<size_t, Vector3>>& reflection_normals =
        scratch.reflection_normals;
    reflection_normals.clear();
    // The photon map, when the surface collects photons (`collect` on, lit by the
    // global lights that shot them).
    const PhotonMap* photons = scene.photons();
    if (photons && (photons->size() == 0 || !m.global_lights ||
                    (m.object && !m.object->photons.collect)))
        photons = nullptr;
    std::vector<const Photon*>& found_photons = scratch.found_photons;
    found_photons.clear();
    bool gathered = false;
    double photon_radius = 0;
    for (int li = nlayers - 1; li >= 0 && trans > adc; --li) {
        const Texture* tex = layers ? &(*layers)[size_t(li)] : nullptr;
        Vector3 Nl = N;
        if (tex && tex->normal && quality.normals()) {
            Nl = perturb_nested(*tex->normal, Ptex, N, env, m.nesting, &surface.normal);
        }
        // After the layer's normal, as POV-Ray (a slope pigment sees it).
        // A layer that finds no colour (an image_map off its image) filters nothing.
        bool colour_found = true;
        const Colour lay =
            tex ? eval_pigment(tex->pigment, Ptex, env, &colour_found) : m.plain_colour;
        if (li == nlayers - 1) top_normal = Nl;
        const float att = legacy ? 1 - (lay.filter * max3(lay.rgb) + lay.transmit)
                                 : 1 - lay.filter - lay.transmit;
        const Finish& f = tex ? *tex->finish : m.plain_finish;
        if (li == nlayers - 1) top_finish = &f;
        Rgb tmp;
        const bool subsurface = subsurface_on && f.subsurface;
        if (subsurface && subsurface_here) {
            // Not scaled by the layer's opacity (POV-Ray 3.7), and the pigment acts
            // only through the albedo; the layers above filter it as any light here.
            tmp += shadows.trace->subsurface->light(
                {ray, hit, m, N, fresnel_relative_ior(ray.interiors, m), ior_of(&m),
                 lay.rgb * f.raw_diffuse, f.translucency});
        }
        // With `subsurface { radiosity on }` the subsurface light holds the radiosity
        // (gathered at its samples): none is added for this layer and those below.
        if (subsurface && sc.settings.subsurface->radiosity) gatherer = nullptr;
        if (gatherer) {
            // POV-Ray gathers once per hit, with the first layer whose diffuse can
            // add enough to the ray.
            if (!radiosity_done) {
                const float most = (fil * lay.rgb).grey() * att * f.raw_diffuse;
                if (most > adc) {
                    radiosity_front =
                        gatherer->ambient(ray, P, N, Nl, double(ray.weight) * most);
                    radiosity_done = true;
                }
            }
            tmp += lay.rgb * radiosity_front * (att * f.raw_diffuse);
            if (f.diffuse_back != 0) {
                if (!radiosity_back_done) {
                    const float most = (fil * lay.rgb).grey() * att * f.raw_diffuse_back;
                    if (most > adc) {
                        radiosity_back =
                            gatherer->ambient(ray, P, -N, -Nl, double(ray.weight) * most);
                        radiosity_back_done = true;
                    }
                }
                tmp += lay.rgb * radiosity_back * (att * f.raw_diffuse_back);
            }
        }
        if (!radiosity_on || legacy)
            tmp += lay.rgb * f.ambient * sc.settings.ambient_light * att;
        tmp += lay.rgb * f.emission * att;
        out.local += tmp * fil;

        // The layer's diffuse, phong, specular and iridescence response to light coming
        // from `dir` (unit), scaled by the light's colour by the caller; false when the
        // light is behind the surface and there is no diffuse back. Iridescence reads
        // `irid_dir` (POV-Ray's area_illumination keeps the light's centre there).
        // Without `facing_test` a light behind the surface lights it as one in front
        // (POV-Ray drops that test for an area_illumination light wherever it does not
        // light sample by sample).
        auto light_response = [&](const Vector3& dir, bool shadowless, size_t index,
                                  Rgb& c, const Vector3& irid_dir, bool facing_test) {
            Real cos_nl = dot(Nl, dir);
            // A light behind the surface lights it only with diffuse back (and then
            // without highlights), unless the object is double_illuminate.
            bool backside = false;
            if (cos_nl < kPovEpsilon && facing_test) {
                if (m.double_illuminate)
                    cos_nl = -cos_nl;
                else if (f.diffuse_back != 0)
                    backside = true;
                else
                    return false;
            }
            c = Rgb{};
            const float diffuse = subsurface ? 0.0f
                                  : backside ? f.diffuse_back
                                             : f.diffuse;
            if (diffuse > 0) {
                Real base = std::fabs(cos_nl);
                Real k = (f.brilliance != 1 ? std::pow(base, Real(f.brilliance)) : base) *
                         diffuse * att;
                // crand: POV-Ray subtracts a fresh random number per light and point;
                // ours is a hash of the point (the same in every mode and process).
                if (f.crand > 0) k -= crand_sample(P, index) * f.crand;
                c += lay.rgb * float(k);
            }
            // No highlights under a radiosity sample ray (POV-Ray's radiosity flag, which
            // the rays it spawns keep).
            if (!shadowless && !backside && ray.radiosity_depth == 0) {
                if (f.phong > 0) {
                    Vector3 R = D - Nl * (2 * dot(D, Nl));
                    Real cc = dot(R, dir);
                    if (cc > 0 && !(f.phong_size >= 60 && cc <= 0.0008)) {
                        float k = float(f.phong * std::pow(cc, Real(f.phong_size)));
                        c += metallic_tint(f.metallic, cos_nl, lay.rgb) * k;
                    }
                }
                if (f.specular > 0) {
                    Vector3 H = (dir - D) * 0.5;
                    Real hl = length(H);
                    Real cc = hl > 0 ? dot(H, Nl) / hl : 0;
                    if (cc > 0) {
                        float k = float(f.specular * std::pow(cc, Real(1 / f.roughness)));
                        c += metallic_tint(f.metallic, cos_nl, lay.rgb) * k;
                    }
                }
            }
            if (f.irid > 0) c *= iridescence(f, sc, P, Nl, irid_dir, D);
            return true;
        };
        if (f.diffuse != 0 || f.diffuse_back != 0 || f.phong != 0 || f.specular != 0) {
            for (size_t l = 0; l < nlights; ++l) {
                const Light& light = sc.lights[l];
                // Light groups: a skipped light stays unlit and gets no shadow ray.
                if (!lights_material(light, m)) continue;
                const bool full_area = full_area_lighting(light, quality, ray);
                if (sample_ok[l] == 2) {
                    // With full area lighting, the centre's ray and the light's own
                    // colour (the shadow test's; the samples are attenuated each).
                    LightSample& ls = samples[l];
                    if (full_area) {
                        sample_ok[l] = light_ray_toward(light, P, light.location, ls);
                        ls.colour = light.colour;
                    } else {
                        sample_ok[l] = light_at(light, P, ls) ? 1 : 0;
                    }
                    // projected_through: no light unless through its object, and then
                    // only what lies before the object shadows (trace/light_masks.h).
                    if (sample_ok[l] && masks && quality.shadows() &&
                        !masks->reaches(l, P, ls.dir, ls.distance, blockers_end[l]))
                        sample_ok[l] = 0;
                    // media_attenuation: fog dims the light along its way (no fog colour
                    // is added to light, as for POV-Ray's shadow test rays).
                    if (sample_ok[l] && light.media_attenuation && !sc.fogs.empty() &&
                        quality.atmosphere() && sees_volume(sc, ray) && ls.distance > 0 &&
                        ls.distance < kInfinity) {
                        ls.colour *= fog_effect(sc, {P, ls.dir}, ls.distance).mul;
                    }
                    if (sample_ok[l] && full_area) {
                        area_range[l].first = uint32_t(area_samples.size());
                        area_lighting_samples(sc, l, P, ls.colour, area_samples);
                        area_range[l].second = uint32_t(area_samples.size());
                    }
                }
                if (!sample_ok[l]) continue;
                const LightSample& s = samples[l];
                Rgb c;
                if (full_area) {
                    // Each sample lights the point from where it is.
                    Rgb sum;
                    for (uint32_t k = area_range[l].first; k < area_range[l].second;
                         ++k) {
                        const LightSample& a = area_samples[k];
                        if (light_response(a.dir, light.shadowless, l, c, s.dir, true))
                            sum += c * a.colour;
                    }
                    lit[l] += sum * fil;
                    continue;
                }
                const bool facing_test = !(light.area && light.area->illumination);
                if (!light_response(s.dir, light.shadowless, l, c, s.dir, facing_test))
                    continue;
                lit[l] += c * s.colour * fil;
            }
        }
        // Photons: their light is added as a light's would be (POV-Ray's
        // ComputePhotonDiffuseLight), gathered once per hit with the first such layer's
        // normal.
        if (photons &&
            (f.diffuse != 0 || f.diffuse_back != 0 || f.phong != 0 || f.specular != 0)) {
            if (!gathered) {
                photon_radius = photons->gather(P, &Nl, found_photons);
                gathered = true;
            }
            Rgb sum;
            for (const Photon* ph : found_photons) {
                const Vector3 d = PhotonMap::incoming(*ph);
                // Lambertian compensation with the raw normal, at most 10x.
                Real a = dot(N, d);
                if (a > 1) a = 1;
                if (a < 0.1) a = 0.1;
                Rgb c;
                if (!light_response(d, false, nlights, c, d, true)) continue;
                sum += c * PhotonMap::flux(*ph) * float(1 / a);
            }
            if (!found_photons.empty())
                out.local += sum * float(1 / (kPi * photon_radius * photon_radius)) * fil;
        }

        // Reflection of this layer; not scaled by the layers above (POV-Ray 3.7).
        const bool has_reflection =
            !f.reflection_max.is_black() || !f.reflection_min.is_black();
        Rgb reflectivity{0.0f};
        float reflection_weight = 0;
        if (has_reflection) {
            // Signed, as POV-Ray's ComputeLightedTexture: where the layer's normal
            // pattern tilts Nl away from the ray (cos_i < 0), fresnel clamps to
            // reflection_max, the variable fraction 1 - cos_i exceeds 1 and metallic's
            // tint goes by an angle past 90 degrees.
            const Real cos_i = -dot(D, Nl);
            Rgb& reflec = reflectivity;
            float& w = reflection_weight;
            if (f.reflection_fresnel) {
                const Real eta = fresnel_relative_ior(ray.interiors, m);
                Real g2 = eta * eta + cos_i * cos_i - 1;
                float F = 1;
                if (g2 > 0) {
                    Real g = std::sqrt(g2);
                    Real a = (g - cos_i) / (g + cos_i);
                    Real b = (cos_i * (g + cos_i) - 1) / (cos_i * (g - cos_i) + 1);
                    F = float(std::clamp(0.5 * a * a * (1 + b * b), 0.0, 1.0));
                }
                reflec = f.reflection_max * F + f.reflection_min * (1 - F);
                w = ray.weight * trans * max3(reflec);
            } else {
                // pow(x, 1) is x exactly: the default falloff needs no pow call.
                float frac = f.reflection_falloff == 1
                                 ? float(1 - cos_i)
                                 : float(std::pow(1 - cos_i, Real(f.reflection_falloff)));
                if (f.reflection_falloff == 1 && frac == 0) frac = 0;
                reflec = f.reflection_max * frac + f.reflection_min * (1 - frac);
                w = ray.weight * trans *
                    std::max(max3(f.reflection_max), max3(f.reflection_min));
            }
            if (f.reflection_metallic != 0) {
                reflec *= metallic_tint(f.reflection_metallic, cos_i, lay.rgb);
            }
        }
        // Reflection rays from +Q8 (the reflectivity still counts for conserve_energy).
        if (has_reflection && quality.reflection()) {
            reflection_normals.push_back({out.children.size(), Nl});
            const Vector3 R = reflected_direction(D, Nl, N);
            ChildRay child;
            child.kind = ChildRay::Kind::Reflection;
            child.trace.ray = {P, R};
            child.trace.depth = ray.depth + 1;
            child.trace.weight = reflection_weight;
            child.trace.use = reflected_use(ray.use);
            child.trace.interiors = ray.interiors;
            child.coeff = reflectivity;
            child.exponent = f.reflection_exponent;
            if (f.irid > 0) tint_reflection(child, iridescence(f, sc, P, Nl, R, D));
            out.children.push_back(child);
        }
        if (colour_found) fil *= rgb_transm(lay);
        if (colour_found && f.conserve_energy) {
            // What a layer reflects does not also pass through it (per channel).
            fil.r *= std::min(1.0f, 1 - reflectivity.r);
            fil.g *= std::min(1.0f, 1 - reflectivity.g);
            fil.b *= std::min(1.0f, 1 - reflectivity.b);
        }
        trans = std::min(1.0f, std::fabs(fil.grey()));
    }

    // One shadow ray per light (shared by all layers); shadowless lights need none.
    const RenderPlan& plan = scene.plan();
    for (size_t l = 0; l < nlights; ++l) {
        // A light that does not reach the point adds nothing: its shadow ray is left out
        // unless the plan is forced on (then it is traced and multiplied by zero).
        if (lit[l].is_black() && (plan.skip_unlit_shadow_rays || sample_ok[l] != 1))
            continue;
        const Light& light = sc.lights[l];
        if (light.shadowless) {
            out.local += lit[l];
            continue;
        }
        const LightSample& s = samples[l];
        ChildRay child = shadow_child(ray, P, s, l);
        if (masks) child.t_max = std::min(child.t_max, blockers_end[l]);
        child.coeff = lit[l];
        child.photon_caustics = photons != nullptr;
        child.area = light.area.has_value();
        // (Not attenuated with full area lighting: POV-Ray refines its grid on the
        // light's own colour then.)
        child.light_colour = s.colour;
        // Below +Q4 nothing blocks a light; below +Q5 an area light is its centre.
        child.unoccluded = child.unoccluded ||
                           (l < plan.lights.size() && plan.lights[l].unoccluded) ||
                           !quality.shadows();
        child.area = child.area && quality.area_lights();
        out.children.push_back(child);
    }

    // What shows through the surface: straight on when the IOR does not change (a
    // continued ray: no trace level used, though met at the last one), refracted
    // otherwise.
    if (trans > adc && quality.refraction()) {
        ChildRay child;
        child.kind = ChildRay::Kind::Transmission;
        child.coeff = fil;
        child.transmit_factor = trans;
        child.trace.interiors = ray.interiors;
        child.trace.use = transmitted_use(ray.use);
        child.trace.weight =
            ray.weight * max3(Rgb(std::fabs(fil.r), std::fabs(fil.g), std::fabs(fil.b)));
        // The interior list, POV-Ray's rules (ComputeRefraction): entering from outside
        // everything; leaving the innermost interior; leaving one the ray is inside of
        // but not innermost (an overlap: no bending); entering one more.
        const InteriorStack& inside = ray.interiors;
        const uintptr_t id = m.interior_id;
        Real eta = 1;         // incident over transmitted index
        Real dispersion = 1;  // the same ratio of the two sides' dispersions
        int bands = dispersion_samples_of(&m);
        if (inside.size == 0) {
            // POV-Ray divides its double atmosphereIOR by the float index (the other
            // ratios are float by float).
            eta = 1 / Real(ior_of(&m));
            dispersion = 1 / Real(dispersion_of(&m));
            child.trace.interiors.push(&m);
        } else if (inside.innermost() && inside.innermost()->interior_id == id) {
            child.trace.interiors.remove(id);
            const Material* next = child.trace.interiors.innermost();
            eta = ior_of(&m) / ior_of(next);
            dispersion = dispersion_of(&m) / dispersion_of(next);
            if (next) bands = std::max(bands, dispersion_samples_of(next));
        } else if (child.trace.interiors.remove(id)) {
            eta = 1;
        } else {
            eta = ior_of(inside.innermost()) / ior_of(&m);
            dispersion = dispersion_of(inside.innermost()) / dispersion_of(&m);
            child.trace.interiors.push(&m);
        }
        // What passes is scaled by the interior's `refraction` and, when the incoming
        // ray travelled inside it, by its fade.
        Rgb att(m.interior ? m.interior->old_refract : 1.0f);
        if (m.interior && inside.contains(id))
            att *= interior_attenuation(*m.interior, hit.t, false);
        child.coeff *= att;
        child.transmit_factor *= att.grey();
        const bool disperses = std::fabs(dispersion - 1) >= kPovEpsilon;
        if (std::fabs(eta - 1) < kPovEpsilon && !disperses) {
            child.trace.ray = {P, D};
            child.trace.depth = ray.depth;
            child.trace.continued = true;
            out.children.push_back(child);
            return;
        }
        child.trace.depth = ray.depth + 1;
        // Bent about the top layer's normal turned to face the ray (a perturbed
        // normal may point away from it).
        Vector3 facing = top_normal;
        Real n = -dot(D, facing);
        if (n < 0) {
            facing = -facing;
            n = -n;
        }
        // `c` bent by `index_ratio`, with `share` of what passes (a band's hue);
        // `band_of_split`: one of the bands dispersion splits the ray into.
        auto bend = [&](ChildRay& c, Real index_ratio, const Rgb& share,
                        bool band_of_split) {
            c.coeff = child.coeff * share;
            Real t = 1 + index_ratio * index_ratio * (n * n - 1);
            if (t >= 0) {
                // Not normalised: POV-Ray traces Heckbert's direction as it comes out
                // (unit but for its last bits, which decide the round-off roots of a
                // sor or lathe met edge-on inside the glass).
                const Vector3 T =
                    D * index_ratio + facing * (index_ratio * n - std::sqrt(t));
                c.trace.ray = {P, T};
                return;
            }
            // Total internal reflection: reflected as a finish reflects (top normal, raw
            // normal, iridescence), no alpha, and the ray stays inside. (Made from the
            // incoming ray: a split's reflections carry all wavelengths.) Not filtered,
            // and the layers whose normal is the top one reflect no more; but a band of
            // a split is summed with the others as light that passed (POV-Ray's
            // dispersion ignores each band's TIR): filtered, and the layers still
            // reflect.
            const Vector3 R = reflected_direction(D, top_normal, N);
            c.kind = ChildRay::Kind::Reflection;
            c.internal_reflection = true;
            c.trace.ray = {P, R};
            c.trace.use = reflected_use(ray.use);
            c.trace.interiors = ray.interiors;
            c.trace.band = ray.band;
            c.coeff = band_of_split ? child.coeff * share : att * share;
            c.transmit_factor = 0;
            if (top_finish && top_finish->irid > 0)
                tint_reflection(c, iridescence(*top_finish, sc, P, top_normal, R, D));
            if (!band_of_split)
                drop_reflections_with_normal(out.children, reflection_normals,
                                             top_normal);
        };
        if (!disperses || ray.band.monochromatic()) {
            // One ray: a split ray bends by its own band's index.
            const Real index_ratio =
                disperses
                    ? SpectralBand(ray.band.index, ray.band.count).ior(eta, dispersion)
                    : eta;
            bend(child, index_ratio, Rgb(1.0f), false);
            out.children.push_back(child);
            return;
        }
        // Dispersion: one ray per band, each weighted by the band's hue (the mean of the
        // hues is about white); what they bring back has no alpha.
        for (int b = 0; b < bands; ++b) {
            const SpectralBand band(b, bands);
            ChildRay split = child;
            split.trace.band = {uint16_t(b), uint16_t(bands)};
            split.transmit_factor = 0;
            bend(split, band.ior(eta, dispersion), band.hue() * (1.0f / float(bands)),
                 true);
            out.children.push_back(split);
        }
    }
}

}  // namespace

TraceResult combine_children(const ShadingRecord& record, const TraceResult* results) {
    TraceResult r;
    r.colour = record.local;
    r.transmit = record.local_transmit;
    // Media samples' shadow children count through record.fog (replay_media()).
    const size_t n = record.media_replay ? record.media_first : record.children.size();
    for (size_t i = 0; i < n; ++i) {
        const ChildRay& c = record.children[i];
        const TraceResult& x = results[i];
        if (c.kind == ChildRay::Kind::Reflection && c.exponent != 1) {
            // As POV-Ray's pow of each channel: a negative one (a parallel light's fade
            // far behind its plane turns negative) gives NaN unless the power is an
            // integer, and POV-Ray writes such a channel as 0.
            float e = 1 / c.exponent;
            Rgb p(std::pow(x.colour.r, e), std::pow(x.colour.g, e),
                  std::pow(x.colour.b, e));
            r.colour += c.coeff * p;
        } else {
            r.colour += c.coeff * x.colour;
        }
        if (c.kind == ChildRay::Kind::Transmission)
            r.transmit += c.transmit_factor * x.transmit;
    }
    const FogEffect& f = record.fog;
    r.colour = f.add + f.mul * r.colour;
    r.transmit = f.add_transmit + f.mul_transmit * r.transmit;
    return r;
}

namespace {

// `after` applied to what `before` gives: colour -> after(before(colour)).
FogEffect then(const FogEffect& before, const FogEffect& after) {
    return {after.mul * before.add + after.add, after.mul * before.mul,
            after.mul_transmit * before.add_transmit + after.add_transmit,
            after.mul_transmit * before.mul_transmit};
}

FogEffect as_fog_effect(const MediaEffect& m) {
    return {m.add, m.mul, 0.0f, m.mul_transmit};
}

FogEffect rainbows(const PreparedScene& scene, const Ray& ray, Real depth) {
    const RainbowEffect r =
        rainbow_effect(scene.scene(), ray, depth, scene.pattern_env());
    return {r.add, r.mul, 0.0f, r.mul_transmit};
}

}  // namespace

bool sees_volume(const Scene& scene, const TraceRay& ray) {
    return ray.radiosity_depth == 0 ||
           (scene.settings.radiosity && scene.settings.radiosity->media);
}

namespace {

// Media and fog fill only "hollow" space: not the inside of a solid (non-hollow) object.
bool hollow_ray(const InteriorStack& interiors) {
    bool hollow = true;
    interiors.for_each([&](const Material* m) {
        if (m && !(m->interior ? m->interior->hollow : m->object->hollow)) hollow = false;
    });
    return hollow;
}

// Whether an interior the ray is inside of has media. (Not whether the box tracing it
// holds objects with media: the ray may have entered one in another box.)
bool in_media(const InteriorStack& interiors) {
    bool media = false;
    interiors.for_each([&](const Material* m) {
        if (m && m->interior && !m->interior->media.empty()) media = true;
    });
    return media;
}

// The media of the interiors a ray is inside of, in the order it entered them.
void interior_media(const InteriorStack& interiors, std::vector<const Media*>& list) {
    list.clear();
    interiors.for_each([&](const Material* m) {
        if (m && m->interior)
            for (const Media& media : m->interior->media) list.push_back(&media);
    });
}

// Whether the atmosphere's media dim shadow rays toward light `l` (media_interaction
// and media_attenuation both on).
bool attenuated_by_atmosphere(const PreparedScene& scene, int l) {
    const Scene& sc = scene.scene();
    if (l < 0 || sc.atmosphere_media.empty() || !scene.plan().quality.atmosphere())
        return false;
    const Light& light = sc.lights[size_t(l)];
    return light.media_interaction && light.media_attenuation;
}

// The atmosphere's media as one list.
void atmosphere_list(const Scene& sc, std::vector<const Media*>& list) {
    list.clear();
    for (const Media& m : sc.atmosphere_media) list.push_back(&m);
}

// The atmosphere's transmittance over [t0, t1] of a shadow ray.
Rgb atmosphere_shadow(const PreparedScene& scene, const Ray& ray, Real t0, Real t1) {
    thread_local std::vector<const Media*> list;
    atmosphere_list(scene.scene(), list);
    return media_effect(list, ray, t0, t1, true, scene.pattern_env()).mul;
}

bool operator<(const MediaSampleKey& a, const MediaSampleKey& b) {
    if (a.list != b.list) return a.list < b.list;
    if (a.sample != b.sample) return a.sample < b.sample;
    return a.light < b.light;
}

// Lights the samples of scattering media along a viewing ray: POV-Ray's TestShadow from
// each sample, a shadow ray that keeps the viewing ray's interiors, traced as `shadows`
// says.
class SampleLight final : public MediaLightProbe {
  public:
    SampleLight(const PreparedScene& scene, const TraceRay& ray,
                const MediaShadows& shadows, uint8_t list, bool photon_caustics)
        : scene_(scene),
          ray_(ray),
          shadows_(shadows),
          list_(list),
          photon_caustics_(photon_caustics) {}
    Rgb arriving(size_t l, const Point3& at, Vector3& to_light,
                 uint64_t sample) override {
        const Scene& sc = scene_.scene();
        const Light& light = sc.lights[l];
        const Quality quality = scene_.plan().quality;
        LightSample s;
        if (full_area_lighting(light, quality, ray_)) {
            // POV-Ray's TestShadow leaves such a light unattenuated here (its samples
            // would be attenuated each on a surface): no cone, no fade.
            if (!light_ray_toward(light, at, light.location, s)) return {};
            s.colour = light.colour;
        } else if (!light_at(light, at, s)) {
            return {};
        }
        to_light = s.dir;
        Real blockers_end = s.distance;
        const LightMasks* masks = scene_.light_masks();
        if (masks && quality.shadows() &&
            !masks->reaches(l, at, s.dir, s.distance, blockers_end))
            return {};
        // As for a lit surface: fog dims a light with media_attenuation.
        if (light.media_attenuation && !sc.fogs.empty() && s.distance > 0 &&
            s.distance < kInfinity)
            s.colour *= fog_effect(sc, {at, s.dir}, s.distance).mul;
        if (!quality.shadows()) return s.colour;
        ChildRay child = shadow_child(ray_, at, s, l);
        child.t_max = std::min(child.t_max, blockers_end);
        child.photon_caustics = photon_caustics_;
        child.area = light.area.has_value() && quality.area_lights();
        child.light_colour = s.colour;
        child.coeff = Rgb{0.0f};  // counts through the media effect only
        const MediaSampleKey key{sample, uint32_t(l), list_};
        Rgb transmittance;
        if (shadows_.trace) {
            transmittance = shadow_transmittance(scene_, child, *shadows_.trace);
        } else if (shadows_.collect) {
            shadows_.collect->children.push_back(child);
            shadows_.collect->media_samples.push_back(key);
            return {};  // a stand-in: every sample is taken while collecting
        } else if (shadows_.replay) {
            const ShadingRecord& r = *shadows_.replay;
            const auto& keys = r.media_samples;
            const uint32_t* order = shadows_.order;
            const uint32_t* found = std::lower_bound(
                order, order + keys.size(), key,
                [&](uint32_t i, const MediaSampleKey& k) { return keys[i] < k; });
            if (found == order + keys.size() || key < keys[*found])
                throw std::logic_error("a media sample's shadow ray was not traced");
            transmittance = shadows_.results[r.media_first + *found].colour;
        } else {
            throw std::logic_error("media scattering without shadow tests");
        }
        const Rgb c = s.colour * transmittance;
        // POV-Ray: a light below 1e-10 in every channel is blocked.
        if (std::fabs(c.r) < 1e-10f && std::fabs(c.g) < 1e-10f && std::fabs(c.b) < 1e-10f)
            return {};
        return c;
    }

  private:
    const PreparedScene& scene_;
    const TraceRay& ray_;
    const MediaShadows& shadows_;
    uint8_t list_;
    bool photon_caustics_;
};

// The media of `list` (0: the interiors', 1: the atmosphere's) along a viewing ray up
// to `depth`, lit by the scene's lights.
FogEffect viewing_media(const PreparedScene& scene, std::span<const Media* const> list,
                        uint8_t which, const TraceRay& ray, Real depth,
                        MediaEndLights end, const MediaShadows& shadows) {
    if (shadows.collect) {
        // Its value comes from replay_media() once the shadow rays are in.
        for (const Media* m : list)
            if (m->scatters()) shadows.collect->media_replay = true;
    }
    // POV-Ray's litObjectIgnoresPhotons for a media sample: unless every media ignores
    // photons (`collect off`), a blocker that refracts the light's photons shadows it
    // fully (the photons bring that light), as for a lit surface.
    bool collects = false;
    for (const Media* m : list) collects = collects || m->collect;
    const PhotonMap* photons = scene.photons();
    SampleLight probe(scene, ray, shadows, which,
                      collects && photons && photons->size() > 0);
    MediaLights lights{scene.scene().lights, end.global_lights, end.light_group, &probe,
                       shadows.collect != nullptr};
    if (scene.photons()) lights.media_photons = scene.photons()->media();
    return as_fog_effect(
        media_effect(list, ray.ray, 0, depth, false, scene.pattern_env(), &lights));
}

FogEffect along_ray(const PreparedScene& scene, const TraceRay& ray, Real depth,
                    MediaEndLights end, const MediaShadows& shadows) {
    const Scene& sc = scene.scene();
    if (!sees_volume(sc, ray)) return {};
    if (sc.fogs.empty() && sc.atmosphere_media.empty() && sc.rainbows.empty() &&
        !in_media(ray.interiors))
        return {};
    if (!hollow_ray(ray.interiors)) return {};
    // POV-Ray: the interiors' media on the surface's colour, then rainbows, the
    // atmosphere's media and fog, each on what the one before gave.
    FogEffect e;
    if (ray.interiors.size > 0) {
        thread_local std::vector<const Media*> list;
        interior_media(ray.interiors, list);
        if (!list.empty()) e = viewing_media(scene, list, 0, ray, depth, end, shadows);
    }
    if (!sc.rainbows.empty()) e = then(e, rainbows(scene, ray.ray, depth));
    if (!sc.atmosphere_media.empty()) {
        thread_local std::vector<const Media*> list;
        atmosphere_list(sc, list);
        e = then(e, viewing_media(scene, list, 1, ray, depth, end, shadows));
    }
    if (!sc.fogs.empty()) e = then(e, fog_effect(sc, ray.ray, depth));
    return e;
}

// What a ray that hits nothing crosses: the atmosphere out to POV-Ray's "infinite"
// depth, 2e10 (lit or glowing media saturate the sky, absorbing media blacken it), then
// fog up to its MAX_DISTANCE. Nothing inside a solid object (POV-Ray's TraceRay: rainbow,
// atmosphere and fog only on a hollow ray, hit or miss): a ray that escapes while still
// inside a solid transparent plane, disc or triangle shows the sky unfogged.
FogEffect along_missing_ray(const PreparedScene& scene, const TraceRay& ray,
                            const MediaShadows& shadows) {
    const Scene& sc = scene.scene();
    FogEffect f;
    if ((sc.fogs.empty() && sc.atmosphere_media.empty() && sc.rainbows.empty()) ||
        !scene.plan().quality.atmosphere() || !sees_volume(sc, ray) ||
        !hollow_ray(ray.interiors))
        return f;
    if (!sc.rainbows.empty()) f = rainbows(scene, ray.ray, 2e10);
    if (!sc.atmosphere_media.empty()) {
        thread_local std::vector<const Media*> list;
        atmosphere_list(sc, list);
        f = then(f, viewing_media(scene, list, 1, ray, 2e10, {}, shadows));
    }
    if (!sc.fogs.empty()) f = then(f, fog_effect(sc, ray.ray, kMaxDistance));
    return f;
}

}  // namespace

FogEffect along_ray_effect(const PreparedScene& scene, const TraceRay& ray, Real depth,
                           MediaEndLights end, RayContext* ctx) {
    MediaShadows shadows;
    shadows.trace = ctx;
    return along_ray(scene, ray, depth, end, shadows);
}

Rgb photon_through_media(const PreparedScene& scene, const TraceRay& ray, Real depth,
                         MediaEndLights end, const Rgb& colour, MediaPhotonSink* sink) {
    if (!in_media(ray.interiors) || !hollow_ray(ray.interiors)) return colour;
    thread_local std::vector<const Media*> list;
    interior_media(ray.interiors, list);
    MediaLights lights{scene.scene().lights, end.global_lights, end.light_group};
    lights.photon = true;
    if (sink)
        return deposit_media_photons(list, ray.ray, depth, lights, scene.pattern_env(),
                                     colour, *sink);
    const MediaEffect e =
        media_effect(list, ray.ray, 0, depth, false, scene.pattern_env(), &lights);
    return e.add + e.mul * colour;
}

void replay_media(const PreparedScene& scene, const TraceRay& ray, ShadingRecord& record,
                  const TraceResult* results) {
    if (!record.media_replay) return;
    thread_local std::vector<uint32_t> order;
    const auto& keys = record.media_samples;
    order.resize(keys.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
    MediaShadows shadows;
    shadows.replay = &record;
    shadows.results = results;
    shadows.order = order.data();
    record.fog = record.media_miss ? along_missing_ray(scene, ray, shadows)
                                   : along_ray(scene, ray, record.media_depth,
                                               record.media_lights, shadows);
}

FogEffect fog_effect(const Scene& scene, const Ray& ray, Real depth) {
    FogEffect e;
    for (const Fog& fog : scene.fogs) {
        if (std::fabs(fog.distance) <= kPovEpsilon) continue;
        // POV-Ray's constant and ground fog.
        Real density = 1;
        Real width = depth;
        if (fog.turbulent) {
            // Turbulence at the middle of the stretch (scaled per axis) thins the fog,
            // less so the longer the stretch is.
            Point3 mid = ray.at(depth * 0.5);
            mid = Point3{mid.x * fog.turbulence.x, mid.y * fog.turbulence.y,
                         mid.z * fog.turbulence.z};
            TurbulenceParams tp;
            tp.octaves = fog.octaves;
            tp.omega = fog.omega;
            tp.lambda = fog.lambda;
            Real k = std::exp(-depth / fog.distance);
            width *= 1.0 - k * std::min(1.0, turbulence(mid, tp,
                                                        scene.settings.noise_generator) *
                                                 fog.turb_depth);
        }
        if (fog.type == 2) {
            Vector3 up = fog.up;
            Real y1 = dot(ray.origin, up), y2 = dot(ray.at(depth), up);
            Real start = (y1 - fog.offset) / fog.alt, end = (y2 - fog.offset) / fog.alt;
            if (start <= 0) {
                density = end <= 0 ? 1.0 : (std::atan(end) - start) / (end - start);
            } else if (end <= 0) {
                density = (std::atan(start) - end) / (start - end);
            } else if (std::fabs(start - end) > kPovEpsilon) {
                density = (std::atan(start) - std::atan(end)) / (start - end);
            } else {
                density = 1 / (start * start + 1);
            }
        }
        float att = float(std::exp(-width * density / fog.distance));
        const Colour& c = fog.colour;
        att = std::max(att, c.transmit);  // minimum transmittance
        const Rgb pass = Rgb(1 - c.filter) + c.rgb * c.filter;
        e.mul *= pass * att;
        e.add += c.rgb * (1 - att);
    }
    e.mul_transmit = e.mul.grey();  // POV-Ray 3.7 scales the ray's transmit only
    return e;
}

namespace {

// Faked caustics: a layer lets more light through where the shadow ray crosses the
// surface head on (POV-Ray's 1 + |N.D|^caustics, with the layer's perturbed normal).
// `nesting` holds the texture maps the layer is in (null: none); `surface` (the hit's
// PNormal), when given, takes the perturbed normal (in the maps' space, as POV-Ray's).
float caustic_gain(const PreparedScene& scene, const Texture* t, float caustics,
                   const Hit& hit, const TextureNesting* nesting, const Ray& ray,
                   SurfaceAtHit* surface = nullptr) {
    // Turned to face the shadow ray before it is perturbed, as POV-Ray's shadow texture
    // does (a bump is not mirrored with the normal, so the side matters).
    SurfaceAtHit facing = surface_facing(hit, ray.direction);
    Vector3 n = facing.normal;
    if (t && t->normal) {
        n = perturb_nested(*t->normal,
                           nesting ? nesting->point : surface_point(*hit.material, hit),
                           n, scene.pattern_env().at_surface(surface ? surface : &facing),
                           nesting, surface ? &surface->normal : nullptr);
    }
    return float(1 + std::pow(std::fabs(dot(n, ray.direction)), Real(caustics)));
}

// What a surface with `layers` lets through toward a light (POV-Ray's shadow texture):
// the product of its layers' filter and transmit; a patterned texture (texture_map,
// checker of textures) blends its two entries around the pattern value, evaluated in
// its pattern's space (`nesting`: the maps the layers are in, null at the top).
// `pattern_normal` is the normal the patterns read (POV-Ray's PNormal, one per hit: a
// map's entries see what the faked caustics of those shaded before left; null: the
// hit's own).
Rgb shadow_filter(const PreparedScene& scene, const LayeredTexture& layers,
                  float caustics, const Hit& hit, const TextureNesting* nesting,
                  const Ray& ray, SurfaceAtHit* pattern_normal = nullptr) {
    SurfaceAtHit own_surface;
    if (!pattern_normal) {
        own_surface = surface_facing(hit, ray.direction);
        pattern_normal = &own_surface;
    }
    const Point3 at = nesting ? nesting->point : surface_point(*hit.material, hit);
    if (layers.size() == 1 && layers.front().map_pattern &&
        !layers.front().map->entries.empty()) {
        const Texture& t = layers.front();
        const int count = int(t.map->entries.size());
        const bool has_values = int(t.map->values.size()) == count;
        if (t.map_pattern->kind == PatternKind::Average) {
            // Every entry, weighted by its value (POV-Ray's average texture).
            Rgb sum(0.0f);
            float total = 0;
            const TextureNesting inner{&*t.map_pattern, pattern_point(*t.map_pattern, at),
                                       nesting};
            for (int i = 0; i < count; ++i) {
                const float v = has_values ? t.map->values[size_t(i)] : 1.0f;
                sum += shadow_filter(scene, t.map->entries[size_t(i)], caustics, hit,
                                     &inner, ray, pattern_normal) *
                       v;
                total += v;
            }
            return sum * (1 / total);
        }
        const MapPick pick =
            pick_map_entries(*t.map_pattern, has_values ? t.map->values.data() : nullptr,
                             count, at, scene.pattern_env().at_surface(pattern_normal));
        const TextureNesting inner{&*t.map_pattern, pick.point, nesting};
        const auto entry = [&](int i) -> const LayeredTexture& {
            return t.map->entries[size_t(std::clamp(i, 0, count - 1))];
        };
        Rgb f = shadow_filter(scene, entry(pick.lookup.cur), caustics, hit, &inner, ray,
                              pattern_normal);
        if (pick.lookup.prev != pick.lookup.cur) {
            const float w = float(pick.lookup.fraction);
            f = f * w + shadow_filter(scene, entry(pick.lookup.prev), caustics, hit,
                                      &inner, ray, pattern_normal) *
                            (1 - w);
        }
        return f;
    }
    Rgb f(1.0f);
    const PatternEnv env = scene.pattern_env().at_surface(pattern_normal);
    for (const Texture& t : layers) {
        f *= rgb_transm(eval_pigment(t.pigment, at, env));
        if (caustics != 0)
            f *= caustic_gain(scene, &t, caustics, hit, nesting, ray, pattern_normal);
    }
    return f;
}

}  // namespace

bool on_pattern_boundary(const PreparedScene& scene, const Hit& hit, Real tolerance) {
    if (!hit.material || hit.material->plain) return false;
    const Real scale = std::max({Real(1), std::fabs(hit.point.x), std::fabs(hit.point.y),
                                 std::fabs(hit.point.z)});
    const Vector3 step = hit.normal * (tolerance * scale);
    const Point3 above = hit.point + step, below = hit.point - step;
    const PatternEnv& env = scene.pattern_env();
    for (const Texture& t : texture_of(*hit.material)) {
        if (t.map_pattern && !t.map->entries.empty()) {
            if (std::fabs(evaluate_pattern(*t.map_pattern, above, env) -
                          evaluate_pattern(*t.map_pattern, below, env)) > 0.1)
                return true;
            continue;
        }
        if (pigment_is_solid(t.pigment)) continue;
        const Colour a = evaluate_pigment(t.pigment, above, env),
                     b = evaluate_pigment(t.pigment, below, env);
        const float d[5] = {a.rgb.r - b.rgb.r, a.rgb.g - b.rgb.g, a.rgb.b - b.rgb.b,
                            a.filter - b.filter, a.transmit - b.transmit};
        for (float x : d) {
            if (std::fabs(x) > 0.1f) return true;
        }
    }
    return false;
}

bool shadow_segment(const PreparedScene& scene, const Ray& ray, Real segment_end,
                    Real light_distance, ShadowState& state, RayContext& ctx) {
    const Real hi = std::min(segment_end, light_distance - kShadowTolerance);
    if (state.blocked) return true;
    if (!(state.t_min < hi)) return false;
    // Most shadow rays meet only opaque blockers or nothing: find out in any order (not
    // while probing for ties, which looks at the crossings in order).
    bool transparent = ctx.tie_tolerance > 0;
    ctx.restart = state.last_hit;
    const bool opaque =
        !transparent &&
        scene.opaque_blocker(ray, state.t_min, hi, transparent, ctx, state.light);
    ctx.restart = 0;
    if (opaque) {
        state.blocked = true;
        state.filter = Rgb{};
        return true;
    }
    if (!transparent) {
        state.t_min = std::max(state.t_min, hi);
        return false;
    }
    // See-through blockers: each crossing multiplies the light by its filter, nearest
    // first, the next search starting 1e-3 past the previous hit as POV-Ray's restarted
    // ray does. The ray enters or leaves each object it crosses; the stretch inside fades
    // with the object's interior. (No adc_bailout test per layer: POV-Ray's combined
    // shadow texture always has filter 1, so that test never fires.)
    for (int guard = 0; guard < 256 && state.t_min < hi; ++guard) {
        Hit hit;
        // POV-Ray restarts the shadow ray at each see-through crossing.
        ctx.restart = state.last_hit;
        const bool met = scene.closest_hit(ray, state.t_min, hi, RayUse::Shadow, hit, ctx,
                                           false, light_distance - kShadowTolerance);
        ctx.restart = 0;
        if (!met) break;
        if (ctx.tie_tolerance > 0 && on_pattern_boundary(scene, hit, ctx.tie_tolerance))
            ++ctx.pattern_ties;
        const Material& m = *hit.material;
        bool black = m.opaque;
        if (state.photon_caustics && m.object && state.light >= 0 &&
            refracts_photons(m.object->photons,
                             scene.scene().lights[size_t(state.light)]))
            black = true;
        if (!black && shows_interior_texture(m, hit, ray)) {
            state.filter *= shadow_filter(scene, *m.interior_texture,
                                          m.interior ? m.interior->caustics : 0.0f, hit,
                                          nullptr, ray);
        } else if (!black && m.blend) {
            // The corners' filters weighted (POV-Ray sums the weighted shadow colours,
            // whose filter is the sum of the weights used).
            float w[3];
            blend_weights(*m.blend, hit.point, w);
            const float adc = scene.scene().settings.adc_bailout;
            Rgb sum{0.0f};
            float used = 0;
            for (int k = 0; k < 3; ++k) {
                if (w[k] < adc) continue;
                const Material& c = *m.blend->corners[k];
                sum += shadow_filter(scene, texture_of(c),
                                     m.interior ? m.interior->caustics : 0.0f, hit,
                                     nullptr, ray) *
                       w[k];
                used += w[k];
            }
            state.filter *= sum * used;
        } else if (!black && m.blob_blend) {
            thread_local std::vector<const Material*> mats;
            thread_local std::vector<float> w;
            const int n = blob_texture_weights(
                *m.blob_blend, hit.point, scene.scene().settings.adc_bailout, mats, w);
            Rgb sum{0.0f};
            float used = 0;
            for (int k = 0; k < n; ++k) {
                sum += shadow_filter(scene, texture_of(*mats[size_t(k)]),
                                     m.interior ? m.interior->caustics : 0.0f, hit,
                                     nullptr, ray) *
                       w[size_t(k)];
                used += w[size_t(k)];
            }
            state.filter *= sum * used;
        } else if (!black && m.plain) {
            state.filter *= rgb_transm(m.plain_colour);
            if (m.interior && m.interior->caustics != 0)
                state.filter *=
                    caustic_gain(scene, nullptr, m.interior->caustics, hit, nullptr, ray);
        } else if (!black) {
            state.filter *= shadow_filter(scene, texture_of(m),
                                          m.interior ? m.interior->caustics : 0.0f, hit,
                                          nullptr, ray);
        }
        if (!black && state.volume && in_media(state.inside) &&
            scene.plan().quality.atmosphere() && hollow_ray(state.inside)) {
            // The media of every interior the ray is in dim the stretch since the last
            // crossing (whatever the light's media_attenuation says, as POV-Ray).
            thread_local std::vector<const Media*> list;
            interior_media(state.inside, list);
            if (!list.empty())
                state.filter *= media_effect(list, ray, state.last_hit, hit.t, true,
                                             scene.pattern_env())
                                    .mul;
        }
        // A light with media_attenuation: the atmosphere's media dim each stretch too
        // (POV-Ray's ComputeShadowMedia at a crossing: hollow or not).
        if (!black && state.volume && attenuated_by_atmosphere(scene, state.light) &&
            state.filter.max_component() >= 1e-10f) {
            state.filter *= atmosphere_shadow(scene, ray, state.last_hit, hit.t);
        }
        if (!black) {
            if (state.inside.contains(m.interior_id)) {
                if (m.interior) {
                    state.filter *=
                        interior_attenuation(*m.interior, hit.t - state.last_hit, true);
                }
                state.inside.remove(m.interior_id);
            } else {
                state.inside.push(&m);
            }
        }
        if (black || state.filter.max_component() <= 0) {
            state.blocked = true;
            state.filter = Rgb{};
            return true;
        }
        state.last_hit = hit.t;
        state.t_min = hit.t + kShadowTolerance;
    }
    state.t_min = std::max(state.t_min, hi);
    return false;
}

void shadow_last_leg(const PreparedScene& scene, const Ray& ray, Real light_distance,
                     ShadowState& state) {
    // POV-Ray's TraceShadowRay: the rest of the way to the light crosses only the
    // atmosphere (a light inside a media container is not dimmed by it there), and only
    // in hollow space.
    if (state.blocked || !state.volume || !attenuated_by_atmosphere(scene, state.light))
        return;
    if (!(light_distance - state.last_hit > kShadowTolerance) ||
        !(light_distance < kInfinity) || !hollow_ray(state.inside))
        return;
    const Rgb& f = state.filter;
    if (f.r < 1e-10f && f.g < 1e-10f && f.b < 1e-10f) return;
    state.filter *= atmosphere_shadow(scene, ray, state.last_hit, light_distance);
}

namespace {

Rgb point_shadow(const ChildRay& shadow, const PreparedScene& scene, const Ray& ray,
                 Real distance, RayContext& ctx) {
    ShadowState state;
    state.inside = shadow.trace.interiors;
    state.light = shadow.light;
    state.photon_caustics = shadow.photon_caustics;
    state.volume = sees_volume(scene.scene(), shadow.trace);
    if (!shadow_segment(scene, ray, kInfinity, distance, state, ctx))
        shadow_last_leg(scene, ray, distance, state);
    return state.filter;
}

float colour_distance(const Rgb& a, const Rgb& b) {
    return std::fabs(a.r - b.r) + std::fabs(a.g - b.g) + std::fabs(a.b - b.b);
}

// POV-Ray's adaptive average over a grid whose samples `sample(u, v)` gives: the corners
// of a region, refined by quadrants while level < adaptive or neighbouring corners differ
// by more than 0.1 (light colour applied); each level averages its 4 quadrants.
template <class Sample>
Rgb adaptive_average(const AreaLight& area, const Rgb& light_colour, int u1, int v1,
                     int u2, int v2, int level, Sample&& sample) {
    Rgb s[4] = {sample(u1, v1), sample(u2, v1), sample(u1, v2), sample(u2, v2)};
    if (u2 - u1 > 1 || v2 - v1 > 1) {
        const Rgb& lc = light_colour;
        bool refine = level < area.adaptive ||
                      colour_distance(lc * s[0], lc * s[1]) > 0.1f ||
                      colour_distance(lc * s[1], lc * s[3]) > 0.1f ||
                      colour_distance(lc * s[3], lc * s[2]) > 0.1f ||
                      colour_distance(lc * s[2], lc * s[0]) > 0.1f;
        if (refine) {
            const int ul = (u1 + u2) / 2,
                      uh = (u1 + u2 + 1) / 2;  // floor, ceil of middle
            const int vl = (v1 + v2) / 2, vh = (v1 + v2 + 1) / 2;
            s[0] = adaptive_average(area, lc, u1, v1, ul, vl, level + 1, sample);
            s[1] = adaptive_average(area, lc, uh, v1, u2, vl, level + 1, sample);
            s[2] = adaptive_average(area, lc, u1, vh, ul, v2, level + 1, sample);
            s[3] = adaptive_average(area, lc, uh, vh, u2, v2, level + 1, sample);
        }
    }
    return (s[0] + s[1] + s[2] + s[3]) * 0.25f;
}

}  // namespace

AreaGrid::AreaGrid(const Scene& scene, const ChildRay& shadow)
    : light(scene.lights[size_t(shadow.light)]),
      light_index(shadow.light),
      area(*light.area),
      at(shadow.trace.ray.origin),
      n1(std::max(1, area.size1)),
      n2(std::max(1, area.size2)),
      axis1(area.axis1),
      axis2(area.axis2),
      light_colour(shadow.light_colour) {
    if (area.orient) {
        // Face the lit point: both axes perpendicular to the light ray (a parallel or
        // cylinder light's runs from point_at), axis1's length.
        const bool parallel_rays = light.kind == Light::Kind::Cylinder ||
                                   light.kind == Light::Kind::Parallel || light.parallel;
        const Vector3 dir =
            normalize(light.location - (parallel_rays ? light.point_at : at));
        const Real len = length(axis1);
        const Vector3 up =
            std::fabs(std::fabs(dir.z) - 1) < 0.01 ? Vector3{0, 1, 0} : Vector3{0, 0, 1};
        axis1 = normalize(cross(dir, up));
        axis2 = normalize(cross(dir, axis1)) * len;
        axis1 *= len;
    }
}

namespace {

// Two numbers in [0, 1) from the lit point, the light and the sample, drawn as crand's
// are: the same for the same sample of the same point in every render mode.
void area_jitter(const Point3& at, int light, int u, int v, Real& a, Real& b) {
    const size_t sample =
        (size_t(uint32_t(light)) << 32 | size_t(uint16_t(u)) << 16 | size_t(uint16_t(v)))
        << 1;
    a = crand_sample(at, sample);
    b = crand_sample(at, sample | 1);
}

}  // namespace

namespace {

// Where sample (u, v) of `grid` is: its cell's point (jittered within the cell with
// `jitter`), on a circle's shells when `circular`.
Point3 area_sample_point(const AreaGrid& grid, int u, int v) {
    const AreaLight& area = grid.area;
    const int n1 = grid.n1, n2 = grid.n2;
    const Vector3 &axis1 = grid.axis1, &axis2 = grid.axis2;
    Vector3 offset{0, 0, 0};
    Real ju = u, jv = v;
    if (area.jitter) {
        Real a, b;
        area_jitter(grid.at, grid.light_index, u, v, a, b);
        ju += a - 0.5;
        jv += b - 0.5;
    }
    if (area.circular && n1 > 1 && n2 > 1) {
        ju = ju / (n1 - 1) - 0.5 + 0.001;
        jv = jv / (n2 - 1) - 0.5 + 0.001;
        const Real scale =
            std::max(std::fabs(ju), std::fabs(jv)) / std::sqrt(ju * ju + jv * jv);
        offset = axis1 * (ju * scale) + axis2 * (jv * scale);
    } else {
        if (n1 > 1) offset += axis1 * (ju / (n1 - 1) - 0.5);
        if (n2 > 1) offset += axis2 * (jv / (n2 - 1) - 0.5);
    }
    return grid.light.location + offset;
}

}  // namespace

bool AreaGrid::sample_ray(int u, int v, Ray& ray, Real& distance) const {
    if (light.kind == Light::Kind::Cylinder || light.kind == Light::Kind::Parallel ||
        light.parallel) {
        // Parallel rays along the line from point_at through the sample.
        LightSample s;
        if (!light_ray_toward(light, at, area_sample_point(*this, u, v), s) ||
            !(s.distance > 0))
            return false;  // behind the light: nothing blocks it
        ray = {at, s.dir};
        distance = s.distance;
        return true;
    }
    const Vector3 to = area_sample_point(*this, u, v) - at;
    distance = length(to);
    if (!(distance > 0)) return false;
    ray = {at, to / distance};
    return true;
}

Rgb AreaGrid::average(const Rgb* samples) const {
    return adaptive_average(area, light_colour, 0, 0, n1 - 1, n2 - 1, 0,
                            [&](int u, int v) { return samples[size_t(u) * n2 + v]; });
}

Rgb shadow_transmittance(const PreparedScene& scene, const ChildRay& shadow,
                         RayContext& ctx) {
    if (!shadow.area)
        return point_shadow(shadow, scene, shadow.trace.ray, shadow.t_max, ctx);
    // The samples the adaptive rule asks for, each traced once.
    const AreaGrid grid(scene.scene(), shadow);
    thread_local std::vector<Rgb> values;
    thread_local std::vector<uint8_t> done;
    values.resize(grid.samples());
    done.assign(grid.samples(), 0);
    return adaptive_average(grid.area, grid.light_colour, 0, 0, grid.n1 - 1, grid.n2 - 1,
                            0, [&](int u, int v) {
                                const size_t k = size_t(u) * grid.n2 + v;
                                if (!done[k]) {
                                    Ray ray;
                                    Real d = 0;
                                    values[k] =
                                        grid.sample_ray(u, v, ray, d)
                                            ? point_shadow(shadow, scene, ray, d, ctx)
                                            : Rgb(1.0f);
                                    done[k] = 1;
                                }
                                return values[k];
                            });
}

namespace {

// Colour of a ray that hits nothing, before what lies along it.
TraceResult sky_colour(const PreparedScene& scene, const TraceRay& traced) {
    const Ray& ray = traced.ray;
    // POV-Ray's ComputeSky: the sky_sphere's pigments (last one on top) over the
    // background.
    const Scene& sc = scene.scene();
    const bool alpha_output = scene.alpha_background();
    // POV-Ray's ticket: only camera rays and the rays they transmit see the background's
    // alpha; a reflected ray and every ray under it, and radiosity's sample rays, see it
    // as an opaque colour (Trace::ComputeReflection clears the ticket's alphaBackground).
    const bool alpha =
        alpha_output &&
        (traced.use == RayUse::Camera || traced.use == RayUse::Refraction) &&
        traced.radiosity_depth == 0;
    const bool sky = sc.sky_sphere && !sc.sky_sphere->pigments.empty();
    Point3 p;
    if (sky) p = sc.sky_sphere->transform.inverse_point(ray.direction);
    // The background as POV-Ray stores it when it parses the statement: a legacy one
    // loses its filter and takes its transmit from +UA; a 3.7 one without +UA is
    // composed over black then (a transmit of 0.6 keeps 0.4 of the colour).
    Colour bg = sc.background;
    if (sc.background_legacy) {
        bg.filter = 0;
        bg.transmit = alpha_output ? 1.0f : 0.0f;
    } else if (!alpha_output) {
        bg.rgb *= 1 - bg.transmit;
        bg.filter = bg.transmit = 0;
    }
    // A ray that does not see the alpha takes the stored colour whole (ComputeSky).
    if (!alpha) bg.filter = bg.transmit = 0;
    const Rgb emission = sky ? sc.sky_sphere->emission : Rgb(1.0f);
    if (sc.language_version < 370) {
        // Legacy: full transparency with alpha; else the 3.6 compositing.
        if (alpha) return TraceResult{Rgb{}, 1.0f};
        if (!sky) return TraceResult{bg.rgb, 0.0f};
        Rgb col, fil(1.0f);
        float ff = 1, ft = 1, trans = 1;
        for (auto it = sc.sky_sphere->pigments.rbegin();
             it != sc.sky_sphere->pigments.rend(); ++it) {
            Colour c = evaluate_pigment(*it, p, scene.pattern_env());
            col += c.rgb * (trans * (1 - c.filter - c.transmit));
            fil *= c.rgb;
            ff *= c.filter;
            ft *= c.transmit;
            trans = std::fabs(ff) + std::fabs(ft);
        }
        col *= emission;
        return TraceResult{col + bg.rgb * (fil * ff + Rgb(ft)), 0.0f};
    }
    Rgb col, fil(1.0f);
    if (sky) {
        for (auto it = sc.sky_sphere->pigments.rbegin();
             it != sc.sky_sphere->pigments.rend(); ++it) {
            Colour c = evaluate_pigment(*it, p, scene.pattern_env());
            col += c.rgb * (1 - c.filter - c.transmit) * fil * emission;
            fil *= rgb_transm(c);
        }
    }
    // The background is one more uniform layer (its filter and transmit are 0 without
    // +UA, see above).
    col += bg.rgb * (1 - bg.filter - bg.transmit) * fil;
    fil *= rgb_transm(bg);
    return TraceResult{col, std::min(1.0f, std::fabs(fil.grey()))};
}

}  // namespace

TraceResult miss_colour(const PreparedScene& scene, const TraceRay& ray,
                        RayContext* ctx) {
    MediaShadows shadows;
    shadows.trace = ctx;
    const TraceResult r = sky_colour(scene, ray);
    const FogEffect f = along_missing_ray(scene, ray, shadows);
    return {f.add + f.mul * r.colour, f.add_transmit + f.mul_transmit * r.transmit};
}

bool spawn_miss(const PreparedScene& scene, const TraceRay& ray, ShadingRecord& out) {
    const Scene& sc = scene.scene();
    if (!scene.plan().quality.atmosphere() || !sees_volume(sc, ray) ||
        !hollow_ray(ray.interiors))
        return false;
    bool scatters = false;
    for (const Media& m : sc.atmosphere_media) scatters = scatters || m.scatters();
    if (!scatters) return false;
    out.clear();
    const TraceResult r = sky_colour(scene, ray);
    out.local = r.colour;
    out.local_transmit = r.transmit;
    MediaShadows shadows;
    shadows.collect = &out;
    out.fog = along_missing_ray(scene, ray, shadows);
    out.media_miss = true;
    out.media_replay = true;
    return true;
}

}  // namespace povwall::trace
