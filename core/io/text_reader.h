#pragma once
// TextReader: a line-and-token reader for the mocap text formats (ASF, AMC, BVH). It accepts LF,
// CRLF and mixed endings, keeps the 1-based line number of every token for error messages, and
// parses numbers strictly (the whole token, finite values only).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace mgp {

class TextReader {
public:
    // Reads the whole file; throws ParseError for a missing, unreadable, non-regular, empty,
    // binary (NUL-bearing) or oversized (> maxBytes) file.
    static TextReader fromFile(const std::string& path, std::size_t maxBytes = 512u << 20);
    // For tests and in-memory data; `name` is used in error messages.
    static TextReader fromString(std::string name, std::string text);

    const std::string& fileName() const { return name_; }

    // Line access (line numbers are 1-based; a trailing CR is stripped).
    bool atEnd() const { return next_ >= lines_.size(); }
    int lineNumber() const;  // number of the line nextLine() would return (or last+1 at end)
    std::string_view peekLine() const;
    std::string_view nextLine();
    int lastLineNumber() const { return static_cast<int>(lines_.size()); }

    // Skips blank lines and lines whose first non-blank character is one of `commentChars`.
    void skipBlankAndComments(std::string_view commentChars);

    [[noreturn]] void fail(const std::string& expected, const std::string& found) const;
    [[noreturn]] void failAt(int line, const std::string& expected, const std::string& found) const;

private:
    std::string name_;
    std::string text_;
    std::vector<std::string_view> lines_;
    std::size_t next_ = 0;
};

// A whole file's bytes, after the checks every reader makes (ParseError for a missing, unreadable,
// non-regular, oversized (> maxBytes) or empty file; `expectedContent` names what an empty file
// should have held). TextReader::fromFile adds the text checks.
std::string readFileBytes(const std::string& path, std::size_t maxBytes, const std::string& expectedContent);

// Splits on spaces/tabs.
std::vector<std::string_view> splitTokens(std::string_view line);
std::string_view trim(std::string_view s);
std::string toLower(std::string_view s);
// Strict parsers: the whole token must be a number; returns false otherwise (NaN/Inf rejected).
bool parseDouble(std::string_view token, double& out);
bool parseInt(std::string_view token, long long& out);
// "3, 5,8": comma-separated integers, each trimmed and parsed by parseInt, each in [lo, hi];
// false (out unspecified) if any item is not, or the text is empty.
bool parseIntList(std::string_view text, long long lo, long long hi, std::vector<long long>& out);
// "dir/35_01.amc" → "35_01" and "amc" (lower case).
std::string fileStem(const std::string& path);
std::string fileExtension(const std::string& path);
// Shortens a token for an error message ("…" past 40 characters).
std::string quoteToken(std::string_view token);

}  // namespace mgp
