#include "scene/mesh_obj.h"

#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <map>
#include <tuple>
#include <vector>

#define TINYOBJLOADER_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <tiny_obj_loader.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include "core/error.h"
#include "core/file_io.h"

namespace pt {
namespace {

constexpr int kStepLines = 1024;  // lines (or faces) between two checks of the work left

// tinyobjloader accepts almost anything (unknown statements, "nan", indices past the
// end, all skipped or clamped silently). This pass reads the text first, strictly, so
// that an error names its line: known statements only, finite numbers of sane size, and
// face indices that refer to an element defined before them (OBJ's rule).
class ObjChecker {
 public:
  ObjChecker(const std::string& path) : path_(path) {}

  // Resumable (a unit: a byte of text); `text` must outlive it.
  Resumable check(const std::string& text) {
    size_t i = 0;
    while (i < text.size()) {
      ++line_;
      size_t e = text.find('\n', i);
      if (e == std::string::npos) e = text.size();
      std::string l = text.substr(i, e - i);
      i = e + 1;
      if (l.find('\0') != std::string::npos) fail("NUL byte in the text");
      const size_t hash = l.find('#');
      if (hash != std::string::npos) l.resize(hash);
      statement(split(l));
      if (line_ % kStepLines == 0) co_await Work{long(i - last_)}, last_ = i;
    }
    if (faces_ == 0) {
      line_ = std::max(line_, 1);
      fail("no faces (the file ends here)");
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, line_, what); }

  static std::vector<std::string> split(const std::string& l) {
    std::vector<std::string> out;
    size_t i = 0;
    for (;;) {
      i = l.find_first_not_of(" \t\r\\", i);
      if (i == std::string::npos) return out;
      const size_t e = l.find_first_of(" \t\r\\", i);
      out.push_back(l.substr(i, e == std::string::npos ? std::string::npos : e - i));
      if (e == std::string::npos) return out;
      i = e;
    }
  }

  void numbers(const std::vector<std::string>& t, size_t lo, size_t hi) {
    if (t.size() - 1 < lo || t.size() - 1 > hi)
      fail("'" + t[0] + "' takes " + std::to_string(lo) + (lo == hi ? "" : " to " + std::to_string(hi)) + " numbers, not " +
           std::to_string(t.size() - 1));
    for (size_t k = 1; k < t.size(); ++k) {
      const char* b = t[k].c_str();
      char* end = nullptr;
      const double x = std::strtod(b, &end);
      const bool plain = t[k].find_first_not_of("0123456789+-.eE") == std::string::npos;
      if (!plain || end != b + t[k].size() || t[k].empty()) fail("'" + t[k] + "' is not a number");
      if (!std::isfinite(x) || std::abs(x) > 1e9) fail("'" + t[k] + "' is not finite or is absurdly large (|x| > 1e9)");
    }
  }

  // One "v", "v/t", "v//n" or "v/t/n" corner of a face; returns which of texture
  // coordinate (1) and normal (2) it gives.
  int corner(const std::string& c) {
    long counts[3] = {v_, vt_, vn_};
    const char* names[3] = {"vertex", "texture coordinate", "normal"};
    int given = 0;
    size_t start = 0;
    for (int k = 0; k < 3; ++k) {
      const size_t slash = c.find('/', start);
      const std::string part = c.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
      if (part.empty()) {
        if (k == 0) fail("face corner '" + c + "' has no vertex index");
      } else {
        char* end = nullptr;
        const long x = std::strtol(part.c_str(), &end, 10);
        if (end != part.c_str() + part.size() || part.size() > 10) fail("face corner '" + c + "' is not an index");
        if (x == 0 || x > counts[k] || x < -counts[k])
          fail("face corner '" + c + "' refers to " + names[k] + " " + std::to_string(x) + ", but " + std::to_string(counts[k]) +
               " are defined before it");
        if (k > 0) given |= k;
      }
      if (slash == std::string::npos) {
        return given;
      }
      if (k == 2) fail("face corner '" + c + "' has more than three indices");
      start = slash + 1;
    }
    return given;
  }

  void statement(const std::vector<std::string>& t) {
    if (t.empty()) return;
    const std::string& k = t[0];
    if (k == "v") {
      numbers(t, 3, 7);  // x y z, optionally w or an r g b colour
      ++v_;
    } else if (k == "vt") {
      numbers(t, 1, 3);
      ++vt_;
    } else if (k == "vn") {
      numbers(t, 3, 3);
      // A normal of zero length has no direction to shade with: refused rather than
      // replaced by a guess (the exporter that wrote it lost the surface's orientation).
      if (std::strtod(t[1].c_str(), nullptr) == 0.0 && std::strtod(t[2].c_str(), nullptr) == 0.0 &&
          std::strtod(t[3].c_str(), nullptr) == 0.0)
        fail("'vn' has zero length");
      ++vn_;
    } else if (k == "f") {
      if (t.size() < 4) fail("a face needs at least 3 corners");
      // A face's corners all give texture coordinates and normals, or none do: half a
      // face with shading normals would blend them with zeros.
      const int first = corner(t[1]);
      for (size_t c = 2; c < t.size(); ++c)
        if (corner(t[c]) != first) fail("face corners '" + t[1] + "' and '" + t[c] + "' differ in giving a texture coordinate or normal");
      ++faces_;
    } else if (k == "o" || k == "g" || k == "s" || k == "usemtl" || k == "mtllib") {
      // names, smoothing groups and materials do not change the geometry we use
    } else {
      fail("unknown or unsupported statement '" + k.substr(0, 20) + "'");
    }
  }

  const std::string& path_;
  size_t last_ = 0;  // the offset of the last check of the work left
  int line_ = 0;
  long v_ = 0, vt_ = 0, vn_ = 0, faces_ = 0;
};

}  // namespace

Resumable parse_mesh_obj_steps(std::string text, std::string path, MeshData& m) {
  m = MeshData();
  ObjChecker checker(path);
  Resumable check = checker.check(text);
  while (!co_await check) {
  }
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // From a string, "mtllib" reads nothing from disk: materials are the scene's.
  if (!reader.ParseFromString(text, "", config)) {
    std::string why = reader.Error();
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    throw InputError(path, 0, why.empty() ? "cannot read the OBJ file" : why);
  }
  const tinyobj::attrib_t& a = reader.GetAttrib();
  std::vector<glm::vec3> positions;
  for (size_t i = 0; i + 2 < a.vertices.size(); i += 3) {
    const glm::vec3 p(a.vertices[i], a.vertices[i + 1], a.vertices[i + 2]);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InputError(path, 0, "vertex " + std::to_string(i / 3 + 1) + " is not finite");
    positions.push_back(p);
  }
  bool has_normals = false, has_uvs = false;
  for (const tinyobj::shape_t& shape : reader.GetShapes())
    for (const tinyobj::index_t& c : shape.mesh.indices) {
      has_normals |= c.normal_index >= 0;
      has_uvs |= c.texcoord_index >= 0;
    }
  // OBJ indexes positions, texture coordinates and normals separately; MeshData has one
  // index per vertex, so each distinct (v, vt, vn) triple becomes one vertex. Corners of
  // faces without vt or vn (where other faces have them) get uv 0 and a zero normal,
  // which the packer leaves out: those triangles shade with their geometric normal.
  std::map<std::tuple<int, int, int>, unsigned> vertex_of;
  auto vertex = [&](const tinyobj::index_t& c, size_t face) -> unsigned {
    if (c.vertex_index < 0 || size_t(c.vertex_index) >= positions.size())
      throw InputError(path, 0, "face " + std::to_string(face + 1) + " refers to a missing vertex");
    const auto key = std::make_tuple(c.vertex_index, c.texcoord_index, c.normal_index);
    const auto found = vertex_of.find(key);
    if (found != vertex_of.end()) return found->second;
    const unsigned k = unsigned(m.positions.size());
    vertex_of.emplace(key, k);
    m.positions.push_back(positions[size_t(c.vertex_index)]);
    if (has_normals) {
      glm::vec3 n(0.0f);
      if (c.normal_index >= 0) {
        if (3 * size_t(c.normal_index) + 2 >= a.normals.size())
          throw InputError(path, 0, "face " + std::to_string(face + 1) + " refers to a missing normal");
        n = glm::vec3(a.normals[3 * size_t(c.normal_index)], a.normals[3 * size_t(c.normal_index) + 1], a.normals[3 * size_t(c.normal_index) + 2]);
      }
      m.normals.push_back(n);
    }
    if (has_uvs) {
      glm::vec2 t(0.0f);
      if (c.texcoord_index >= 0) {
        if (2 * size_t(c.texcoord_index) + 1 >= a.texcoords.size())
          throw InputError(path, 0, "face " + std::to_string(face + 1) + " refers to a missing texture coordinate");
        t = glm::vec2(a.texcoords[2 * size_t(c.texcoord_index)], a.texcoords[2 * size_t(c.texcoord_index) + 1]);
      }
      m.uvs.push_back(t);
    }
    return k;
  };
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const auto& idx = shape.mesh.indices;
    for (size_t f = 0; f + 2 < idx.size(); f += 3) {
      glm::uvec3 tri;
      for (int k = 0; k < 3; ++k) tri[k] = vertex(idx[f + size_t(k)], f / 3);  // in order: vertices number as first used
      m.triangles.push_back(tri);
      if (m.triangles.size() % kStepLines == 0) co_await Work{16 * kStepLines};  // about the bytes of text of as many faces
    }
  }
  if (m.triangles.empty()) throw InputError(path, 0, "no faces");
}

MeshData parse_mesh_obj(const std::string& text, const std::string& path) {
  MeshData m;
  parse_mesh_obj_steps(text, path, m).finish();
  return m;
}

MeshData load_mesh_obj(const std::string& path) {
  const auto text = read_file(path);
  if (!text) throw InputError(path, 0, "cannot open the mesh file");
  return parse_mesh_obj(*text, path);
}

}  // namespace pt
