// A piece from a Wavefront OBJ file: `v` positions, `f` faces of exactly four vertices (pieces are
// quad meshes, section 4.1), and rims as `l` polylines of six vertices in a group or object named
// `rim:<name>` (`g rim:root` then `l 1 2 3 4 5 6`). Errors name the file and line.
#include <fstream>
#include <sstream>

#include "backends/pieces/piece_build.h"
#include "core/input_file.h"

namespace ramus::pieces {

namespace {

// An OBJ vertex reference ("7", "7/2", "7//3", "-1") -> 0-based index.
std::uint32_t obj_index(const std::string& token, std::size_t count, const std::string& where) {
  std::string head = token.substr(0, token.find('/'));
  long long i = 0;
  try {
    std::size_t used = 0;
    i = std::stoll(head, &used);
    if (used != head.size()) throw std::invalid_argument(head);
  } catch (const std::exception&) {
    throw PiecesError(where + ": '" + token + "' is not a vertex index");
  }
  long long k = i > 0 ? i - 1 : (long long)count + i;
  if (i == 0 || k < 0 || k >= (long long)count) {
    throw PiecesError(where + ": vertex " + std::to_string(i) + " does not exist");
  }
  return std::uint32_t(k);
}

}  // namespace

PieceDraft draft_obj_file(const std::string& name, const std::string& path,
                          const std::string* bytes) {
  std::ifstream file;
  std::istringstream memory;
  if (bytes) {
    memory.str(*bytes);
  } else {
    if (std::string e = input_file_size_error(path); !e.empty()) throw PiecesError(path + ": " + e);
    file.open(path, std::ios::binary);
    if (!file) throw PiecesError(path + ": cannot read the piece file");
  }
  std::istream& in = bytes ? static_cast<std::istream&>(memory) : file;
  std::vector<Vec3> positions;
  std::vector<std::array<std::uint32_t, 4>> quads;
  std::vector<RawRim> rims;
  std::string group, line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string where = path + ":" + std::to_string(line_no);
    std::istringstream ls(line);
    std::string tag;
    if (!(ls >> tag) || tag[0] == '#') continue;
    if (tag == "v") {
      Vec3 p;
      if (!(ls >> p.x >> p.y >> p.z) || !is_finite(p)) {
        throw PiecesError(where + ": a vertex needs three finite numbers");
      }
      positions.push_back(p);
    } else if (tag == "g" || tag == "o") {
      std::getline(ls >> std::ws, group);
      while (!group.empty() && (group.back() == '\r' || group.back() == ' ')) group.pop_back();
    } else if (tag == "f") {
      std::vector<std::uint32_t> f;
      std::string t;
      while (ls >> t) f.push_back(obj_index(t, positions.size(), where));
      if (f.size() != 4) {
        throw PiecesError(where + ": a face has " + std::to_string(f.size()) +
                          " vertices; pieces are quad meshes");
      }
      quads.push_back({f[0], f[1], f[2], f[3]});
    } else if (tag == "l") {
      if (group.rfind("rim:", 0) != 0) continue;  // other lines are not ours
      RawRim r;
      r.name = group.substr(4);
      std::string t;
      while (ls >> t) r.vertices.push_back(obj_index(t, positions.size(), where));
      for (RawRim& old : rims) {
        if (old.name == r.name) throw PiecesError(where + ": rim:" + r.name + " is given twice");
      }
      rims.push_back(std::move(r));
    }
  }
  return draft_from_raw(name, path, std::move(positions), std::move(quads), std::move(rims));
}

}  // namespace ramus::pieces
