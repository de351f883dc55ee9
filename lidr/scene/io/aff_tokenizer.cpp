#include "lidr/scene/io/aff_tokenizer.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>

#include "lidr/base/error.h"
#include "lidr/scene/io/file_checks.h"

namespace lidr {

namespace {
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
bool isBrace(char c) { return c == '{' || c == '}'; }
}  // namespace

std::shared_ptr<const std::string> AffTokens::readFile(const std::string& path) {
    return std::make_shared<const std::string>(readWholeFile(path, maxAffFileBytes, "AFF file"));
}

AffTokens::AffTokens(std::string path, std::shared_ptr<const std::string> text)
    : path_(std::move(path)), text_(std::move(text)) {}

void AffTokens::skip() {
    const std::string& t = *text_;
    while (pos_ < t.size()) {
        const char c = t[pos_];
        if (c == '\n' || c == '\r') {
            ++nextLine_;
            pos_ += (c == '\r' && pos_ + 1 < t.size() && t[pos_ + 1] == '\n') ? 2 : 1;  // CRLF is one line end
        } else if (isSpace(c)) {
            ++pos_;
        } else if (c == '%' || c == '#') {
            while (pos_ < t.size() && t[pos_] != '\n' && t[pos_] != '\r') ++pos_;
        } else {
            return;
        }
    }
}

bool AffTokens::atEnd() {
    skip();
    return pos_ >= text_->size();
}

std::string AffTokens::peek() {
    skip();
    const std::string& t = *text_;
    if (pos_ >= t.size()) return {};
    if (isBrace(t[pos_])) return std::string(1, t[pos_]);
    size_t end = pos_;
    while (end < t.size() && !isSpace(t[end]) && !isBrace(t[end])) ++end;
    return t.substr(pos_, end - pos_);
}

std::string AffTokens::word(const std::string& what) {
    const std::string token = peek();
    if (token.empty()) fail("expected " + what + ", the file ends");  // at the last token's line
    line_ = nextLine_;
    pos_ += token.size();
    return token;
}

void AffTokens::expect(const std::string& expected, const std::string& context) {
    const std::string got = word("'" + expected + "' (" + context + ")");
    if (got != expected) fail("expected '" + expected + "' (" + context + "), got '" + clipped(got, 40) + "'");
}

namespace {
// The token as a double, or false where it is not one whole number.
bool parseNumber(const std::string& token, double& value) {
    if (token.empty() || token.size() > 64) return false;
    errno = 0;
    char* end = nullptr;
    value = std::strtod(token.c_str(), &end);
    return end == token.c_str() + token.size();
}
}  // namespace

bool AffTokens::nextIsNumber() {
    double value = 0.0;
    return parseNumber(peek(), value);
}

float AffTokens::number(const std::string& what) {
    const std::string token = word(what);
    double value = 0.0;
    if (!parseNumber(token, value)) fail(what + " '" + clipped(token, 40) + "' is not a number");
    if (!std::isfinite(value) || std::abs(value) > double(std::numeric_limits<float>::max()))
        fail(what + " '" + clipped(token, 40) + "' is not a finite float");
    return float(value);
}

long AffTokens::integer(const std::string& what, long min, long max) {
    const std::string token = word(what);
    double value = 0.0;
    if (!parseNumber(token, value) || value != std::floor(value) || !std::isfinite(value))
        fail(what + " '" + clipped(token, 40) + "' is not a whole number");
    if (value < double(min) || value > double(max))
        fail(what + " " + clipped(token, 40) + " is out of range (" + std::to_string(min) + " .. " + std::to_string(max) + ")");
    return long(value);
}

void AffTokens::fail(const std::string& problem) const { failAt(line_, problem); }

void AffTokens::failAt(int line, const std::string& problem) const {
    throw Error(path_ + ":" + std::to_string(line) + ": " + problem);
}

}  // namespace lidr
