// Pieces read from files (section 4.1, docs/pieces.md): OBJ with `l` loops in groups rim:<name>,
// glTF with triangle pairs and rim:<name> nodes. Both become canonical pieces that interlock
// with the built-in ones.
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "backends/pieces/piece_build.h"
#include "test_piece_support.h"

using namespace piece_test;
namespace fs = std::filesystem;

namespace {

const std::string kBent = std::string(RAMUS_SOURCE_DIR) + "/examples/pieces/bent.obj";

std::string base64(const std::string& bytes) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8 |
                 (unsigned char)bytes[i + 2];
    out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], t[v & 63]};
  }
  if (i + 1 == bytes.size()) {
    unsigned v = (unsigned char)bytes[i] << 16;
    out += {t[v >> 18], t[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    unsigned v = (unsigned char)bytes[i] << 16 | (unsigned char)bytes[i + 1] << 8;
    out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], '='};
  }
  return out;
}

struct ObjMesh {
  std::vector<Vec3> v;
  std::vector<std::array<std::uint32_t, 4>> f;
  std::vector<std::vector<std::uint32_t>> rims;  // root, tip
};

ObjMesh read_bent() {
  ObjMesh m;
  std::ifstream in(kBent);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      Vec3 p;
      ls >> p.x >> p.y >> p.z;
      m.v.push_back(p);
    } else if (tag == "f") {
      std::array<std::uint32_t, 4> q;
      for (auto& i : q) {
        ls >> i;
        --i;
      }
      m.f.push_back(q);
    } else if (tag == "l") {
      std::vector<std::uint32_t> r;
      std::uint32_t i;
      while (ls >> i) r.push_back(i - 1);
      m.rims.push_back(r);
    }
  }
  return m;
}

// The bent piece as glTF: float positions, each quad as triangles (a,b,c),(a,c,d), the rims as
// POINTS primitives of nodes rim:root and rim:tip, everything under a scaled, moved parent node.
std::string bent_gltf(bool break_pairs = false) {
  ObjMesh m = read_bent();
  std::string bin;
  auto put_f = [&](float x) { bin.append(reinterpret_cast<const char*>(&x), 4); };
  auto put_u = [&](std::uint32_t x) { bin.append(reinterpret_cast<const char*>(&x), 4); };
  float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
  for (const Vec3& p : m.v) {
    float c[3] = {float(p.x), float(p.y), float(p.z)};
    for (int k = 0; k < 3; ++k) {
      put_f(c[k]);
      lo[k] = std::min(lo[k], c[k]);
      hi[k] = std::max(hi[k], c[k]);
    }
  }
  std::size_t pos_bytes = bin.size();
  for (const auto& q : m.f) {
    for (std::uint32_t i : {q[0], q[1], q[2], q[0], q[2], q[3]}) put_u(i);
  }
  if (break_pairs) std::swap(bin[pos_bytes + 4], bin[pos_bytes + 12]);
  std::size_t idx_bytes = bin.size() - pos_bytes;
  for (const auto& r : m.rims) {
    for (std::uint32_t i : r) put_u(i);
  }
  std::ostringstream j;
  j << R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
    << R"("nodes":[{"children":[1,2,3],"scale":[2,2,2],"translation":[5,0,-1]},)"
    << R"({"name":"bark","mesh":0},{"name":"rim:root","mesh":1},{"name":"rim:tip","mesh":2}],)"
    << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]},)"
    << R"({"primitives":[{"attributes":{"POSITION":0},"indices":2,"mode":0}]},)"
    << R"({"primitives":[{"attributes":{"POSITION":0},"indices":3,"mode":0}]}],)"
    << R"("buffers":[{"byteLength":)" << bin.size()
    << R"(,"uri":"data:application/octet-stream;base64,)" << base64(bin) << R"("}],)"
    << R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":)" << pos_bytes << "},"
    << R"({"buffer":0,"byteOffset":)" << pos_bytes << R"(,"byteLength":)" << idx_bytes << "},"
    << R"({"buffer":0,"byteOffset":)" << pos_bytes + idx_bytes << R"(,"byteLength":24},)"
    << R"({"buffer":0,"byteOffset":)" << pos_bytes + idx_bytes + 24 << R"(,"byteLength":24}],)"
    << R"("accessors":[{"bufferView":0,"componentType":5126,"count":)" << m.v.size()
    << R"(,"type":"VEC3","min":[)" << lo[0] << "," << lo[1] << "," << lo[2] << "],\"max\":["
    << hi[0] << "," << hi[1] << "," << hi[2] << "]},"
    << R"({"bufferView":1,"componentType":5125,"count":)" << m.f.size() * 6
    << R"(,"type":"SCALAR"},)"
    << R"({"bufferView":2,"componentType":5125,"count":6,"type":"SCALAR"},)"
    << R"({"bufferView":3,"componentType":5125,"count":6,"type":"SCALAR"}]})";
  return j.str();
}

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("ramus_piece_files_" + std::to_string(::getpid()));
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

void check_canonical(const PieceType& t) {
  const PieceMesh& m = t.lods[0];
  for (int k = 0; k < 6; ++k) {
    double a = M_PI / 3 * k;
    CHECK(distance(m.positions[t.root.corners[k]], Vec3{std::cos(a), std::sin(a), 0}) < 1e-9);
  }
  REQUIRE(t.leaves.size() == 1);
  CHECK(t.leaves[0].name == "tip");
  // Modelled with a 10 cm rim narrowing by 20% and bending by 40 degrees over the arc.
  CHECK(t.leaves[0].building.s == Approx(0.8).epsilon(1e-6));
  double bend = std::acos(t.leaves[0].building.r.rotate({0, 0, 1}).z) * 180 / M_PI;
  CHECK(bend == Approx(40).epsilon(1e-5));
  CHECK(m.quads.size() == 36);
  // The file's other vertices moved with the rims: the tip rim's centre is one arc away.
  CHECK(length(t.leaves[0].building.t) > 4);
}

}  // namespace

TEST_CASE("an OBJ piece with named rims becomes a canonical piece") {
  PieceDraft d = draft_mesh_file("Bent", kBent);
  PieceType t = finish_piece(d, {1, 2});
  check_canonical(t);
  CHECK(t.kind == PieceKind::Mesh);
  CHECK(t.joints.size() == 2);
  CHECK(t.joints[1].name == "rim:tip");
}

TEST_CASE("a glTF piece: triangle pairs become quads, node transforms are applied") {
  TempDir tmp;
  fs::path file = tmp.path / "bent.gltf";
  std::ofstream(file) << bent_gltf();
  PieceType t = finish_piece(draft_mesh_file("Bent", file.string()), {1});
  check_canonical(t);
  // Same piece as from the OBJ file, to float precision.
  PieceType o = finish_piece(draft_mesh_file("Bent", kBent), {1});
  REQUIRE(o.lods[0].positions.size() == t.lods[0].positions.size());
  CHECK(distance(o.leaves[0].building.t, t.leaves[0].building.t) < 1e-5);

  // The container is told by its magic, not by the name: the same model as a GLB (its JSON the
  // only chunk, the buffer a data URI) in a file named .gltf reads the same.
  std::string json = bent_gltf();
  json.append((4 - json.size() % 4) % 4, ' ');
  std::string glb = "glTF";
  const auto u32 = [&](std::uint32_t v) {
    for (int k = 0; k < 4; ++k) glb.push_back(char((v >> (8 * k)) & 0xff));
  };
  u32(2), u32(std::uint32_t(12 + 8 + json.size())), u32(std::uint32_t(json.size()));
  u32(0x4E4F534A);  // "JSON"
  glb += json;
  fs::path binary = tmp.path / "binary.gltf";
  std::ofstream(binary, std::ios::binary) << glb;
  PieceType g = finish_piece(draft_mesh_file("Bent", binary.string()), {1});
  CHECK(distance(o.leaves[0].building.t, g.leaves[0].building.t) < 1e-5);

  fs::path broken = tmp.path / "broken.gltf";
  std::ofstream(broken) << bent_gltf(true);
  CHECK_THROWS_WITH(draft_mesh_file("Bent", broken.string()),
                    Catch::Contains("share no edge, so they are not a quad"));
}

TEST_CASE("file pieces interlock with built-in ones in the rest pose and posed") {
  TempDir tmp;
  fs::copy_file(kBent, tmp.path / "bent.obj");
  fs::path file = tmp.path / "mixed.ramus";
  std::ofstream(file) << "pieces m { piece I = tube(); piece B = mesh(\"bent.obj\"); root B;\n"
                         "  B.tip -> I | B; I.top -> B 2 | I; depth 9; }\n";
  SourceManager sm;
  DiagnosticSink diags;
  Program prog = load_program(file.string(), sm, diags);
  check_program(prog, sm, diags);
  REQUIRE(!diags.has_errors());
  PieceSet set = lower_pieces(prog, sm, {}, diags);
  REQUIRE(!diags.has_errors());
  Tree tree = assemble(set, {});
  CHECK(tree.pieces.size() == 10);
  RimGap g = rim_gaps(set, tree, tree.pose, 1, 2);
  CHECK(g.position < 1e-5);
  CHECK(g.normal < 1e-5);
  for (std::uint64_t seed = 0; seed < 100; ++seed) {
    RimGap p = rim_gaps(set, tree, random_pose(tree, tree.pose, seed));
    REQUIRE(p.position < 1e-5);
    REQUIRE(p.normal < 1e-5);
  }
}

TEST_CASE("bad piece files are reported with file and line") {
  TempDir tmp;
  auto write = [&](const std::string& name, const std::string& text) {
    fs::path p = tmp.path / name;
    std::ofstream(p) << text;
    return p.string();
  };
  std::string tri = write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  CHECK_THROWS_WITH(draft_mesh_file("T", tri),
                    tri + ":4: a face has 3 vertices; pieces are quad meshes");
  std::string missing = write("missing.obj", "v 0 0 0\nf 1 2 3 4\n");
  CHECK_THROWS_WITH(draft_mesh_file("T", missing), missing + ":2: vertex 2 does not exist");
  std::string norim = write("norim.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  CHECK_THROWS_WITH(draft_mesh_file("T", norim), norim + ": the piece has no rim named rim:root");
  std::string square = write("square.obj",
                             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 0 0 2\n"
                             "f 1 2 3 4\ng rim:root\nl 1 2 3 4 5 6\n");
  CHECK_THROWS_WITH(draft_mesh_file("T", square),
                    Catch::Contains("rim:root is not a regular hexagon"));
  CHECK_THROWS_WITH(draft_mesh_file("T", (tmp.path / "none.glb").string()),
                    Catch::Contains("none.glb: cannot open the file"));
  CHECK_THROWS_WITH(draft_mesh_file("T", (tmp.path / "x.stl").string()),
                    Catch::Contains("a piece file is .gltf, .glb or .obj"));
  std::string junk = write("junk.glb", "glTF not really");
  CHECK_THROWS_WITH(draft_mesh_file("T", junk),
                    Catch::Contains("cannot read the glTF file: byte 4: expected GLB version 2"));
}

TEST_CASE("a missing piece file is a diagnostic at the mesh constructor") {
  SourceManager sm;
  DiagnosticSink diags;
  Program prog = load_program_text("/nonexistent/dir/m.ramus",
                                   "pieces m { piece B = mesh(\"nope.obj\"); root B; }", sm, diags);
  check_program(prog, sm, diags);
  REQUIRE(!diags.has_errors());
  lower_pieces(prog, sm, {}, diags);
  REQUIRE(diags.all().size() == 1);
  CHECK(diags.all()[0].message == "/nonexistent/dir/nope.obj: cannot read the piece file");
}
