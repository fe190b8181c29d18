// Command-line settings shared by the subcommands, and POV-Ray's +X switches.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <iostream>
#include <istream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "distrib/distribution_plan.h"
#include "distrib/space_render.h"
#include "distrib/wire/job.h"
#include "distrib/work_queue.h"
#include "parser/parser.h"
#include "trace/render.h"

namespace povwall::distrib {
class TcpSession;
}

namespace CLI {
class App;
}

namespace povwall::output {
struct DiffThresholds;
}

namespace povwall::cli {

// --max-loop-iterations and --max-parse-seconds, for every command that parses a scene.
void add_parse_limit_options(CLI::App& app, uint64_t& max_loop_iterations,
                             double& max_parse_seconds);

// --plan: leave out what the scene does not need (auto), or nothing (all).
enum class PlanChoice { Auto, All };
// --worker-start: --procs workers forked after the parse (inheriting the scene) or
// executed afresh (each parses the scene).
enum class WorkerStart { Fork, Exec };
// --worker-cores: --procs workers that outnumber the cores each kept on one core with the
// workers it trades most rays with (auto), or placed by the system (off).
enum class WorkerCores { Auto, Off };
// Their names, on the command line and in a worker's job (distrib/wire/job_fields.h).
inline std::array<std::pair<PlanChoice, const char*>, 2> enum_names(PlanChoice) {
    return {{{PlanChoice::Auto, "auto"}, {PlanChoice::All, "all"}}};
}
inline std::array<std::pair<WorkerStart, const char*>, 2> enum_names(WorkerStart) {
    return {{{WorkerStart::Fork, "fork"}, {WorkerStart::Exec, "exec"}}};
}
inline std::array<std::pair<WorkerCores, const char*>, 2> enum_names(WorkerCores) {
    return {{{WorkerCores::Auto, "auto"}, {WorkerCores::Off, "off"}}};
}

struct RenderOptions {
    std::string scene;
    std::string output;  // empty: scene name with the format's extension
    int width = 320, height = 240;
    std::vector<std::string> library_paths;
    trace::RenderSettings render;  // threads, antialias, alpha, partial rows
    int bits = 8;
    // File_Gamma: the output file's encoding as a power law of this display gamma (1:
    // linear values); none: sRGB, POV-Ray's default.
    std::optional<float> file_gamma;
    char format = 'N';          // POV-Ray +F letter: N png, T tga, P ppm, E exr
    bool format_given = false;  // +F seen: that format whatever -o's extension says
    // +SR/+ER/+SC/+EC as given: a row/column number (1-based) or, written with a decimal
    // point and at most 1, a fraction of the image (POV-Ray's rule); resolved once the
    // size is known.
    struct Partial {
        double value = -1;
        bool fraction = false;
    } start_row, end_row, start_col, end_col;
    std::map<std::string, double> declares;
    // +MV / Version=: the language version the scene starts under (times 100).
    std::optional<int> language_version;
    // POV-Ray's animation options (+KFI +KFF +KI +KF +KC +SF +EF, Initial_Frame=...) and
    // the clock of a still image (+K).
    struct Animation {
        int initial_frame = 1, final_frame = 1;
        double initial_clock = 0.0, final_clock = 1.0;
        bool cyclic = false;
        // +SF/+EF as given (POV-Ray reads them as numbers): 0 or at least 1 a frame
        // number, between 0 and 1 a fraction of the frames; unset: the first / the last.
        std::optional<double> subset_start, subset_end;
        double clock = 0.0;  // still image
    } animation;
    bool continue_trace = false;  // +C: frames whose image exists are kept, not rendered
    struct FrameValues {
        int number = 0;
        double clock = 0.0, clock_delta = 0.0;
        bool operator==(const FrameValues&) const = default;
    };
    std::optional<FrameValues> frame;  // set while one frame of an animation renders
    // Set by an animation for all its frames: the black-box workers (--procs, --workers)
    // stay alive from one frame to the next.
    std::shared_ptr<std::unique_ptr<distrib::TcpSession>> frame_workers;
    // Overrides of the scene's global_settings (quick previews, `povwall sweep`).
    std::optional<int> max_trace_level;
    std::optional<double> adc_bailout;
    // Parse limits (ParseOptions): a runaway scene stops with a located error.
    uint64_t max_loop_iterations = 10'000'000;
    double max_parse_seconds = 0;  // 0: no limit
    bool quiet = false;
    std::string stats_file;
    // Space subdivision (virtual walls): empty lets --mode decide; "1x1x1" is one box.
    std::string boxes;
    distrib::RenderMode mode = distrib::RenderMode::Auto;  // names: cli/option_names.h
    int procs =
        0;  // worker processes: screen tiles, or boxes over TCP (0: as many as cores)
    bool tile_worker = false;  // internal: serve screen tiles on stdin/stdout
    std::string
        worker_memory;  // "2G": the budget auto mode fits each worker's scene into
    PlanChoice plan = PlanChoice::Auto;
    bool explain = false;  // print the render plan before rendering
    distrib::SpaceOptions::Results results = distrib::SpaceOptions::Results::Auto;
    distrib::QueuePolicy queue = distrib::QueuePolicy::Priority;
    // Black boxes in running workers over TCP (--procs starts local ones).
    std::vector<std::string> workers;  // "host:port"
    std::string token;                 // job token the workers were started with
    WorkerStart worker_start = WorkerStart::Fork;
    WorkerCores worker_cores = WorkerCores::Auto;
    // Teams of workers, each hosting every box: a count that divides the workers, or
    // "auto" (distrib::SpaceOptions::teams).
    std::string teams = "auto";
    // A lost worker process (--procs) or tile worker: its work goes to the others (true)
    // or the render stops with it named (false, --no-recover).
    bool recover = true;
};

// The parse options `render` uses for `o` (the frame `o.frame`, or the still's clock;
// #write files go to `output_dir`).
parser::ParseOptions render_parse_options(const RenderOptions& o,
                                          const std::string& output_dir);

// The scene as `render` parses it for `o` (no messages, no #write files); throws
// parser::ParseError.
Scene parse_render_scene(const RenderOptions& o);

// Applies one POV-Ray switch (+W320, -A, +Ldir, Declare=X=1, ...) to `o`.
// Returns false when `arg` is not a POV-Ray switch povwall knows; throws on a bad value.
bool apply_pov_switch(const std::string& arg, RenderOptions& o);

// True when `arg` looks like a POV-Ray switch rather than one of povwall's own options.
bool looks_like_pov_switch(const std::string& arg);

// POV-Ray .ini option files (Input_File_Name=..., Width=..., Antialias=on, ...), read
// as POV-Ray 3.7 reads them: `spec` is a file name, optionally with the [Section] to read
// (file.ini[Section]). Keys povwall does not implement that could change the image give
// one warning line on `warnings` (none when null or o.quiet); errors (an unknown key, a
// bad number) throw UsageError("file:line: ...").
bool looks_like_ini_file(const std::string& arg);
// An INI option given on the command line (`File_Gamma=1.0`), as POV-Ray takes them: a
// known key, '=', a value. looks_like_pov_switch and apply_pov_switch take them too.
bool looks_like_ini_option(const std::string& arg);
void apply_ini_option(const std::string& arg, RenderOptions& o);
void apply_ini_file(const std::string& spec, RenderOptions& o,
                    std::ostream* warnings = &std::cerr, int depth = 0);
// The INI file POV-Ray 3.7's Unix front end reads before the command line
// (UnixOptionsProcessor::Process_povray_ini): the first that exists of $POVINI,
// ./povray.ini and ~/.povray/3.7/povray.ini; empty when none does (POV-Ray then reads
// the installed one, whose library paths povwall has built in).
std::string default_ini_file();
// Applies it, when there is one, as apply_ini_file() (an error in it stops POV-Ray too:
// "Failed to parse INI file").
void apply_default_ini(RenderOptions& o, std::ostream* warnings = &std::cerr);
// Same, from a stream; `path` names it in messages ("file:line: ...").
void apply_ini_stream(std::istream& in, const std::string& path, RenderOptions& o,
                      std::ostream* warnings = &std::cerr);

std::string default_output_name(const RenderOptions& o);

// One frame of an animation: its number, clock and output name (POV-Ray's numbering: the
// frame number zero-padded to the width of the final frame's, before the extension).
struct Frame {
    int number = 0;
    double clock = 0.0, clock_delta = 0.0;
    std::string output;
};
// The frames to render (subset applied); empty when `o` is a still image.
std::vector<Frame> animation_frames(const RenderOptions& o);
// The file extension of the +F format (".png", ".tga", ".ppm", ".exr").
std::string format_extension(char format);

// Fills o.render's 0-based partial-render bounds from the +SR/+ER/+SC/+EC values.
void resolve_partial_render(RenderOptions& o);

// compare and bench: --max-rmse, --max-bad-fraction and --fail for the diff against
// POV-Ray's image.
void add_diff_threshold_options(CLI::App& app, output::DiffThresholds& t);
// compare and bench: parses the arguments with `app` after taking out the POV-Ray +X
// switches, which then apply to `o` and are kept in `switches` (to pass on);
// `before_switches`, when set, runs on `o` between the two. Returns -1 when the command
// goes on, else its exit code (0 after --help, 2 on a usage error).
int parse_with_pov_switches(
    CLI::App& app, int argc, char** argv, RenderOptions& o,
    std::vector<std::string>& switches,
    const std::function<void(RenderOptions&)>& before_switches = {});

int run_render(RenderOptions o);
int run_diff(int argc, char** argv);
int run_compare(int argc, char** argv);
int run_bench(int argc, char** argv);
int run_parse(int argc, char** argv);
int run_worker_command(int argc, char** argv);
int run_check_numerics(int argc, char** argv);
int run_batch(int argc, char** argv);
int run_sweep(int argc, char** argv);
int run_corpus(int argc, char** argv);

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
// A mistake inside an INI file, located by its file and line: the command line was
// fine, so no usage text follows the message.
struct IniFileError : UsageError {
    using UsageError::UsageError;
};

}  // namespace povwall::cli
