#include "trace/object_queries.h"

#include <algorithm>
#include <deque>
#include <limits>
#include <mutex>

#include "trace/pov_bounds.h"
#include "trace/prepared_scene.h"
#include "trace/render_plan.h"

namespace povwall::trace {

namespace {

class ShapeQueries final : public ObjectQueries {
  public:
    std::optional<Hit> trace(const std::shared_ptr<Object>& object, const Point3& origin,
                             const Vector3& direction) override {
        std::lock_guard lock(mutex_);
        Prepared& p = prepared(object);
        const Ray ray{origin, direction};
        trace::Hit hit;
        // Find_Intersection tests no flag of the object itself; its CSG nodes test their
        // children's as for a camera ray (trace() makes a primary ray).
        if (!p.prepared->closest_hit(ray, 0, kInfinity, RayUse::Query, hit, p.context))
            return std::nullopt;
        return Hit{hit.point, hit.normal};
    }
    bool inside(const std::shared_ptr<Object>& object, const Point3& p) override {
        return inside_object(*object, p);
    }
    Csg::PovBox box(const Object& object) override {
        const PovBBox b = pov_object_bbox(object);
        Csg::PovBox r;
        for (int a = 0; a < 3; ++a) {
            r.lo[a] = b.lo[a];
            r.len[a] = b.len[a];
        }
        return r;
    }

  private:
    struct Prepared {
        std::shared_ptr<Object> object;  // held: its address names it
        Scene scene;
        std::unique_ptr<PreparedScene> prepared;
        RayContext context;
        bool flat = true;  // a flat list of its primitives, no octree yet
    };
    static constexpr size_t kKept = 4;

    // An object is first prepared as a flat list: scenes that grow an object in a loop
    // trace each version once (a union nested N deep, traced at every step), where an
    // octree built per call cost O(N log N) a step against POV-Ray's walk of its boxes.
    // Traced again, it gets its octree.
    void prepare(Prepared& p, bool flat) {
        RenderPlan plan = make_render_plan(p.scene);
        if (flat) plan.flat_threshold = std::numeric_limits<int>::max();
        p.prepared = std::make_unique<PreparedScene>(p.scene, &plan);
        p.context = RayContext{};
        p.prepared->init_context(p.context);
        p.flat = flat;
    }

    Prepared& prepared(const std::shared_ptr<Object>& object) {
        auto found = std::find_if(cache_.begin(), cache_.end(),
                                  [&](const auto& p) { return p->object == object; });
        if (found != cache_.end()) {
            std::rotate(cache_.begin(), found, found + 1);  // most recent first
            Prepared& p = *cache_.front();
            if (p.flat) prepare(p, false);
            return p;
        }
        auto p = std::make_unique<Prepared>();
        p->object = object;
        p->scene.objects.push_back(*object);
        prepare(*p, true);
        cache_.push_front(std::move(p));
        if (cache_.size() > kKept) cache_.pop_back();
        return *cache_.front();
    }

    std::mutex mutex_;
    std::deque<std::unique_ptr<Prepared>> cache_;
};

}  // namespace

std::shared_ptr<ObjectQueries> parse_time_object_queries() {
    return std::make_shared<ShapeQueries>();
}

}  // namespace povwall::trace
