// ramus info: what this build of ramus contains (version, compiler, formats), for bug reports.
#include <cstdio>

#include "cli/command.h"

namespace ramus::cli {

void add_version_info(CLI::App& app, const GlobalOptions&, std::function<int()>& run) {
  CLI::App* sub = app.add_subcommand("info", "print what this build of ramus contains");
  sub->callback([&run] {
    run = [] {
      std::printf("ramus 0.1.0\n");
      std::printf("compiler      GCC %d.%d.%d, C++%ld\n", __GNUC__, __GNUC_MINOR__,
                  __GNUC_PATCHLEVEL__, __cplusplus / 100 % 100 + 0L);
      std::printf("grammars      .ramus (lsystem, pieces and voxels blocks; docs/language.md)\n");
      std::printf("scans in      .ply .xyz .txt .asc .csv .las (1.0-1.4, formats 0-10) .pcd\n");
      std::printf("meshes out    .glb .gltf .obj .ply; previews .png .svg\n");
      std::printf("binaries      .rmb version 1 (docs/binary-format.md)\n");
      return 0;
    };
  });
}

}  // namespace ramus::cli
