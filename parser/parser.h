// Entry point of the scene language: a .pov file in, a core::Scene out.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image.h"
#include "core/object_queries.h"
#include "core/published_place.h"
#include "core/scene.h"

namespace povwall::parser {

struct ParseOptions {
    // Include search path after the scene's own folder (POV-Ray's +L), in order; the
    // installed standard include folder is searched last.
    std::vector<std::string> library_paths;
    std::string standard_include_dir = "/usr/share/povray-3.7/include";
    // Values the language exposes: image_width, image_height, clock, frame_number, ...
    int image_width = 320, image_height = 240;
    double clock = 0.0;
    int frame_number = 0;
    int initial_frame = 1, final_frame = 1;
    double initial_clock = 0.0, final_clock = 0.0;
    double clock_delta = 0.0;  // clock step between frames (0 for a still image)
    std::map<std::string, double> declares;  // Declare=NAME=value from the command line
    // The language version given with +MV / Version= (times 100): the scene starts as if
    // it began with that #version. Absent: POV-Ray's default state (parser/README.md).
    std::optional<int> language_version;
    // The output file type (POV-Ray's +F letter: N png, T tga, P ppm, E exr, ...): an
    // image file named with neither type keyword nor extension is read as this type.
    char output_file_type = 'N';
    // Where #debug/#warning/#render text goes (POV-Ray's console streams); null:
    // discarded.
    std::ostream* messages = nullptr;
    // #fopen: a relative name opened for writing or appending lands in this folder, and a
    // relative name opened for reading is looked for here first (then the scene's folder
    // and the library paths). Writes are allowed only under this folder and the scene's;
    // reads also under the library paths. Empty: the working directory.
    std::string output_dir;
    // False: #fopen ... write/append opens nothing and #write discards its text (a
    // black-box worker re-parses the coordinator's scene; the coordinator writes).
    bool write_user_files = true;
    // Evaluates the patterns of `function { pattern { ... } }` when the scene calls such
    // a function while parsing (trace/ has the patterns; the commands pass
    // trace::parse_time_function_hooks()). Without it they give 0; a pigment function
    // called while parsing is an error.
    FunctionHooks function_hooks;
    // Answers trace(), inside(), min_extent() and max_extent() on objects, and gives each
    // CSG POV-Ray's box when it is closed (trace/ has the shapes; the commands pass
    // trace::parse_time_object_queries()). Without it those functions stop with
    // `unsupported:`, and CSG boxes are joined from their children when asked.
    std::shared_ptr<ObjectQueries> object_queries;
    // Reads image_map/bump_map files. Without one the scene records the file references
    // only (enough to list the files a scene reads), and cannot be rendered.
    ImageReader image_reader;
    // Resource limits that turn a runaway scene into a located error.
    uint64_t max_loop_iterations = 10'000'000;  // per run of one #while or #for
    double max_parse_seconds = 0;               // wall time of the whole parse; 0: none
    // Growth of the process's resident memory during the parse (a loop that makes objects
    // without end); 0: half the memory available when the parse starts.
    uint64_t max_parse_memory = 0;
    // When set, kept current with the file and line being read (every few thousand
    // tokens and at each #include's start and end), so that a signal handler or another
    // thread can name where an interrupted parse was.
    PublishedPlace* place = nullptr;
    // Called with each finished top-level object; false leaves it out of Scene::objects
    // (its light sources stay). A black-box worker keeps only what overlaps its boxes,
    // so its memory holds its part of the scene, never the whole. Null: everything.
    std::function<bool(const Object&)> keep_object;
    // How many top-level objects the scene will keep, when known (a black-box worker is
    // told by the coordinator): reserved up front, so the object list never reallocates
    // (a reallocation holds the old and the new list at once: up to 3x its size).
    size_t expected_objects = 0;
    // Expressions inside loops and macros run as compiled programs
    // (parser/expression_program.h); false reads every one token by token, which is the
    // definition the programs must match.
    bool compile_expressions = true;
    // When set, counts how the parse read its expressions.
    struct ExpressionCounts {
        uint64_t compiled = 0;  // positions compiled into a program
        uint64_t runs = 0;      // expressions answered by a program
    }* expression_counts = nullptr;
};

// A located diagnostic. what() is the full text as printed: "file:line:col: error: msg",
// then the source line and a caret, then notes (macro call sites, include chain).
class ParseError : public std::runtime_error {
  public:
    enum class Kind { Syntax, Unsupported, Io };
    ParseError(Kind kind, std::string formatted, std::string message, SourceLoc loc,
               bool deferrable = true)
        : std::runtime_error(std::move(formatted)),
          kind_(kind),
          message_(std::move(message)),
          loc_(loc),
          deferrable_(deferrable) {}
    Kind kind() const { return kind_; }
    // An unsupported feature in a #declare's value may wait until the identifier is
    // used, unless skipping it would change other variables (trace's normal argument).
    bool deferrable() const { return deferrable_; }
    const std::string& message() const { return message_; }  // without location or caret
    SourceLoc loc() const { return loc_; }

  private:
    Kind kind_;
    std::string message_;
    SourceLoc loc_;
    bool deferrable_;
};

// Parses `path` and everything it includes. Throws ParseError on the first error.
Scene parse_scene_file(const std::string& path, const ParseOptions& options);
// Same, from text in memory; `display_name` is used in diagnostics and for relative
// includes. The parse keeps the text (tokens view it): pass an rvalue to spare a copy.
Scene parse_scene_text(std::string text, const std::string& display_name,
                       const ParseOptions& options);

// POV-Ray 3.7's rand() stream: a 32-bit linear congruential generator, exactly as the
// reference renderer draws it (scenes place objects with it).
class RandomStream {
  public:
    explicit RandomStream(int seed) : state_(static_cast<uint32_t>(seed)) {}
    double next() {
        state_ = state_ * 1812433253u + 12345u;
        return static_cast<double>(state_) / 4294967295.0;
    }

  private:
    uint32_t state_;
};

}  // namespace povwall::parser
