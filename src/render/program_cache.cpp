// The integrator programs by feature set (render/program_cache.h).
#include "render/program_cache.h"

namespace pt {

bool ProgramCache::ready(const Features& f) {
  auto& slot = cache_[f.key()];
  if (!slot) {
    auto c = std::make_unique<Entry>();
    c->source = generate_integrator(f);
#ifndef __EMSCRIPTEN__
    if (f.compute) c->program = Program::start_compute(c->source);
    else
#endif
      c->program = Program::start(fullscreen_vertex(), c->source);
    slot = std::move(c);
  }
  return slot->program.completed();
}

ProgramCache::Entry& ProgramCache::get(const Features& f) {
  ready(f);
  auto& slot = cache_[f.key()];
  try {
    slot->program.finish();
  } catch (...) {
    cache_.erase(f.key());
    throw;
  }
  return *slot;
}

}  // namespace pt
