#pragma once
#include <string>

// Absolute path of a file given relative to the repository root.
inline std::string repo_path(const std::string& rel) { return std::string(PT_SOURCE_DIR) + "/" + rel; }
