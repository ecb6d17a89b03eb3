#pragma once
// Mesh files: .off (course flavour, standard OFF/COFF) and .obj (through tinyobjloader).

#include <string>
#include <string_view>

#include "facet/error.hpp"
#include "facet/load_control.hpp"
#include "facet/mesh.hpp"

namespace facet {

/// Parses OFF text; `fileName` only labels errors. Polygons are fanned into triangles. The
/// optional `control` (here and in every loader below) gets the progress and may cancel.
Result<Mesh> parseOff(std::string_view text, const std::string& fileName,
                      const LoadControl* control = nullptr);

/// Reads and parses an .off file.
Result<Mesh> loadOff(const std::string& path, const LoadControl* control = nullptr);

/// Reads an .obj file (and its .mtl); v/vt/vn triples become single-index vertices, v flipped to
/// the top-down convention, map_Kd resolved into Mesh::texturePath. The `vn` normals are kept
/// (Mesh::normals) when every face corner has one; split positions are kept in positionIds.
Result<Mesh> loadObj(const std::string& path, const LoadControl* control = nullptr);

/// Loads by extension (.off or .obj, case-insensitive).
Result<Mesh> loadMesh(const std::string& path, const LoadControl* control = nullptr);

/// Writes a mesh as OFF with colours (and uv when present) in the course's vertex layout.
Status writeOff(const Mesh& mesh, const std::string& path);

}  // namespace facet
