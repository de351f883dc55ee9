#pragma once
// The words of one AFF file (BART's scene format, aff_importer.h): whitespace-separated tokens with their line
// numbers. CRLF, LF and a lone CR each end a line (BART's files mix them); `{` and `}` are tokens of their own
// wherever they stand; `%` or `#` at the start of a token comments out the rest of its line. Every problem is an
// lidr::Error "<file>:<line>: <problem>".
#include <cstddef>
#include <memory>
#include <string>

namespace lidr {

// The largest AFF file read (city2.aff, the largest of BART's Robots, is 1.1 MB).
constexpr size_t maxAffFileBytes = size_t(256) << 20;

class AffTokens {
public:
    // Reads the file whole; throws lidr::Error naming it where it is missing, not a regular file or too large.
    static std::shared_ptr<const std::string> readFile(const std::string& path);
    AffTokens(std::string path, std::shared_ptr<const std::string> text);

    bool atEnd();                       // only whitespace and comments left
    std::string peek();                 // the next token, not consumed; empty at the end
    bool nextIsNumber();                // the next token reads as a number (a command never does)
    std::string word(const std::string& what);   // the next token; at the end: "expected <what>, the file ends"
    void expect(const std::string& word, const std::string& context);  // the next token must be `word`
    float number(const std::string& what);       // a finite float, else an error naming the token
    long integer(const std::string& what, long min, long max);  // a whole number in [min, max]
    [[noreturn]] void fail(const std::string& problem) const;   // at the line of the last token read
    [[noreturn]] void failAt(int line, const std::string& problem) const;
    int line() const { return line_; }  // of the last token read
    const std::string& path() const { return path_; }

private:
    void skip();  // whitespace and comments before the next token
    std::string path_;
    std::shared_ptr<const std::string> text_;
    size_t pos_ = 0;
    int nextLine_ = 1;  // the line pos_ is on
    int line_ = 1;
};

}  // namespace lidr
