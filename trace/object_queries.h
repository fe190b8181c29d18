// The renderer's answers to the scene language's questions about objects while parsing
// (trace(), inside(), min_extent(), max_extent(); core/object_queries.h).
#pragma once

#include <memory>

#include "core/object_queries.h"

namespace povwall::trace {

// One per parse (ParseOptions::object_queries). trace() prepares the object as a scene
// of its own the first time it is asked about it and keeps the few most recent ones, as
// scenes call trace() in loops on the same object (scattering trees on a height field).
std::shared_ptr<ObjectQueries> parse_time_object_queries();

}  // namespace povwall::trace
