#include "core/records.h"

#include <cassert>
#include <cctype>

namespace pt {

#define PT_FIELD_LIST(t, n, tex, comp) n,
#define PT_LAYOUT_DEF(name, texels, fields)                                           \
  const RecordLayout& name##_layout() {                                               \
    using namespace name##_rec;                                                       \
    static const RecordLayout l{#name, kTexels, {fields(PT_FIELD_LIST)}, {}};         \
    return l;                                                                         \
  }
PT_RECORDS(PT_LAYOUT_DEF)
#undef PT_LAYOUT_DEF
#undef PT_FIELD_LIST

namespace {
// The material record's GLSL struct with its hit slots (see PT_MATERIAL_RECORD).
RecordLayout material_glsl_layout() {
  RecordLayout l = material_layout();
  l.locals = {"p9", "p10", "p11"};
  return l;
}
}  // namespace

const RecordLayout& material_glsl() {
  static const RecordLayout l = material_glsl_layout();
  return l;
}

std::string glsl_record(const RecordLayout& l) {
  std::string cap = l.name;
  cap[0] = char(std::toupper(cap[0]));
  const std::string tex = "u_" + std::string(l.name) + "_data";
  std::string s = "uniform highp sampler2D " + tex + ";\n";
  s += "struct " + cap + "Rec {";
  for (const Field& f : l.fields) s += " " + std::string(f.type) + " " + f.name + ";";
  for (const char* f : l.locals) s += " float " + std::string(f) + ";";
  s += " };\n";
  s += cap + "Rec load_" + l.name + "(int i) {\n";
  s += "  int base = i * " + std::to_string(l.texels) + ";\n";
  s += "  ivec2 at = ivec2(base & " + std::to_string(kDataWidth - 1) + ", base >> " + std::to_string(kDataWidthLog2) + ");\n";
  for (int t = 0; t < l.texels; ++t)
    s += "  vec4 t" + std::to_string(t) + " = texelFetch(" + tex + ", at + ivec2(" + std::to_string(t) + ", 0), 0);\n";
  s += "  " + cap + "Rec r;\n";
  static const char* kComp = "xyzw";
  for (const Field& f : l.fields) {
    const std::string src = "t" + std::to_string(f.texel) + "." + std::string(kComp + f.comp, size_t(f.width));
    const bool is_int = f.type[0] == 'i';
    s += "  r." + std::string(f.name) + " = " + (is_int ? "int(" + src + ")" : src) + ";\n";
  }
  for (const char* f : l.locals) s += "  r." + std::string(f) + " = 0.0;\n";
  s += "  return r;\n}\n";
  return s;
}

int RecordBuffer::add() {
  data_.resize(data_.size() + size_t(texels_) * 4, 0.0f);
  return count_++;
}

void RecordBuffer::set(int rec, const Field& f, float v) {
  assert(f.width == 1 && rec < count_);
  data_[(size_t(rec) * texels_ + f.texel) * 4 + f.comp] = v;
}

void RecordBuffer::set(int rec, const Field& f, glm::vec3 v) {
  assert(f.width == 3 && rec < count_);
  float* p = &data_[(size_t(rec) * texels_ + f.texel) * 4 + f.comp];
  p[0] = v.x;
  p[1] = v.y;
  p[2] = v.z;
}

void RecordBuffer::set(int rec, const Field& f, glm::vec2 v) {
  assert(f.width == 2 && rec < count_);
  float* p = &data_[(size_t(rec) * texels_ + f.texel) * 4 + f.comp];
  p[0] = v.x;
  p[1] = v.y;
}

int RecordBuffer::rows() const {
  const int n = count_ * texels_;
  return n == 0 ? 1 : (n + kDataWidth - 1) / kDataWidth;
}

std::vector<float> RecordBuffer::texels() const {
  std::vector<float> out(size_t(rows()) * kDataWidth * 4, 0.0f);
  std::copy(data_.begin(), data_.end(), out.begin());
  return out;
}

}  // namespace pt
