#include "cli/preview_input.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "cli/command.h"
#include "formats/point_cloud_io.h"

namespace ramus::cli {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// The first bytes of the file: enough for every signature and a PLY header.
std::string head_of(const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr || std::filesystem::is_directory(path)) {
    if (f) std::fclose(f);
    throw UserError(path + ": cannot open the file");
  }
  std::string bytes(16384, '\0');
  bytes.resize(std::fread(bytes.data(), 1, bytes.size(), f));
  std::fclose(f);
  return bytes;
}

// A PLY header's `element face N` with N > 0. Meshes written by ramus and most tools have one;
// point clouds have none (or zero faces).
bool ply_has_faces(const std::string& head) {
  std::istringstream in(head);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line == "end_header") break;
    std::istringstream words(line);
    std::string element, name;
    long long count = 0;
    if (words >> element >> name >> count && element == "element" && name == "face") {
      return count > 0;
    }
  }
  return false;
}

}  // namespace

const char* preview_input_name(PreviewInput kind) {
  switch (kind) {
    case PreviewInput::kGrammar:
      return "grammar";
    case PreviewInput::kBinaryGrammar:
      return "binary grammar";
    case PreviewInput::kSkeleton:
      return "skeleton";
    case PreviewInput::kMesh:
      return "mesh";
    case PreviewInput::kScan:
      return "scan";
  }
  return "input";
}

PreviewInput classify_preview_input(const std::string& path) {
  const std::string head = head_of(path);
  const std::string ext = lower_extension(path);
  if (ext == ".ramus") return PreviewInput::kGrammar;
  if (head.compare(0, 4, "RMB\x1a", 4) == 0 || ext == ".rmb") return PreviewInput::kBinaryGrammar;
  if (head.compare(0, 4, "glTF") == 0 || ext == ".glb" || ext == ".gltf" || ext == ".obj") {
    return PreviewInput::kMesh;
  }
  if (ext == ".json") return PreviewInput::kSkeleton;
  if (head.compare(0, 3, "ply") == 0) {
    return ply_has_faces(head) ? PreviewInput::kMesh : PreviewInput::kScan;
  }
  if (format_from_extension(path) != Format::kAuto || sniff_format(head) != Format::kAuto) {
    return PreviewInput::kScan;
  }
  throw UserError(path +
                  ": cannot tell what this is; preview reads grammars (.ramus, .rmb), skeletons "
                  "(.json), meshes (.glb .gltf .obj .ply) and scans (.ply .xyz .txt .asc .csv "
                  ".las .laz .pcd)");
}

}  // namespace ramus::cli
