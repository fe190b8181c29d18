// Parsing snippets in the shape parser tests (tests/parser/shape_*_test.cpp).
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

// The first line of the error a scene stops with.
inline std::string error_of(const std::string& text) {
    try {
        parse(text);
    } catch (const ParseError& e) {
        const std::string what = e.what();
        return what.substr(0, what.find('\n'));
    }
    return "(no error)";
}

// The only object of a scene, as shape S.
template <class S>
S only_shape(const Scene& s) {
    return std::get<S>(s.objects.at(0).shape);
}

}  // namespace povwall::parser::test
