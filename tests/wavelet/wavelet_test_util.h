// Helpers shared by the test_wavelet_*.cpp files: random grids and the Python oracles
// (tests/tools/*.py run with a python3 that has numpy, PyWavelets and SciPy).
#pragma once

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "core/rng.h"
#include "infer/wavelet/voxel_grid.h"

namespace ramus::wavelet::test {

inline VoxelGrid random_grid(int levels, std::uint64_t seed, double occupied_share = -1) {
  VoxelGrid g(levels);
  Rng rng(seed);
  for (double& v : g.values) {
    double u = rng.uniform01();
    v = occupied_share < 0 ? u : (u < occupied_share ? 1.0 : 0.0);
  }
  return g;
}

// A python3 (PATH first, then the system one) that can import `modules` (e.g. "numpy, pywt");
// empty when none can.
inline std::string python_with(const std::string& modules) {
  for (const char* candidate : {"python3", "/usr/bin/python3"}) {
    std::string cmd = std::string(candidate) + " -c \"import " + modules + "\" >/dev/null 2>&1";
    if (std::system(cmd.c_str()) == 0) return candidate;
  }
  return {};
}

inline std::string temp_path(const std::string& name) {
  return std::string(RAMUS_BINARY_DIR) + "/wavelet_test_" + name;
}

inline std::string tool(const std::string& name) {
  return std::string(RAMUS_SOURCE_DIR) + "/tests/tools/" + name;
}

}  // namespace ramus::wavelet::test
