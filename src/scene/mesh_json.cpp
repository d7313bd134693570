#include "scene/mesh_json.h"

#include <cmath>
#include <cstdlib>
#include <map>

#include "core/error.h"

namespace pt {
namespace {

// One array of numbers and the line of its key and of each number, for messages.
struct Array {
  std::vector<double> v;
  std::vector<int> lines;
  int key_line = 0;
};

// Just enough JSON for the format: one object whose values are arrays of numbers.
class Reader {
 public:
  Reader(const std::string& text, const std::string& path) : s_(text), path_(path) {}

  std::map<std::string, Array> object() {
    std::map<std::string, Array> out;
    expect('{');
    if (peek() == '}') return ++i_, out;
    for (;;) {
      peek();
      const int key_line = line_;
      const std::string key = string();
      expect(':');
      if (out.count(key)) fail("duplicate key \"" + key + "\"");
      out[key] = array();
      out[key].key_line = key_line;
      if (peek() == ',') {
        ++i_;
        continue;
      }
      expect('}');
      break;
    }
    if (peek() != '\0') fail("unexpected text after the object");
    return out;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, line_, what); }
  char peek() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\r' || s_[i_] == '\t')) line_ += s_[i_++] == '\n';
    // A NUL byte would end strtod's view of the text early: it is an error, not the end.
    if (i_ < s_.size() && s_[i_] == '\0') fail("NUL byte in the text");
    return i_ < s_.size() ? s_[i_] : '\0';
  }
  void expect(char c) {
    if (peek() != c) fail(std::string("expected '") + c + "'");
    ++i_;
  }
  std::string string() {
    expect('"');
    const size_t start = i_;
    while (i_ < s_.size() && s_[i_] != '"' && s_[i_] != '\\') ++i_;
    if (i_ >= s_.size() || s_[i_] != '"') fail("unterminated or escaped string");
    return s_.substr(start, i_++ - start);
  }
  Array array() {
    Array v;
    expect('[');
    if (peek() == ']') return ++i_, v;
    for (;;) {
      peek();
      const char* begin = s_.c_str() + i_;
      // JSON numbers only: strtod would also take "nan", "inf", hex floats and spaces.
      if (!(*begin == '-' || (*begin >= '0' && *begin <= '9'))) fail("expected a number");
      char* end = nullptr;
      const double x = std::strtod(begin, &end);
      if (end == begin) fail("expected a number");
      for (const char* c = begin; c < end; ++c)
        if (*c == 'x' || *c == 'X' || *c == 'p' || *c == 'P' || *c == 'n' || *c == 'N' || *c == 'i' || *c == 'I')
          fail("expected a number");
      if (!std::isfinite(x)) fail("a number is not finite");
      if (std::abs(x) > 1e9) fail("a number is absurdly large (|x| > 1e9)");
      i_ += size_t(end - begin);
      v.v.push_back(x);
      v.lines.push_back(line_);
      if (peek() == ',') {
        ++i_;
        continue;
      }
      expect(']');
      return v;
    }
  }

  const std::string& s_;
  const std::string& path_;
  size_t i_ = 0;
  int line_ = 1;  // line of s_[i_]
};

}  // namespace

MeshData parse_mesh_json(const std::string& text, const std::string& path) {
  auto fields = Reader(text, path).object();
  for (const auto& [key, values] : fields)
    if (key != "vertex" && key != "normal" && key != "uv" && key != "indices")
      throw InputError(path, values.key_line, "unknown key \"" + key + "\"");
  const Array& v = fields["vertex"];
  const Array& n = fields["normal"];
  const Array& t = fields["uv"];
  const Array& ix = fields["indices"];
  // A missing key reads as an empty array at line 0: the message then names no line.
  if (v.v.empty() || v.v.size() % 3) throw InputError(path, v.key_line, "\"vertex\" needs 3 numbers per vertex");
  const size_t count = v.v.size() / 3;
  if (!n.v.empty() && n.v.size() != v.v.size()) throw InputError(path, n.key_line, "\"normal\" must have one normal per vertex");
  if (!t.v.empty() && t.v.size() != count * 2) throw InputError(path, t.key_line, "\"uv\" must have one pair per vertex");
  if (ix.v.empty() || ix.v.size() % 3) throw InputError(path, ix.key_line, "\"indices\" needs 3 indices per triangle");
  MeshData m;
  for (size_t i = 0; i < count; ++i) m.positions.emplace_back(v.v[3 * i], v.v[3 * i + 1], v.v[3 * i + 2]);
  for (size_t i = 0; i < n.v.size() / 3; ++i) m.normals.emplace_back(n.v[3 * i], n.v[3 * i + 1], n.v[3 * i + 2]);
  for (size_t i = 0; i < t.v.size() / 2; ++i) m.uvs.emplace_back(t.v[2 * i], t.v[2 * i + 1]);
  for (size_t i = 0; i < ix.v.size(); i += 3) {
    glm::uvec3 tri;
    for (int k = 0; k < 3; ++k) {
      const double x = ix.v[i + size_t(k)];
      if (x < 0 || x >= double(count) || x != std::floor(x))
        throw InputError(path, ix.lines[i + size_t(k)],
                         "index " + std::to_string(x) + " is not a vertex (there are " + std::to_string(count) + ")");
      tri[k] = unsigned(x);
    }
    m.triangles.push_back(tri);
  }
  return m;
}


}  // namespace pt
