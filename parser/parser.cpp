#include "parser/parser.h"

#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "parser/interpreter.h"

namespace povwall::parser {

namespace {

// This process's resident memory in bytes (0 when unknown).
uint64_t resident_bytes() {
    FILE* f = std::fopen("/proc/self/statm", "r");
    if (!f) return 0;
    unsigned long long size = 0, resident = 0;
    const bool ok = std::fscanf(f, "%llu %llu", &size, &resident) == 2;
    std::fclose(f);
    return ok ? resident * uint64_t(sysconf(_SC_PAGESIZE)) : 0;
}

// MemAvailable of /proc/meminfo in bytes (0 when unknown).
uint64_t available_bytes() {
    std::ifstream in("/proc/meminfo");
    std::string key;
    unsigned long long kb = 0;
    std::string unit;
    while (in >> key >> kb >> unit) {
        if (key == "MemAvailable:") return uint64_t(kb) * 1024;
    }
    return 0;
}

}  // namespace

Interpreter::Interpreter(const ParseOptions& options, SourceManager& sources)
    : options_(options), sources_(sources) {
    // A hint only: capped so that a wrong one cannot reserve absurd memory.
    scene_.objects.reserve(std::min<size_t>(options_.expected_objects, size_t(1) << 26));
    resident_at_start_ = resident_bytes();
    memory_limit_ =
        options_.max_parse_memory ? options_.max_parse_memory : available_bytes() / 2;
    if (resident_at_start_ == 0) memory_limit_ = 0;  // cannot measure: no check
    if (options_.max_parse_seconds > 0)
        parse_deadline_ = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(options_.max_parse_seconds));
}

void Interpreter::publish_place(int file, uint32_t offset) {
    if (!options_.place || file < 0) return;
    const auto line = uint32_t(sources_.location(file, offset).line);
    if (file == published_file_) {
        options_.place->set_line(line);
    } else {
        options_.place->set(sources_.file(file).path, line);
        published_file_ = file;
    }
}

void Interpreter::check_parse_limits(const Token& at) {
    tokens_since_clock_ = 0;
    publish_place(at.file, at.offset);
    if (memory_limit_ && ++clock_reads_ % 16 == 0) {
        const uint64_t now = resident_bytes();
        if (now > resident_at_start_ && now - resident_at_start_ > memory_limit_) {
            error(at, "the scene outgrew the parse memory limit of " +
                          std::to_string(memory_limit_ >> 20) + " MB (" +
                          (options_.max_parse_memory ? "set by the caller"
                                                     : "half the memory available") +
                          "; a loop without end?)");
        }
    }
    if (options_.max_parse_seconds > 0 &&
        std::chrono::steady_clock::now() > parse_deadline_) {
        char limit[32];
        std::snprintf(limit, sizeof limit, "%g", options_.max_parse_seconds);
        error(at, std::string("parse time limit of ") + limit +
                      " s exceeded (--max-parse-seconds)");
    }
}

void Interpreter::check_stack(const Token& at) {
    if (stack_floor_ && uintptr_t(__builtin_frame_address(0)) < stack_floor_)
        error(at, "directives, macros and expressions nested too deeply for the stack");
}

namespace {

// The lowest address this thread's stack may reach while parsing: its end plus room for
// reporting an error (formatting the message, unwinding). 0 when unknown.
uintptr_t stack_floor() {
    pthread_attr_t attr;
    if (pthread_getattr_np(pthread_self(), &attr) != 0) return 0;
    void* low = nullptr;
    size_t size = 0;
    const int rc = pthread_attr_getstack(&attr, &low, &size);
    pthread_attr_destroy(&attr);
    constexpr size_t kReserve = 512 << 10;
    if (rc != 0 || size < 2 * kReserve) return 0;
    return uintptr_t(low) + kReserve;
}

}  // namespace

Scene Interpreter::run(int root_file) {
    stack_floor_ = stack_floor();
    scene_dir_ =
        std::filesystem::path(sources_.file(root_file).path).parent_path().string();
    if (options_.language_version) {  // +MV / Version=: as a #version before the scene
        version_ = *options_.language_version;
        version_set_ = true;
    }
    scopes_.emplace_back();  // global #declare table
    // POV-Ray's front end declares the scene file's name (without its folder) before the
    // command line's Declare= values.
    bind(scopes_[0], sources_.intern("input_file_name")).value =
        std::filesystem::path(sources_.file(root_file).path).filename().string();
    for (const auto& [name, value] : options_.declares) {
        bind(scopes_[0], sources_.intern(name)).value = Numeric::scalar(value);
    }
    scopes_.emplace_back();  // the scene file's own #local table
    frames_.push_back({root_file,
                       0,
                       sources_.file(root_file).tokens.size(),
                       Frame::Kind::File,
                       1,
                       {},
                       &sources_.file(root_file).tokens});
    publish_place(root_file, sources_.file(root_file).tokens.front().offset);
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
    finish_version_state();
    settle_isosurfaces();
    settle_mesh_copies();
    check_radiosity();
    if (subsurface_finish_at_)
        warn(*subsurface_finish_at_,
             "this rendering uses the following experimental feature(s): subsurface "
             "light transport (POV-Ray 3.7: its design and implementation are likely to "
             "change in future versions)");
    // POV-Ray shoots a projected_through light's photons only through its object.
    if (projected_through_at_ && scene_.settings.photons)
        unsupported(*projected_through_at_, "projected_through with photons");
    // A camera normal's patterns read the final settings too.
    scene_.camera.normal_noise_generator = scene_.settings.noise_generator;
    scene_.camera.normal_number_of_waves = scene_.settings.number_of_waves;
    return std::move(scene_);
}

void Interpreter::count_mesh_copies(const Object& o) {
    if (auto m = std::get_if<Mesh>(&o.shape)) ++mesh_copies_[m->data.get()];
    if (auto csg = std::get_if<Csg>(&o.shape))
        for (const Object& c : csg->children) count_mesh_copies(c);
}

void Interpreter::settle_mesh_copies() {
    if (mesh_copies_.empty()) return;
    auto visit = [&](auto& self, Object& o) -> void {
        if (auto m = std::get_if<Mesh>(&o.shape)) {
            const auto it = mesh_copies_.find(m->data.get());
            m->copies = it == mesh_copies_.end() ? 1 : it->second;
        }
        if (auto csg = std::get_if<Csg>(&o.shape))
            for (Object& c : csg->children) self(self, c);
    };
    for (Object& o : scene_.objects) visit(visit, o);
    for (Light& l : scene_.lights)
        for (Object& o : l.looks_like) visit(visit, o);
}

void Interpreter::settle_isosurfaces() {
    // The settings an isosurface's function reads while rendering are the scene's final
    // ones, wherever global_settings comes.
    const GlobalSettings& g = scene_.settings;
    auto visit = [&](auto& self, Object& o) -> void {
        if (auto iso = std::get_if<Isosurface>(&o.shape)) {
            iso->noise_generator = g.noise_generator;
            iso->number_of_waves = g.number_of_waves;
        }
        if (auto par = std::get_if<Parametric>(&o.shape)) {
            par->noise_generator = g.noise_generator;
            par->number_of_waves = g.number_of_waves;
        }
        if (auto csg = std::get_if<Csg>(&o.shape)) {
            for (Object& c : csg->children) self(self, c);
            for (Light& l : csg->lights)
                for (Object& c : l.looks_like) self(self, c);
        }
        if (o.clipped_by.allocated())
            for (Object& c : o.clipped_by.edit()) self(self, c);
        if (o.bounded_by.allocated())
            for (Object& c : o.bounded_by.edit()) self(self, c);
    };
    for (Object& o : scene_.objects) visit(visit, o);
    for (Light& l : scene_.lights) {
        for (Object& o : l.looks_like) visit(visit, o);
        if (l.projected_through) {
            auto mask = std::make_shared<Object>(*l.projected_through);
            visit(visit, *mask);
            l.projected_through = std::move(mask);
        }
    }
}

Scene parse_scene_file(const std::string& path, const ParseOptions& options) {
    SourceText text;
    if (!text.read_file(path)) {
        std::string msg = "cannot open scene file '" + path + "'";
        throw ParseError(ParseError::Kind::Io, "povwall: error: " + msg, msg, {});
    }
    SourceManager sources;
    const int root = sources.add(path, std::move(text));
    Interpreter interpreter(options, sources);
    return interpreter.run(root);
}

Scene parse_scene_text(std::string text, const std::string& display_name,
                       const ParseOptions& options) {
    SourceManager sources;
    const int root = sources.add(display_name, std::move(text));
    Interpreter interpreter(options, sources);
    return interpreter.run(root);
}

}  // namespace povwall::parser
