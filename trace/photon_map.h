// POV-Ray 3.7's surface photon map (caustics): photons shot from the lights at each
// photon target's bounding sphere, followed through the targets' reflection and
// refraction, and stored where they land; shading gathers the nearest ones at a hit (see
// photon_contribution in shading.cpp).
//
// The map is built once per frame, before tracing, from the whole scene, by one thread,
// with our own random numbers drawn from a hash of (light, target, ring, photon): every
// process that holds the whole scene (one process, each screen-mode worker, the black
// boxes' host in one process, the TCP coordinator) builds the same map, and a TCP worker,
// which holds a part of the scene, receives the coordinator's (distrib/wire/photons.h):
// every mode renders the same image. POV-Ray draws its jitter from per-thread random
// sequences, so its photons and ours agree statistically (compared by block means).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/scene.h"

namespace povwall::trace {

class PreparedScene;

// One stored photon, as POV-Ray keeps it: a single-precision position, the flux in
// Ward's RGBE (exponent offset 250) and the incoming direction in two signed bytes.
struct Photon {
    float pos[3];
    uint8_t rgbe[4];
    int8_t theta, phi;
    uint8_t axis = 0;  // kd-tree split axis of this node
};

class PhotonMap {
  public:
    size_t size() const { return photons_.size(); }
    // The media map (POV-Ray's mediaPhotonMap: photons stored along the media intervals
    // photons cross, gathered at the samples of scattering media); null without
    // `media` in the photons block.
    const PhotonMap* media() const { return media_.get(); }
    // The gather radius the map starts with (POV-Ray's minGatherRad, times the radius
    // multiplier).
    double min_gather_radius() const { return min_radius_; }
    // POV-Ray's adaptive gather at `p` with surface normal `n`: up to gather_max photons
    // within the start radius (distances flattened along `n`; a media map has no
    // normal), expanded once when fewer than gather_min are found and the density
    // holds. Returns the radius the estimate divides by; `out` gets the photons.
    double gather(const Point3& p, const Vector3* n,
                  std::vector<const Photon*>& out) const;

    // What another process needs to gather as this map does: the photons in kd-tree
    // order, the radii and the gather settings (gather_min, gather_max, expand_*).
    const std::vector<Photon>& photons() const { return photons_; }
    double radius_step() const { return radius_step_; }
    const PhotonSettings& settings() const { return settings_; }
    // The map those make (`photons` in the order photons() gave them).
    static std::shared_ptr<PhotonMap> assemble(const PhotonSettings& settings,
                                               std::vector<Photon> photons,
                                               double min_radius, double radius_step,
                                               std::shared_ptr<PhotonMap> media);

    // The flux and the unit direction toward where the photon came from.
    static Rgb flux(const Photon& ph);
    static Vector3 incoming(const Photon& ph);

    // Shoots the photons of `scene` (whose Scene has settings.photons) and sorts them.
    friend std::shared_ptr<const PhotonMap> build_photon_map(const PreparedScene& scene);

  private:
    // k nearest within `radius` (flattened distance); returns the radius POV-Ray reports:
    // the farthest kept photon's distance when more than k were in reach, else `radius`.
    double nearest(const Point3& p, const Vector3* n, double radius,
                   std::vector<const Photon*>& out) const;
    void build_tree(size_t lo, size_t hi);
    // POV-Ray's setGatherOptions: `radius` and `multiplier` as the settings give them
    // (the surface's or the media's); a media map counts density per volume.
    void estimate_gather_radius(double radius, double multiplier, bool media);

    PhotonSettings settings_;
    std::vector<Photon> photons_;  // a balanced kd-tree: each range's middle is its node
    double min_radius_ = 0, radius_step_ = 0;
    std::shared_ptr<PhotonMap> media_;
};

// The map for `scene` when its scene has photons and the quality level renders them
// (+Q9); null otherwise. (The parser refuses what the map does not do yet: media
// photons, parallel and cylinder lights.)
std::shared_ptr<const PhotonMap> build_photon_map(const PreparedScene& scene);

// Whether `leaf` (hit by a shadow ray toward `light`) makes caustics with photons: a
// target whose photon refraction is on for that light (POV-Ray 3.7's
// ComputeShadowColour: its filtered shadow is black, the photons bring the light).
bool refracts_photons(const ObjectPhotons& leaf, const Light& light);

}  // namespace povwall::trace
