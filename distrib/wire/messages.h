// The control messages between a coordinator, its workers and the rendezvous, as types.
// Each lists its fields once (fields(), distrib/wire/job_fields.h) beside its "type";
// message_frame() writes one, read_message() reads one back and refuses what no writer
// makes (a missing or mistyped field, counts that do not pair up, a negative range), so
// the coordinator and the workers never read a message by string keys. The order in
// which they travel is in distrib/wire/control.h; the job and frame messages are
// distrib/wire/job.h's, the photon map's distrib/wire/photons.h's.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "distrib/space_render.h"
#include "distrib/wire/control.h"
#include "distrib/wire/job_fields.h"

namespace povwall::distrib {

// worker -> coordinator, every second while it parses and builds its boxes.
struct BusyMessage {
    static constexpr const char* kType = "busy";
    template <class Self, class Visit>
    static void fields(Self&, Visit&&) {}
};

// worker -> coordinator: its boxes are built; the primitives each holds (boxes[k] holds
// primitives[k]) and the scene's objects it kept and left out while parsing.
struct ReadyMessage {
    static constexpr const char* kType = "ready";
    std::vector<int> boxes;
    std::vector<uint64_t> primitives;
    uint64_t objects_kept = 0, objects_left_out = 0;
    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("boxes", s.boxes);
        v("primitives", s.primitives);
        v("objects_kept", s.objects_kept);
        v("objects_left_out", s.objects_left_out);
    }
};

// coordinator -> worker: the Samples frames before it hold `count` camera samples.
struct SamplesSentMessage {
    static constexpr const char* kType = "samples";
    uint64_t count = 0;
    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("count", s.count);
    }
};

// worker -> coordinator: it holds the wave's samples.
struct SamplesTakenMessage {
    static constexpr const char* kType = "samples";
    template <class Self, class Visit>
    static void fields(Self&, Visit&&) {}
};

// coordinator -> worker: a run starts (a frame's first, or an anti-aliasing wave's); each
// box's reach as six bit patterns (reach_to_json), so every process routes with the same
// doubles.
struct StartMessage {
    static constexpr const char* kType = "start";
    nlohmann::json reach;
    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("reach", s.reach);
    }
};

// coordinator -> worker: make the camera rays of pixel slots [begin, end).
struct PixelRangeMessage {
    static constexpr const char* kType = "pixels";
    int64_t begin = 0, end = 0;
    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("begin", s.begin);
        v("end", s.end);
    }
};

// coordinator -> worker: answer with a status carrying `seq` (a termination wave).
struct ProbeMessage {
    static constexpr const char* kType = "probe";
    int64_t seq = 0;
    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("seq", s.seq);
    }
};

// coordinator -> worker: the run is over; send the pixel sums and "done".
struct FinishMessage {
    static constexpr const char* kType = "finish";
    template <class Self, class Visit>
    static void fields(Self&, Visit&&) {}
};

// worker -> coordinator every 10 ms while tracing (and as a probe's answer, `seq` >= 0;
// else -1): items created and finished, camera rays made, items sent to each worker.
struct StatusMessage {
    static constexpr const char* kType = "status";
    int64_t seq = -1;
    uint64_t created = 0, finished = 0, pixels = 0;
    std::vector<uint64_t> sent;
    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("seq", s.seq);
        v("created", s.created);
        v("finished", s.finished);
        v("pixels", s.pixels);
        v("sent", s.sent);
    }
};

// One hosted box's statistics in a "done" message, named by the box's index.
struct BoxReport {
    int box = -1;
    BoxStats stats;
};
void to_json(nlohmann::json& j, const BoxReport& report);
void from_json(const nlohmann::json& j, BoxReport& report);

// worker -> coordinator after its pixel sums: the run's statistics of each hosted box and
// the process's peak resident memory.
struct DoneMessage {
    static constexpr const char* kType = "done";
    std::vector<BoxReport> boxes;
    uint64_t peak_resident = 0;
    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("boxes", s.boxes);
        v("peak_resident", s.peak_resident);
    }
};

// worker -> coordinator: the job failed here. `culprit` names another worker that caused
// it (one this worker could not reach, or one that sent it a malformed item frame); -1
// when the fault is this worker's own (a scene error: no recovery).
struct ErrorMessage {
    static constexpr const char* kType = "error";
    std::string message;
    int64_t culprit = -1;
    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("message", s.message);
        v("culprit", s.culprit);
    }
};

// launcher worker -> rendezvous: rank `rank` of `size` listens at `address`.
struct RegisterMessage {
    static constexpr const char* kType = "register";
    std::string token;
    int64_t rank = 0, size = 0;
    std::string address;
    template <class Self, class Visit>
    static void fields(Self& s, Visit&& v) {
        v("token", s.token);
        v("rank", s.rank);
        v("size", s.size);
        v("address", s.address);
    }
};

// Throws nlohmann::json::exception (naming the field) where a message's values are
// inconsistent in a way no writer makes them; nothing for the others.
void check_message(const ReadyMessage& m);
void check_message(const PixelRangeMessage& m);
void check_message(const StatusMessage& m);
void check_message(const DoneMessage& m);
void check_message(const ErrorMessage& m);
void check_message(const RegisterMessage& m);
template <class M>
void check_message(const M&) {}

template <class M>
nlohmann::json message_json(const M& m) {
    nlohmann::json j = job_to_json(m);
    j["type"] = M::kType;
    return j;
}

template <class M>
Buffer message_frame(const M& m) {
    return control_frame(message_json(m));
}

// The message of type M in `j` (whose "type" the caller matched); throws
// nlohmann::json::exception when a field is missing, mistyped or inconsistent.
template <class M>
M read_message(const nlohmann::json& j) {
    M m;
    job_from_json(j, m);
    check_message(m);
    return m;
}

}  // namespace povwall::distrib
