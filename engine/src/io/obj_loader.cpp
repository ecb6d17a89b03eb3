// The .obj reader (spec §3) on top of tinyobjloader.
//
// tinyobjloader is lenient where this project wants errors: it reads "nan" or "abc" as 0, accepts
// out-of-range indices with a warning (and its ear-clipper then reads past its arrays for
// polygons of five or more corners, in quadratic time) and reports most problems without a line.
// So the text is first checked here, line by line; tinyobjloader then parses that same text
// without triangulating, and the polygons are fanned here, as OFF polygons are, after every index
// has been checked. Material files are read through MtlReader, under the same size limit.
//
// tinyobjloader keeps a face's corner count in an unsigned char, so a face of more than 255
// corners is handed to it as several faces that share the first corner and form together the
// same fan (same triangles, order and winding); each keeps the line of the face it came from.
//
// A map_Kd texture is resolved relative to the .obj's folder and kept even when that file is
// missing: the texture loader then reports the path it could not open, which tells the user more
// than a texture that silently disappeared.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <streambuf>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <tiny_obj_loader.h>
#include <glm/geometric.hpp>

#include "facet/limits.hpp"
#include "facet/mesh_io.hpp"
#include "io/load_progress.hpp"
#include "io/text_scan.hpp"

namespace facet {

namespace {

// tinyobjloader stores a face's corner count in an unsigned char.
constexpr std::size_t tinyObjMaxCorners = 255;

// A face line the line check wrote as `extra` + 1 lines of the text tinyobjloader reads.
struct SplitFace {
    int line = 0;
    int extra = 0;
    bool operator==(const SplitFace&) const = default;
};

// What the line check learned: the line of every face, in the order tinyobjloader lists faces,
// and, when some face had more than tinyObjMaxCorners corners, the text to give tinyobjloader
// instead of the file's, with those faces split.
struct ObjLines {
    std::vector<int> faceLines;
    std::string splitText;
    std::vector<SplitFace> splits;

    // The file's line for line `line` of the text tinyobjloader read.
    int originalLine(int line) const {
        int shift = 0;
        for (const SplitFace& split : splits) {
            if (line < split.line + shift) break;
            if (line <= split.line + shift + split.extra) return split.line;
            shift += split.extra;
        }
        return line - shift;
    }
};

// Appends `corners` (a face's corner tokens) to `out` as faces of at most tinyObjMaxCorners
// corners: c0 c1 .. c254, then c0 c254 c255 .., each starting at the first corner and at the
// last corner of the one before, so that fanning each from its first corner gives the fan of the
// whole face. Returns how many faces it wrote.
int appendSplitFace(std::string& out, const std::string_view* corners, std::size_t count) {
    int faces = 0;
    std::size_t begin = 1;
    while (begin < count - 1) {
        const std::size_t end = std::min(begin + tinyObjMaxCorners - 2, count - 1);
        if (faces > 0) out += '\n';
        out += "f ";
        out += corners[0];
        for (std::size_t i = begin; i <= end; ++i) out.append(" ").append(corners[i]);
        ++faces;
        begin = end;
    }
    return faces;
}

// Opens the .mtl files an OBJ names as tinyobjloader's own reader does (relative to the OBJ's
// folder), but refuses what is not a regular file or exceeds kMaxFileBytes: "mtllib /dev/zero"
// must not read forever.
class MtlReader : public tinyobj::MaterialReader {
  public:
    explicit MtlReader(std::filesystem::path folder) : folder_(std::move(folder)) {}

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* names, std::string* warn,
                    std::string* err) override {
        const std::string path =
            (folder_.empty() ? std::filesystem::path(name) : folder_ / name).string();
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec)) {
            if (warn) *warn += "material file " + path + " not found\n";
            return false;
        }
        auto text = text::readFile(path);
        if (!text) {
            if (problem_) problem_ = text.error();
            return false;
        }
        std::istringstream stream(std::move(*text));
        tinyobj::LoadMtl(names, materials, &stream, warn, err);
        return true;
    }

    // The first material file that could not be read within the limits.
    const Status& problem() const { return problem_; }

  private:
    std::filesystem::path folder_;
    Status problem_;
};

// Checks the numbers of a `v`, `vt` or `vn` line (tokens after the keyword).
std::optional<std::string> checkNumbers(const std::vector<std::string_view>& tokens) {
    for (std::size_t i = 1; i < tokens.size(); ++i) {
        float v = 0.0f;
        switch (text::parseReal(tokens[i], v)) {
            case text::NumberStatus::ok:
                break;
            case text::NumberStatus::notANumber:
                return "expected a number, got " + text::quoted(tokens[i]);
            case text::NumberStatus::nonFinite:
                return "non-finite number " + text::quoted(tokens[i]) +
                       " (coordinates must be finite)";
        }
    }
    return std::nullopt;
}

// Checks one face corner: "v", "v/vt", "v//vn" or "v/vt/vn" with non-zero integers.
std::optional<std::string> checkCorner(std::string_view corner) {
    const auto bad = [&] {
        return "expected a face corner like 7, 7/3, 7//2 or 7/3/2, got " + text::quoted(corner);
    };
    std::size_t part = 0;
    std::size_t start = 0;
    while (true) {
        const std::size_t slash = corner.find('/', start);
        const std::string_view field = corner.substr(start, slash - start);
        // Only the texture slot of "v//vn" may be empty.
        if (!(field.empty() && part == 1 && slash != std::string_view::npos)) {
            std::int64_t index = 0;
            if (!text::parseInt(field, index)) return bad();
            if (index == 0) {
                return "index 0 in " + text::quoted(corner) + ": OBJ indices start at 1";
            }
        }
        if (slash == std::string_view::npos) break;
        if (++part > 2) return bad();
        start = slash + 1;
    }
    return std::nullopt;
}

// The checks tinyobjloader does not make, with line numbers.
Result<ObjLines> checkObjText(std::string_view text, const std::string& path,
                              io::ProgressMeter& meter) {
    ObjLines result;
    std::uint64_t positions = 0, texcoords = 0, corners = 0, triangles = 0;
    std::size_t copied = 0;  // bytes of `text` already in result.splitText
    text::LineReader lines(text::skipBom(text));
    std::vector<std::string_view> tokens;
    std::string_view line;
    while (lines.next(line)) {
        const int number = lines.lineNumber();
        if (static_cast<std::uint64_t>(number) % io::kLinesPerStep == 0 &&
            !meter.step(text.size() - lines.remaining(), text.size())) {
            return io::ProgressMeter::cancelledError(path);
        }
        const auto fail = [&](std::string message) {
            return Error{{path, number}, std::move(message)};
        };
        // tinyobjloader reads face lines whole, so a comment there is an error (below); for the
        // other lines it is harmless to drop it.
        text::splitTokens(line, tokens);
        if (tokens.empty() || tokens[0].front() == '#') continue;
        const std::string_view keyword = tokens[0];
        if (keyword == "v" || keyword == "vt" || keyword == "vn") {
            text::splitTokens(text::stripComment(line), tokens);
            const std::size_t need = keyword == "vt" ? 1 : 3;
            if (tokens.size() - 1 < need) {
                if (keyword == "vt") return fail("a texture coordinate needs u [v]");
                return fail(std::string(keyword == "v" ? "a vertex" : "a normal") +
                            " needs 3 numbers (x y z), got " + std::to_string(tokens.size() - 1));
            }
            if (auto message = checkNumbers(tokens)) return fail(*message);
            ++(keyword == "v" ? positions : texcoords);
        } else if (keyword == "f") {
            const std::size_t n = tokens.size() - 1;
            if (n < 3) return fail("a face needs at least 3 vertices, got " + std::to_string(n));
            // Checked before the corners, so an absurd face costs one pass over its line.
            if (n > kMaxObjFaceCorners) {
                return fail("a face has " + std::to_string(n) + " vertices; at most " +
                            std::to_string(kMaxObjFaceCorners) + " are supported");
            }
            for (std::size_t i = 1; i < tokens.size(); ++i) {
                if (auto message = checkCorner(tokens[i])) return fail(*message);
            }
            if (n <= tinyObjMaxCorners) {
                result.faceLines.push_back(number);
            } else {
                // The text up to this line as it is, then the face as several.
                const auto lineStart = static_cast<std::size_t>(line.data() - text.data());
                result.splitText.append(text, copied, lineStart - copied);
                const int faces = appendSplitFace(result.splitText, &tokens[1], n);
                copied = lineStart + line.size();
                result.faceLines.insert(result.faceLines.end(), static_cast<std::size_t>(faces),
                                        number);
                result.splits.push_back({number, faces - 1});
            }
            corners += n;
            triangles += n - 2;
        }
    }
    // One engine vertex per distinct (position, texcoord) pair a corner uses.
    const std::uint64_t vertices = std::min(corners, positions * (texcoords + 1));
    if (auto problem = meshMemoryProblem(vertices, triangles)) return Error{{path, 0}, *problem};
    if (!result.splits.empty()) result.splitText.append(text, copied);
    return result;
}

// What tinyobjloader reads the text through: handed out in chunks, each boundary a progress
// report and a cancellation point. A cancelled load sees the end of the text, which stops
// tinyobjloader as the end of a file would; the caller then returns the cancelled error.
class MeteredText : public std::streambuf {
  public:
    MeteredText(std::string& text, io::ProgressMeter& meter) : text_(text), meter_(meter) {}

  protected:
    int_type underflow() override {
        if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
        if (next_ >= text_.size() || !meter_.step(next_, text_.size())) return traits_type::eof();
        constexpr std::size_t kChunk = std::size_t(1) << 18;
        const std::size_t n = std::min(kChunk, text_.size() - next_);
        char* begin = text_.data() + next_;
        setg(begin, begin, begin + n);
        next_ += n;
        return traits_type::to_int_type(*begin);
    }

  private:
    std::string& text_;
    io::ProgressMeter& meter_;
    std::size_t next_ = 0;
};

// The line number in a tinyobjloader message ("... line 12.)"), 0 if none.
int lineInMessage(const std::string& message) {
    const std::size_t at = message.find("line ");
    if (at == std::string::npos) return 0;
    int line = 0;
    for (std::size_t i = at + 5; i < message.size() && message[i] >= '0' && message[i] <= '9';
         ++i) {
        line = line * 10 + (message[i] - '0');
    }
    return line;
}

// One engine vertex per distinct corner: position, texcoord and (when used) normal index.
struct CornerKey {
    std::int64_t v = 0;
    std::int64_t vt = -1;
    std::int64_t vn = -1;
    bool operator==(const CornerKey&) const = default;
};

struct CornerKeyHash {
    std::size_t operator()(const CornerKey& k) const {
        const std::uint64_t h = static_cast<std::uint64_t>(k.v) * 0x9E3779B97F4A7C15ull ^
                                static_cast<std::uint64_t>(k.vt + 1) * 0xC2B2AE3D27D4EB4Full ^
                                static_cast<std::uint64_t>(k.vn + 1) * 0x165667B19E3779F9ull;
        return static_cast<std::size_t>(h ^ (h >> 31));
    }
};

// True when every corner of every face names a normal (spec §3: only then are the
// file's normals used; a partial set would leave some vertices without one).
bool everyCornerHasNormal(const tinyobj::attrib_t& attrib,
                          const std::vector<tinyobj::shape_t>& shapes) {
    if (attrib.normals.empty()) return false;
    for (const auto& shape : shapes) {
        for (const tinyobj::index_t& idx : shape.mesh.indices) {
            if (idx.normal_index < 0) return false;
        }
    }
    return true;
}

std::string firstLine(const std::string& message) {
    return message.substr(0, message.find('\n'));
}

// The map_Kd of the first material a face uses, else of any material, else empty.
std::string diffuseTexture(const std::vector<tinyobj::shape_t>& shapes,
                           const std::vector<tinyobj::material_t>& materials) {
    for (const auto& shape : shapes) {
        for (const int id : shape.mesh.material_ids) {
            if (id >= 0 && static_cast<std::size_t>(id) < materials.size() &&
                !materials[static_cast<std::size_t>(id)].diffuse_texname.empty()) {
                return materials[static_cast<std::size_t>(id)].diffuse_texname;
            }
        }
    }
    for (const auto& m : materials) {
        if (!m.diffuse_texname.empty()) return m.diffuse_texname;
    }
    return {};
}

}  // namespace

Result<Mesh> loadObj(const std::string& path, const LoadControl* control) {
    // The phases' shares of the time, measured on Nefertiti (100k triangles): reading 2 %,
    // the line check 20 %, tinyobjloader 60 %, building the mesh 18 %.
    io::ProgressMeter meter(control);
    meter.phase(0.0f, 0.02f);
    auto text = text::readFile(path, &meter);
    if (!text) return text.error();
    meter.phase(0.02f, 0.22f);
    auto lines = checkObjText(*text, path, meter);
    if (!lines) return lines.error();
    const std::vector<int>& faceLines = lines->faceLines;

    // The text just checked, not the file again: it may have changed on disk since.
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    MtlReader mtl(std::filesystem::path(path).parent_path());
    {
        // Faces longer than tinyobjloader takes were rewritten into pieces (checkObjText).
        if (!lines->splits.empty()) text->swap(lines->splitText);
        meter.phase(0.22f, 0.82f);
        MeteredText buffer(*text, meter);
        std::istream stream(&buffer);
        // triangulate off: fanned below, after the indices are known to be valid; vertex colours
        // without a fallback, so that attrib.colors stays empty when the file has none.
        const bool parsed = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &stream,
                                             &mtl, /*triangulate=*/false,
                                             /*default_vcols_fallback=*/false);
        if (meter.cancelled()) return io::ProgressMeter::cancelledError(path);
        if (!mtl.problem()) return mtl.problem().error();
        if (!parsed) {
            return Error{{path, lines->originalLine(lineInMessage(err))},
                         "cannot parse OBJ: " + firstLine(err)};
        }
    }
    std::string().swap(*text);  // parsed: its memory goes before the mesh's is taken
    std::string().swap(lines->splitText);
    meter.phase(0.82f, 1.0f);
    const auto positionCount = static_cast<std::int64_t>(attrib.vertices.size() / 3);
    const auto texcoordCount = static_cast<std::int64_t>(attrib.texcoords.size() / 2);
    const bool hasColors = !attrib.colors.empty() && attrib.colors.size() == attrib.vertices.size();

    std::size_t faceCount = 0;
    std::size_t cornerCount = 0;
    for (const auto& shape : shapes) {
        faceCount += shape.mesh.num_face_vertices.size();
        cornerCount += shape.mesh.indices.size();
    }
    if (faceCount == 0) return Error{{path, 0}, "no faces: the file has no triangles to draw"};
    // The line check and tinyobjloader agree on what a face line is; if they ever did not, the
    // error below would point at the wrong line, so it names none instead.
    const bool linesKnown = faceLines.size() == faceCount;

    Mesh mesh;
    mesh.positions.reserve(cornerCount / 2);
    mesh.uvs.reserve(texcoordCount > 0 ? cornerCount / 2 : 0);
    mesh.indices.reserve(3 * cornerCount);
    bool anyUv = false;
    const bool useNormals = everyCornerHasNormal(attrib, shapes);
    const auto normalCount = static_cast<std::int64_t>(attrib.normals.size() / 3);
    // One engine vertex per distinct (position, texcoord[, normal]) triple; positionIds remembers
    // the position each came from, kept only if some position was split.
    std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> merged;
    merged.reserve(cornerCount);
    std::vector<bool> positionUsed(static_cast<std::size_t>(positionCount), false);
    bool positionSplit = false;
    std::vector<std::uint32_t> corners;
    std::size_t face = 0;
    for (const auto& shape : shapes) {
        std::size_t offset = 0;
        for (const unsigned char n : shape.mesh.num_face_vertices) {
            if (face % (4 * io::kLinesPerStep) == 0 && !meter.step(face, faceCount))
                return io::ProgressMeter::cancelledError(path);
            const int line = linesKnown ? faceLines[face] : 0;
            corners.clear();
            for (std::size_t k = 0; k < n; ++k) {
                const tinyobj::index_t& idx = shape.mesh.indices[offset + k];
                const std::int64_t v = idx.vertex_index;
                const std::int64_t vt = idx.texcoord_index;
                if (v < 0 || v >= positionCount) {
                    return Error{{path, line},
                                 "vertex index out of range: the face refers to vertex " +
                                     std::to_string(v + 1) + " but the file has " +
                                     std::to_string(positionCount) + " (1 to " +
                                     std::to_string(positionCount) + ")"};
                }
                if (vt < -1 || vt >= texcoordCount) {
                    return Error{{path, line},
                                 "texture coordinate index out of range: the face refers to vt " +
                                     std::to_string(vt + 1) + " but the file has " +
                                     std::to_string(texcoordCount)};
                }
                const std::int64_t vn = useNormals ? idx.normal_index : -1;
                if (vn >= normalCount) {
                    return Error{{path, line},
                                 "normal index out of range: the face refers to vn " +
                                     std::to_string(vn + 1) + " but the file has " +
                                     std::to_string(normalCount)};
                }
                const auto [it, inserted] = merged.try_emplace(
                    CornerKey{v, vt, vn}, static_cast<std::uint32_t>(mesh.positions.size()));
                if (inserted) {
                    const auto vi = static_cast<std::size_t>(v);
                    positionSplit = positionSplit || positionUsed[vi];
                    positionUsed[vi] = true;
                    mesh.positionIds.push_back(static_cast<std::uint32_t>(v));
                    if (useNormals) {
                        const auto ni = static_cast<std::size_t>(vn);
                        const glm::vec3 normal(attrib.normals[3 * ni], attrib.normals[3 * ni + 1],
                                               attrib.normals[3 * ni + 2]);
                        const float length = glm::length(normal);
                        // A zero vn gives no diffuse or specular term, as a computed one would.
                        mesh.normals.push_back(length > 0.0f ? normal / length : glm::vec3(0.0f));
                    }
                    mesh.positions.emplace_back(attrib.vertices[3 * vi],
                                                attrib.vertices[3 * vi + 1],
                                                attrib.vertices[3 * vi + 2]);
                    if (hasColors) {
                        mesh.colors.emplace_back(attrib.colors[3 * vi], attrib.colors[3 * vi + 1],
                                                 attrib.colors[3 * vi + 2]);
                    }
                    if (texcoordCount > 0) {
                        // OBJ puts v = 0 at the image bottom, the engine at the top. A corner
                        // without vt in a file that has some gets (0, 0).
                        glm::vec2 uv(0.0f);
                        if (vt >= 0) {
                            const auto ti = static_cast<std::size_t>(vt);
                            uv = {attrib.texcoords[2 * ti], 1.0f - attrib.texcoords[2 * ti + 1]};
                            anyUv = true;
                        }
                        mesh.uvs.push_back(uv);
                    }
                }
                corners.push_back(it->second);
            }
            for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
                mesh.indices.insert(mesh.indices.end(), {corners[0], corners[k], corners[k + 1]});
            }
            offset += n;
            ++face;
        }
    }
    if (!anyUv) mesh.uvs.clear();
    if (!positionSplit) mesh.positionIds = {};

    const std::string texture = diffuseTexture(shapes, materials);
    if (!texture.empty()) {
        std::string named = texture;
        std::replace(named.begin(), named.end(), '\\', '/');  // written on Windows
        const std::filesystem::path file(named);
        mesh.texturePath = file.is_absolute()
                               ? file.string()
                               : (std::filesystem::path(path).parent_path() / file).string();
    }
    meter.finish();
    return mesh;
}

}  // namespace facet
