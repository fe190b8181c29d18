#include "cli/interrupt.h"

#include <cstdint>

namespace povwall::cli {

static_assert(std::atomic<RenderPhase>::is_always_lock_free &&
                  std::atomic<trace::RenderProgress::Stage>::is_always_lock_free &&
                  std::atomic<uint64_t>::is_always_lock_free &&
                  std::atomic<int>::is_always_lock_free,
              "the signal handler reads these");

constinit RenderRecord g_render_record;

namespace {

// Appends to a fixed buffer, cutting what does not fit: no allocation, no snprintf (it
// may take locks), so a signal handler can use it.
class Line {
  public:
    Line(char* out, size_t capacity) : out_(out), capacity_(capacity) {}
    Line& text(const char* s) {
        while (*s) put(*s++);
        return *this;
    }
    // 41200 -> "41,200".
    Line& count(uint64_t v) {
        char digits[32];
        int n = 0;
        do {
            digits[n++] = char('0' + v % 10);
            v /= 10;
        } while (v);
        for (int i = n - 1; i >= 0; --i) {
            put(digits[i]);
            if (i > 0 && i % 3 == 0) put(',');
        }
        return *this;
    }
    // done / total as "6.4 %", rounded down: 100.0 % only when all is done.
    Line& percent(uint64_t done, uint64_t total) {
        const uint64_t tenths = total ? done * 1000 / total : 0;
        count(tenths / 10);
        put('.');
        put(char('0' + tenths % 10));
        return text(" %");
    }
    size_t finish() {
        const size_t n = length_ < capacity_ ? length_ : capacity_ - 1;
        out_[n] = '\0';
        return n;
    }

  private:
    void put(char c) {
        if (length_ + 1 < capacity_) out_[length_] = c;
        ++length_;
    }
    char* out_;
    size_t capacity_;
    size_t length_ = 0;
};

}  // namespace

size_t interrupt_message(const RenderRecord& record, bool partial_removed, char* out,
                         size_t capacity) noexcept {
    if (capacity == 0) return 0;
    Line line(out, capacity);
    line.text("\npovwall: ");
    const RenderPhase phase = record.phase.load();
    if (const int frame = record.frame.load(); frame >= 0 && phase != RenderPhase::None)
        line.text("frame ").count(uint64_t(frame)).text(": ");
    char name[PublishedPlace::kCapacity];
    uint32_t at = 0;
    const char* no_image = "; no image written\n";
    switch (phase) {
        case RenderPhase::None:
            line.text(partial_removed
                          ? "interrupted: the partly written image was removed; no "
                            "image written\n"
                          : "interrupted: no image written\n");
            break;
        case RenderPhase::Parsing:
            line.text("interrupted while parsing");
            // A parser stopped in the middle of publishing its place goes without.
            if (record.parse.get(name, sizeof name, at) && name[0]) {
                line.text(" ").text(name);
                if (at > 0) line.text(":").count(at);
            }
            line.text(no_image);
            break;
        case RenderPhase::Rendering: {
            const trace::RenderProgress& p = record.progress;
            const uint64_t objects = p.objects.load();
            switch (p.stage.load()) {
                case trace::RenderProgress::Stage::Preparing:
                    line.text("interrupted while preparing the scene (")
                        .count(objects)
                        .text(objects == 1 ? " object)" : " objects)");
                    break;
                case trace::RenderProgress::Stage::BuildingOctree:
                    line.text("interrupted while building the octree (")
                        .count(objects)
                        .text(objects == 1 ? " primitive)" : " primitives)");
                    break;
                case trace::RenderProgress::Stage::ShootingPhotons:
                    line.text("interrupted while shooting photons");
                    break;
                case trace::RenderProgress::Stage::Pretracing:
                    line.text("interrupted in radiosity's pretrace");
                    break;
                case trace::RenderProgress::Stage::Tracing: {
                    const uint64_t total = p.pixels_total.load();
                    const uint64_t done = p.pixels_done.load();
                    line.text("interrupted while tracing: ")
                        .count(done)
                        .text(" of ")
                        .count(total)
                        .text(" pixels (")
                        .percent(done, total)
                        .text(")");
                    break;
                }
            }
            line.text(no_image);
            break;
        }
        case RenderPhase::Writing:
            line.text("interrupted while writing");
            if (record.output.get(name, sizeof name, at) && name[0])
                line.text(" ").text(name);
            line.text(partial_removed
                          ? ": the partly written image was removed; no image written\n"
                          : no_image);
            break;
        case RenderPhase::Written:
            line.text("interrupted after writing");
            if (record.output.get(name, sizeof name, at) && name[0])
                line.text(" ").text(name);
            line.text(", which is complete\n");
            break;
    }
    return line.finish();
}

}  // namespace povwall::cli
