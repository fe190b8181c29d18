#include "trace/radiosity/gatherer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/hash_fold.h"
#include "trace/tracer.h"

namespace povwall::trace::radiosity {

RadiosityFrame::RadiosityFrame(const RadiositySettings& s, const Point3& camera_,
                               int max_trace_level_)
    : settings(s),
      recursion(recursion_settings(s)),
      directions(size_t(std::max(1, s.direction_pool))),
      camera(camera_),
      max_trace_level(max_trace_level_) {}

std::vector<double> RadiosityFrame::address_factors() const {
    std::vector<double> f;
    for (const RecursionSettings& r : recursion)
        f.push_back(r.max_error_bound / r.overfill_factor);
    return f;
}

}  // namespace povwall::trace::radiosity

namespace povwall::trace {
namespace {

using namespace radiosity;

// POV-Ray's constants of ComputeAmbient and GatherLight.
constexpr double kWeightErrorBoundOffset = 0.25;  // low weights loosen the error bound
constexpr double kPovEpsilonWeight = 1e-10;

// Where in the direction pool a render block's first gather of a depth starts: a hash
// of its point. The block's later gathers of that depth continue the sequence, as
// POV-Ray's do (one sequence per thread and depth), so neighbouring gathers use
// consecutive runs of the low-discrepancy pool, which complement each other where the
// cache averages them; ours restarts per block, so a pixel depends on its block only.
size_t pool_start(const Point3& P, int depth, size_t pool) {
    uint64_t h = 0x2545f4914f6cdd1dull * uint64_t(depth + 1);
    for (double v : {P.x, P.y, P.z}) h = hash_fold(h, v);
    return size_t(h % pool);
}

// The sample directions of one gather about `normal` (the pool's +y), skipping those
// behind the raw normal when the normal is perturbed (POV-Ray's
// SampleDirectionGenerator: at most 5 x count tries, then the raw normal).
class DirectionRun {
  public:
    DirectionRun(const SampleDirections& pool, size_t start, const Vector3& normal,
                 const Vector3& raw_normal, bool raw_mode, size_t tries)
        : pool_(&pool),
          next_(start),
          left_(tries),
          raw_(raw_normal),
          raw_mode_(raw_mode) {
        y_ = normal;
        const Vector3 off = std::fabs(y_.z) > 0.9 ? Vector3{0, 1, 0} : Vector3{0, 0, 1};
        x_ = normalize(cross(y_, off));
        z_ = normalize(cross(x_, y_));
    }
    size_t position() const { return next_; }
    bool next(Vector3& dir) {
        while (left_ > 0) {
            --left_;
            const Vector3& v = (*pool_)[next_++];
            dir = x_ * v.x + y_ * v.y + z_ * v.z;
            if (raw_mode_ || dot(dir, raw_) > 0) return true;
        }
        return false;
    }

  private:
    const SampleDirections* pool_;
    size_t next_, left_;
    Vector3 raw_, x_, y_, z_;
    bool raw_mode_;
};

bool similar(const Vector3& a, const Vector3& b) {
    return std::fabs(a.x - b.x) < 1e-10 && std::fabs(a.y - b.y) < 1e-10 &&
           std::fabs(a.z - b.z) < 1e-10;
}

}  // namespace

RadiosityGatherer::RadiosityGatherer(Tracer& tracer, const RadiosityFrame& frame,
                                     const IrradianceCache* cache, int pass)
    : tracer_(tracer),
      frame_(frame),
      cache_(cache),
      final_block_(frame.address_factors()),
      pass_(pass),
      error_bound_(frame.settings.error_bound) {
    if (pass != kFinalPass) error_bound_ *= frame.settings.low_error_factor;
    const size_t depths = size_t(std::max(1, frame.settings.recursion_limit)) + 1;
    next_direction_.assign(depths, 0);
    direction_fresh_.assign(depths, 1);
}

Rgb RadiosityGatherer::ambient(const TraceRay& ray, const Point3& P,
                               const Vector3& raw_normal, const Vector3& layer_normal,
                               double weight) {
    const RadiositySettings& s = frame_.settings;
    const int depth = ray.radiosity_depth;
    const RecursionSettings& rs = frame_.recursion[size_t(depth)];
    const Vector3 normal = s.normal ? layer_normal : raw_normal;
    double bound = error_bound_;
    if (weight < kWeightErrorBoundOffset) bound += kWeightErrorBoundOffset - weight;
    bound *= rs.error_bound_factor;
    const bool final_pass = pass_ == kFinalPass;
    Reuse found;
    if (cache_)
        cache_->accumulate(P, normal, bound, depth, final_pass && depth == 0, found);
    if (block_)
        block_->accumulate(P, normal, bound, depth, final_pass && depth == 0, found);
    double reuse = found.weights;
    Rgb amb = reuse > 0 ? found.weighted_sum * float(1 / reuse) : Rgb{};
    const bool enough =
        reuse * 4 >= rs.reuse_count || (final_pass && !s.always_sample && reuse > 0);
    if (!enough) {
        Rgb gathered;
        const double q = gather(ray, P, raw_normal, normal, gathered);
        amb = reuse > 0
                  ? (amb * float(reuse) + gathered * float(q)) * float(1 / (reuse + q))
                  : gathered;
        reuse += q;
    }
    quality_ = std::min(4 * reuse / rs.reuse_count, quality_);
    amb = amb * float(1 - s.gray_threshold) + Rgb(float(s.gray_threshold) * amb.grey());
    return amb * float(s.brightness);
}

double RadiosityGatherer::gather(const TraceRay& ray, const Point3& P,
                                 const Vector3& raw_normal, const Vector3& normal,
                                 Rgb& illuminance) {
    ++gathers_;
    const RadiositySettings& s = frame_.settings;
    const int depth = ray.radiosity_depth;
    const RecursionSettings& rs = frame_.recursion[size_t(depth)];
    const double to_eye = length(frame_.camera - P);
    const double reuse_min = to_eye * rs.min_reuse_factor;
    const double max_distance = to_eye * rs.max_reuse_factor;
    const size_t pool = frame_.directions.size();
    const size_t count = std::min(size_t(rs.rays_per_sample), pool);

    // The sample rays start a new ray tree: POV-Ray's trace level and weight for this
    // bounce, the radiosity adc_bailout, no interiors.
    TraceRay sample;
    sample.use = RayUse::Radiosity;
    sample.radiosity_depth = uint8_t(depth + 1);
    sample.depth = rs.trace_level + 1;
    const int max_level = ray.max_level > 0 ? ray.max_level : frame_.max_trace_level;
    sample.max_level = std::max(max_level, rs.trace_level + 1);
    sample.adc_bailout = float(s.adc_bailout);
    sample.weight = float(std::max(double(s.adc_bailout) + kPovEpsilonWeight, rs.weight));

    const double saved_quality = quality_;
    bool raw_mode = similar(raw_normal, normal);
    // By index: the sample rays' own gathers (one depth down) run in between.
    const size_t d = size_t(depth);
    if (direction_fresh_[d]) {
        next_direction_[d] = pool_start(P, depth, pool);
        direction_fresh_[d] = 0;
    }
    DirectionRun run(frame_.directions, next_direction_[d],
                     raw_mode ? raw_normal : normal, raw_normal, raw_mode,
                     raw_mode ? pool : std::min(count * 5, pool));
    Rgb sum;
    double quality_sum = 0, inverse_distance_sum = 0;
    double smallest = kInfinity;
    Vector3 to_nearest{0, 1, 0};
    size_t ok = 0, ok_raw = 0;
    for (size_t i = 0; i < count; ++i) {
        Vector3 dir;
        bool got = run.next(dir);
        if (!got && !raw_mode) {
            raw_mode = true;
            run = DirectionRun(frame_.directions, run.position(), raw_normal, raw_normal,
                               true, pool);
            got = run.next(dir);
        }
        if (!got) break;
        ++ok;
        if (raw_mode) ++ok_raw;
        quality_ = 1;
        sample.ray = {P, dir};
        const float queried = count > 1 ? float(i) / float(count - 1) : 0.0f;
        Real hit_depth = kInfinity;
        float importance = 1;
        Rgb colour =
            tracer_.trace_radiosity_sample(sample, queried, hit_depth, importance);
        if (importance >= queried) {
            double q = quality_;
            if (importance < 1) {
                const double last = std::floor(double(importance) * double(count - 1));
                q *= double(count) / (last + 1);
            }
            const float brightest = std::max({colour.r, colour.g, colour.b});
            if (s.max_sample > 0 && brightest > s.max_sample)
                colour *= float(s.max_sample / brightest);
            quality_sum += q;
            sum += colour * float(q);
        }
        if (hit_depth < smallest) {
            smallest = hit_depth;
            to_nearest = dir;
        }
        inverse_distance_sum += 1 / hit_depth;
    }
    next_direction_[d] = run.position() % pool;
    illuminance = quality_sum == 0 ? sum : sum * float(1 / quality_sum);
    const double quality = ok > 0 ? quality_sum / double(ok) : 0;
    quality_ = std::max(saved_quality, quality);
    double mean = double(ok) / inverse_distance_sum;
    // A gather almost on top of another surface is not kept (its rays may be flawed).
    if (block_ && smallest > max_distance * 0.0001) {
        if (mean < reuse_min) mean = reuse_min;
        if (mean > max_distance) mean = max_distance;
        CacheEntry e;
        e.point = P;
        e.normal = ok_raw > ok - ok_raw ? raw_normal : normal;
        e.to_nearest = to_nearest;
        e.illuminance = illuminance;
        e.harmonic_mean = float(mean);
        e.nearest = float(smallest);
        e.quality = float(quality);
        e.depth = uint8_t(depth);
        e.pass = uint8_t(pass_);
        block_->insert(e);
    }
    return quality;
}

}  // namespace povwall::trace
