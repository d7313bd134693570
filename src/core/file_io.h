#pragma once
#include <optional>
#include <string>

namespace pt {

// Whole file as bytes; nullopt when it cannot be opened.
std::optional<std::string> read_file(const std::string& path);
// Writes to a temporary file beside `path`, then renames it over `path`.
bool write_file_atomic(const std::string& path, const void* data, size_t size);
std::string directory_of(const std::string& path);

}  // namespace pt
