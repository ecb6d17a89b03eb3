#pragma once
// Files the Scene panel offers and the screenshot names: a folder's .scene files, the recent
// list, and the next free numbered file name.

#include <cstddef>
#include <string>
#include <vector>

namespace facet::view {

/// The .scene files directly inside `folder`, sorted by name; an unreadable folder gives an
/// empty list and, when `error` is given, a message.
std::vector<std::string> listSceneFiles(const std::string& folder, std::string* error = nullptr);

/// Puts `path` (made absolute) first in `recent`, dropping an older copy and entries beyond `max`.
void pushRecent(std::vector<std::string>& recent, const std::string& path, std::size_t max);

/// `folder`/`stem`-NNNN.png with the smallest NNNN (from 0001) not taken yet.
std::string nextFreePath(const std::string& folder, const std::string& stem);

}  // namespace facet::view
