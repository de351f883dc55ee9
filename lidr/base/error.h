#pragma once
// Errors lidr reports. Every failure a user can cause (bad files, bad values, missing GL features) is an
// lidr::Error with a message that says what was wrong and where; tools print it and exit non-zero.
#include <stdexcept>
#include <string>

namespace lidr {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A GL call failed (glGetError) or a GL object could not be built (shader compile, incomplete FBO).
class GlError : public Error {
public:
    using Error::Error;
};

// The context lacks something a requested path needs; decided before drawing.
class UnsupportedError : public Error {
public:
    using Error::Error;
};

// Throws GlError naming `where` if glGetError reports anything; drains the whole error queue.
void checkGl(const char* where);

}  // namespace lidr
