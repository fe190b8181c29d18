// Parses every scene listed in a corpus file and tallies ok / unsupported / error,
// printing each failure's first line. Usage: parser_corpus LIST EXAMPLES_DIR [-v]
// [--compare-compiled]. The last parses each scene a second time with
// ParseOptions::compile_expressions off and reports every scene whose objects, lights,
// camera or #debug text differ in any bit.
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "parser/parser.h"

namespace {

// The bits of a parsed scene that expressions feed: every object's transform, shape
// numbers and first texture's colour and finish, the lights and the camera.
struct Digest {
    std::string bytes;
    template <class T>
    void add(const T& v) {
        bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    void add_vec(const povwall::Vector3& v) { add(v.x), add(v.y), add(v.z); }
    void add_object(const povwall::Object& o) {
        const auto& m = o.transform.forward().m;
        for (const auto& row : m)
            for (double x : row) add(x);
        add(o.shape.index());
        if (auto s = std::get_if<povwall::Sphere>(&o.shape)) {
            add_vec(s->centre);
            add(s->radius);
        } else if (auto b = std::get_if<povwall::Box>(&o.shape)) {
            add_vec(b->corner1);
            add_vec(b->corner2);
        } else if (auto c = std::get_if<povwall::Cylinder>(&o.shape)) {
            add_vec(c->base);
            add_vec(c->cap);
            add(c->radius);
        } else if (auto csg = std::get_if<povwall::Csg>(&o.shape)) {
            for (const auto& child : csg->children) add_object(child);
        }
        if (!o.texture.empty()) {
            const povwall::Texture& t = o.texture[0];
            const povwall::Colour& c = t.pigment.colour;
            add(c.rgb.r), add(c.rgb.g), add(c.rgb.b), add(c.filter), add(c.transmit);
            add(t.finish->diffuse), add(t.finish->phong), add(t.finish->reflection_max.r);
            for (const auto& e : t.pigment.maps->colour_map)
                add(e.value), add(e.colour.rgb.r);
        }
    }
    void add_scene(const povwall::Scene& s) {
        add(s.objects.size());
        for (const auto& o : s.objects) add_object(o);
        for (const auto& l : s.lights) add_vec(l.location), add(l.colour.r);
        add_vec(s.camera.location);
        add_vec(s.camera.direction);
        add_vec(s.camera.right);
        add_vec(s.camera.up);
    }
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: parser_corpus LIST EXAMPLES_DIR [-v]\n";
        return 2;
    }
    bool verbose = false, compare_compiled = false;
    for (int i = 3; i < argc; ++i) {
        if (std::string(argv[i]) == "--compare-compiled")
            compare_compiled = true;
        else
            verbose = true;
    }
    int differ = 0;
    // Files the scenes write go to a scratch folder, removed at the end.
    const std::string output_dir = (std::filesystem::temp_directory_path() /
                                    ("povwall-corpus-" + std::to_string(::getpid())))
                                       .string();
    std::filesystem::create_directories(output_dir);
    std::ifstream list(argv[1]);
    std::string rel;
    int ok = 0, unsupported = 0, errors = 0;
    while (std::getline(list, rel)) {
        if (rel.empty() || rel[0] == '#') continue;
        std::filesystem::path path = std::filesystem::path(argv[2]) / rel;
        povwall::parser::ParseOptions options;
        options.library_paths.push_back(path.parent_path().string());
        options.output_dir = output_dir;  // files the scenes write (#fopen)
        if (verbose) options.messages = &std::cerr;
        // Scenes with an .ini (the portfolio) render frame 1 of an animation.
        std::filesystem::path ini = path;
        ini.replace_extension(".ini");
        if (std::filesystem::exists(ini)) {
            std::ifstream in(ini);
            std::string line;
            while (std::getline(in, line)) {
                if (line.rfind("Final_Frame=", 0) == 0)
                    options.final_frame = std::atoi(line.c_str() + 12);
            }
            options.frame_number = 1;
            options.initial_frame = 1;
            options.final_clock = 1;
        }
        auto start = std::chrono::steady_clock::now();
        std::clock_t cpu_start = std::clock();
        std::string status;
        try {
            povwall::Scene scene =
                povwall::parser::parse_scene_file(path.string(), options);
            ++ok;
            std::ostringstream s;
            s << "ok " << scene.objects.size() << " objects";
            status = s.str();
            if (compare_compiled) {
                // Both parses again with #debug captured, so the text is compared too.
                povwall::parser::ParseOptions::ExpressionCounts counts;
                std::ostringstream compiled_text, plain_text;
                Digest compiled, plain;
                options.messages = &compiled_text;
                options.expression_counts = &counts;
                compiled.add_scene(
                    povwall::parser::parse_scene_file(path.string(), options));
                options.messages = &plain_text;
                options.compile_expressions = false;
                plain.add_scene(
                    povwall::parser::parse_scene_file(path.string(), options));
                s << ", " << counts.compiled << " compiled, " << counts.runs << " runs";
                status = s.str();
                if (compiled.bytes != plain.bytes ||
                    compiled_text.str() != plain_text.str()) {
                    ++differ;
                    status = "DIFFERS " + status;
                }
            }
        } catch (const povwall::parser::ParseError& e) {
            std::string first = e.what();
            first = first.substr(0, first.find('\n'));
            if (e.kind() == povwall::parser::ParseError::Kind::Unsupported) {
                ++unsupported;
                status = "UNSUPPORTED " + first;
            } else {
                ++errors;
                status = "ERROR " + first;
            }
        }
        double secs =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
                .count();
        double cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
        if (verbose || status.rfind("ok", 0) != 0 ||
            (compare_compiled && status.find(" 0 compiled") == std::string::npos))
            std::cout << rel << ": " << status << " (" << secs << " s wall, " << cpu
                      << " s cpu)\n";
    }
    std::cout << "ok " << ok << "  unsupported " << unsupported << "  error " << errors;
    if (compare_compiled) std::cout << "  differ " << differ;
    std::cout << "\n";
    std::error_code ec;
    std::filesystem::remove_all(output_dir, ec);
    return 0;
}
