#include "core/file_io.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

namespace pt {

std::optional<std::string> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return std::nullopt;
  // One read of the size the file has (a stream that cannot tell its size is copied).
  const std::streamoff size = in.tellg();
  if (size >= 0 && in.seekg(0)) {
    std::string bytes(size_t(size), '\0');
    if (in.read(bytes.data(), size) && in.peek() == std::char_traits<char>::eof()) return bytes;
    in.clear();
    in.seekg(0);
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Resumable read_file_steps(std::string path, std::optional<std::string>& out) {
  out.reset();
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) co_return;
  const std::streamoff size = in.tellg();
  if (size < 0 || !in.seekg(0)) {  // cannot tell its size: one step
    out = read_file(path);
    co_return;
  }
  constexpr size_t kChunk = size_t(1) << 18;
  std::string bytes;
  bytes.reserve(size_t(size));
  while (bytes.size() < size_t(size)) {
    const size_t at = bytes.size(), n = std::min(kChunk, size_t(size) - at);
    bytes.resize(at + n);
    if (!in.read(bytes.data() + at, std::streamsize(n))) {  // it shrank meanwhile: read it again whole
      out = read_file(path);
      co_return;
    }
    co_await Work{4096};
  }
  if (in.peek() != std::char_traits<char>::eof()) {  // it grew meanwhile
    out = read_file(path);
    co_return;
  }
  out = std::move(bytes);
}

// Nothing is lost: the new bytes go to a fresh temporary file in the same folder (so the
// rename never crosses file systems), are flushed to disk, then renamed over `path` in
// one step. A reader, a crash or a full disk sees the old file or the new one, never a
// part; two writers do not share a temporary name.
bool write_file_atomic(const std::string& path, const void* data, size_t size) {
  const std::string dir = directory_of(path);
  std::string tmp = dir + "/." + path.substr(path.find_last_of('/') + 1) + ".XXXXXX";
  const int fd = mkstemp(tmp.data());
  if (fd < 0) return false;
  const char* p = static_cast<const char*>(data);
  size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, p + done, size - done);
    if (n <= 0) break;
    done += size_t(n);
  }
  const bool ok = done == size && ::fsync(fd) == 0 && ::fchmod(fd, 0644) == 0;
  if (::close(fd) != 0 || !ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

std::string directory_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

}  // namespace pt
