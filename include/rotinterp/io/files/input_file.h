// The files a read opens: the input itself and every file it refers to (a glTF
// buffer's uri). Each is checked the same way before a byte is read: a regular file
// (a FIFO, a device or /dev/zero would block or never end), not empty; a referenced
// file also stays in the input's folder unless the caller allows otherwise.
#pragma once

#include "rotinterp/core/result.h"

#include <filesystem>
#include <string>

namespace rotinterp {

// Before any parser runs: the path names a non-empty regular file we may open
// (errors of kind no_file, directory, cannot_open or unreadable).
Status check_file(const std::filesystem::path& path, const std::string& label);

// check_file, then the whole file's bytes.
Result<std::string> read_input_file(const std::filesystem::path& path, const std::string& label);

// The file that `reference` (a relative path from a file in `folder`, already
// percent-decoded) names. Refused, naming `what` (e.g. "file.gltf: buffer 0: uri
// '../x.bin'"), when it is absolute or leads out of `folder` (a `..` part, or a
// symbolic link pointing out of it) unless `allow_outside`; then check_file.
Result<std::filesystem::path> referenced_file(const std::filesystem::path& folder, const std::string& reference,
                                              bool allow_outside, const std::string& what);

}  // namespace rotinterp
