// The .off reader (spec §2): the course's line-oriented flavour and standard OFF/COFF.
// Every malformed input becomes an Error naming the file and line; the header's counts are checked
// against the file size before anything is allocated, so a corrupt header cannot exhaust memory.

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "facet/limits.hpp"
#include "facet/mesh_io.hpp"
#include "io/load_progress.hpp"
#include "io/text_scan.hpp"

namespace facet {

namespace {

// Lower bounds on the bytes a vertex line ("0 0 0\n") and a face line ("3 0 1 2\n") take.
constexpr std::uint64_t minVertexBytes = 6;
constexpr std::uint64_t minFaceBytes = 8;

bool isVertexLayout(std::size_t numbers) {
    return numbers == 3 || numbers == 6 || numbers == 7 || numbers == 8;
}

// Not through an integer cast: a colour of 4.4e35 (found by fuzzing) does not fit in one.
bool isWholeNumber(float v) {
    return std::trunc(v) == v;
}

// Streams the non-blank, comment-free lines of an OFF text as tokens.
class OffReader {
  public:
    OffReader(std::string_view text, const std::string& fileName)
        : lines_(text::skipBom(text)), fileName_(fileName) {}

    // Advances to the next line with content; false at the end of the text.
    bool next() {
        std::string_view line;
        while (lines_.next(line)) {
            text::splitTokens(text::stripComment(line), tokens_);
            if (!tokens_.empty()) return true;
        }
        return false;
    }

    const std::vector<std::string_view>& tokens() const { return tokens_; }
    int line() const { return lines_.lineNumber(); }
    std::size_t remainingBytes() const { return lines_.remaining(); }

    Error error(std::string message) const {
        return Error{{fileName_, line()}, std::move(message)};
    }

    // Parses token `i` of the current line as a finite float, or explains why not.
    bool real(std::size_t i, float& out, Error& err) const {
        switch (text::parseReal(tokens_[i], out)) {
            case text::NumberStatus::ok:
                return true;
            case text::NumberStatus::notANumber:
                err = error("expected a number, got " + text::quoted(tokens_[i]));
                return false;
            case text::NumberStatus::nonFinite:
                err = error("non-finite number " + text::quoted(tokens_[i]) +
                            " (coordinates and attributes must be finite)");
                return false;
        }
        return false;
    }

  private:
    text::LineReader lines_;
    const std::string& fileName_;
    std::vector<std::string_view> tokens_;
};

// Reads "NV NF [NE]" starting at token `first` of the current line.
Result<std::pair<std::int64_t, std::int64_t>> readCounts(const OffReader& in, std::size_t first) {
    const auto& t = in.tokens();
    const std::size_t n = t.size() - first;
    if (n < 2 || n > 3) {
        return in.error("the counts line needs 3 integers (NV NF NE; NE may be left out), got " +
                        std::to_string(n));
    }
    std::int64_t nv = 0;
    std::int64_t nf = 0;
    if (!text::parseInt(t[first], nv) || nv < 0) {
        return in.error("vertex count NV must be a non-negative integer, got " +
                        text::quoted(t[first]));
    }
    if (!text::parseInt(t[first + 1], nf) || nf < 0) {
        return in.error("face count NF must be a non-negative integer, got " +
                        text::quoted(t[first + 1]));
    }
    // NE (edges) is ignored, as every reader of OFF does.
    return std::pair{nv, nf};
}

// The parser proper; `meter` is in the phase the caller chose and counts bytes consumed.
Result<Mesh> parseOffText(std::string_view text, const std::string& fileName,
                          io::ProgressMeter& meter) {
    OffReader in(text, fileName);
    // Every kLinesPerStep vertices or faces: report the bytes consumed, stop if cancelled.
    const auto stepOn = [&](std::int64_t i) {
        return (static_cast<std::uint64_t>(i) % io::kLinesPerStep) != 0 ||
               meter.step(text.size() - in.remainingBytes(), text.size());
    };
    Error err;

    // Header: OFF or COFF, counts on the same line or the next.
    if (!in.next()) return in.error("empty file: expected OFF or COFF");
    const std::string_view magic = in.tokens()[0];
    if (magic != "OFF" && magic != "COFF") {
        return in.error("expected OFF or COFF as the first word, got " + text::quoted(magic));
    }
    std::size_t first = 1;
    if (in.tokens().size() == 1) {
        if (!in.next()) return in.error("file ends before the counts line (NV NF NE)");
        first = 0;
    }
    auto counts = readCounts(in, first);
    if (!counts) return counts.error();
    const auto [nv, nf] = *counts;
    if (nv == 0 && nf > 0) {
        return in.error("the header promises " + text::countNoun(std::uint64_t(nf), "face") +
                        " but no vertices");
    }
    if (nf == 0) return in.error("no faces (NF = 0): the file has no triangles to draw");

    const std::uint64_t bytes = in.remainingBytes();
    const std::uint64_t room = bytes + 1;  // the last line may lack its newline
    const auto unv = static_cast<std::uint64_t>(nv);
    const auto unf = static_cast<std::uint64_t>(nf);
    if (unv > room / minVertexBytes || unf > room / minFaceBytes ||
        unv * minVertexBytes + unf * minFaceBytes > room ||
        unv > std::numeric_limits<std::uint32_t>::max()) {
        return in.error("header promises " + std::to_string(nv) + " vertices and " +
                        std::to_string(nf) + " faces but the file has only " +
                        std::to_string(bytes) + " bytes after it");
    }
    if (auto problem = meshMemoryProblem(unv, unf)) return in.error(*problem);

    Mesh mesh;
    mesh.positions.reserve(unv);

    // Vertices: the first line fixes the layout for the whole file.
    std::size_t layout = 0;
    int layoutLine = 0;
    bool colorsAllWhole = true;
    bool colorsAbove1 = false;
    for (std::int64_t i = 0; i < nv; ++i) {
        if (!stepOn(i)) return io::ProgressMeter::cancelledError(fileName);
        if (!in.next()) {
            return in.error("file ends after " + std::to_string(i) + " of " + std::to_string(nv) +
                            " vertices");
        }
        const std::size_t n = in.tokens().size();
        if (layout == 0) {
            if (!isVertexLayout(n)) {
                return in.error(
                    "a vertex needs 3, 6, 7 or 8 numbers (x y z | x y z r g b | x y z r g b a | "
                    "x y z r g b u v), got " +
                    std::to_string(n));
            }
            layout = n;
            layoutLine = in.line();
            if (layout >= 6) mesh.colors.reserve(unv);
            if (layout == 8) mesh.uvs.reserve(unv);
        } else if (n != layout) {
            return in.error("vertex has " + text::countNoun(n, "number") +
                            " but the first vertex (line " + std::to_string(layoutLine) + ") has " +
                            std::to_string(layout) + "; every vertex line needs the same layout");
        }
        float v[8];
        for (std::size_t k = 0; k < n; ++k) {
            if (!in.real(k, v[k], err)) return err;
        }
        mesh.positions.emplace_back(v[0], v[1], v[2]);
        if (layout >= 6) {
            mesh.colors.emplace_back(v[3], v[4], v[5]);
            for (std::size_t k = 3; k < 6; ++k) {
                colorsAllWhole = colorsAllWhole && isWholeNumber(v[k]);
                colorsAbove1 = colorsAbove1 || v[k] > 1.0f;
            }
        }
        if (layout == 8) mesh.uvs.emplace_back(v[6], v[7]);
    }
    // spec §2: integer colours above 1 mean the file uses 0-255.
    if (colorsAllWhole && colorsAbove1) {
        for (auto& c : mesh.colors) c /= 255.0f;
    }

    // Faces: polygons are split as a fan (i0, ik, ik+1).
    mesh.indices.reserve(unf * 3);
    std::vector<std::uint32_t> corners;
    for (std::int64_t f = 0; f < nf; ++f) {
        if (!stepOn(f)) return io::ProgressMeter::cancelledError(fileName);
        if (!in.next()) {
            return in.error("file ends after " + std::to_string(f) + " of " + std::to_string(nf) +
                            " faces");
        }
        const auto& t = in.tokens();
        std::int64_t n = 0;
        if (!text::parseInt(t[0], n)) {
            return in.error("a face must start with its vertex count n, got " + text::quoted(t[0]));
        }
        if (n < 3) {
            return in.error("a face needs at least 3 vertices, got n = " + std::to_string(n));
        }
        if (static_cast<std::uint64_t>(n) > t.size() - 1) {
            return in.error("face says " + std::to_string(n) + " vertices but lists only " +
                            std::to_string(t.size() - 1) + (t.size() == 2 ? " index" : " indices"));
        }
        corners.clear();
        for (std::int64_t k = 1; k <= n; ++k) {
            const std::string_view tok = t[static_cast<std::size_t>(k)];
            std::int64_t index = 0;
            if (!text::parseInt(tok, index)) {
                return in.error("expected a vertex index, got " + text::quoted(tok));
            }
            if (index < 0 || index >= nv) {
                return in.error("vertex index " + std::to_string(index) +
                                " out of range: the file has " + std::to_string(nv) +
                                " vertices (0 to " + std::to_string(nv - 1) + ")");
            }
            corners.push_back(static_cast<std::uint32_t>(index));
        }
        for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
            mesh.indices.insert(mesh.indices.end(), {corners[0], corners[k], corners[k + 1]});
        }
    }
    // Anything after the last face (some exporters append notes) is ignored.
    return mesh;
}

}  // namespace

Result<Mesh> parseOff(std::string_view text, const std::string& fileName,
                      const LoadControl* control) {
    io::ProgressMeter meter(control);
    auto mesh = parseOffText(text, fileName, meter);
    if (mesh) meter.finish();
    return mesh;
}

Result<Mesh> loadOff(const std::string& path, const LoadControl* control) {
    io::ProgressMeter meter(control);
    // Reading is a few times faster than parsing, byte for byte.
    meter.phase(0.0f, 0.1f);
    auto text = text::readFile(path, &meter);
    if (!text) return text.error();
    meter.phase(0.1f, 1.0f);
    auto mesh = parseOffText(*text, path, meter);
    if (mesh) meter.finish();
    return mesh;
}

}  // namespace facet
