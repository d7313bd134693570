#include "scene/mesh_json.h"

#include <cmath>
#include <cstdlib>
#include <map>

#include "core/error.h"
#include "core/file_io.h"

namespace pt {
namespace {

// Just enough JSON for the format: one object whose values are arrays of numbers.
class Reader {
 public:
  Reader(const std::string& text, const std::string& path) : s_(text), path_(path) {}

  std::map<std::string, std::vector<double>> object() {
    std::map<std::string, std::vector<double>> out;
    expect('{');
    if (peek() == '}') return ++i_, out;
    for (;;) {
      const std::string key = string();
      expect(':');
      if (out.count(key)) fail("duplicate key \"" + key + "\"");
      out[key] = array();
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
  [[noreturn]] void fail(const std::string& what) const {
    int line = 1;
    for (size_t k = 0; k < i_ && k < s_.size(); ++k) line += s_[k] == '\n';
    throw InputError(path_, line, what);
  }
  char peek() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\r' || s_[i_] == '\t')) ++i_;
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
  std::vector<double> array() {
    std::vector<double> v;
    expect('[');
    if (peek() == ']') return ++i_, v;
    for (;;) {
      peek();
      const char* begin = s_.c_str() + i_;
      char* end = nullptr;
      const double x = std::strtod(begin, &end);
      if (end == begin) fail("expected a number");
      if (!std::isfinite(x)) fail("a number is not finite");
      i_ += size_t(end - begin);
      v.push_back(x);
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
};

}  // namespace

MeshData parse_mesh_json(const std::string& text, const std::string& path) {
  auto fields = Reader(text, path).object();
  for (const auto& [key, values] : fields)
    if (key != "vertex" && key != "normal" && key != "uv" && key != "indices")
      throw InputError(path, 0, "unknown key \"" + key + "\"");
  const std::vector<double>& v = fields["vertex"];
  const std::vector<double>& n = fields["normal"];
  const std::vector<double>& t = fields["uv"];
  const std::vector<double>& ix = fields["indices"];
  if (v.empty() || v.size() % 3) throw InputError(path, 0, "\"vertex\" needs 3 numbers per vertex");
  const size_t count = v.size() / 3;
  if (!n.empty() && n.size() != v.size()) throw InputError(path, 0, "\"normal\" must have one normal per vertex");
  if (!t.empty() && t.size() != count * 2) throw InputError(path, 0, "\"uv\" must have one pair per vertex");
  if (ix.empty() || ix.size() % 3) throw InputError(path, 0, "\"indices\" needs 3 indices per triangle");
  MeshData m;
  for (size_t i = 0; i < count; ++i) m.positions.emplace_back(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  for (size_t i = 0; i < n.size() / 3; ++i) m.normals.emplace_back(n[3 * i], n[3 * i + 1], n[3 * i + 2]);
  for (size_t i = 0; i < t.size() / 2; ++i) m.uvs.emplace_back(t[2 * i], t[2 * i + 1]);
  for (size_t i = 0; i < ix.size(); i += 3) {
    glm::uvec3 tri;
    for (int k = 0; k < 3; ++k) {
      const double x = ix[i + size_t(k)];
      if (x < 0 || x >= double(count) || x != std::floor(x))
        throw InputError(path, 0, "index " + std::to_string(x) + " is not a vertex (there are " + std::to_string(count) + ")");
      tri[k] = unsigned(x);
    }
    m.triangles.push_back(tri);
  }
  return m;
}

MeshData load_mesh_json(const std::string& path) {
  const auto text = read_file(path);
  if (!text) throw InputError(path, 0, "cannot open the mesh file");
  return parse_mesh_json(*text, path);
}

}  // namespace pt
