#pragma once
// Files the Scene panel offers and the screenshot names: a folder's entries (a small file
// browser), the recent list kept across runs in the user's config folder, and the next free
// numbered file name.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace facet::view {

/// What a browser entry is, by its extension (the listing reads no file).
enum class EntryKind { parent, folder, scene, mesh, image };

/// One entry of a folder listing.
struct FolderEntry {
    std::string name;  ///< as shown: "..", a folder name with '/', or a file name
    std::string path;  ///< to open or to list
    EntryKind kind = EntryKind::scene;
    bool operator==(const FolderEntry&) const = default;
};

/// What a file name is to the browser: scene, mesh, image, or nullopt for anything else.
std::optional<EntryKind> entryKind(const std::string& fileName);

/// The parent folder (unless `folder` is the root), then subfolders, then the .scene, .off,
/// .obj and image files directly inside `folder`, each group sorted by name; hidden entries are
/// left out. An unreadable folder gives just the parent and, when `error` is given, a message.
std::vector<FolderEntry> listFolder(const std::string& folder, std::string* error = nullptr);

/// The .scene files directly inside `folder`, sorted by name; an unreadable folder gives an
/// empty list and, when `error` is given, a message.
std::vector<std::string> listSceneFiles(const std::string& folder, std::string* error = nullptr);

/// The viewer's folder for its settings: $XDG_CONFIG_HOME/facet, else ~/.config/facet; empty
/// when neither variable is set. Not created here.
std::string configFolder();

/// Reads a recent list (one path per line, most recent first, at most `max`); a missing file
/// is an empty list.
std::vector<std::string> readRecent(const std::string& file, std::size_t max);

/// Writes a recent list, creating the folder; false when it cannot be written.
bool writeRecent(const std::string& file, const std::vector<std::string>& recent);

/// Puts `path` (made absolute) first in `recent`, dropping an older copy and entries beyond `max`.
void pushRecent(std::vector<std::string>& recent, const std::string& path, std::size_t max);

/// Where "Save scene" proposes to write, as an absolute path: `stem`.scene in the opened file's
/// folder, or `stem`-NNNN.scene there when that is taken (the first save asks, so a read-only
/// folder is seen and changed, never silently replaced by the working folder).
std::string defaultSavePath(const std::string& opened);

/// What a drop of files on the window does: the last scene or mesh is opened, the last image
/// becomes the texture, a folder is listed in the browser; anything else is refused by name.
struct DropPlan {
    std::string open;                  ///< scene or mesh to open, or empty
    std::string texture;               ///< image to load as the texture, or empty
    std::string folder;                ///< folder to list, or empty
    std::vector<std::string> refused;  ///< "PATH: why" for each file it cannot use
};

/// Sorts dropped paths by what they hold (their content, else their extension).
DropPlan planDrop(const std::vector<std::string>& paths);

/// `folder`/`stem`-NNNN`extension` with the smallest NNNN (from 0001) not taken yet.
std::string nextFreePath(const std::string& folder, const std::string& stem,
                         const std::string& extension = ".png");

}  // namespace facet::view
