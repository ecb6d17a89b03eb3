#pragma once
// Where screenshots go: the user's pictures folder, in a "facet" folder created on demand.
// The pictures folder is $XDG_PICTURES_DIR when set, else the XDG_PICTURES_DIR line of
// user-dirs.dirs (the file xdg-user-dirs writes into $XDG_CONFIG_HOME, else ~/.config), else
// ~/Pictures; without a home folder, the working folder.

#include <string>

#include "facet/error.hpp"

namespace facet::view {

/// What the choice depends on, read from the environment and the user-dirs file (so tests can
/// give their own).
struct PicturesEnv {
    std::string xdgPicturesDir;  ///< $XDG_PICTURES_DIR ("" when unset)
    std::string home;            ///< $HOME ("" when unset)
    std::string userDirs;        ///< the text of user-dirs.dirs ("" when absent)
};

/// The environment of this process (reads $XDG_CONFIG_HOME/user-dirs.dirs or
/// $HOME/.config/user-dirs.dirs).
PicturesEnv picturesEnvFromProcess();

/// XDG_PICTURES_DIR's value in a user-dirs.dirs text (`XDG_PICTURES_DIR="$HOME/Pictures"`, with
/// $HOME expanded; relative paths are taken from the home folder); "" when not there.
std::string picturesDirFromUserDirs(const std::string& text, const std::string& home);

/// The screenshot folder: <pictures>/facet, or "facet" in the working folder without a home.
std::string screenshotFolder(const PicturesEnv& env);

/// Creates `folder` (and its parents) when missing; the error names it.
Status ensureFolder(const std::string& folder);

}  // namespace facet::view
