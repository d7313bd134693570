// The integrator programs built so far, one per feature set (the scene's kinds, the render
// mode, the kernel): a scene of kinds seen before never compiles again, and editing values
// never compiles at all. A build starts without waiting for the driver where the context
// has KHR_parallel_shader_compile, so a page keeps drawing while it compiles.
//
// A build started but never asked for (a load replaced by another before its program was
// used, a program built ahead for settings that changed on the way) is finished by poll()
// once the driver has it: its two shader objects and the copies of its sources go then,
// not at the next get() of that feature set, which may never come (the page's long-use
// test, tests/browser/endurance_test.mjs, saw one pending for good: 2 shaders, 250 KB).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "gpu/program.h"
#include "shadergen/shadergen.h"

namespace pt {

class ProgramCache {
 public:
  struct Entry {
    ShaderSource source;
    Program program;
    Features features;  // what it was built for (pending()'s description)
    std::string error;  // a build that failed in poll(): get() throws it
  };
  // Starts the build for f when it is new; true once it is built (get() will not block).
  bool ready(const Features& f);
  // The built program for f, waiting for the driver where it is still compiling. A failed
  // build throws (naming the snippet file and line) and is not cached: the next try
  // reports it again.
  Entry& get(const Features& f);
  // Finishes every build the driver has completed, without blocking: called every frame,
  // also while the page idles at its sample limit. A build that failed keeps only its error
  // (its GL objects are deleted), which get() throws as its own failure would. Without
  // KHR_parallel_shader_compile completed() is true at once and finish() waits for the
  // driver, as the get() after a load's build does one frame later anyway.
  void poll();
  // The builds started and not finished yet, each described (ptStats().pendingPrograms).
  std::vector<std::string> pending() const;
  size_t size() const { return cache_.size(); }

 private:
  std::unordered_map<std::string, std::unique_ptr<Entry>> cache_;  // by Features::key()
};

// A feature set in a line: its words in hex and its flags (a debug description).
std::string describe(const Features& f);

}  // namespace pt
