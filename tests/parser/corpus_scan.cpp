// Parses every scene listed in a corpus file and tallies ok / unsupported / error, printing
// each failure's first line. Usage: parser_corpus LIST EXAMPLES_DIR [-v]
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <iostream>
#include <sstream>

#include "parser/parser.h"

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: parser_corpus LIST EXAMPLES_DIR [-v]\n";
        return 2;
    }
    bool verbose = argc > 3;
    std::ifstream list(argv[1]);
    std::string rel;
    int ok = 0, unsupported = 0, errors = 0;
    while (std::getline(list, rel)) {
        if (rel.empty() || rel[0] == '#') continue;
        std::filesystem::path path = std::filesystem::path(argv[2]) / rel;
        povwall::parser::ParseOptions options;
        options.library_paths.push_back(path.parent_path().string());
        if (verbose) options.messages = &std::cerr;
        // Scenes with an .ini (the portfolio) render frame 1 of an animation.
        std::filesystem::path ini = path;
        ini.replace_extension(".ini");
        if (std::filesystem::exists(ini)) {
            std::ifstream in(ini);
            std::string line;
            while (std::getline(in, line)) {
                if (line.rfind("Final_Frame=", 0) == 0) options.final_frame = std::atoi(line.c_str() + 12);
            }
            options.frame_number = 1;
            options.initial_frame = 1;
            options.final_clock = 1;
        }
        auto start = std::chrono::steady_clock::now();
        std::clock_t cpu_start = std::clock();
        std::string status;
        try {
            povwall::Scene scene = povwall::parser::parse_scene_file(path.string(), options);
            ++ok;
            std::ostringstream s;
            s << "ok " << scene.objects.size() << " objects";
            status = s.str();
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
        double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        double cpu = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
        if (verbose || status.rfind("ok", 0) != 0)
            std::cout << rel << ": " << status << " (" << secs << " s wall, " << cpu << " s cpu)\n";
    }
    std::cout << "ok " << ok << "  unsupported " << unsupported << "  error " << errors << "\n";
    return 0;
}
