// ramus info [FILE.rmb]: what this build of ramus contains (version, compiler, formats), for
// bug reports; with an .rmb file, the format version and flags its header holds.
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/command.h"
#include "cli/read_file.h"
#include "formats/rmb/rmb.h"

namespace ramus::cli {
namespace {

// The header of docs/binary-format.md: magic "RMB\x1a", u16 version, u16 flags. Only the header
// is read: info says what a file claims to be, even one this build cannot decode.
int print_rmb_header(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  if (bytes.size() < 8 || bytes.compare(0, 4, "RMB\x1a", 4) != 0) {
    throw UserError(path + ": not an .rmb file (no RMB signature)");
  }
  auto u16 = [&](std::size_t at) {
    return std::uint16_t(std::uint8_t(bytes[at]) | std::uint8_t(bytes[at + 1]) << 8);
  };
  const std::uint16_t version = u16(4);
  const std::uint16_t flags = u16(6);
  std::string names;
  if (flags & kRmbQuantized) names += " quantized";
  if (flags & kRmbZstd) names += " zstd";
  if (flags & kRmbStripped) names += " stripped";
  if (flags & ~kRmbKnownFlags) names += " unknown";
  const bool readable = version >= kRmbOldestVersion && version <= kRmbVersion;
  std::printf("%s: .rmb version %u%s, flags 0x%04x%s, %zu bytes\n", path.c_str(), unsigned(version),
              readable ? "" : " (this build does not read it)", unsigned(flags), names.c_str(),
              bytes.size());
  return 0;
}

int print_build() {
  std::printf("ramus 0.1.0\n");
  std::printf("compiler      GCC %d.%d.%d, C++%ld\n", __GNUC__, __GNUC_MINOR__, __GNUC_PATCHLEVEL__,
              __cplusplus / 100 % 100 + 0L);
  std::printf("grammars      .ramus (lsystem, pieces and voxels blocks; docs/language.md)\n");
  std::printf("scans in      .ply .xyz .txt .asc .csv .las (1.0-1.4, formats 0-10) .laz .pcd\n");
  std::printf(
      "meshes out    .glb .gltf (y up, MSFT_lod) .obj .ply (--up y|z); previews .png .svg\n");
  std::printf("meshes in     .glb .gltf .obj .ply (ramus preview)\n");
  // From the codec's constants, so the line cannot fall behind the format again.
  std::printf(
      "binaries      .rmb version %u written, versions %u-%u read (docs/binary-format.md)\n",
      unsigned(kRmbVersion), unsigned(kRmbOldestVersion), unsigned(kRmbVersion));
  return 0;
}

}  // namespace

void add_version_info(CLI::App& app, const GlobalOptions&, std::function<int()>& run) {
  auto file = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand(
      "info", "print what this build of ramus contains, or the version of an .rmb file");
  sub->add_option("file", *file, "an .rmb file: print its format version and flags");
  sub->callback([file, &run] {
    run = [file] { return file->empty() ? print_build() : print_rmb_header(*file); };
  });
}

}  // namespace ramus::cli
