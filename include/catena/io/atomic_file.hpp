// Output files are written whole or not at all: a temporary file beside the target, then rename.
#pragma once

#include <string>
#include <string_view>

namespace catena::io {

/// Writes `content` to `path` atomically. Throws std::runtime_error naming the path on failure;
/// the target is then left as it was.
void write_file_atomic(const std::string& path, std::string_view content);

}  // namespace catena::io
