#include "trace/light_masks.h"

#include <atomic>

#include "trace/prepared_scene.h"

namespace povwall::trace {

struct LightMasks::Mask {
    Scene scene;  // the object alone, with the scene's settings (patterns, noise)
    std::unique_ptr<PreparedScene> prepared;
};

namespace {

std::atomic<uint64_t> g_next_masks_id{1};

// Each thread's ray contexts for the masks of one LightMasks (the last one it used).
struct MaskContexts {
    uint64_t owner = 0;
    std::vector<RayContext> contexts;
};
thread_local MaskContexts t_mask_contexts;

}  // namespace

LightMasks::LightMasks(const Scene& scene) : id_(g_next_masks_id++) {
    per_light_.resize(scene.lights.size());
    for (size_t l = 0; l < scene.lights.size(); ++l) {
        const Light& light = scene.lights[l];
        if (!light.projected_through) continue;
        auto mask = std::make_unique<Mask>();
        mask->scene.settings = scene.settings;
        mask->scene.objects.push_back(*light.projected_through);
        mask->prepared = std::make_unique<PreparedScene>(mask->scene);
        per_light_[l] = std::move(mask);
        ++lights_with_masks_;
    }
}

LightMasks::~LightMasks() = default;

bool LightMasks::reaches(size_t light, const Point3& at, const Vector3& to_light,
                         Real distance, Real& blockers_end) const {
    blockers_end = distance;
    const Mask* mask = light < per_light_.size() ? per_light_[light].get() : nullptr;
    if (!mask) return true;
    MaskContexts& mine = t_mask_contexts;
    if (mine.owner != id_) {
        mine.owner = id_;
        mine.contexts.assign(per_light_.size(), RayContext{});
        for (size_t l = 0; l < per_light_.size(); ++l)
            if (per_light_[l]) per_light_[l]->prepared->init_context(mine.contexts[l]);
    }
    Hit hit;
    // A query as trace() makes: the object's own flags are not tested.
    if (!mask->prepared->closest_hit({at, to_light}, 0, kInfinity, RayUse::Query, hit,
                                     mine.contexts[light]))
        return false;
    if (!(hit.t < distance)) return false;
    blockers_end = hit.t;
    return true;
}

}  // namespace povwall::trace
