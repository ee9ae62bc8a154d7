#include "backends/mesh/gltf_container.h"

#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "core/atomic_file.h"

namespace ramus::mesh {

namespace {

// The JSON chunk of a GLB container (glTF 2.0, "Binary glTF Layout": a 12-byte header, then the
// JSON chunk's length, type and space-padded text).
std::string glb_json(const std::string& glb) {
  if (glb.size() < 20) return {};
  std::uint32_t len = 0;
  std::memcpy(&len, glb.data() + 12, 4);
  std::string json = glb.substr(20, len);
  while (!json.empty() && json.back() == ' ') json.pop_back();
  return json;
}

std::string uri_escape(const std::string& s) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : s) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
      out += char(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

}  // namespace

std::optional<std::string> gltf_json_with_buffer_uri(const std::string& glb,
                                                     const std::string& bin_uri) {
  std::string json = glb_json(glb);
  const std::string key = "\"buffers\":[{";
  const std::size_t at = json.find(key);
  if (at == std::string::npos) return std::nullopt;
  json.insert(at + key.size(), "\"uri\":\"" + uri_escape(bin_uri) + "\",");
  return json + "\n";
}

std::string glb_bin(const std::string& glb) {
  std::uint32_t json_len = 0, bin_len = 0;
  if (glb.size() < 20) return {};
  std::memcpy(&json_len, glb.data() + 12, 4);
  const std::size_t at = 20 + std::size_t(json_len);
  if (at + 8 > glb.size()) return {};
  std::memcpy(&bin_len, glb.data() + at, 4);
  return glb.substr(at + 8, bin_len);
}

bool write_gltf_files(
    const std::string& path,
    const std::function<GltfBytes(bool binary, const std::string& bin_uri)>& encode) {
  const std::filesystem::path p(path);
  const std::string ext = p.extension().string();
  if (ext == ".glb") {
    write_file_atomically(path, encode(true, "").main);
    return true;
  }
  if (ext != ".gltf") return false;
  std::filesystem::path bin = p;
  bin.replace_extension(".bin");
  const GltfBytes bytes = encode(false, bin.filename().string());
  write_file_atomically(bin.string(), bytes.bin);
  write_file_atomically(path, bytes.main);
  return true;
}

}  // namespace ramus::mesh
