#include "core/xml_attrs.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include <tinyxml2.h>

#include "core/error.h"

namespace pt {

bool parse_floats(const char* text, float* out, int n) {
  const char* p = text;
  for (int i = 0; i < n; ++i) {
    while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') ++p;
    if (i > 0 && *p == ',') {
      ++p;
      while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') ++p;
    }
    if (*p == '\0') return false;
    char* end = nullptr;
    errno = 0;
    const float v = std::strtof(p, &end);
    if (end == p || errno == ERANGE || !std::isfinite(v)) return false;
    out[i] = v;
    p = end;
  }
  while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') ++p;
  return *p == '\0';
}

XmlAttrs::XmlAttrs(const tinyxml2::XMLElement* e, const std::string& file) : e_(e), file_(file) {}

int XmlAttrs::line() const { return e_->GetLineNum(); }

void XmlAttrs::fail(const std::string& what) const {
  throw InputError(file_, line(), "<" + std::string(e_->Name()) + ">: " + what);
}

bool XmlAttrs::has(const char* name) const { return e_->Attribute(name) != nullptr; }

const char* XmlAttrs::raw(const char* name) {
  used_.insert(name);
  return e_->Attribute(name);
}

// Finite but absurd magnitudes overflow float arithmetic in the shader (a squared
// distance of 1e20 is inf): every number in a scene stays within +-kMaxMagnitude.
void XmlAttrs::check_range(const char* name, const char* text, const float* v, int n) const {
  for (int i = 0; i < n; ++i)
    if (std::abs(v[i]) > kMaxMagnitude)
      fail(std::string("attribute '") + name + "' is absurdly large (|x| > 1e9): \"" + text + "\"");
}

float XmlAttrs::number(const char* name) {
  const char* t = raw(name);
  if (!t) fail(std::string("missing attribute '") + name + "'");
  float v;
  if (!parse_floats(t, &v, 1)) fail(std::string("attribute '") + name + "' is not a finite number: \"" + t + "\"");
  check_range(name, t, &v, 1);
  return v;
}

float XmlAttrs::number(const char* name, float fallback) { return has(name) ? number(name) : (raw(name), fallback); }

glm::vec3 XmlAttrs::vec3(const char* name) {
  const char* t = raw(name);
  if (!t) fail(std::string("missing attribute '") + name + "'");
  glm::vec3 v;
  if (!parse_floats(t, &v.x, 3)) fail(std::string("attribute '") + name + "' needs 3 finite numbers: \"" + t + "\"");
  check_range(name, t, &v.x, 3);
  return v;
}

glm::vec3 XmlAttrs::vec3(const char* name, glm::vec3 fallback) { return has(name) ? vec3(name) : (raw(name), fallback); }

glm::vec2 XmlAttrs::vec2(const char* name) {
  const char* t = raw(name);
  if (!t) fail(std::string("missing attribute '") + name + "'");
  glm::vec2 v;
  if (!parse_floats(t, &v.x, 2)) fail(std::string("attribute '") + name + "' needs 2 finite numbers: \"" + t + "\"");
  check_range(name, t, &v.x, 2);
  return v;
}

std::string XmlAttrs::text(const char* name) {
  const char* t = raw(name);
  if (!t || !*t) fail(std::string("missing attribute '") + name + "'");
  return t;
}

bool XmlAttrs::boolean(const char* name, bool fallback) {
  const char* t = raw(name);
  if (!t) return fallback;
  if (!std::strcmp(t, "true") || !std::strcmp(t, "1")) return true;
  if (!std::strcmp(t, "false") || !std::strcmp(t, "0")) return false;
  fail(std::string("attribute '") + name + "' must be true or false: \"" + t + "\"");
}

void XmlAttrs::finish() const {
  for (const tinyxml2::XMLAttribute* a = e_->FirstAttribute(); a; a = a->Next()) {
    if (!used_.count(a->Name())) fail(std::string("unknown attribute '") + a->Name() + "'");
  }
}

}  // namespace pt
