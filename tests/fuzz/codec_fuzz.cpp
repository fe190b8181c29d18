// libFuzzer target: every decoder that reads bytes from another process (distrib/wire/).
// The input is a stream of frames as a connection receives it: each complete frame is
// decoded as its type says (item records against a small scene's objects, pixel sums,
// camera sample positions, photon records and the photons message that closes them,
// control JSON with the plan and reach parts). Nothing may crash
// or read out of bounds; item records that are accepted must write back to records that
// read the same again.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <span>
#include <string>
#include <vector>

#include "distrib/wire/control.h"
#include "distrib/wire/frame.h"
#include "distrib/wire/items.h"
#include "distrib/wire/job.h"
#include "distrib/wire/messages.h"
#include "distrib/wire/photons.h"
#include "distrib/wire/pixels.h"
#include "distrib/wire/samples.h"
#include "parser/parser.h"

using namespace povwall;
using namespace povwall::distrib;

namespace {

const ObjectNumbers& numbers() {
    static const Scene scene = parser::parse_scene_text(
        "light_source { <5,5,-5>, 1 }\n"
        "sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.5 } }\n"
        "union { box { -1, 1 } sphere { 2, 1 } pigment { rgbf 0.9 } }\n",
        "fuzz.pov", {});
    static const ObjectNumbers n(scene);
    return n;
}

constexpr ItemLimits kLimits{8, 1, 4096};

void items(const Frame& f) {
    std::vector<uint8_t> again;
    ItemReader rd(f.body, f.count, kLimits, numbers());
    uint32_t read = 0;
    while (!rd.done()) {
        Item item;
        int box;
        size_t bytes = 0;
        if (!rd.read(box, item, bytes)) break;
        if (box < 0 || box >= kLimits.boxes || bytes == 0) std::abort();
        write_item(again, box, item, numbers());
        ++read;
    }
    // What was read writes back to records that read back to the same bytes.
    std::vector<uint8_t> twice;
    ItemReader second(again, read, kLimits, numbers());
    while (!second.done()) {
        Item item;
        int box;
        size_t bytes = 0;
        if (!second.read(box, item, bytes)) std::abort();
        write_item(twice, box, item, numbers());
    }
    if (second.bad() || twice != again) std::abort();
}

// A control message of type M that reads is written back as a message that reads the
// same.
template <class M>
void read_and_write_back(const nlohmann::json& j) {
    if (control_type(j) != M::kType) return;
    try {
        const nlohmann::json again = message_json(read_message<M>(j));
        if (message_json(read_message<M>(again)) != again) std::abort();
    } catch (const nlohmann::json::exception&) {
    }
}

void control(const Frame& f, std::vector<trace::Photon>& photons) {
    const nlohmann::json j = parse_control(f);
    if (j.is_discarded() || !j.is_object()) return;
    if (j.value("type", nlohmann::json()) == "photons") {
        std::shared_ptr<const trace::PhotonMap> map;
        (void)photon_map_from_message(j, std::move(photons), map);
        photons.clear();
    }
    if (j.contains("plan")) {
        try {
            (void)plan_from_json(j["plan"]);
        } catch (const nlohmann::json::exception&) {
        }
    }
    // The job and control messages: a malformed one throws a JSON error naming its field;
    // one that reads writes back to the same message.
    const nlohmann::json type = j.value("type", nlohmann::json());
    try {
        if (type == "job") (void)worker_job_from_json(j);
        if (type == "frame") (void)frame_job_from_json(j);
    } catch (const nlohmann::json::exception&) {
    }
    read_and_write_back<BusyMessage>(j);
    read_and_write_back<ReadyMessage>(j);
    read_and_write_back<SamplesSentMessage>(j);
    read_and_write_back<SamplesTakenMessage>(j);
    read_and_write_back<StartMessage>(j);
    read_and_write_back<PixelRangeMessage>(j);
    read_and_write_back<ProbeMessage>(j);
    read_and_write_back<FinishMessage>(j);
    read_and_write_back<StatusMessage>(j);
    read_and_write_back<DoneMessage>(j);
    read_and_write_back<ErrorMessage>(j);
    read_and_write_back<RegisterMessage>(j);
    if (j.contains("reach")) {
        std::vector<Bounds3> reach;
        (void)reach_from_json(j["reach"], 4, reach);
    }
}

// Seeds from the real encoder: frames of items (rays with and without their optional
// parts, results), pixel sums and control messages.
void write_seeds(const std::string& dir) {
    std::vector<std::vector<uint8_t>> seeds;
    std::vector<uint8_t> records;
    Item ray;
    ray.ray.trace.ray.direction = {0, 0, 1};
    ray.ray.pixel = 17;
    write_item(records, 1, ray, numbers());
    Item shadow = ray;
    shadow.ray.shadow = true;
    shadow.ray.shadow_state.light = 0;
    shadow.ray.light_distance = 4;
    shadow.ray.parent = 99, shadow.ray.parent_box = 2, shadow.ray.slot = 3;
    shadow.ray.transmit_contribution = 0.5f;
    shadow.ray.trace.interiors.size = 1;
    shadow.ray.trace.interiors.items[0] = numbers().material(0);
    write_item(records, 2, shadow, numbers());
    Item result;
    result.is_result = true;
    result.result.parent = 99, result.result.slot = 3;
    write_item(records, 3, result, numbers());
    seeds.emplace_back();
    encode_frame(FrameType::Items, 3, records, seeds.back());
    std::vector<uint8_t> sums;
    const double v[4] = {0.5, 0.25, 1, 1};
    write_pixel_sum(sums, 7, v, 4);
    seeds.emplace_back();
    encode_frame(FrameType::Pixels, 1, sums, seeds.back());
    std::vector<uint8_t> positions;
    write_sample_position(positions, {3.25, -0.5});
    write_sample_position(positions, {0, 7});
    seeds.emplace_back();
    encode_frame(FrameType::Samples, 2, positions, seeds.back());
    trace::RenderPlan plan;
    plan.lights.push_back({});
    seeds.push_back(*control_frame({{"type", "frame"}, {"plan", plan_to_json(plan)}}));
    WorkerJob job;
    job.fixed.scene = "sphere { 0, 1 }";
    job.fixed.width = job.fixed.height = 8;
    job.frame.plan = plan;
    job.frame.expected_objects = {1};
    job.workers = {"127.0.0.1:1"};
    seeds.push_back(*control_frame(to_json(job)));
    seeds.push_back(*control_frame(
        {{"type", "start"}, {"reach", reach_to_json(std::vector<Bounds3>(4))}}));
    // No map, then the frames of a real map (photons through a glass sphere).
    for (const Buffer& b : photon_map_frames(nullptr)) seeds.push_back(*b);
    std::vector<trace::Photon> surface(3), media(1);
    for (size_t i = 0; i < surface.size(); ++i)
        surface[i] = {
            {0.5f * float(i), -2, 1}, {200, 17, 3, 248}, -5, 127, uint8_t(i % 3)};
    media[0] = {{4, 5, 6}, {1, 2, 3, 251}, 0, -127, 2};
    PhotonSettings settings;
    const auto map = trace::PhotonMap::assemble(
        settings, surface, 0.25, 0.5,
        trace::PhotonMap::assemble(settings, media, 0.5, 1, nullptr));
    seeds.emplace_back();
    for (const Buffer& b : photon_map_frames(map.get()))
        seeds.back().insert(seeds.back().end(), b->begin(), b->end());
    for (size_t i = 0; i < seeds.size(); ++i) {
        std::ofstream(dir + "/seed-" + std::to_string(i), std::ios::binary)
            .write(reinterpret_cast<const char*>(seeds[i].data()),
                   std::streamsize(seeds[i].size()));
    }
}

}  // namespace

// POVWALL_FUZZ_WRITE_SEEDS=DIR: writes the seed frames to DIR first (scripts/fuzz).
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    if (const char* dir = std::getenv("POVWALL_FUZZ_WRITE_SEEDS")) write_seeds(dir);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::span<const uint8_t> bytes(data, size);
    std::vector<trace::Photon> photons;  // the Photons frames' records so far
    while (!bytes.empty()) {
        Frame frame;
        // Without the CRC: a peer can send any body under a valid one.
        if (decode_frame(bytes, frame, CrcCheck::Off) != DecodeStatus::Complete) break;
        if (frame.consumed == 0 || frame.consumed > bytes.size()) std::abort();
        switch (frame.type) {
            case FrameType::Items:
                items(frame);
                break;
            case FrameType::Pixels: {
                double total = 0;
                (void)read_pixel_sums(frame.body, frame.count, 4, 4096,
                                      [&](uint32_t, const double* v) { total += v[0]; });
                (void)read_pixel_sums(frame.body, frame.count, 3, 4096,
                                      [&](uint32_t, const double* v) { total += v[2]; });
                break;
            }
            case FrameType::Samples: {
                std::vector<trace::SamplePosition> positions;
                if (read_sample_positions(frame.body, frame.count, 64, positions) &&
                    positions.size() != frame.count)
                    std::abort();
                if (!positions.empty() && std::abs(positions.back().x) > 64) std::abort();
                break;
            }
            case FrameType::Photons: {
                const size_t before = photons.size();
                if (!read_photons(frame.body, frame.count, photons) &&
                    photons.size() != before)
                    std::abort();  // a refused frame adds nothing
                if (photons.size() > (size_t(1) << 20)) photons.clear();
                break;
            }
            case FrameType::Control:
                control(frame, photons);
                break;
        }
        bytes = bytes.subspan(frame.consumed);
    }
    return 0;
}
