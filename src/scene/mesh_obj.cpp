#include "scene/mesh_obj.h"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <charconv>
#include <string_view>
#include <vector>

#define TINYOBJLOADER_IMPLEMENTATION
#include "scene/tinyobj.h"

#include "core/error.h"

namespace pt {
namespace {

constexpr int kStepLines = 1024;  // lines (or faces) between two checks of the work left

// tinyobjloader accepts almost anything (unknown statements, "nan", indices past the
// end, all skipped or clamped silently), and it reads a file in one call. This reader goes
// through the text once, strictly, a slice at a time (an error names its line): known
// statements only, finite numbers of sane size, face indices that refer to an element
// defined before them (OBJ's rule). It keeps the numbers and faces as it goes; triangles
// and quads are split here as tinyobjloader splits them (a quad along its shorter
// diagonal), and a larger polygon by tinyobjloader's ear clipping (ear_clip).
class ObjReader {
 public:
  explicit ObjReader(const std::string& path) : path_(path) {}

  struct Corner {
    int v, vt, vn;  // 0-based; -1: not given
  };
  std::vector<float> v, vt, vn;  // x y z per v and vn; u v per vt
  std::vector<Corner> corners;   // triangles, three corners each
  bool has_vt = false, has_vn = false;

  // Resumable (a unit: a byte of text); `text` must outlive it.
  Resumable read(const std::string& text) {
    // First the statements are counted (a quick look at each line's start), so that the
    // arrays are allocated once: growing them by doubling copied up to 50 MB in one slice.
    size_t nv = 0, nvt = 0, nvn = 0, ncorners = 0;
    for (size_t i = 0, last = 0; i < text.size();) {
      size_t e = text.find('\n', i);
      if (e == std::string::npos) e = text.size();
      if (e - i >= 2 && text[i] == 'v') {
        nv += text[i + 1] == ' ' || text[i + 1] == '\t';
        nvt += text[i + 1] == 't';
        nvn += text[i + 1] == 'n';
      } else if (e - i >= 2 && text[i] == 'f') {
        size_t tokens = 0;  // after the "f": a triangle's 3, a quad's split into 6
        for (size_t k = i + 1; k < e; ++k) tokens += text[k] > ' ' && (text[k - 1] == ' ' || text[k - 1] == '\t');
        ncorners += tokens <= 3 ? 3 : 3 * (tokens - 2);
      }
      i = e + 1;
      if (i - last >= size_t(kStepLines) * 64) {
        co_await Work{long(i - last) / 8};
        last = i;
      }
    }
    v.reserve(3 * nv);
    vt.reserve(2 * nvt);
    vn.reserve(3 * nvn);
    corners.reserve(ncorners);
    size_t i = 0, last = 0;
    while (i < text.size()) {
      ++line_;
      size_t e = text.find('\n', i);
      if (e == std::string::npos) e = text.size();
      std::string_view l(text.data() + i, e - i);
      i = e + 1;
      if (l.find('\0') != std::string_view::npos) fail("NUL byte in the text");
      const size_t hash = l.find('#');
      if (hash != std::string_view::npos) l = l.substr(0, hash);
      split(l);
      statement();
      if (line_ % kStepLines == 0) {
        co_await Work{long(i - last)};
        last = i;
      }
    }
    if (faces_ == 0) {
      line_ = std::max(line_, 1);
      fail("no faces (the file ends here)");
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_, line_, what); }

  void split(std::string_view l) {
    t_.clear();
    constexpr std::string_view kSep = " \t\r\\";
    size_t i = 0;
    for (;;) {
      i = l.find_first_not_of(kSep, i);
      if (i == std::string_view::npos) return;
      const size_t e = l.find_first_of(kSep, i);
      t_.push_back(l.substr(i, e == std::string_view::npos ? std::string_view::npos : e - i));
      if (e == std::string_view::npos) return;
      i = e;
    }
  }

  std::string token(size_t k) const { return std::string(t_[k]); }

  // Reads numbers 1..n of the statement (n in [lo, hi]) into x[0..n-1].
  size_t numbers(size_t lo, size_t hi, double* x) {
    const size_t n = t_.size() - 1;
    if (n < lo || n > hi)
      fail("'" + token(0) + "' takes " + std::to_string(lo) + (lo == hi ? "" : " to " + std::to_string(hi)) + " numbers, not " + std::to_string(n));
    for (size_t k = 1; k <= n; ++k) {
      const std::string_view t = t_[k];
      const bool plain = t.find_first_not_of("0123456789+-.eE") == std::string_view::npos;
      // The character after a token is a separator, '#', a line end or the text's end:
      // none continues a number, so strtod stops at the token's end.
      char* end = nullptr;
      const double value = plain ? std::strtod(t.data(), &end) : 0.0;
      if (!plain || end != t.data() + t.size() || t.empty()) fail("'" + token(k) + "' is not a number");
      if (!std::isfinite(value) || std::abs(value) > 1e9) fail("'" + token(k) + "' is not finite or is absurdly large (|x| > 1e9)");
      x[k - 1] = value;
    }
    return n;
  }

  // One "v", "v/t", "v//n" or "v/t/n" corner of a face; `given` says which of texture
  // coordinate (1) and normal (2) it gives.
  Corner corner(std::string_view c, int& given) {
    const long counts[3] = {long(v.size() / 3), long(vt.size() / 2), long(vn.size() / 3)};
    const char* names[3] = {"vertex", "texture coordinate", "normal"};
    int out[3] = {-1, -1, -1};
    given = 0;
    size_t start = 0;
    for (int k = 0; k < 3; ++k) {
      const size_t slash = c.find('/', start);
      const std::string_view part = c.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
      if (part.empty()) {
        if (k == 0) fail("face corner '" + std::string(c) + "' has no vertex index");
      } else {
        long x = 0;
        const auto [end, ec] = std::from_chars(part.data() + (part[0] == '+' ? 1 : 0), part.data() + part.size(), x);
        if (ec != std::errc() || end != part.data() + part.size() || part.size() > 10) fail("face corner '" + std::string(c) + "' is not an index");
        if (x == 0 || x > counts[k] || x < -counts[k])
          fail("face corner '" + std::string(c) + "' refers to " + names[k] + " " + std::to_string(x) + ", but " + std::to_string(counts[k]) +
               " are defined before it");
        out[k] = int(x > 0 ? x - 1 : counts[k] + x);
        if (k > 0) given |= k;
      }
      if (slash == std::string_view::npos) break;
      if (k == 2) fail("face corner '" + std::string(c) + "' has more than three indices");
      start = slash + 1;
    }
    return {out[0], out[1], out[2]};
  }

  // A polygon of more than four corners, triangulated by tinyobjloader's ear clipping: the
  // polygon alone as a small OBJ text (its corners' positions, one face), so that what is
  // split is exactly what this reader read. Indices into face_, three per triangle.
  std::vector<int> ear_clip() const {
    std::string text;
    char line[96];
    for (const Corner& c : face_) {
      std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(v[size_t(c.v) * 3]), double(v[size_t(c.v) * 3 + 1]), double(v[size_t(c.v) * 3 + 2]));
      text += line;
    }
    text += "f";
    for (size_t k = 1; k <= face_.size(); ++k) text += " " + std::to_string(k);
    text += "\n";
    tinyobj::ObjReaderConfig config;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, "", config)) fail("tinyobjloader cannot triangulate this polygon");
    std::vector<int> out;
    for (const tinyobj::shape_t& shape : reader.GetShapes())
      for (const tinyobj::index_t& i : shape.mesh.indices) {
        if (i.vertex_index < 0 || size_t(i.vertex_index) >= face_.size()) fail("tinyobjloader triangulated this polygon with a corner it does not have");
        out.push_back(i.vertex_index);
      }
    return out;
  }

  float sq_distance(const Corner& a, const Corner& b) const {
    float d = 0.0f;
    for (int k = 0; k < 3; ++k) {
      const float e = v[size_t(b.v) * 3 + size_t(k)] - v[size_t(a.v) * 3 + size_t(k)];
      d += e * e;
    }
    return d;
  }

  void statement() {
    if (t_.empty()) return;
    const std::string_view k = t_[0];
    double x[7];
    if (k == "v") {
      numbers(3, 7, x);  // x y z, optionally w or an r g b colour
      v.insert(v.end(), {float(x[0]), float(x[1]), float(x[2])});
    } else if (k == "vt") {
      const size_t n = numbers(1, 3, x);
      vt.insert(vt.end(), {float(x[0]), n > 1 ? float(x[1]) : 0.0f});
    } else if (k == "vn") {
      numbers(3, 3, x);
      // A normal of zero length has no direction to shade with: refused rather than
      // replaced by a guess (the exporter that wrote it lost the surface's orientation).
      if (x[0] == 0.0 && x[1] == 0.0 && x[2] == 0.0) fail("'vn' has zero length");
      vn.insert(vn.end(), {float(x[0]), float(x[1]), float(x[2])});
    } else if (k == "f") {
      if (t_.size() < 4) fail("a face needs at least 3 corners");
      // A face's corners all give texture coordinates and normals, or none do: half a
      // face with shading normals would blend them with zeros.
      face_.clear();
      int first = 0;
      for (size_t c = 1; c < t_.size(); ++c) {
        int given = 0;
        face_.push_back(corner(t_[c], given));
        if (c == 1) first = given;
        else if (given != first) fail("face corners '" + token(1) + "' and '" + token(c) + "' differ in giving a texture coordinate or normal");
      }
      has_vt |= (first & 1) != 0;
      has_vn |= (first & 2) != 0;
      if (face_.size() == 3) {
        corners.insert(corners.end(), face_.begin(), face_.end());
      } else if (face_.size() == 4) {  // tinyobjloader's split: along the shorter diagonal
        const Corner& a = face_[0], &b = face_[1], &c = face_[2], &d = face_[3];
        if (sq_distance(a, c) < sq_distance(b, d)) corners.insert(corners.end(), {a, b, c, a, c, d});
        else corners.insert(corners.end(), {a, b, d, b, c, d});
      } else {
        for (const int c : ear_clip()) corners.push_back(face_[size_t(c)]);
      }
      ++faces_;
    } else if (k == "o" || k == "g" || k == "s" || k == "usemtl" || k == "mtllib") {
      // names, smoothing groups and materials do not change the geometry we use
    } else {
      fail("unknown or unsupported statement '" + std::string(k.substr(0, 20)) + "'");
    }
  }

  const std::string& path_;
  int line_ = 0;
  long faces_ = 0;
  std::vector<std::string_view> t_;  // the tokens of the current line
  std::vector<Corner> face_;
};

}  // namespace

Resumable parse_mesh_obj_steps(std::string text, std::string path, MeshData& m) {
  m = MeshData();
  ObjReader r(path);
  Resumable read = r.read(text);
  while (!co_await read) {
  }
  // OBJ indexes positions, texture coordinates and normals separately; MeshData has one
  // index per vertex, so each distinct (v, vt, vn) triple becomes one vertex, numbered as
  // first used. Corners of faces without vt or vn (where other faces have them) get uv 0
  // and a zero normal, which the packer leaves out: those triangles shade with their
  // geometric normal. The triples seen per position are chained in flat arrays.
  std::vector<int> head(r.v.size() / 3, -1);
  struct Seen {
    int vt, vn, next;
  };
  std::vector<Seen> seen;
  // Usually one vertex per position; a file that splits more grows these (doubling).
  seen.reserve(head.size());
  m.positions.reserve(head.size());
  if (r.has_vn) m.normals.reserve(head.size());
  if (r.has_vt) m.uvs.reserve(head.size());
  auto vertex = [&](const ObjReader::Corner& c) -> unsigned {
    for (int s = head[size_t(c.v)]; s >= 0; s = seen[size_t(s)].next)
      if (seen[size_t(s)].vt == c.vt && seen[size_t(s)].vn == c.vn) return unsigned(s);
    const int k = int(seen.size());
    seen.push_back({c.vt, c.vn, head[size_t(c.v)]});
    head[size_t(c.v)] = k;
    m.positions.emplace_back(r.v[3 * size_t(c.v)], r.v[3 * size_t(c.v) + 1], r.v[3 * size_t(c.v) + 2]);
    if (r.has_vn) m.normals.push_back(c.vn >= 0 ? glm::vec3(r.vn[3 * size_t(c.vn)], r.vn[3 * size_t(c.vn) + 1], r.vn[3 * size_t(c.vn) + 2]) : glm::vec3(0.0f));
    if (r.has_vt) m.uvs.push_back(c.vt >= 0 ? glm::vec2(r.vt[2 * size_t(c.vt)], r.vt[2 * size_t(c.vt) + 1]) : glm::vec2(0.0f));
    return unsigned(k);
  };
  m.triangles.reserve(r.corners.size() / 3);
  for (size_t f = 0; f + 2 < r.corners.size(); f += 3) {
    glm::uvec3 tri;
    for (int k = 0; k < 3; ++k) tri[k] = vertex(r.corners[f + size_t(k)]);  // in order: vertices number as first used
    m.triangles.push_back(tri);
    if (m.triangles.size() % kStepLines == 0) co_await Work{16 * kStepLines};  // about the bytes of text of as many faces
  }
  if (m.triangles.empty()) throw InputError(path, 0, "no faces");
}

MeshData parse_mesh_obj(const std::string& text, const std::string& path) {
  MeshData m;
  parse_mesh_obj_steps(text, path, m).finish();
  return m;
}


}  // namespace pt
