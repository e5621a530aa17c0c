#pragma once
// SHA-256 of a file's bytes, as the scene file records its layout and asset library (SCENE.md
// `layout.sha256`, `library.sha256`): a reader can tell whether the files it finds are the ones the scene
// was made from. OpenSSL's libcrypto does the hashing, inside file_digest.cpp.
#include <filesystem>
#include <string>
#include <string_view>

#include "util/result.h"

namespace villa::scene {

// 64 lowercase hex digits.
std::string Sha256Hex(std::string_view bytes);
// Of the whole file; the error names the file.
Result<std::string> FileSha256(const std::filesystem::path& path);

}  // namespace villa::scene
