#include "platform/egl.h"

#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <dlfcn.h>
#include <link.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "gpu/gl.h"

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

namespace pt {
namespace {

bool has_ext(const char* list, const char* ext) {
  if (!list) return false;
  const size_t n = std::strlen(ext);
  for (const char* p = list; (p = std::strstr(p, ext)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

EGLDisplay try_init(EGLDisplay d) {
  if (d == EGL_NO_DISPLAY) return d;
  EGLint major = 0, minor = 0;
  return eglInitialize(d, &major, &minor) ? d : EGL_NO_DISPLAY;
}

// Under LeakSanitizer only. At exit, libEGL_mesa dlcloses the driver (swrast_dri.so);
// what the driver still holds (LLVM JIT state: 128 + 2 x 56 bytes) is then referenced
// only from unmapped memory, and LSan, which scans after the unload, reports it as leaked
// from "<unknown module>". Marking every library loaded so far RTLD_NODELETE keeps them
// mapped, so the scan sees those references and any real leak keeps a named stack.
// docs/reliability.md ("Sanitizers") shows the dlclose stack that proves it.
[[maybe_unused]] void keep_libraries_mapped() {
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void*) {
        if (info->dlpi_name && *info->dlpi_name) dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        return 0;
      },
      nullptr);
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kLeakCheck = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kLeakCheck = true;
#else
constexpr bool kLeakCheck = false;
#endif
#else
constexpr bool kLeakCheck = false;
#endif

}  // namespace

HeadlessGl::HeadlessGl() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  auto query_device_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
  const bool force_software = std::getenv("PT_EGL_SOFTWARE") && std::strcmp(std::getenv("PT_EGL_SOFTWARE"), "0") != 0;
  EGLDisplay dpy = EGL_NO_DISPLAY;
  std::string platform;

  if (!force_software && get_platform_display && query_devices && has_ext(client, "EGL_EXT_platform_device")) {
    EGLDeviceEXT devices[16];
    EGLint n = 0;
    if (query_devices(16, devices, &n)) {
      for (EGLint i = 0; i < n && dpy == EGL_NO_DISPLAY; ++i) {
        const char* dev_ext = query_device_string ? query_device_string(devices[i], EGL_EXTENSIONS) : nullptr;
        if (has_ext(dev_ext, "EGL_MESA_device_software")) continue;  // prefer hardware
        dpy = try_init(get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr));
        if (dpy != EGL_NO_DISPLAY) platform = "EGL device " + std::to_string(i);
      }
    }
  }
  if (dpy == EGL_NO_DISPLAY && get_platform_display && has_ext(client, "EGL_MESA_platform_surfaceless")) {
    dpy = try_init(get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
    if (dpy != EGL_NO_DISPLAY) platform = "EGL surfaceless (Mesa)";
  }
  if (dpy == EGL_NO_DISPLAY) {
    dpy = try_init(eglGetDisplay(EGL_DEFAULT_DISPLAY));
    if (dpy != EGL_NO_DISPLAY) platform = "EGL default display";
  }
  if (dpy == EGL_NO_DISPLAY) throw std::runtime_error("EGL: no display could be initialised (no GPU and no Mesa?)");
  display_ = dpy;

  if (!eglBindAPI(EGL_OPENGL_ES_API)) throw std::runtime_error("EGL: OpenGL ES is not supported");
  const EGLint cfg_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  EGLConfig cfg = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(dpy, cfg_attribs, &cfg, 1, &count) || count == 0) {
    const EGLint any[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_NONE};
    if (!eglChooseConfig(dpy, any, &cfg, 1, &count) || count == 0)
      throw std::runtime_error("EGL: no OpenGL ES 3 configuration");
  }
  // The newest of 3.2, 3.1, 3.0: from 3.1 the renderer can run its compute kernel.
  EGLContext ctx = EGL_NO_CONTEXT;
  for (EGLint minor = 2; minor >= 0 && ctx == EGL_NO_CONTEXT; --minor) {
    const EGLint ctx_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, minor, EGL_NONE};
    ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, ctx_attribs);
  }
  if (ctx == EGL_NO_CONTEXT) throw std::runtime_error("EGL: cannot create an OpenGL ES 3.0 context");
  context_ = ctx;
  if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx))
    throw std::runtime_error("EGL: cannot make the context current without a surface");
  if (kLeakCheck) keep_libraries_mapped();  // the driver is loaded now
  description_ = std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))) + " (" +
                 reinterpret_cast<const char*>(glGetString(GL_VERSION)) + ") via " + platform;
}

HeadlessGl::~HeadlessGl() {
  if (display_) {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }
}

}  // namespace pt
