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

std::string glb_layout_error(const unsigned char* data, std::size_t size) {
  const auto u32 = [&](std::size_t at) {
    return std::uint32_t(data[at]) | std::uint32_t(data[at + 1]) << 8 |
           std::uint32_t(data[at + 2]) << 16 | std::uint32_t(data[at + 3]) << 24;
  };
  const auto at = [](std::size_t byte, const std::string& what) {
    return "byte " + std::to_string(byte) + ": " + what;
  };
  if (size < 12) return at(size, "the file ends inside the 12-byte GLB header");
  if (u32(0) != 0x46546C67u) return at(0, "expected the GLB magic \"glTF\"");
  if (u32(4) != 2) return at(4, "expected GLB version 2, found " + std::to_string(u32(4)));
  if (u32(8) != size) {
    return at(8, "the header gives a length of " + std::to_string(u32(8)) +
                     " bytes, the file has " + std::to_string(size));
  }
  constexpr std::uint32_t kJson = 0x4E4F534Au, kBin = 0x004E4942u;
  std::size_t offset = 12;
  for (int chunk = 0; offset < size; ++chunk) {
    if (size - offset < 8) return at(offset, "the file ends inside a chunk header (8 bytes)");
    const std::uint32_t length = u32(offset), type = u32(offset + 4);
    if (chunk == 0 && type != kJson) return at(offset + 4, "expected the JSON chunk first");
    if (chunk > 0 && type == kJson) return at(offset + 4, "a second JSON chunk");
    if (type == kBin && chunk != 1) return at(offset + 4, "a BIN chunk that is not the second");
    if (length % 4 != 0) {
      return at(offset, "a chunk length of " + std::to_string(length) +
                            " bytes, not a multiple of 4 (chunks are 4-byte aligned)");
    }
    if (length > size - offset - 8) {
      return at(offset, "a chunk of " + std::to_string(length) +
                            " bytes, past the end of the file (" +
                            std::to_string(size - offset - 8) + " bytes left)");
    }
    offset += 8 + std::size_t(length);
  }
  if (offset == 12) return at(12, "expected the JSON chunk");
  return {};
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
