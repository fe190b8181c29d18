// Command-line settings shared by the subcommands, and POV-Ray's +X switches.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "trace/render.h"

namespace povwall::cli {

struct RenderOptions {
    std::string scene;
    std::string output;  // empty: scene name with the format's extension
    int width = 320, height = 240;
    std::vector<std::string> library_paths;
    trace::RenderSettings render;  // threads, antialias, alpha, partial rows
    int bits = 8;
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
    bool quiet = false;
    std::string stats_file;
    // Space subdivision (virtual walls): "1x1x1" renders in one process without boxes.
    std::string boxes = "1x1x1";
    std::string results = "auto";  // forward | parents | auto
    std::string queue = "priority";  // priority | fifo
};

// Applies one POV-Ray switch (+W320, -A, +Ldir, Declare=X=1, ...) to `o`.
// Returns false when `arg` is not a POV-Ray switch povwall knows; throws on a bad value.
bool apply_pov_switch(const std::string& arg, RenderOptions& o);

// True when `arg` looks like a POV-Ray switch rather than one of povwall's own options.
bool looks_like_pov_switch(const std::string& arg);

// POV-Ray .ini option files (Input_File_Name=..., Width=..., Antialias=on, ...).
bool looks_like_ini_file(const std::string& arg);
void apply_ini_file(const std::string& path, RenderOptions& o);

std::string default_output_name(const RenderOptions& o);
// The file extension of the +F format (".png", ".tga", ".ppm", ".exr").
std::string format_extension(char format);

// Fills o.render's 0-based partial-render bounds from the +SR/+ER/+SC/+EC values.
void resolve_partial_render(RenderOptions& o);

int run_render(RenderOptions o);
int run_diff(int argc, char** argv);
int run_compare(int argc, char** argv);
int run_parse(int argc, char** argv);

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace povwall::cli
