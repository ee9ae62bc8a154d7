// The C API of the embeddable runtime (runtime/ramus_runtime.h) grows the same skeleton as the
// full pipeline: lower -> encode_rmb -> ramus_load -> ramus_grow equals grow_file on the source
// grammar, node for node and bit for bit, for the same seed; bad images give errors, not crashes.
#include <catch2/catch.hpp>
#include <cstring>
#include <memory>
#include <string>

#include "compiler/grow.h"
#include "compiler/pipeline.h"
#include "core/skeleton.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_pieces_ast.h"
#include "grammar/loader.h"
#include "runtime/ramus_runtime.h"

namespace {

using GrammarPtr = std::unique_ptr<ramus_grammar, decltype(&ramus_free_grammar)>;
using SkeletonPtr = std::unique_ptr<ramus_skeleton, decltype(&ramus_free_skeleton)>;

std::string path_of(const std::string& example) {
  return std::string(RAMUS_SOURCE_DIR) + "/examples/" + example;
}

std::string encode_example(const std::string& example) {
  ramus::SourceManager sm;
  ramus::DiagnosticSink diags;
  return ramus::encode_rmb(ramus::lower_file(path_of(example), {}, sm, diags));
}

ramus::Skeleton grow_source(const std::string& example, std::uint64_t seed) {
  ramus::SourceManager sm;
  ramus::DiagnosticSink diags;
  ramus::GrowOptions o;
  o.seed = seed;
  return ramus::grow_file(path_of(example), o, sm, diags);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void require_same(const ramus::Skeleton& want, const ramus_skeleton* got) {
  REQUIRE(ramus_node_count(got) == want.nodes.size());
  REQUIRE(ramus_organ_count(got) == want.organs.size());
  for (std::size_t i = 0; i < want.nodes.size(); ++i) {
    const ramus::SkeletonNode& n = want.nodes[i];
    double p[3], r = -1;
    REQUIRE(ramus_node_position(got, i, p) == 0);
    REQUIRE(ramus_node_radius(got, i, &r) == 0);
    INFO("node " << i);
    REQUIRE((same_bits(p[0], n.position.x) && same_bits(p[1], n.position.y) &&
             same_bits(p[2], n.position.z)));
    REQUIRE(same_bits(r, n.radius));
    const std::int64_t parent = n.parent == ramus::kNoParent ? -1 : std::int64_t(n.parent);
    REQUIRE(ramus_node_parent(got, i) == parent);
  }
  for (std::size_t i = 0; i < want.organs.size(); ++i) {
    const ramus::OrganAnchor& o = want.organs[i];
    double p[3], size = -1;
    REQUIRE(ramus_organ_position(got, i, p) == 0);
    REQUIRE(ramus_organ_size(got, i, &size) == 0);
    INFO("organ " << i);
    REQUIRE((same_bits(p[0], o.position.x) && same_bits(p[1], o.position.y) &&
             same_bits(p[2], o.position.z)));
    REQUIRE(same_bits(size, o.size));
  }
}

}  // namespace

TEST_CASE("C API: grows the same skeleton as grow_file", "[runtime]") {
  const std::string example =
      GENERATE(as<std::string>{}, "abop/fig1_24a.ramus", "abop/fig1_24d.ramus",
               "abop/fig1_25.ramus", "abop/fig1_31a.ramus", "abop/fig2_6a_monopodial.ramus",
               "abop/fig2_8a_ternary.ramus", "abop/hilbert3d.ramus", "trees/weeping.ramus");
  INFO(example);
  const std::string bytes = encode_example(example);
  char err[256] = "unset";
  GrammarPtr g(ramus_load(bytes.data(), bytes.size(), err, sizeof err), ramus_free_grammar);
  REQUIRE(g);
  CHECK(std::string(err).empty());
  const std::uint64_t file_seed = ramus_grammar_seed(g.get());
  for (std::uint64_t seed : {file_seed, file_seed + 12345}) {
    INFO("seed " << seed);
    SkeletonPtr s(ramus_grow(g.get(), -1, seed, err, sizeof err), ramus_free_skeleton);
    INFO(err);
    REQUIRE(s);
    REQUIRE(ramus_node_count(s.get()) > 0);
    require_same(grow_source(example, seed), s.get());
  }
}

TEST_CASE("C API: an explicit step count equals the grammar's own", "[runtime]") {
  const std::string bytes = encode_example("abop/fig1_24a.ramus");
  GrammarPtr g(ramus_load(bytes.data(), bytes.size(), nullptr, 0), ramus_free_grammar);
  REQUIRE(g);
  const int steps = ramus_grammar_steps(g.get());
  REQUIRE(steps > 1);
  const std::uint64_t seed = ramus_grammar_seed(g.get());
  SkeletonPtr own(ramus_grow(g.get(), -1, seed, nullptr, 0), ramus_free_skeleton);
  SkeletonPtr same(ramus_grow(g.get(), steps, seed, nullptr, 0), ramus_free_skeleton);
  SkeletonPtr fewer(ramus_grow(g.get(), steps - 1, seed, nullptr, 0), ramus_free_skeleton);
  REQUIRE((own && same && fewer));
  CHECK(ramus_node_count(own.get()) == ramus_node_count(same.get()));
  CHECK(ramus_node_count(fewer.get()) < ramus_node_count(own.get()));
  char err[128];
  CHECK(ramus_grow(g.get(), -2, seed, err, sizeof err) == nullptr);
  CHECK(std::string(err).find("negative") != std::string::npos);
}

// The string buffers a grow keeps for the next one are given back on request (a client done
// growing trees): the first call returns their bytes, a second one finds nothing, and the next
// grow is unchanged.
TEST_CASE("C API: ramus_release_memory gives back the kept string buffers", "[runtime]") {
  const std::string bytes = encode_example("abop/fig1_24a.ramus");
  GrammarPtr g(ramus_load(bytes.data(), bytes.size(), nullptr, 0), ramus_free_grammar);
  REQUIRE(g);
  const std::uint64_t seed = ramus_grammar_seed(g.get());
  const int steps = ramus_grammar_steps(g.get()) + 1;  // strings past the 64 KB buffers
  ramus_release_memory();                              // whatever earlier tests left
  SkeletonPtr before(ramus_grow(g.get(), steps, seed, nullptr, 0), ramus_free_skeleton);
  REQUIRE(before);
  CHECK(ramus_release_memory() >= 64 * 1024);
  CHECK(ramus_release_memory() == 0);
  SkeletonPtr after(ramus_grow(g.get(), steps, seed, nullptr, 0), ramus_free_skeleton);
  REQUIRE(after);
  CHECK(ramus_node_count(after.get()) == ramus_node_count(before.get()));
}

TEST_CASE("C API: a corrupted or truncated image is an error with the byte offset", "[runtime]") {
  const std::string good = encode_example("abop/fig1_24a.ramus");
  char err[256];
  SECTION("a flipped byte") {
    std::string bad = good;
    bad[bad.size() / 2] = char(bad[bad.size() / 2] ^ 0x5a);
    CHECK(ramus_load(bad.data(), bad.size(), err, sizeof err) == nullptr);
    CHECK(std::string(err).rfind("byte ", 0) == 0);
  }
  SECTION("every truncation") {
    for (std::size_t n = 0; n < good.size(); ++n) {
      INFO("length " << n);
      std::strcpy(err, "unset");
      REQUIRE(ramus_load(good.data(), n, err, sizeof err) == nullptr);
      REQUIRE(std::string(err).rfind("byte ", 0) == 0);
    }
  }
  SECTION("a short error buffer is truncated and terminated") {
    char tiny[6];
    CHECK(ramus_load(good.data(), 3, tiny, sizeof tiny) == nullptr);
    CHECK(std::string(tiny) == "byte ");
  }
  SECTION("null arguments") {
    CHECK(ramus_load(nullptr, 10, err, sizeof err) == nullptr);
    CHECK(std::string(err).find("null") != std::string::npos);
    CHECK(ramus_grow(nullptr, -1, 0, err, sizeof err) == nullptr);
    CHECK(ramus_node_count(nullptr) == 0);
    CHECK(ramus_node_parent(nullptr, 0) == -1);
    double p[3];
    CHECK(ramus_node_position(nullptr, 0, p) == -1);
  }
}

TEST_CASE("C API: accessors reject indices out of range", "[runtime]") {
  const std::string bytes = encode_example("abop/fig1_24a.ramus");
  GrammarPtr g(ramus_load(bytes.data(), bytes.size(), nullptr, 0), ramus_free_grammar);
  REQUIRE(g);
  SkeletonPtr s(ramus_grow(g.get(), -1, 1, nullptr, 0), ramus_free_skeleton);
  REQUIRE(s);
  const std::size_t n = ramus_node_count(s.get());
  double p[3] = {7, 7, 7}, r = 7;
  CHECK(ramus_node_position(s.get(), n, p) == -1);
  CHECK(p[0] == 7);
  CHECK(ramus_node_radius(s.get(), n, &r) == -1);
  CHECK(ramus_node_parent(s.get(), n) == -1);
  CHECK(ramus_organ_position(s.get(), ramus_organ_count(s.get()), p) == -1);
  CHECK(ramus_organ_size(s.get(), ramus_organ_count(s.get()), &r) == -1);
  CHECK(ramus_node_parent(s.get(), 0) == -1);  // the first node is a root
}

TEST_CASE("C API: the seed reaches a grammar that draws random numbers", "[runtime]") {
  const std::string bytes = encode_example("trees/weeping.ramus");
  GrammarPtr g(ramus_load(bytes.data(), bytes.size(), nullptr, 0), ramus_free_grammar);
  REQUIRE(g);
  SkeletonPtr a(ramus_grow(g.get(), -1, 1, nullptr, 0), ramus_free_skeleton);
  SkeletonPtr b(ramus_grow(g.get(), -1, 2, nullptr, 0), ramus_free_skeleton);
  REQUIRE((a && b));
  bool differ = ramus_node_count(a.get()) != ramus_node_count(b.get());
  for (std::size_t i = 0; !differ && i < ramus_node_count(a.get()); ++i) {
    double p[3], q[3];
    ramus_node_position(a.get(), i, p);
    ramus_node_position(b.get(), i, q);
    differ = std::memcmp(p, q, sizeof p) != 0;
  }
  CHECK(differ);
}

TEST_CASE("C API: a stripped image grows the same skeleton as its source", "[runtime]") {
  const std::string example = GENERATE(as<std::string>{}, "trees/broadleaf.ramus",
                                       "abop/fig1_31a.ramus", "abop/fig2_6a_monopodial.ramus");
  INFO(example);
  ramus::SourceManager sm;
  ramus::DiagnosticSink diags;
  ramus::RmbEncodeOptions o;
  o.strip = true;
  const std::string bytes =
      ramus::encode_rmb(ramus::lower_file(path_of(example), {}, sm, diags), o);
  REQUIRE(bytes.size() < encode_example(example).size());
  char err[256] = "unset";
  GrammarPtr g(ramus_load(bytes.data(), bytes.size(), err, sizeof err), ramus_free_grammar);
  INFO(err);
  REQUIRE(g);
  const std::uint64_t seed = ramus_grammar_seed(g.get());
  SkeletonPtr s(ramus_grow(g.get(), -1, seed, err, sizeof err), ramus_free_skeleton);
  INFO(err);
  REQUIRE(s);
  require_same(grow_source(example, seed), s.get());
}

TEST_CASE("C API: images with piece sets load, and their grammar grows as without them",
          "[runtime]") {
  // The runtime verifies the piece-set section (section 10) and leaves it aside: it grows the
  // lsystem block; a file of pieces blocks alone has an empty grammar and grows nothing.
  for (const std::string example : {"pieces/grown.ramus", "pieces/orchard.ramus"}) {
    INFO(example);
    ramus::SourceManager sm;
    ramus::DiagnosticSink diags;
    const ramus::Program program = ramus::load_program(path_of(example), sm, diags);
    REQUIRE(!diags.has_errors());
    const ramus::RmbPieces pieces = ramus::piece_sets_of(program, path_of(example));
    REQUIRE(pieces.sets.size() == 1);
    const bool lsystem = example == "pieces/grown.ramus";
    ramus::SourceManager sm2;
    ramus::DiagnosticSink diags2;
    const ramus::ir::Grammar grammar = lsystem
                                           ? ramus::lower_file(path_of(example), {}, sm2, diags2)
                                           : ramus::ir::make_grammar("");
    const std::string bytes = ramus::encode_rmb(grammar, {}, pieces);
    char err[256] = "unset";
    GrammarPtr g(ramus_load(bytes.data(), bytes.size(), err, sizeof err), ramus_free_grammar);
    INFO(err);
    REQUIRE(g);
    SkeletonPtr s(ramus_grow(g.get(), -1, ramus_grammar_seed(g.get()), err, sizeof err),
                  ramus_free_skeleton);
    REQUIRE(s);
    if (lsystem) {
      REQUIRE(ramus_node_count(s.get()) > 0);
      require_same(grow_source(example, ramus_grammar_seed(g.get())), s.get());
    } else {
      CHECK(ramus_node_count(s.get()) == 0);
    }
    // Damage inside the section is found by the runtime's decoder too.
    std::string bad = bytes;
    bad.resize(bad.size() - 5);
    CHECK(ramus_load(bad.data(), bad.size(), err, sizeof err) == nullptr);
    CHECK(std::string(err).find("byte ") == 0);
  }
}
