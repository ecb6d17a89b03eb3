#pragma once
// Shared lexing for the line-oriented text formats (.off, .scene, the pre-check of .obj): physical
// lines with their 1-based numbers, comments, white-space tokens and locale-independent numbers.
// Private to the engine: the loaders report errors in the same words through these helpers.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "facet/error.hpp"
#include "facet/limits.hpp"
#include "io/load_progress.hpp"

namespace facet::text {

/// Drops a UTF-8 byte order mark, which some editors put at the start of text files.
inline std::string_view skipBom(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    return text;
}

/// Walks physical lines; "\n", "\r\n" and a lone "\r" all end a line (tinyobjloader counts lines
/// the same way, so line numbers agree with its messages).
class LineReader {
  public:
    explicit LineReader(std::string_view text) : text_(text) {}

    /// Next line without its terminator; false at the end of the text.
    bool next(std::string_view& line) {
        if (pos_ >= text_.size()) return false;
        const std::size_t start = pos_;
        std::size_t end = start;
        while (end < text_.size() && text_[end] != '\n' && text_[end] != '\r') ++end;
        line = text_.substr(start, end - start);
        pos_ = end;
        if (pos_ < text_.size()) {
            if (text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') ++pos_;
            ++pos_;
        }
        ++line_;
        return true;
    }

    /// 1-based number of the line last returned (0 before the first).
    int lineNumber() const { return line_; }

    /// Bytes not yet consumed.
    std::size_t remaining() const { return text_.size() - pos_; }

  private:
    std::string_view text_;
    std::size_t pos_ = 0;
    int line_ = 0;
};

/// True for the white space that separates tokens.
inline bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

/// The line without a `#` comment and surrounding white space.
inline std::string_view stripComment(std::string_view line) {
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    while (!line.empty() && isSpace(line.front())) line.remove_prefix(1);
    while (!line.empty() && isSpace(line.back())) line.remove_suffix(1);
    return line;
}

/// Splits on white space into `tokens` (cleared first; reused to avoid allocations per line).
inline void splitTokens(std::string_view line, std::vector<std::string_view>& tokens) {
    tokens.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !isSpace(line[i])) ++i;
        if (i > start) tokens.push_back(line.substr(start, i - start));
    }
}

/// Why a token is not an acceptable number.
enum class NumberStatus { ok, notANumber, nonFinite };

/// from_chars rejects a leading '+', which people do write.
inline std::string_view dropPlus(std::string_view token) {
    if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') {
        token.remove_prefix(1);
    }
    return token;
}

/// Parses a whole token as a finite float or double. Values too small for the type become
/// (signed) zero like strtod would; values too large are non-finite.
template <class T>
NumberStatus parseReal(std::string_view token, T& out) {
    token = dropPlus(token);
    if (token.empty()) return NumberStatus::notANumber;
    T value{};
    const char* first = token.data();
    const char* last = first + token.size();
    const auto [ptr, ec] = std::from_chars(first, last, value);
    if (ptr != last) return NumberStatus::notANumber;
    if (ec == std::errc::result_out_of_range) {
        // The exponent's sign tells underflow from overflow.
        const std::size_t e = token.find_first_of("eE");
        if (e == std::string_view::npos || e + 1 >= token.size() || token[e + 1] != '-') {
            return NumberStatus::nonFinite;
        }
        out = token[0] == '-' ? -T(0) : T(0);
        return NumberStatus::ok;
    }
    if (ec != std::errc()) return NumberStatus::notANumber;
    if (!std::isfinite(value)) return NumberStatus::nonFinite;
    out = value;
    return NumberStatus::ok;
}

/// Parses a whole token as a (possibly negative) integer; false if it is anything else.
inline bool parseInt(std::string_view token, std::int64_t& out) {
    token = dropPlus(token);
    if (token.empty()) return false;
    const char* first = token.data();
    const char* last = first + token.size();
    const auto [ptr, ec] = std::from_chars(first, last, out);
    return ec == std::errc() && ptr == last;
}

/// `what` quoted for a message, shortened so a binary file does not flood the terminal.
inline std::string quoted(std::string_view what, std::size_t maxLength = 40) {
    std::string s = "'";
    s += what.substr(0, maxLength);
    if (what.size() > maxLength) s += "...";
    return s + "'";
}

/// "1 number" / "3 numbers".
inline std::string countNoun(std::size_t n, std::string_view noun) {
    return std::to_string(n) + " " + std::string(noun) + (n == 1 ? "" : "s");
}

/// Reads a whole regular file of at most kMaxFileBytes; the error names the file (line 0). With
/// a meter, the read goes in chunks that report the bytes read and stop when cancelled.
inline Result<std::string> readFile(const std::string& path, io::ProgressMeter* meter = nullptr) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        return Error{{path, 0}, "is a folder, not a file"};
    }
    // A device or pipe has no size to check and may never end.
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) {
        return Error{{path, 0}, "is not a regular file"};
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{{path, 0}, "cannot open file"};
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) return Error{{path, 0}, "cannot read file"};
    if (static_cast<std::uint64_t>(size) > kMaxFileBytes) {
        return Error{{path, 0},
                     "the file is " + std::to_string(size) + " bytes; the limit is " +
                         std::to_string(kMaxFileBytes)};
    }
    in.seekg(0, std::ios::beg);
    std::string text(static_cast<std::size_t>(size), '\0');
    // A cold disk or a network folder may take seconds for a large model.
    constexpr std::size_t kChunk = std::size_t(1) << 20;
    for (std::size_t done = 0; done < text.size();) {
        const std::size_t n = std::min(kChunk, text.size() - done);
        if (!in.read(text.data() + done, static_cast<std::streamsize>(n))) {
            return Error{{path, 0}, "cannot read file"};
        }
        done += n;
        if (meter && !meter->step(done, text.size()))
            return io::ProgressMeter::cancelledError(path);
    }
    return text;
}

}  // namespace facet::text
