// LAZ decoding speed: our decoder (formats/laz/) against laz-perf (npm, LASzip in WebAssembly,
// the tests' oracle) on the same file in one run, as points per second and their ratio.
//   bench_laz [FILE.laz ...]   (default ../shared/data/treels_spruce.laz)
// For each file: the best of 5 runs of decompress_laz (records only, what laz-perf's loop does),
// of a full read_point_cloud (records -> recentred cloud), and of the oracle's decode loop
// (tests/formats/laz/laz_oracle.js --time, which times only its loop, not the WebAssembly
// start-up). The oracle columns say n/a when node or tools/node_modules/laz-perf is missing.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "formats/las_file.h"
#include "formats/point_cloud_io.h"

using namespace ramus;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

template <typename F>
double best_seconds(F&& f, int runs = 5) {
  double best = 1e30;
  for (int i = 0; i < runs; ++i) {
    const auto t0 = Clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return best;
}

// The oracle's own timing of its decode loop (best of 5 runs); < 0 when it cannot run.
double oracle_seconds(const std::string& file, const fs::path& scratch) {
  const fs::path script = fs::path(RAMUS_SOURCE_DIR) / "tests/formats/laz/laz_oracle.js";
  if (!fs::exists(fs::path(RAMUS_SOURCE_DIR) / "tools/node_modules/laz-perf")) return -1;
  double best = 1e30;
  for (int i = 0; i < 5; ++i) {
    const std::string cmd = "node \"" + script.string() + "\" \"" + file + "\" \"" +
                            (scratch / "oracle.las").string() + "\" --time 2>/dev/null";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
    if (!pipe) return -1;
    std::array<char, 128> line{};
    if (!fgets(line.data(), int(line.size()), pipe.get())) return -1;
    unsigned long long points = 0;
    double seconds = 0;
    if (std::sscanf(line.data(), "%llu %lf", &points, &seconds) != 2) return -1;
    best = std::min(best, seconds);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) files.push_back(argv[i]);
  if (files.empty())
    files.push_back(std::string(RAMUS_SOURCE_DIR) + "/../shared/data/treels_spruce.laz");
  const fs::path scratch = fs::temp_directory_path() / "ramus_bench_laz";
  fs::create_directories(scratch);
  std::printf(
      "| file | points | ramus records (Mpt/s) | ramus cloud (Mpt/s) | laz-perf (Mpt/s) | "
      "ramus / laz-perf |\n|---|---|---|---|---|---|\n");
  for (const std::string& file : files) {
    const std::string bytes = slurp(file);
    std::size_t points = 0;
    try {
      points = read_point_cloud_bytes(bytes, Format::kLas, file).size();
    } catch (const FormatError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 1;
    }
    std::size_t sink = 0;
    const double records = best_seconds([&] { sink += decompress_laz(bytes, file).size(); });
    const double cloud =
        best_seconds([&] { sink += read_point_cloud_bytes(bytes, Format::kLas, file).size(); });
    const double oracle = oracle_seconds(file, scratch);
    const double mp = double(points) / 1e6;
    char oracle_col[32] = "n/a", ratio_col[32] = "n/a";
    if (oracle > 0) {
      std::snprintf(oracle_col, sizeof oracle_col, "%.1f", mp / oracle);
      std::snprintf(ratio_col, sizeof ratio_col, "%.2f", oracle / records);
    }
    std::printf("| %s | %zu | %.1f | %.1f | %s | %s |\n", fs::path(file).filename().c_str(), points,
                mp / records, mp / cloud, oracle_col, ratio_col);
    if (sink == 0) std::printf("(nothing decoded)\n");
  }
  fs::remove_all(scratch);
  return 0;
}
