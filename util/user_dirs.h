#pragma once
// Where villa keeps what a user's runs share (caches), as the XDG base directory spec says.
#include <filesystem>

namespace villa {

// $XDG_CACHE_HOME/villa, else $HOME/.cache/villa (a relative XDG value is ignored, as the spec says).
std::filesystem::path UserCacheDir();

}  // namespace villa
