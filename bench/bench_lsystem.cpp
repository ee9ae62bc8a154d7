// The ramus side of bench/lsystem_vs_lindenmayer.sh: derives one of the benchmark systems and
// prints what the script compares (the same systems as bench/lindenmayer_runner.js).
// usage: bench_lsystem CASE N [THREADS [REPEAT [--print | --warmup]]]
//   --warmup derives once before the REPEAT timed runs: every timed run then finds the pages
//   and caches a long-running program has (the steady state); without it the first timed run
//   pays for the process's fresh memory.
//   length L / modules_total T (sum of the lengths after each step) / seconds S (derivation,
//   wall clock, mean of REPEAT runs) / cpu_seconds C (user + system time of all threads, mean) /
//   user_seconds U / system_seconds Y (the two parts of C: the engine's own work, and the kernel's
//   -- mostly supplying the fresh pages the strings are written to) /
//   string_bytes B / bytes_per_module b / bytes_per_parametric_module p (its symbol, offset and
//   parameters) / block_offset_bytes_per_module o (shared by all modules) / peak_rss_kb K
// CPU time is what the comparison script ranks by: it does not depend on how busy the machine is.
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "compiler/derive.h"
#include "compiler/pipeline.h"

namespace {

const char* source_of(const std::string& kase) {
  if (kase == "a") {  // ABOP fig. 1.24f as a plain string system
    return "lsystem a { angle 22.5; axiom X; X -> F - [ [ X ] + X ] + F [ + F X ] - X; F -> F F; }";
  }
  if (kase == "b") {  // parametric binary tree
    return "lsystem b { axiom A(1); A(s) -> F(s) [ + A(s / 1.456) ] [ - A(s / 1.456) ]; }";
  }
  if (kase == "s") {  // ABOP fig. 1.27, stochastic (examples/abop/fig1_27.ramus)
    return "lsystem s { angle 22.5; seed 1; axiom F;"
           "  F -> (0.33) F[+F]F[-F]F | (0.33) F[+F]F | (0.34) F[-F]F; }";
  }
  if (kase == "p") {  // the binary tree of (b) with a stochastic choice between two shapes
    return "lsystem p { seed 1; axiom A(1);"
           "  A(s) -> (0.5) F(s) [ + A(s / 1.456) ] [ - A(s / 1.456) ]"
           "        | (0.5) F(s) [ - A(s / 1.456) ] + A(s / 1.2); }";
  }
  if (kase == "c1") {  // ABOP fig. 1.31a (0 and 1 are the modules Z and O here)
    return R"(module Z, O;
      lsystem c1 { ignore + - F; angle 22.5; axiom F O F O F O;
        Z < Z > Z -> Z;  Z < Z > O -> O [ + F O F O ];  Z < O > Z -> O;  Z < O > O -> O;
        O < Z > Z -> Z;  O < Z > O -> O F O;  O < O > Z -> O;  O < O > O -> Z;
        + -> -;  - -> +; })";
  }
  if (kase == "c2") {
    // Internodes F elongate only above a node I; F is ignored by contexts as in ABOP 1.31, so
    // the left context of every F lies before its whole internode.
    return "lsystem c2 { ignore + - F; axiom I F A; A -> I F [ + A ] I F A; I < F -> F F; }";
  }
  return nullptr;
}

}  // namespace

// User and system CPU seconds of the process so far.
struct CpuTime {
  double user = 0, system = 0;
};
CpuTime cpu_time() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return {double(ru.ru_utime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec),
          double(ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_stime.tv_usec)};
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_lsystem CASE N [THREADS [REPEAT [--print | --warmup]]]\n");
    return 2;
  }
  const char* src = source_of(argv[1]);
  if (!src) {
    std::fprintf(stderr, "bench_lsystem: unknown case %s\n", argv[1]);
    return 2;
  }
  ramus::SourceManager sources;
  ramus::DiagnosticSink diags;
  ramus::ir::Grammar g;
  try {
    g = ramus::lower_text(std::string(argv[1]) + ".ramus", src, {}, sources, diags);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_lsystem: %s\n", e.what());
    return 1;
  }
  ramus::DeriveOptions d;
  d.steps = std::atoi(argv[2]);
  d.threads = argc > 3 ? std::atoi(argv[3]) : 0;
  d.max_modules = 1'000'000'000;
  const int repeat = argc > 4 ? std::max(1, std::atoi(argv[4])) : 1;
  const bool print = argc > 5 && std::strcmp(argv[5], "--print") == 0;
  const bool warmup = argc > 5 && std::strcmp(argv[5], "--warmup") == 0;
  if (argc > 5 && !print && !warmup) {
    std::fprintf(stderr, "bench_lsystem: unknown option %s\n", argv[5]);
    return 2;
  }
  ramus::DeriveStats st;
  ramus::ModuleString s;
  if (warmup) s = ramus::derive(g, d, &st);
  double wall = 0, user = 0, system = 0;
  for (int r = 0; r < repeat; ++r) {
    s = ramus::ModuleString();
    const CpuTime c0 = cpu_time();
    s = ramus::derive(g, d, &st);
    const CpuTime c1 = cpu_time();
    user += c1.user - c0.user;
    system += c1.system - c0.system;
    wall += st.seconds;
  }
  const double cpu = user + system;
  std::size_t total = 0;
  for (std::size_t k = 1; k < st.lengths.size(); ++k) total += st.lengths[k];
  std::size_t parametric = 0;
  for (std::size_t i = 0; i < s.size(); ++i) parametric += s.nparams(i) > 0;
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf("length %zu\nmodules_total %zu\nseconds %.6f\ncpu_seconds %.6f\n", s.size(), total,
              wall / repeat, cpu / repeat);
  std::printf("user_seconds %.6f\nsystem_seconds %.6f\n", user / repeat, system / repeat);
  std::printf("string_bytes %zu\nbytes_per_module %.2f\n", s.bytes(),
              double(s.bytes()) / double(s.size()));
  if (parametric) {
    // A parametric module's own bytes (symbol, offset, parameters); every module also shares
    // the block offsets, 4 bytes per 1024 modules, printed apart.
    std::printf(
        "bytes_per_parametric_module %.2f\n",
        double(ramus::module_bytes(0)) + 8.0 * double(s.param_count()) / double(parametric));
    std::printf("block_offset_bytes_per_module %.4f\n", 4.0 / double(1u << ramus::kBlockShift));
  }
  std::printf("peak_rss_kb %ld\n", ru.ru_maxrss);
  if (print) {
    std::printf("string %s\n", ramus::to_text(g, s).c_str());
  }
  return 0;
}
