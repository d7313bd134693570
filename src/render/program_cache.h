// The integrator programs built so far, one per feature set (the scene's kinds, the render
// mode, the kernel): a scene of kinds seen before never compiles again, and editing values
// never compiles at all. A build starts without waiting for the driver where the context
// has KHR_parallel_shader_compile, so a page keeps drawing while it compiles.
#pragma once
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "gpu/program.h"
#include "shadergen/shadergen.h"

namespace pt {

class ProgramCache {
 public:
  struct Entry {
    ShaderSource source;
    Program program;
  };
  // Starts the build for f when it is new; true once it is built (get() will not block).
  bool ready(const Features& f);
  // The built program for f, waiting for the driver where it is still compiling. A failed
  // build throws (naming the snippet file and line) and is not cached: the next try
  // reports it again.
  Entry& get(const Features& f);
  size_t size() const { return cache_.size(); }

 private:
  std::unordered_map<std::string, std::unique_ptr<Entry>> cache_;  // by Features::key()
};

}  // namespace pt
