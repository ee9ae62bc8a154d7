// Lossy quantization (flag bit 0, `ramus build --tolerance T`) and the zstd stage (flag bit 1)
// of the .rmb format (docs/binary-format.md): every decoded real is within the tolerance of the
// original, the tree the turtle draws stays within the stated bound, files are lossless unless
// a tolerance is asked for, and zstd files decode to the same grammar.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "../cli/cli_runner.h"
#include "compiler/turtle.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_zstd.h"
#include "rmb_test_util.h"

using namespace ramus;

namespace {

// Every real the format stores, in a fixed order: settings, constants, the pool, code values.
std::vector<double> reals(const ir::Grammar& g) {
  const ir::Settings& s = g.settings;
  std::vector<double> v = {s.angle,      s.step,       s.width,      s.width_decay,
                           s.tropism[0], s.tropism[1], s.tropism[2], s.elasticity};
  for (const ir::Constant& c : g.constants) v.push_back(c.value);
  v.insert(v.end(), g.consts.begin(), g.consts.end());
  for (const ir::Code& c : g.codes) v.push_back(c.value);
  return v;
}

Skeleton tree_of(const ir::Grammar& g) {
  const ModuleString s = test::derive_steps(g, g.settings.derive);
  TurtleOptions t;
  t.seed = g.settings.seed;
  t.steps = g.settings.derive;
  t.threads = 1;
  return interpret(g, s, t);
}

double extent(const Skeleton& k) {
  Vec3 lo = k.nodes.at(0).position, hi = lo;
  for (const SkeletonNode& n : k.nodes) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], n.position[i]);
      hi[i] = std::max(hi[i], n.position[i]);
    }
  }
  return distance(lo, hi);
}

}  // namespace

TEST_CASE("binary: files are lossless unless a tolerance is asked for", "[binary]") {
  for (const std::string& file : test::example_grammars()) {
    INFO(file);
    const ir::Grammar g = test::lower_example(file);
    const std::string bytes = encode_rmb(g);
    CHECK(bytes[6] == 0);  // no flags
    CHECK(reals(decode_rmb(bytes)) == reals(g));
  }
}

TEST_CASE("binary: every quantized real is within the tolerance", "[binary]") {
  for (double tolerance : {0.5, 1e-3, 1e-6}) {
    for (const std::string& file : test::example_grammars()) {
      INFO(file << " tolerance " << tolerance);
      const ir::Grammar g = test::lower_example(file);
      const std::string exact = encode_rmb(g);
      RmbEncodeOptions o;
      o.tolerance = tolerance;
      const std::string lossy = encode_rmb(g, o);
      CHECK((lossy[6] & kRmbQuantized) != 0);
      // Version 2 stores hand-written numbers as short decimals already; a quantized value is
      // stored as the shorter of its decimal and its multiple, so the file does not grow by
      // more than the exponent byte and rounding.
      CHECK(lossy.size() <= exact.size() + exact.size() / 100 + 1);
      const ir::Grammar back = decode_rmb(lossy);
      const std::vector<double> a = reals(g), b = reals(back);
      REQUIRE(a.size() == b.size());
      for (std::size_t i = 0; i < a.size(); ++i) {
        CHECK(std::fabs(a[i] - b[i]) <= tolerance);
        if (a[i] == std::round(a[i]) && std::fabs(a[i]) < 1e6 && tolerance < 1) {
          CHECK(b[i] == a[i]);  // integers are multiples of every quantum below 1: exact
        }
      }
      CHECK(encode_rmb(back, o) == lossy);  // quantizing is idempotent
    }
  }
}

// The stated bound (docs/binary-format.md): with --tolerance 1e-3, every node of the tree the
// turtle draws from a deterministic example moves by at most 1% of the tree's extent.
TEST_CASE("binary: the quantized tree stays within 1 percent of its extent", "[binary]") {
  RmbEncodeOptions o;
  o.tolerance = 1e-3;
  int compared = 0;
  for (const std::string& file : test::example_grammars()) {
    const ir::Grammar g = test::lower_example(file);
    bool random = false;
    for (const ir::Alternative& a : g.alternatives) random |= a.probability != ir::kNoCode;
    for (const ir::Code& c : g.codes) random |= c.random;
    if (random) continue;  // a stochastic choice may flip at a probability boundary
    INFO(file);
    const Skeleton a = tree_of(g), b = tree_of(decode_rmb(encode_rmb(g, o)));
    REQUIRE(a.size() == b.size());
    if (a.size() < 2) continue;  // draws nothing (param_p42)
    double worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      CHECK(a.nodes[i].parent == b.nodes[i].parent);
      worst = std::max(worst, distance(a.nodes[i].position, b.nodes[i].position));
    }
    CHECK(worst <= 0.01 * extent(a));
    ++compared;
  }
  CHECK(compared >= 15);
}

TEST_CASE("binary: a bad tolerance or quantum exponent is refused", "[binary]") {
  CHECK_THROWS_AS(rmb_quantum_exponent(0), RmbError);
  CHECK_THROWS_AS(rmb_quantum_exponent(-1), RmbError);
  CHECK_THROWS_AS(rmb_quantum_exponent(NAN), RmbError);
  CHECK(rmb_quantum_exponent(1e-3) == -9);  // 2^-9 = 0.00195 <= 0.002
  CHECK(rmb_quantum_exponent(0.5) == 0);
  CHECK(rmb_quantum_exponent(1e-30) == rmb::kMinQuantumExponent);
  // A reserved flag bit is rejected with its offset.
  std::string bytes = encode_rmb(test::lower_example("examples/abop/fig1_24a.ramus"));
  bytes[6] = 8;  // bit 3: reserved (bit 2 is stripped)
  try {
    decode_rmb(bytes, RmbDecodeOptions{false});
    FAIL("decoded a file with a reserved flag");
  } catch (const RmbError& e) {
    CHECK(e.offset == 6);
  }
}

TEST_CASE("binary: quantized files are rejected when truncated at any length", "[binary]") {
  RmbEncodeOptions o;
  o.tolerance = 1e-3;
  const std::string bytes = encode_rmb(test::lower_example("examples/abop/param_p42.ramus"), o);
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const std::string cut = bytes.substr(0, n);  // a fresh buffer, so ASan sees overruns
    CHECK_THROWS_AS(decode_rmb(cut, RmbDecodeOptions{false}), RmbError);
  }
}

TEST_CASE("binary: zstd files decode to the same grammar", "[binary]") {
  REQUIRE(rmb_zstd_available());
  for (const std::string& file : test::example_grammars()) {
    INFO(file);
    const ir::Grammar g = test::lower_example(file);
    for (bool lossy : {false, true}) {
      RmbEncodeOptions plain, packed;
      if (lossy) plain.tolerance = packed.tolerance = 1e-3;
      packed.zstd = true;
      const std::string a = encode_rmb(g, plain), z = encode_rmb(g, packed);
      CHECK((z[6] & kRmbZstd) != 0);
      const std::string image = rmb_uncompressed(z);  // same table and sections
      CHECK(image.substr(8, image.size() - 12) == a.substr(8, a.size() - 12));
      CHECK(encode_rmb(decode_rmb(z), plain) == a);
    }
  }
}

TEST_CASE("binary: damaged zstd files are rejected with an offset", "[binary]") {
  RmbEncodeOptions o;
  o.zstd = true;
  const std::string z = encode_rmb(test::lower_example("examples/trees/broadleaf.ramus"), o);
  for (std::size_t n = 0; n < z.size(); ++n) {
    const std::string cut = z.substr(0, n);
    CHECK_THROWS_AS(decode_rmb(cut), RmbError);
  }
  for (std::size_t i = 0; i < z.size(); ++i) {  // the checksum covers the compressed bytes
    std::string bad = z;
    bad[i] ^= 0x10;
    CHECK_THROWS_AS(decode_rmb(bad), RmbError);
  }
  // Without the checksum, frame damage is still caught by zstd or the section checks.
  for (std::size_t i = 8; i < z.size() - 4; ++i) {
    std::string bad = z;
    bad[i] ^= 0x01;
    try {
      decode_rmb(bad, RmbDecodeOptions{false});
    } catch (const RmbError&) {
    }
  }
}

TEST_CASE("binary: ramus build --tolerance --zstd, then dump and decompile", "[binary][cli]") {
  using namespace cli_test;
  TempDir tmp;
  const std::string src = std::string(RAMUS_SOURCE_DIR) + "/examples/abop/fig1_24a.ramus";
  const fs::path plain = tmp.path / "plain.rmb", packed = tmp.path / "packed.rmb";
  REQUIRE(run_ramus({"-q", "build", src, "--target", "binary", "-o", plain.string()}).status == 0);
  REQUIRE(run_ramus({"-q", "build", src, "--target", "binary", "--tolerance", "1e-3", "--zstd",
                     "-o", packed.string()})
              .status == 0);
  const std::string bytes = slurp(packed);
  CHECK(bytes[6] == char(kRmbQuantized | kRmbZstd));
  const CliResult dump = run_ramus({"dump", packed.string()});
  CHECK(dump.status == 0);
  CHECK(dump.out.rfind("-- zstd: ", 0) == 0);
  CHECK(dump.out.find("quantum exponent") != std::string::npos);
  CHECK(dump.out.find(std::to_string(bytes.size()) + " bytes\n") != std::string::npos);
  // A lossy, compressed file decompiles (spelling the quantized values); a zero tolerance is a
  // usage error.
  CHECK(run_ramus({"decompile", packed.string()}).status == 0);
  CHECK(run_ramus({"build", src, "--target", "binary", "--tolerance", "0", "-o",
                   (tmp.path / "x.rmb").string()})
            .status != 0);
}
