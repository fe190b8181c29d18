#include "distrib/wire/messages.h"

#include "distrib/stats_json.h"

namespace povwall::distrib {

using json = nlohmann::json;

namespace {

[[noreturn]] void bad(const char* field, const json& value) {
    job_fields_detail::bad_json_value(field, value);
}

// Indices into lists of workers or boxes: a process has at most 2^20 of either.
constexpr int64_t kMaxIndex = int64_t(1) << 20;

}  // namespace

void to_json(json& j, const BoxReport& report) {
    j = box_stats_json(report.stats);
    j["box"] = report.box;
}

void from_json(const json& j, BoxReport& report) {
    report.box = j.at("box").get<int>();
    if (report.box < 0 || report.box >= kMaxIndex) bad("box", j.at("box"));
    report.stats = box_stats_from_json(j);
}

void check_message(const ReadyMessage& m) {
    if (m.boxes.size() != m.primitives.size())
        bad("primitives", {m.boxes.size(), m.primitives.size()});
    for (int b : m.boxes)
        if (b < 0 || b >= kMaxIndex) bad("boxes", b);
}

void check_message(const PixelRangeMessage& m) {
    if (m.begin < 0 || m.begin > m.end) bad("pixels", {m.begin, m.end});
}

void check_message(const StatusMessage& m) {
    if (m.seq < -1) bad("seq", m.seq);
    if (m.sent.size() > size_t(kMaxIndex)) bad("sent", m.sent.size());
}

void check_message(const DoneMessage& m) {
    for (size_t k = 1; k < m.boxes.size(); ++k)
        if (m.boxes[k].box <= m.boxes[k - 1].box) bad("boxes", m.boxes[k].box);
}

void check_message(const ErrorMessage& m) {
    if (m.culprit < -1 || m.culprit >= kMaxIndex) bad("culprit", m.culprit);
}

void check_message(const RegisterMessage& m) {
    // The rendezvous says what is wrong with a rank or size that fits an int.
    constexpr int64_t kInt = int64_t(1) << 31;
    if (m.rank <= -kInt || m.rank >= kInt) bad("rank", m.rank);
    if (m.size <= -kInt || m.size >= kInt) bad("size", m.size);
}

}  // namespace povwall::distrib
