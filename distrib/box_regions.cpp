// Where the black boxes are and what each holds: the walls, each box's local scene and
// reach, the route of a ray through the boxes, and the photon map every box reads
// (BoxHost's layout; distrib/box_host.h).
#include <algorithm>
#include <cmath>

#include "distrib/box_host.h"
#include "distrib/object_boxes.h"
#include "trace/photon_map.h"

namespace povwall::distrib {

// Whether the ray's segment in box `s.box` can meet the box's reach. Skipping a box
// where it cannot is exact: a hit point lies in its object's bounds and in the region of
// the box that finds it, so in that box's reach.
bool BoxHost::reaches(const Ray& ray, const VirtualWalls::Segment& s) const {
    const Bounds3& b = reach_[size_t(s.box)];
    // The segment's own bounds against the reach: no division, and enough (a segment
    // whose bounds miss the reach misses it).
    for (int a = 0; a < 3; ++a) {
        const Real o = ray.origin[a], d = ray.direction[a];
        const Real p0 = o + d * s.t_enter;
        const Real p1 = std::isinf(s.t_exit) ? (d > 0   ? kInfinity
                                                : d < 0 ? -kInfinity
                                                        : o)
                                             : o + d * s.t_exit;
        if (std::max(p0, p1) < b.lo[a] || std::min(p0, p1) > b.hi[a]) return false;
    }
    return true;
}

void BoxHost::classify_boxes() {
    visit_.assign(reach_.size(), BoxVisit::Never);
    for (size_t b = 0; b < reach_.size(); ++b) {
        if (reach_[b].empty()) continue;
        visit_[b] = b < boxes_.size() && boxes_[b]->scene ? BoxVisit::Always
                                                          : BoxVisit::IfReached;
    }
}

// The first box along the ray from t_from whose reach the ray meets (the boxes before
// it cannot stop or shade the ray, so it skips them without a message), or the box it
// starts in when it meets none, with `at` at its segment; -1 for a ray that visits
// nothing (NaN).
int BoxHost::enter(const Ray& ray, Real t_from, VirtualWalls::WalkState& at) const {
    if (!walls_.start_walk(ray, t_from, kInfinity, at)) return -1;
    const bool one_box = reach_.size() == 1;  // nowhere else to go
    int box = -1, first = -1;
    walls_.continue_walk(ray, at, kInfinity, [&](const VirtualWalls::Segment& s) {
        if (first < 0) first = s.box;
        if (!one_box && !visits(ray, s)) return false;
        box = s.box;
        return true;
    });
    if (box >= 0 || first < 0) return box;
    // Nothing ahead: the starting box finds the miss. (The walk starts again rather
    // than from a copy of its start, which stalled every call on store forwarding.)
    walls_.start_walk(ray, t_from, kInfinity, at);
    walls_.continue_walk(ray, at, kInfinity,
                         [](const VirtualWalls::Segment&) { return true; });
    return first;
}

// From `at` (the start of a box's segment): that segment, extended over the segments
// after it that meet no reach, and the next box whose reach the ray meets (-1: none, and
// the segment reaches infinity); `at` moves to that box's segment.
void BoxHost::route(const Ray& ray, VirtualWalls::WalkState& at,
                    VirtualWalls::Segment& seg, int& next) const {
    bool first = true;
    next = -1;
    walls_.continue_walk(ray, at, kInfinity, [&](const VirtualWalls::Segment& s) {
        if (first) {
            // Field by field: a copy of the whole struct was one 16-byte load of what
            // the walk had just stored in pieces, a store-forwarding stall that was a
            // third of route()'s time.
            seg.box = s.box;
            seg.t_enter = s.t_enter;
            seg.t_exit = s.t_exit;
            first = false;
            return false;
        }
        if (!visits(ray, s)) {
            seg.t_exit = s.t_exit;  // nothing to meet there: the current box goes on
            return false;
        }
        next = s.box;
        return true;
    });
    if (next < 0) seg.t_exit = kInfinity;
}

int BoxHost::first_box(const Ray& ray, Real t_from, VirtualWalls::Segment& seg, int& next,
                       VirtualWalls::WalkState& at) const {
    const int box = enter(ray, t_from, at);
    if (box < 0) {  // NaN ray: stays where it is and misses
        seg = {0, t_from, kInfinity};
        next = -1;
        return 0;
    }
    route(ray, at, seg, next);
    return seg.box;
}

namespace {
std::vector<Bounds3> all_object_bounds(const Scene& scene) {
    std::vector<Bounds3> bounds;
    for (const Object& o : scene.objects) bounds.push_back(trace::object_world_bounds(o));
    return bounds;
}
}  // namespace

void BoxHost::place_walls() {
    Bounds3 world;
    std::vector<Bounds3> finite;
    for (const Bounds3& b : all_object_bounds(scene_)) {
        if (b.infinite()) continue;
        world.extend(b);
        finite.push_back(b);
    }
    const auto& n = options_.boxes;
    walls_ = options_.balanced ? VirtualWalls::balanced(finite, n[0], n[1], n[2])
                               : VirtualWalls::uniform(world, n[0], n[1], n[2]);
}

void BoxHost::build_boxes(const std::vector<int>& hosted) {
    const int count = walls_.box_count();
    std::vector<uint8_t> host(count, 0);
    for (int b : hosted) host[b] = 1;
    std::vector<std::vector<uint32_t>> local(count);
    // Reach: where a box's objects can be hit (a plane: its surface), within the box's
    // region, padded by a millionth of the coordinates' size (hit points computed in a
    // box stray from its region and from their objects' bounds by rounding only).
    reach_.assign(count, Bounds3{});
    // A box holding an object whose surface can lie outside its POV-Ray box holds the
    // objects between the two as well (walk_reaches); its reach stays its own objects'.
    const std::vector<WalkReach> walk = walk_reaches(walls_, scene_);
    for (uint32_t i = 0; i < scene_.objects.size(); ++i) {
        const Bounds3 hit = trace::object_hit_bounds(scene_.objects[i]);
        std::vector<int> boxes = boxes_of_object(walls_, scene_.objects[i]);
        for (int b : boxes) reach_[b].extend(hit);
        for (int b : boxes_holding(std::move(boxes), scene_.objects[i], walk))
            if (host[b]) local[b].push_back(i);
    }
    for (int b = 0; b < count; ++b) {
        Bounds3& r = reach_[b];
        const Bounds3 region = walls_.box_bounds(b);
        for (int a = 0; a < 3; ++a) {
            auto pad = [](Real v) {
                return std::isinf(v) ? 0 : 1e-6 * (1 + std::fabs(v));
            };
            r.lo[a] = std::max(r.lo[a], region.lo[a]);
            r.hi[a] = std::min(r.hi[a], region.hi[a]);
            r.lo[a] -= pad(r.lo[a]);
            r.hi[a] += pad(r.hi[a]);
        }
    }
    boxes_.clear();
    for (int b = 0; b < count; ++b) {
        auto box = std::make_unique<Box>(options_.queue);
        box->index = b;
        box->next_id = (uint64_t(b) + 1) << 40;
        box->stats.region = walls_.box_bounds(b);
        if (host[b]) {
            trace::PrepareOptions prepare;
            prepare.threads = settings_.threads;
            prepare.whole_scene = whole_scene_;
            box->scene =
                std::make_unique<trace::PreparedScene>(scene_, local[b], &plan_, prepare);
            box->scene->set_alpha_background(settings_.alpha);
            box->stats.objects = local[b].size();
            box->stats.resident_bytes = box->scene->resident_bytes();
            if (box->scene->primitive_count() == 0) reach_[b] = Bounds3{};
        }
        boxes_.push_back(std::move(box));
    }
    classify_boxes();
}

void BoxHost::build_photon_map() {
    photons_ = nullptr;
    if (scene_.settings.photons && plan_.quality.atmosphere()) {
        // As render_scene prepares the scene for its pass (same plan, same options): the
        // same hits, so the same photons.
        trace::PrepareOptions prepare;
        prepare.threads = settings_.threads;
        trace::PreparedScene whole(scene_, &plan_, prepare);
        whole.set_alpha_background(settings_.alpha);
        photons_ = trace::build_photon_map(whole);
    }
    set_photon_map(photons_);
}

void BoxHost::set_photon_map(std::shared_ptr<const trace::PhotonMap> map) {
    photons_ = std::move(map);
    for (auto& box : boxes_)
        if (box->scene) box->scene->set_photons(photons_);
}

}  // namespace povwall::distrib
