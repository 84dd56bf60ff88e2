#include "io/text_reader.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "io/parse_error.h"

namespace mgp {

std::string describeParseProblem(const std::string& file, int line, const std::string& expected,
                                 const std::string& found) {
    std::ostringstream os;
    os << file;
    if (line > 0) os << ':' << line;
    os << ": expected " << expected << ", found " << found;
    return os.str();
}

void throwParseError(const std::string& file, int line, const std::string& expected, const std::string& found) {
    throw ParseError(describeParseProblem(file, line, expected, found));
}

std::string readFileBytes(const std::string& path, std::size_t maxBytes, const std::string& expectedContent) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throwParseError(path, 0, "a readable file", std::string("none (") + std::strerror(errno) + ")");
    if (S_ISDIR(st.st_mode)) throwParseError(path, 0, "a file", "a directory");
    if (!S_ISREG(st.st_mode)) throwParseError(path, 0, "a regular file", "a special file");
    if (static_cast<unsigned long long>(st.st_size) > maxBytes)
        throwParseError(path, 0, "a file of at most " + std::to_string(maxBytes >> 20) + " MB",
                        std::to_string(st.st_size) + " bytes");
    std::ifstream in(path, std::ios::binary);
    // Say why (a chmod-000 file, EACCES, is the usual case).
    if (!in)
        throwParseError(path, 0, "a readable file",
                        std::string("a file that cannot be opened (") + std::strerror(errno) + ")");
    std::string text(static_cast<std::size_t>(st.st_size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.empty()) throwParseError(path, 0, expectedContent, "an empty file");
    return text;
}

TextReader TextReader::fromFile(const std::string& path, std::size_t maxBytes) {
    std::string text = readFileBytes(path, maxBytes, "mocap text");
    // A UTF-16 file (Windows "Unicode" save) is all NUL bytes to us: name it instead of reporting
    // "binary data".
    if (text.size() >= 2 && ((text[0] == '\xFF' && text[1] == '\xFE') || (text[0] == '\xFE' && text[1] == '\xFF')))
        throwParseError(path, 0, "UTF-8 or ASCII text",
                        text[0] == '\xFF' ? "UTF-16 (byte-order mark FF FE)" : "UTF-16 (byte-order mark FE FF)");
    if (const auto nul = text.find('\0'); nul != std::string::npos) {
        const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + nul, '\n'));
        throwParseError(path, line, "text", "binary data (a NUL byte)");
    }
    return fromString(path, std::move(text));
}

TextReader TextReader::fromString(std::string name, std::string text) {
    TextReader r;
    r.name_ = std::move(name);
    r.text_ = std::move(text);
    // A UTF-8 byte-order mark (some Windows editors write one) is not part of the first keyword.
    if (r.text_.compare(0, 3, "\xEF\xBB\xBF") == 0) r.text_.erase(0, 3);
    std::string_view all(r.text_);
    std::size_t start = 0;
    while (start < all.size()) {
        std::size_t end = all.find('\n', start);
        if (end == std::string_view::npos) end = all.size();
        std::string_view line = all.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        r.lines_.push_back(line);
        start = end + 1;
    }
    return r;
}

int TextReader::lineNumber() const { return static_cast<int>(next_) + 1; }

std::string_view TextReader::peekLine() const { return atEnd() ? std::string_view() : lines_[next_]; }

std::string_view TextReader::nextLine() {
    if (atEnd()) fail("more lines", "the end of the file");
    return lines_[next_++];
}

void TextReader::skipBlankAndComments(std::string_view commentChars) {
    while (!atEnd()) {
        std::string_view t = trim(lines_[next_]);
        if (!t.empty() && commentChars.find(t.front()) == std::string_view::npos) return;
        ++next_;
    }
}

void TextReader::fail(const std::string& expected, const std::string& found) const {
    failAt(std::min<int>(lineNumber(), std::max(1, lastLineNumber())), expected, found);
}

void TextReader::failAt(int line, const std::string& expected, const std::string& found) const {
    throwParseError(name_, line, expected, found);
}

std::vector<std::string_view> splitTokens(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        std::size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
        if (j > i) out.push_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

std::string toLower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool parseDouble(std::string_view token, double& out) {
    if (token.empty() || token.size() > 64) return false;
    char buf[80];
    std::memcpy(buf, token.data(), token.size());
    buf[token.size()] = '\0';
    // strtod accepts "nan"/"inf"/hex; require a plain decimal number.
    for (char c : token)
        if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E'))
            return false;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(buf, &end);
    if (end != buf + token.size() || errno == ERANGE || !std::isfinite(v)) return false;
    out = v;
    return true;
}

bool parseInt(std::string_view token, long long& out) {
    if (token.empty() || token.size() > 19) return false;
    long long v = 0;
    std::size_t i = 0;
    bool neg = false;
    if (token[0] == '-' || token[0] == '+') {
        neg = token[0] == '-';
        i = 1;
        if (token.size() == 1) return false;
    }
    for (; i < token.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(token[i]))) return false;
        // 19 digits can exceed 2^63 − 1 (signed overflow, found by fuzzing): not a number.
        if (v > (std::numeric_limits<long long>::max() - (token[i] - '0')) / 10) return false;
        v = v * 10 + (token[i] - '0');
    }
    out = neg ? -v : v;
    return true;
}

bool parseIntList(std::string_view text, long long lo, long long hi, std::vector<long long>& out) {
    out.clear();
    if (text.empty()) return false;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        long long v = 0;
        const std::string_view item =
            text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start);
        if (!parseInt(trim(item), v) || v < lo || v > hi) return false;
        out.push_back(v);
        if (comma == std::string_view::npos) return true;
        start = comma + 1;
    }
}

std::string fileStem(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    const std::size_t dot = base.find_last_of('.');
    return dot == std::string::npos ? base : base.substr(0, dot);
}

std::string fileExtension(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    return toLower(path.substr(dot + 1));
}

std::string quoteToken(std::string_view token) {
    std::string t(token.substr(0, 40));
    for (char& c : t)
        if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    return "'" + t + (token.size() > 40 ? "...'" : "'");
}

}  // namespace mgp
