// Parsing snippets in the parser tests (tests/parser/*_test.cpp).
#pragma once

#include <sstream>
#include <string>

#include "parser/parser.h"

namespace povwall::parser::test {

inline Scene parse(const std::string& text, std::string* messages = nullptr) {
    std::ostringstream out;
    ParseOptions o;
    o.messages = &out;
    Scene s = parse_scene_text(text, "test.pov", o);
    if (messages) *messages = out.str();
    return s;
}

// The error a scene stops with, whole (its located line and any lines after).
inline std::string full_error_of(const std::string& text) {
    try {
        parse(text);
    } catch (const ParseError& e) {
        return e.what();
    }
    return "(no error)";
}

// The first line of the error a scene stops with.
inline std::string error_of(const std::string& text) {
    const std::string what = full_error_of(text);
    return what.substr(0, what.find('\n'));
}

// The only object of a scene, as shape S.
template <class S>
S only_shape(const Scene& s) {
    return std::get<S>(s.objects.at(0).shape);
}

}  // namespace povwall::parser::test
