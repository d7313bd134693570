// A program's text and its line map: what the shader generator produces and what
// gpu::Program compiles, shared vocabulary below both (layers point down).
#pragma once
#include <string>
#include <vector>

namespace pt {

// A program's text after include resolution, and the files that its "#line L S"
// directives number S (0 is the generated text), so logs can name the snippet file.
struct ShaderSource {
  std::string text;
  std::vector<std::string> files;
  // Rewrites "0:12:" / "ERROR: 3:45:" locations in a compiler log to "file:line:".
  std::string map_log(const std::string& log) const;
};

}  // namespace pt
