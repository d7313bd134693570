// The integrator programs by feature set (render/program_cache.h).
#include "render/program_cache.h"

#include <cstdio>

namespace pt {

bool ProgramCache::ready(const Features& f) {
  auto& slot = cache_[f.key()];
  if (!slot) {
    auto c = std::make_unique<Entry>();
    c->features = f;
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
    if (!slot->error.empty()) throw GlError(slot->error);
    slot->program.finish();
  } catch (...) {
    cache_.erase(f.key());
    throw;
  }
  return *slot;
}

void ProgramCache::poll() {
  for (auto& [key, e] : cache_) {
    if (e->program.finished() || !e->program.completed()) continue;
    try {
      e->program.finish();
    } catch (const GlError& err) {
      e->error = err.what();  // kept until a get() reports it (then not cached, as there)
    }
  }
}

std::vector<std::string> ProgramCache::pending() const {
  std::vector<std::string> out;
  for (const auto& [key, e] : cache_)
    if (!e->program.finished()) out.push_back(describe(e->features));
  return out;
}

std::string describe(const Features& f) {
  char text[192];
  std::snprintf(text, sizeof text, "shapes %#x materials %#x lights %#x punctual %#x material features %#x mode %d%s%s%s%s%s%s%s",
                unsigned(f.shapes), unsigned(f.materials), unsigned(f.lights), unsigned(f.punctual), unsigned(f.material_features),
                int(f.mode), f.env_map ? " env" : "", f.motion ? " motion" : "", f.compute ? " compute" : "", f.aux ? " aux" : "",
                f.adaptive ? " adaptive" : "", f.flat ? " flat" : "", f.count_ops ? " count-ops" : "");
  return text;
}

}  // namespace pt
