// Strict attribute reading for one XML element: every attribute must be asked for, or
// finish() reports it as unknown; numbers must be finite; vectors take spaces and/or
// commas ("0, 1, 0" and "0 1 0").
#pragma once
#include <set>
#include <string>

#include <glm/glm.hpp>

namespace tinyxml2 {
class XMLElement;
}

namespace pt {

// The largest magnitude any number in a scene may have (see check_range).
constexpr float kMaxMagnitude = 1e9f;

class XmlAttrs {
 public:
  XmlAttrs(const tinyxml2::XMLElement* e, const std::string& file);
  bool has(const char* name) const;
  float number(const char* name);
  float number(const char* name, float fallback);
  glm::vec3 vec3(const char* name);
  glm::vec3 vec3(const char* name, glm::vec3 fallback);
  glm::vec2 vec2(const char* name);
  bool boolean(const char* name, bool fallback);
  std::string text(const char* name);  // required, non-empty
  // Throws for attributes nobody asked for.
  void finish() const;
  [[noreturn]] void fail(const std::string& what) const;
  int line() const;
  const std::string& file() const { return file_; }

 private:
  const char* raw(const char* name);
  void check_range(const char* name, const char* text, const float* v, int n) const;
  const tinyxml2::XMLElement* e_;
  const std::string& file_;
  std::set<std::string> used_;
};

// Parses "a b c" / "a, b, c" into exactly n finite floats; false on any other text.
bool parse_floats(const char* text, float* out, int n);

}  // namespace pt
