#include "parser/parser.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "parser/interpreter.h"

namespace povwall::parser {

Interpreter::Interpreter(const ParseOptions& options, SourceManager& sources)
    : options_(options), sources_(sources) {
    if (options_.max_parse_seconds > 0)
        parse_deadline_ = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(options_.max_parse_seconds));
}

void Interpreter::check_parse_time(const Token& at) {
    tokens_since_clock_ = 0;
    if (options_.max_parse_seconds > 0 &&
        std::chrono::steady_clock::now() > parse_deadline_) {
        char limit[32];
        std::snprintf(limit, sizeof limit, "%g", options_.max_parse_seconds);
        error(at, std::string("parse time limit of ") + limit +
                      " s exceeded (--max-parse-seconds)");
    }
}

Scene Interpreter::run(int root_file) {
    scene_dir_ =
        std::filesystem::path(sources_.file(root_file).path).parent_path().string();
    scopes_.emplace_back();  // global #declare table
    for (const auto& [name, value] : options_.declares) {
        bind(scopes_[0], sources_.intern(name)).value = Numeric::scalar(value);
    }
    scopes_.emplace_back();  // the scene file's own #local table
    frames_.push_back(
        {root_file, 0, sources_.file(root_file).tokens.size(), Frame::Kind::File, 1, {}});
    for (;;) {
        Token t = next();
        if (t.kind == TokenKind::End) break;
        parse_top_level_item(t);
    }
    if (!conds_.empty()) {
        const Cond& c = conds_.back();
        error(c.at, "#" + std::string(c.at.text) + " has no matching #end");
    }
    for (int i = 0; i < sources_.count(); ++i)
        scene_.files.push_back(sources_.file(i).path);
    // Image files after the sources (SourceLoc indexes only the sources).
    for (const auto& f : image_files_) scene_.files.push_back(f);
    scene_.language_version = version_;
    scene_.version_set = version_set_;
    return std::move(scene_);
}

Scene parse_scene_file(const std::string& path, const ParseOptions& options) {
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    if (!in || std::filesystem::is_directory(path, ec)) {
        std::string msg = "cannot open scene file '" + path + "'";
        throw ParseError(ParseError::Kind::Io, "povwall: error: " + msg, msg, {});
    }
    std::stringstream ss;
    ss << in.rdbuf();
    return parse_scene_text(ss.str(), path, options);
}

Scene parse_scene_text(const std::string& text, const std::string& display_name,
                       const ParseOptions& options) {
    SourceManager sources;
    int root = sources.add(display_name, text);
    Interpreter interpreter(options, sources);
    return interpreter.run(root);
}

}  // namespace povwall::parser
