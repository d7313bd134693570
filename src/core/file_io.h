#pragma once
#include <optional>
#include <string>

#include "core/resumable.h"

namespace pt {

// Whole file as bytes; nullopt when it cannot be opened.
std::optional<std::string> read_file(const std::string& path);
// The same in slices of 256 KB (core/resumable.h; a slice is 4096 units), for a page reading
// a large mesh: `out` is nullopt when it cannot be opened. `out` must outlive it.
Resumable read_file_steps(std::string path, std::optional<std::string>& out);
// Writes to a temporary file beside `path`, then renames it over `path`.
bool write_file_atomic(const std::string& path, const void* data, size_t size);
std::string directory_of(const std::string& path);

}  // namespace pt
