#include "core/shader_source.h"

#include <cctype>

namespace pt {

std::string ShaderSource::map_log(const std::string& log) const {
  // Drivers print "0:12:" (ANGLE), "0:12(7):" (Mesa, with a column) or "0(12) :" (NVIDIA):
  // source 0 is files[0].
  auto digits = [&](size_t i) {
    size_t j = i;
    while (j < log.size() && std::isdigit(static_cast<unsigned char>(log[j]))) ++j;
    return j;
  };
  std::string out;
  for (size_t i = 0; i < log.size();) {
    const bool starts = std::isdigit(static_cast<unsigned char>(log[i])) &&
                        (i == 0 || !std::isalnum(static_cast<unsigned char>(log[i - 1])));
    const size_t a_end = starts ? digits(i) : i;
    if (a_end > i && a_end - i <= 6 && a_end + 1 < log.size() && (log[a_end] == ':' || log[a_end] == '(')) {
      const size_t b_end = digits(a_end + 1);
      size_t after = b_end;
      if (log[a_end] == '(' && after < log.size() && log[after] == ')') ++after;
      if (log[a_end] == ':' && after < log.size() && log[after] == '(') {  // Mesa's column
        after = digits(after + 1);
        if (after < log.size() && log[after] == ')') ++after;
      }
      while (log[a_end] == '(' && after < log.size() && log[after] == ' ') ++after;
      const size_t src = std::stoul(log.substr(i, a_end - i));
      if (b_end > a_end + 1 && after < log.size() && log[after] == ':' && src < files.size()) {
        out += files[src] + ":" + log.substr(a_end + 1, b_end - a_end - 1) + ":";
        i = after + 1;
        continue;
      }
    }
    out += log[i++];
  }
  return out;
}

}  // namespace pt
