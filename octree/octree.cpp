#include "octree/octree.h"

namespace povwall::octree {

void Octree::build(const BuildInput& input, const BuildOptions& options) {
    bounds_ = Bounds3{};
    all_ids_.clear();
    for (uint32_t i = 0; i < input.bounds.size(); ++i) {
        bounds_.extend(input.bounds[i]);
        all_ids_.push_back(i);
    }
    primitive_count_ = input.bounds.size();
    stats_ = BuildStats{1, 1, 0, primitive_count_, 0};
}

}  // namespace povwall::octree
