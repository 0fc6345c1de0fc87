#pragma once

// Private helpers of corridor_io: whole-file reads and atomic (temporary name, then rename)
// writes. Not installed; other modules use the public io headers.

#include <string>

#include "corridor_depth/status.h"

namespace corridor {

// Reads a whole file into *bytes. NotFound when the path does not exist, InvalidArgument when it
// is a folder, IoError when it cannot be read. An empty file is returned as an empty string.
Status ReadFileToString(const std::string& path, std::string* bytes);

// Creates the parent folders of `path` and picks a hidden temporary sibling for it that keeps the
// extension (".name.tmp-<pid>-<n>.png"), so encoders that look at the extension still work and
// folder listings that skip hidden files never see a half-written file.
Status PrepareAtomicWrite(const std::string& path, std::string* tmp_path);

// Renames tmp_path over path. On failure removes tmp_path and names both files.
Status FinishAtomicWrite(const std::string& tmp_path, const std::string& path);

// The extension with its dot, lower-cased: "a/B.PNG" -> ".png"; "" when there is none.
std::string LowerExtension(const std::string& path);

}  // namespace corridor
