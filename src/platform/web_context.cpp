#include "platform/web_context.h"

#include <cstdlib>

#include <emscripten.h>

// Returns a malloc'ed string.
EM_JS(char*, pt_js_gl_renderer, (), {
  const gl = Module.ctx;
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  const size = lengthBytesUTF8(name) + 1;
  const ptr = _malloc(size);
  stringToUTF8(name, ptr, size);
  return ptr;
});

EM_JS(int, pt_js_context_state, (), { return Module.ptContextState | 0; });
EM_JS(void, pt_js_context_rebuilt, (), { Module.ptContextState = 0; });

// Emscripten's tables from GL names to WebGL objects still hold the lost context's
// objects: dropped, so they can be collected (deleting them on the new context would only
// make WebGL warn, once per object).
EM_JS(void, pt_js_forget_lost_objects, (), {
  for (const table of [GL.buffers, GL.programs, GL.framebuffers, GL.renderbuffers, GL.textures, GL.shaders,
                       GL.vaos, GL.queries, GL.samplers, GL.syncs])
    if (table) table.fill(null);
});

// Emscripten (3.1.6, library_webgl.js) names every GL object with one counter shared by
// all its tables (GL.getNewId: GL.counter++) and pads the table up to the new name with
// nulls, never reusing a deleted name: each table's array grows by one slot for every
// object ever made, of any kind (scene loads make textures, context restores make
// everything again: tests/browser/endurance_test.mjs prints the tables' lengths). Names are
// reused instead, as GL itself may: the lowest free slot of the table (deleted, or never
// used by this table), else the next one; GL.counter stays above every name given (its
// glGetProgramiv checks against it). Safe with stale names: after a context loss every
// slot is emptied (forget_lost_objects) before anything is made on the new context, and
// the wrappers never delete a name of an earlier context (gpu/gl_objects.h); ImGui's
// backend deletes its old names before it makes new ones (web_imgui.cpp).
EM_JS(void, pt_js_reuse_gl_names, (), {
  GL.getNewId = (table) => {
    let id = 1;
    while (id < table.length && table[id] != null) ++id;
    if (id >= GL.counter) GL.counter = id + 1;
    return id;
  };
});

// KHR_parallel_shader_compile lets the driver compile in the background (gpu/program.cpp
// polls it); the timer query times draws where the browser allows it.
EM_JS(void, pt_js_enable_extensions, (), {
  const gl = Module.ctx;
  for (const name of ["EXT_color_buffer_float", "EXT_color_buffer_half_float", "EXT_float_blend",
                      "OES_texture_float_linear", "KHR_parallel_shader_compile", "WEBGL_debug_renderer_info",
                      "EXT_disjoint_timer_query_webgl2"])
    gl.getExtension(name);
});

namespace pt::web {

std::string gl_renderer() {
  char* name = pt_js_gl_renderer();
  std::string out = name ? name : "";
  std::free(name);
  return out;
}

ContextState context_state() { return ContextState(pt_js_context_state()); }
void context_rebuilt() { pt_js_context_rebuilt(); }
void forget_lost_objects() { pt_js_forget_lost_objects(); }
void reuse_gl_names() { pt_js_reuse_gl_names(); }
void enable_extensions() { pt_js_enable_extensions(); }

}  // namespace pt::web
