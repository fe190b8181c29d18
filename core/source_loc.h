// A place in the user's scene text, carried from the lexer to every diagnostic.
#pragma once

#include <cstdint>

namespace povwall {

struct SourceLoc {
    int32_t file = -1;  // index into the scene's file table; -1 when unknown
    int32_t line = 0;   // 1-based
    int32_t column = 0; // 1-based, in bytes
    bool valid() const { return file >= 0; }
};

}  // namespace povwall
