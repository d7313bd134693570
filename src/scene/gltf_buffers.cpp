// The buffers of a glTF and tinygltf's parse of its JSON (and tinygltf's implementation):
// every buffer that is not a data: URI is ours to read - the GLB's BIN chunk where it
// lies, a buffer file in slices - so that tinygltf neither copies tens of MB nor reads a
// file in one step; tinygltf opens no file at all (its own search - its base folder, then
// the working directory - is never used).
#define TINYGLTF_IMPLEMENTATION
#include "scene/gltf_buffers.h"

#include "core/error.h"
#include "core/file_io.h"

namespace pt::gltf {
namespace {

// tinygltf's file callbacks.
bool file_exists(const std::string&, void*) { return true; }
std::string expand_path(const std::string& p, void*) { return p; }
bool write_file(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }
// Every buffer file is read by read_model before tinygltf parses (own_buffers):
// tinygltf is never to read one itself.
bool refuse_file(std::vector<unsigned char>*, std::string* err, const std::string&, void*) {
  *err = "buffer files are read before tinygltf parses";
  return false;
}

// Images: their bytes are kept, undecoded (image.as_is), and decoded by our own image
// reader when a material uses them (gltf_materials.cpp). An image in a bufferView is read
// then too, from the buffers as the conversion has them (Reader::view; tinygltf may not
// hold the bytes).
bool keep_image(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes, int size, void*) {
  image->as_is = true;
  if (image->bufferView >= 0) return true;
  if (size < 0 || (size > 0 && !bytes)) return false;
  image->image.assign(bytes, bytes + size);
  return true;
}

// A buffer we read ourselves: stored in the GLB's BIN chunk, or in a file named by its
// (URL-decoded) uri.
struct OwnBuffer {
  size_t index = 0;
  bool bin_chunk = false;
  std::string uri;
  size_t length = 0;  // byteLength
};

// The buffers of the JSON that are ours to read - every one but data: URIs, which
// tinygltf decodes - and in *rewritten the JSON for tinygltf with each of them replaced
// by a 1-byte data: URI (left empty when there are none). JSON that does not parse is
// left to tinygltf, which reports where.
std::vector<OwnBuffer> own_buffers(const GltfJson& json, const std::string& path, std::string* rewritten) {
  std::vector<OwnBuffer> out;
  nlohmann::json doc = nlohmann::json::parse(json.text, json.text + json.size, nullptr, false);
  if (!doc.is_object() || !doc.contains("buffers") || !doc["buffers"].is_array()) return out;
  nlohmann::json& buffers = doc["buffers"];
  for (size_t i = 0; i < buffers.size(); ++i) {
    nlohmann::json& b = buffers[i];
    const std::string at = pointer("buffers", i);
    if (!b.is_object()) throw InputError(path, 0, at + ": not an object");
    if (!b.contains("byteLength") || !b["byteLength"].is_number_unsigned())
      throw InputError(path, 0, at + ": byteLength must be a whole number of bytes");
    OwnBuffer o;
    o.index = i;
    o.length = b["byteLength"].get<size_t>();
    if (!b.contains("uri")) {
      if (!json.binary) throw InputError(path, 0, at + ": no uri (only a binary glTF's buffers may have none)");
      if (!json.has_bin) throw InputError(path, 0, at + ": no uri, and the file has no BIN chunk");
      if (o.length > json.bin_size)
        throw InputError(path, 0, at + ": byteLength " + std::to_string(o.length) + " is more than the BIN chunk's " +
                                      std::to_string(json.bin_size) + " bytes");
      o.bin_chunk = true;
    } else {
      if (!b["uri"].is_string()) throw InputError(path, 0, at + ": uri is not a string");
      const std::string uri = b["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) continue;
      o.uri = url_decode(uri);
    }
    b["uri"] = "data:application/octet-stream;base64,AA==";
    b["byteLength"] = 1;
    out.push_back(std::move(o));
  }
  if (!out.empty()) *rewritten = doc.dump();
  return out;
}

}  // namespace

std::string url_decode(const std::string& uri) { return tinygltf::dlib::urldecode(uri); }

std::optional<std::string> resolve_referenced(const Context& c, const std::string& uri, std::string* why) {
  const std::string rel = !uri.empty() && uri[0] == '/' ? uri : directory_of(c.path) + "/" + uri;
  if (!c.resolve || !*c.resolve) {
    *why = "file references are disabled for this glTF";
    return std::nullopt;
  }
  try {
    return (*c.resolve)(rel);
  } catch (const InputError& e) {
    *why = e.what();
  }
  return std::nullopt;
}

Resumable read_model(const std::string& bytes, const GltfJson& json, const Context& ctx, tinygltf::Model& model,
                     std::vector<Bytes>& buffers, std::deque<std::string>& files) {
  const std::string& path = ctx.path;
  // Each buffer stored in the BIN chunk or in a file is read here, and tinygltf is given
  // the JSON with that buffer replaced by a 1-byte data: URI. Buffers that are data: URIs
  // stay tinygltf's to decode (one step).
  std::string text;  // the JSON tinygltf parses, when rewritten
  const std::vector<OwnBuffer> ours = own_buffers(json, path, &text);
  std::vector<std::optional<Bytes>> own;
  for (const OwnBuffer& o : ours) {
    if (own.size() <= o.index) own.resize(o.index + 1);
    const std::string at = pointer("buffers", o.index);
    if (o.bin_chunk) {
      own[o.index] = Bytes{reinterpret_cast<const unsigned char*>(bytes.data()) + json.bin_offset, o.length};
      continue;
    }
    std::string why;
    const std::optional<std::string> file = resolve_referenced(ctx, o.uri, &why);
    if (!file) throw InputError(path, 0, at + ": " + why);
    std::optional<std::string> read;
    Resumable reading = read_file_steps(*file, read);
    while (!co_await reading) {
    }
    if (!read) throw InputError(path, 0, at + ": cannot open the buffer file " + *file);
    if (read->size() < o.length)
      throw InputError(path, 0, at + ": the buffer file " + *file + " has " + std::to_string(read->size()) + " bytes, byteLength says " +
                                    std::to_string(o.length));
    files.push_back(std::move(*read));  // a deque: growing moves none of the files read before
    own[o.index] = Bytes{reinterpret_cast<const unsigned char*>(files.back().data()), o.length};
  }
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&keep_image, nullptr);
  loader.SetFsCallbacks({&file_exists, &expand_path, &refuse_file, &write_file, nullptr});
  std::string err, warn;
  const bool ok = !text.empty() ? loader.LoadASCIIFromString(&model, &err, &warn, text.data(), unsigned(text.size()), "")
                  : json.binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                              unsigned(bytes.size()), "")
                                : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), "");
  if (!ok) fail_gltf_parse(err, path, json);
  for (size_t i = 0; i < model.buffers.size(); ++i)
    buffers.push_back(i < own.size() && own[i] ? *own[i] : Bytes{model.buffers[i].data.data(), model.buffers[i].data.size()});
}

}  // namespace pt::gltf
