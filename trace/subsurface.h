// Subsurface light transport, as POV-Ray 3.7 defines it (its experimental SSLT: Jensen et
// al. 2001's dipole diffusion term, a single-scattering term and an unscattered term
// seen through the object), evaluated at a surface point by tracing rays against the
// object's own surface. It replaces the finish's diffuse term (docs/subsurface.md).
//
// POV-Ray draws the sample directions and distances from two fixed tables, each thread
// walking them in the order it shades points; here each evaluation starts at a place in
// the tables that a hash of the shaded point picks, so every mode, thread count and
// process renders the same image (within POV-Ray's own noise, which differs between its
// renders with 1 and 2 threads).
#pragma once

#include <array>
#include <vector>

#include "trace/shading.h"

namespace povwall::trace {

class Tracer;

namespace subsurface {

// POV-Ray's approximation of the diffuse Fresnel reflectance for relative index `eta`.
double diffuse_fresnel_reflectance(double eta);
// Fresnel transmittance through an interface at incidence cosine `cos_angle`; 1 where
// the formula has no value (past the critical angle, a cosine beyond [-1, 1]), as
// POV-Ray's clamp of its NaN gives.
double fresnel_transmittance(double cos_angle, double eta);

// Jensen et al.'s dipole diffuse reflectance (per mm², without POV-Ray's 1/pi, which
// its light intensities hold) for light entering `r2` mm² from where it leaves, in a
// medium of reduced extinction and absorption (1/mm) and reduced albedo, with
// a = (1 + Fdr) / (1 - Fdr) for the relative index.
double dipole_reflectance(double extinction, double absorption, double albedo, double a,
                          double r2);

// The reduced albedo that gives a total diffuse reflectance, for one absolute index of
// refraction: POV-Ray's table of 101 single-precision values read linearly.
class AlbedoTable {
  public:
    explicit AlbedoTable(double ior);
    double ior() const { return ior_; }
    double reduced_albedo(double reflectance) const;
    float entry(int k) const { return table_[size_t(k)]; }

  private:
    double ior_;
    std::array<float, 101> table_;
};

// POV-Ray's two sample tables (32,767 entries each): uniform numbers from a
// default-seeded MT19937, and Halton directions over the whole sphere.
constexpr size_t kTableSize = 32767;
double uniform_number(size_t k);
const Vector3& sphere_direction(size_t k);

}  // namespace subsurface

// What an evaluation needs of the shaded point.
struct SubsurfacePoint {
    const TraceRay& ray;
    const Hit& hit;
    const Material& material;
    Vector3 normal;    // the raw normal turned to face the ray
    Real eta;          // relative index of refraction at the hit (as for refraction)
    float ior;         // the object's own index (its albedo table)
    Rgb reflectance;   // the layer's pigment times its raw diffuse
    Rgb translucency;  // the finish's, mm
};

// One per tracer (thread): traces its rays with the tracer's context and, for the light
// seen through the object, the tracer itself.
class SubsurfaceTracer {
  public:
    SubsurfaceTracer(Tracer& tracer, RayContext& ctx);
    // The layer's subsurface colour (added to the layer's colour as it is).
    Rgb light(const SubsurfacePoint& at);

  private:
    const subsurface::AlbedoTable& table_for(double ior);

    Tracer& tracer_;
    RayContext& ctx_;
    int depth_ = 0;  // evaluations in progress on this thread (POV-Ray's SSLT depth)
    std::vector<subsurface::AlbedoTable> tables_;
};

}  // namespace povwall::trace
