#include "parser/parser.h"

#include <fstream>
#include <sstream>

namespace povwall::parser {

Scene parse_scene_file(const std::string& path, const ParseOptions& options) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::string msg = "cannot open scene file '" + path + "'";
        throw ParseError(ParseError::Kind::Io, path + ": error: " + msg, msg, {});
    }
    std::stringstream ss;
    ss << in.rdbuf();
    return parse_scene_text(ss.str(), path, options);
}

Scene parse_scene_text(const std::string& text, const std::string& display_name,
                       const ParseOptions& options) {
    std::string msg = "the scene language is not implemented yet";
    throw ParseError(ParseError::Kind::Unsupported, display_name + ":1:1: error: " + msg, msg,
                     {0, 1, 1});
}

}  // namespace povwall::parser
