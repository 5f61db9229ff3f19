#pragma once
// Errors that cross shadelab's layers.
//
// InputError is bad input from the user (a file, a field, a flag): the CLI prints its one-line message
// and exits with status 2. Anything else that escapes (GL failures, I/O faults) exits with status 1.
#include <stdexcept>
#include <string>

namespace shadelab {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The GL ran out of memory for what was asked: an input error too (exit 2), which the headless front
// end names with the request ("scene.json: a 1280x720 frame: the GL ran out of memory in render ...").
class GlOutOfMemory : public InputError {
public:
    using InputError::InputError;
};

// A GLSL program that does not compile or link (a --shader-dir of one's own, an edit reloaded with F5):
// bad input too (exit 2); the message names the program, the stage, and the file and line of each
// driver message (render/program.hpp builds programs).
class ShaderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace shadelab
