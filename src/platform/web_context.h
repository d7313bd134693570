// The page's WebGL 2 context as the browser keeps it (web_context.cpp): the GPU's name,
// its loss and restoration (web/index.html tracks the events), and the extensions that
// must be asked for on every new context.
#pragma once
#include <string>

namespace pt::web {

enum class ContextState { Usable = 0, Lost = 1, Restored = 2 };  // Restored: not yet rebuilt

// The GPU's name: the unmasked renderer when the browser tells it, else GL_RENDERER.
std::string gl_renderer();
ContextState context_state();
void context_rebuilt();  // after every GL object was made again on the restored context
// On a restored context, before anything is made: the lost context's objects are
// forgotten (the wrappers then drop their names without deleting: gpu/gl_objects.h).
void forget_lost_objects();
// Before the first GL object: Emscripten reuses deleted GL names (its tables would
// otherwise grow by a slot for every object ever made: web_context.cpp).
void reuse_gl_names();
// WebGL extensions are off until asked for: ask again on a restored context (Emscripten
// enables its defaults only when it creates one).
void enable_extensions();

}  // namespace pt::web
