// The piece-set section (id 10, docs/binary-format.md) of `pieces` blocks: encoded from the AST
// with numbers folded and mesh files embedded, decoded and verified (counts, indices, names,
// limits), dumped, and decompiled back to `pieces` blocks whose trees are the same glTF bytes
// as the source's -- for every example in examples/pieces/.
#include <catch2/catch.hpp>

#include "../cli/cli_runner.h"
#include "compiler/pipeline.h"
#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_decompile.h"
#include "formats/rmb/rmb_pieces_ast.h"
#include "grammar/loader.h"
#include "rejects_damage.h"

using namespace ramus;
using namespace cli_test;

namespace {

// Every kind, named and positional arguments (the last one written wins), a rim without a
// radius, a fixed twist, constants, a mesh kept as a path.
const char* kSource = R"(const s = 20;

pieces grove {
  rim hexagon();
  piece I = tube(3, length: 5, taper: 0.5 + 0.25);
  piece Y = fork(angle: s + 1);
  piece P = trifurcation(planar: 1, angle: s);
  piece A = attachment(2, 40, 0.9, 0.5);
  piece M = mesh("m.obj");
  root Y;
  Y.left -> I 2 | M;
  M.tip -> P 0.125;
  A.branch -> I;
  twist 3;
}

pieces tiny {
  piece T = tube();
  root T;
  T.top -> T;
  depth 4096;
}
)";

RmbPieces parse_pieces(const std::string& text, bool mesh_paths = true) {
  SourceManager sm;
  DiagnosticSink diags;
  Program p = load_program_text("grove.ramus", text, sm, diags);
  REQUIRE(!diags.has_errors());
  RmbPiecesOptions o;
  o.mesh_paths = mesh_paths;
  return piece_sets_of(p, "grove.ramus", o);
}

std::string fix_crc(std::string bytes) {
  const std::uint32_t crc = rmb::crc32(std::string_view(bytes).substr(0, bytes.size() - 4));
  for (int k = 0; k < 4; ++k) bytes[bytes.size() - 4 + k] = char((crc >> (8 * k)) & 0xFF);
  return bytes;
}

std::string encode_pieces(const RmbPieces& pieces, const RmbEncodeOptions& o = {}) {
  return encode_rmb(ir::make_grammar(""), {}, pieces, o);
}

// The offset of the n-th trace line of `field` (0-based).
std::size_t field_at(const std::string& bytes, const std::string& field, int n = 0) {
  std::vector<rmb::TraceEntry> trace;
  decode_rmb_contents(bytes, {}, &trace);
  for (const rmb::TraceEntry& e : trace) {
    if (e.field == field && n-- == 0) return e.offset;
  }
  FAIL("no field " << field);
  return 0;
}

// A grammar with productions whose name was cleared: what no lsystem block lowers to.
ir::Grammar unnamed_grammar() {
  SourceManager sm;
  DiagnosticSink d;
  ir::Grammar g = lower_text("x.ramus", "lsystem x { axiom A; A -> F; }", GrowOptions{}, sm, d);
  REQUIRE(!d.has_errors());
  g.name.clear();
  return g;
}

std::vector<fs::path> piece_examples() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(fs::path(RAMUS_SOURCE_DIR) / "examples/pieces")) {
    if (e.path().extension() == ".ramus") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("binary: pieces blocks are folded into the piece-set section as written", "[binary]") {
  const RmbPieces pieces = parse_pieces(kSource);
  REQUIRE(pieces.sets.size() == 2);
  CHECK(pieces.meshes.empty());
  const RmbPieceSet& g = pieces.sets[0];
  CHECK(g.name == "grove");
  CHECK(g.rim);
  CHECK(!g.rim_radius);
  REQUIRE(g.pieces.size() == 5);
  CHECK(g.pieces[0].kind == RmbPieceKind::Tube);
  CHECK(g.pieces[0].args == std::vector<std::optional<double>>{5.0, 0.75});  // length: 5 wins
  CHECK(g.pieces[1].args == std::vector<std::optional<double>>{std::nullopt, 21.0, std::nullopt});
  CHECK(g.pieces[2].args ==
        std::vector<std::optional<double>>{std::nullopt, 20.0, std::nullopt, 1.0});
  CHECK(g.pieces[3].args == std::vector<std::optional<double>>{2.0, 40.0, 0.9, 0.5});
  CHECK(g.pieces[4].kind == RmbPieceKind::MeshPath);
  CHECK(g.pieces[4].path == "m.obj");
  CHECK(g.root == 1);
  CHECK(g.twist == std::optional<std::uint8_t>(3));
  CHECK(!g.depth);
  REQUIRE(g.rules.size() == 3);
  CHECK(g.rules[0].piece == 1);
  CHECK(g.rules[0].rim == "left");
  CHECK(g.rules[0].targets == std::vector<RmbAttachTarget>{{0, 2.0}, {4, std::nullopt}});
  CHECK(g.rules[1].rim == "tip");
  CHECK(g.rules[1].targets == std::vector<RmbAttachTarget>{{2, 0.125}});
  CHECK(pieces.sets[1].depth == std::optional<std::uint32_t>(4096));
  CHECK(!pieces.sets[1].twist);

  // decode(encode(x)) == x, re-encoding gives the same bytes; stripping leaves it alone.
  const std::string bytes = encode_pieces(pieces);
  const RmbContents back = decode_rmb_contents(bytes);
  CHECK(back.pieces == pieces);
  CHECK(!rmb_has_lsystem(back.grammar));
  CHECK(encode_pieces(back.pieces) == bytes);
  RmbEncodeOptions strip;
  strip.strip = true;
  CHECK(decode_rmb_contents(encode_pieces(pieces, strip)).pieces == pieces);
  RmbEncodeOptions z;
  z.zstd = true;
  CHECK(decode_rmb_contents(encode_pieces(pieces, z)).pieces == pieces);

  // Quantized: every number within the tolerance, integers exact.
  RmbEncodeOptions q;
  q.tolerance = 0.01;
  const RmbPieces lossy = decode_rmb_contents(encode_pieces(pieces, q)).pieces;
  REQUIRE(lossy.sets.size() == 2);
  for (std::size_t b = 0; b < 2; ++b) {
    const RmbPieceSet &x = pieces.sets[b], &y = lossy.sets[b];
    REQUIRE(x.pieces.size() == y.pieces.size());
    for (std::size_t i = 0; i < x.pieces.size(); ++i) {
      REQUIRE(x.pieces[i].args.size() == y.pieces[i].args.size());
      for (std::size_t k = 0; k < x.pieces[i].args.size(); ++k) {
        REQUIRE(bool(x.pieces[i].args[k]) == bool(y.pieces[i].args[k]));
        if (x.pieces[i].args[k])
          CHECK(std::abs(*x.pieces[i].args[k] - *y.pieces[i].args[k]) <= 0.01);
      }
    }
    REQUIRE(x.rules.size() == y.rules.size());
    for (std::size_t r = 0; r < x.rules.size(); ++r) {
      for (std::size_t t = 0; t < x.rules[r].targets.size(); ++t) {
        const auto &wx = x.rules[r].targets[t].weight, &wy = y.rules[r].targets[t].weight;
        REQUIRE(bool(wx) == bool(wy));
        if (wx) CHECK(std::abs(*wx - *wy) <= 0.01);
      }
    }
  }
  CHECK(lossy.sets[0].pieces[3].args[1] == std::optional<double>(40.0));
}

TEST_CASE("binary: the piece-set section has the bytes docs/binary-format.md specifies",
          "[binary]") {
  RmbPieces p;
  p.meshes.push_back(RmbMeshFile{"a.obj", "v"});
  RmbPieceSet s;
  s.name = "t";
  s.rim = true;
  s.rim_radius = 0.5;
  s.twist = kRmbTwistAny;
  s.depth = 200;
  s.pieces.push_back(RmbPiece{"I", RmbPieceKind::Tube, {std::nullopt, 0.5}, 0, ""});
  s.pieces.push_back(RmbPiece{"B", RmbPieceKind::Mesh, {}, 0, ""});
  s.pieces.push_back(RmbPiece{"C", RmbPieceKind::MeshPath, {}, 0, "c.glb"});
  s.root = 0;
  s.rules.push_back(RmbAttachRule{0, "top", {{0, std::nullopt}, {1, 2.0}}});
  s.rules.push_back(RmbAttachRule{1, "tip", {{2, std::nullopt}}});
  p.sets.push_back(s);
  rmb::Writer w;
  w.decimal();  // lossless reals as version 2 writes them
  write_rmb_pieces(w, p);
  static const char kWant[] =
      "\x01"  // one mesh file
      "\x05"
      "a.obj"  // its name
      "\x01"
      "v"     // its bytes
      "\x01"  // one block
      "\x01"
      "t"         // name
      "\x3f"      // rim, radius, twist 7 (any), depth
      "\x51"      // radius 0.5 (5, one decimal)
      "\xc8\x01"  // depth 200 (varint)
      "\x03"      // three pieces
      "\x01"
      "I"
      "\x00"  // I = tube
      "\x02"  // taper given
      "\x51"  // taper 0.5
      "\x01"
      "B"
      "\x04"  // B = embedded mesh
      "\x00"  // mesh file 0
      "\x01"
      "C"
      "\x05"  // C = mesh path
      "\x05"
      "c.glb"  // the path
      "\x00"   // root I
      "\x02"   // two rules
      "\x00"
      "\x00"  // I, rim 0 (top)
      "\x02"
      "\x00"  // two targets: I unweighted
      "\x03"  // B weighted
      "\x20"  // weight 2 (no decimals)
      "\x01"
      "\x03"
      "tip"  // B, rim "tip" (a mesh piece: by name)
      "\x01"
      "\x04";  // one target: C unweighted
  const std::string want(kWant, sizeof kWant - 1);
  CHECK(rmb::hex_bytes(w.data(), 1000) == rmb::hex_bytes(want, 1000));
  // The section comes between 9 (ignored) and 11 (voxel rule tables) in the table.
  const std::string file = encode_pieces(p);
  CHECK(decode_rmb_contents(file).pieces == p);
  CHECK(file.find(w.data()) != std::string::npos);
}

TEST_CASE("binary: every pieces example grows the same glb after build and decompile", "[binary]") {
  for (const fs::path& src : piece_examples()) {
    for (const std::vector<std::string>& opts :
         {std::vector<std::string>{}, std::vector<std::string>{"--strip", "--zstd"}}) {
      INFO(src.string() << (opts.empty() ? "" : " --strip --zstd"));
      TempDir tmp;
      const fs::path rmb = tmp.path / "g.rmb", back = tmp.path / "dec" / "g.ramus";
      std::vector<std::string> build{"-q",     "build", src.string(), "--target",
                                     "binary", "-o",    rmb.string()};
      build.insert(build.end(), opts.begin(), opts.end());
      REQUIRE(run_ramus(build).status == 0);
      fs::create_directories(back.parent_path());
      const CliResult dec = run_ramus({"-q", "decompile", rmb.string(), "-o", back.string()});
      REQUIRE(dec.status == 0);
      CHECK(run_ramus({"check", back.string()}).status == 0);
      CHECK(run_ramus({"fmt", "--check", back.string()}).status == 0);
      const fs::path a = tmp.path / "src.glb", b = tmp.path / "dec.glb";
      REQUIRE(
          run_ramus({"-q", "build", src.string(), "--target", "pieces", "-o", a.string()}).status ==
          0);
      REQUIRE(run_ramus({"-q", "build", back.string(), "--target", "pieces", "-o", b.string()})
                  .status == 0);
      const std::string ga = slurp(a);
      CHECK(ga.size() > 1000);
      CHECK(ga == slurp(b));
      // Decompiling the decompiled grammar's .rmb gives the same text again.
      const fs::path rmb2 = tmp.path / "g2.rmb", back2 = tmp.path / "dec2" / "g.ramus";
      build[2] = back.string();
      build[6] = rmb2.string();
      REQUIRE(run_ramus(build).status == 0);
      fs::create_directories(back2.parent_path());
      REQUIRE(run_ramus({"-q", "decompile", rmb2.string(), "-o", back2.string()}).status == 0);
      CHECK(slurp(back2) == slurp(back));
    }
  }
}

TEST_CASE(
    "binary: a mesh piece is embedded, written beside the decompiled grammar or kept as a "
    "path",
    "[binary]") {
  const fs::path src = fs::path(RAMUS_SOURCE_DIR) / "examples/pieces/orchard.ramus";
  const std::string obj = slurp(src.parent_path() / "bent.obj");
  REQUIRE(!obj.empty());
  TempDir tmp;
  const fs::path rmb = tmp.path / "o.rmb";
  REQUIRE(
      run_ramus({"-q", "build", src.string(), "--target", "binary", "-o", rmb.string()}).status ==
      0);
  const RmbContents c = decode_rmb_contents(slurp(rmb));
  REQUIRE(c.pieces.meshes.size() == 1);
  CHECK(c.pieces.meshes[0].name == "bent.obj");
  CHECK(c.pieces.meshes[0].bytes == obj);
  const CliResult dump = run_ramus({"dump", rmb.string()});
  REQUIRE(dump.status == 0);
  CHECK(dump.out.find("2311 bytes, CRC-32 ") != std::string::npos);

  // Without -o there is no folder to write the mesh into.
  const CliResult to_stdout = run_ramus({"decompile", rmb.string()});
  CHECK(to_stdout.status == 1);
  CHECK(to_stdout.out.find("give -o FILE.ramus") != std::string::npos);
  // Another file of that name is not replaced; the same one is left as it is.
  const fs::path other = tmp.path / "other";
  write_text(other / "bent.obj", "# another mesh\n");
  const CliResult clash =
      run_ramus({"decompile", rmb.string(), "-o", (other / "o.ramus").string()});
  CHECK(clash.status == 1);
  CHECK(clash.out.find("not replacing") != std::string::npos);
  CHECK(slurp(other / "bent.obj") == "# another mesh\n");
  write_text(other / "bent.obj", obj);
  CHECK(run_ramus({"-q", "decompile", rmb.string(), "-o", (other / "o.ramus").string()}).status ==
        0);
  CHECK(slurp(other / "o.ramus").find("mesh(\"bent.obj\")") != std::string::npos);

  // --mesh-paths: the path as written, no bytes; the file must then sit beside the text.
  const fs::path paths = tmp.path / "p.rmb";
  REQUIRE(run_ramus({"-q", "build", src.string(), "--target", "binary", "--mesh-paths", "-o",
                     paths.string()})
              .status == 0);
  const RmbContents pc = decode_rmb_contents(slurp(paths));
  CHECK(pc.pieces.meshes.empty());
  CHECK(slurp(paths).size() + obj.size() < slurp(rmb).size());
  const fs::path pdir = tmp.path / "pdir";
  fs::create_directories(pdir);
  REQUIRE(
      run_ramus({"-q", "decompile", paths.string(), "-o", (pdir / "o.ramus").string()}).status ==
      0);
  CHECK(!fs::exists(pdir / "bent.obj"));
  fs::copy_file(src.parent_path() / "bent.obj", pdir / "bent.obj");
  const fs::path a = tmp.path / "a.glb", b = tmp.path / "b.glb";
  REQUIRE(run_ramus({"-q", "build", src.string(), "--target", "pieces", "-o", a.string()}).status ==
          0);
  REQUIRE(run_ramus(
              {"-q", "build", (pdir / "o.ramus").string(), "--target", "pieces", "-o", b.string()})
              .status == 0);
  CHECK(slurp(a) == slurp(b));
}

TEST_CASE("binary: two mesh files of one name are both embedded, one file used twice once",
          "[binary]") {
  TempDir tmp;
  const std::string obj = slurp(fs::path(RAMUS_SOURCE_DIR) / "examples/pieces/bent.obj");
  write_text(tmp.path / "a" / "bent.obj", obj);
  write_text(tmp.path / "b" / "bent.obj", obj + "# the same mesh, other bytes\n");
  const fs::path src = tmp.write("two.ramus", R"(pieces two {
  piece I = tube();
  piece A = mesh("a/bent.obj");
  piece A2 = mesh("a/bent.obj");
  piece B = mesh("b/bent.obj");
  root I;
  I.top -> A | A2 | B;
}
)");
  const fs::path rmb = tmp.path / "two.rmb";
  REQUIRE(
      run_ramus({"-q", "build", src.string(), "--target", "binary", "-o", rmb.string()}).status ==
      0);
  const RmbContents c = decode_rmb_contents(slurp(rmb));
  REQUIRE(c.pieces.meshes.size() == 2);
  CHECK(c.pieces.meshes[0].name == "bent.obj");
  CHECK(c.pieces.meshes[1].name == "bent_2.obj");
  CHECK(c.pieces.sets[0].pieces[1].mesh == 0);
  CHECK(c.pieces.sets[0].pieces[2].mesh == 0);
  CHECK(c.pieces.sets[0].pieces[3].mesh == 1);
  const fs::path back = tmp.path / "out" / "two.ramus";
  fs::create_directories(back.parent_path());
  REQUIRE(run_ramus({"-q", "decompile", rmb.string(), "-o", back.string()}).status == 0);
  CHECK(slurp(tmp.path / "out" / "bent_2.obj") == slurp(tmp.path / "b" / "bent.obj"));
  const fs::path ga = tmp.path / "a.glb", gb = tmp.path / "b.glb";
  REQUIRE(
      run_ramus({"-q", "build", src.string(), "--target", "pieces", "-o", ga.string()}).status ==
      0);
  REQUIRE(
      run_ramus({"-q", "build", back.string(), "--target", "pieces", "-o", gb.string()}).status ==
      0);
  CHECK(slurp(ga) == slurp(gb));
}

TEST_CASE("binary: what the piece-set section cannot carry is a build error", "[binary]") {
  TempDir tmp;
  auto build = [&](const std::string& text) {
    const fs::path src = tmp.write("bad.ramus", text);
    return run_ramus(
        {"build", src.string(), "--target", "binary", "-o", (tmp.path / "bad.rmb").string()});
  };
  const CliResult twist = build("pieces p { piece I = tube(); root I; twist 7; }\n");
  CHECK(twist.status == 1);
  CHECK(twist.out.find("cannot encode pieces p: 'twist' 7 is not an integer in 0..5") !=
        std::string::npos);
  const CliResult arg = build("pieces p { piece I = tube(width: 2); root I; }\n");
  CHECK(arg.status == 1);
  CHECK(arg.out.find("'tube' has no argument 'width'") != std::string::npos);
  const CliResult missing = build("pieces p { piece M = mesh(\"nowhere.obj\"); root M; }\n");
  CHECK(missing.status == 1);
  CHECK(missing.out.find("cannot read the mesh file") != std::string::npos);
  tmp.write("ext.gltf", R"({"asset":{"version":"2.0"},"buffers":[{"uri" : "ext.bin"}]})");
  const CliResult gltf = build("pieces p { piece M = mesh(\"ext.gltf\"); root M; }\n");
  CHECK(gltf.status == 1);
  CHECK(gltf.out.find("refers to files beside it") != std::string::npos);
  // The checks run first: an unknown piece is the checker's error, with its location.
  const CliResult unknown = build("pieces p { piece I = tube(); root J; }\n");
  CHECK(unknown.status == 1);
  CHECK(unknown.out.find("bad.ramus:1:") != std::string::npos);
}

TEST_CASE("binary: damaged piece sets are rejected with the byte offset", "[binary]") {
  const RmbPieces pieces = parse_pieces(kSource);
  RmbPieces with_mesh = pieces;
  with_mesh.meshes.push_back(RmbMeshFile{"m.obj", "v 0 0 0\n"});
  with_mesh.sets[0].pieces[4].kind = RmbPieceKind::Mesh;
  with_mesh.sets[0].pieces[4].mesh = 0;
  for (const RmbPieces* p : std::vector<const RmbPieces*>{&pieces, &with_mesh}) {
    const std::string bytes = encode_pieces(*p);
    test::check_rejects_truncation_and_damage(
        bytes, [](std::string_view b) { return decode_rmb_contents(b); });
    // Behind a valid checksum every damaged byte is rejected or decodes to piece sets that
    // encode and decompile again (or are refused by name), never a crash.
    RmbDecodeOptions no_crc;
    no_crc.verify_checksum = false;
    for (std::size_t i = 0; i + 4 < bytes.size(); ++i) {
      for (std::uint8_t x : {0x01, 0x41, 0x80, 0xff}) {
        std::string bad = bytes;
        bad[i] = char(bad[i] ^ x);
        try {
          const RmbContents c = decode_rmb_contents(bad, no_crc);
          (void)encode_rmb(c.grammar, c.voxels, c.pieces);
          try {
            (void)decompile(c);
          } catch (const DecompileError&) {
          }
        } catch (const RmbError&) {
        }
      }
    }
  }

  const std::string bytes = encode_pieces(with_mesh);
  auto rejects = [&](std::size_t at, char value, const std::string& message) {
    std::string bad = bytes;
    bad[at] = value;
    try {
      decode_rmb_contents(fix_crc(bad));
      FAIL("decoded " << message);
    } catch (const RmbError& e) {
      CHECK(e.offset == at);
      CHECK_THAT(e.what(), Catch::Contains(message));
    }
  };
  // A mesh file name that leaves the folder: "m.obj" -> "/.obj".
  const std::size_t name_at = bytes.find(
      "\x05"
      "m.obj");
  REQUIRE(name_at != std::string::npos);
  {
    std::string bad = bytes;
    bad[name_at + 1] = '/';
    try {
      decode_rmb_contents(fix_crc(bad));
      FAIL("decoded a path as a mesh name");
    } catch (const RmbError& e) {
      CHECK(e.offset == name_at);
      CHECK_THAT(e.what(), Catch::Contains("expected a plain file name"));
    }
  }
  rejects(field_at(bytes, "root"), 9, "expected root <= 4");
  rejects(field_at(bytes, "kind"), 6, "expected a piece kind 0..5");
  rejects(field_at(bytes, "arguments given"), 4, "expected an argument mask below 4");
  rejects(field_at(bytes, "mesh file"), 1, "expected mesh file <= 0");
  rejects(field_at(bytes, "settings"), 0x42, "the radius bit only with the rim bit");
  rejects(field_at(bytes, "targets"), 0, "expected at least one target");
  // Rule 2 (A.branch) made a second rule for Y.left: piece 1, rim 0.
  {
    std::string bad = bytes;
    const std::size_t at = field_at(bytes, "piece", 2);
    bad[at] = 1;
    bad[at + 1] = 0;
    try {
      decode_rmb_contents(fix_crc(bad));
      FAIL("decoded two rules for one rim");
    } catch (const RmbError& e) {
      CHECK(e.offset == at);
      CHECK_THAT(e.what(), Catch::Contains("expected one rule per piece and rim"));
    }
  }
  // A grammar that is not an lsystem block cannot have productions: the runtime would grow
  // what decompiling drops.
  const std::string unnamed = fix_crc(encode_rmb(unnamed_grammar(), {}, pieces));
  CHECK_THROWS_WITH(decode_rmb_contents(unnamed),
                    Catch::Contains("expected a named lsystem block"));
}

TEST_CASE("binary: the dump of a piece set matches its golden file", "[binary]") {
  TempDir tmp;
  const fs::path rmb = tmp.path / "almond.rmb";
  REQUIRE(run_ramus({"-q", "build",
                     (fs::path(RAMUS_SOURCE_DIR) / "examples/pieces/almond.ramus").string(),
                     "--target", "binary", "-o", rmb.string()})
              .status == 0);
  const CliResult dump = run_ramus({"dump", rmb.string()});
  REQUIRE(dump.status == 0);
  const fs::path golden = fs::path(RAMUS_SOURCE_DIR) / "tests/golden/rmb/pieces_almond.rmb.txt";
  INFO("golden file: " << golden.string());
  if (std::getenv("RAMUS_UPDATE_GOLDENS")) write_text(golden, dump.out);
  CHECK(slurp(golden) == dump.out);
}
