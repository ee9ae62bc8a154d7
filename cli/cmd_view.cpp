// ramus view FILE -o PAGE.html [--lod N] [grammar options]
// Writes a self-contained HTML page (cli/view_page.h) that shows a glTF asset in three.js with
// orbit controls, a switch between its MSFT_lod levels, its wind animation playing and a switch
// between leaf cards and 2.5D foliage impostors (cli/view_impostors.cpp). FILE is a
// .glb, a .gltf (its .bin and images go into the page too) or a grammar, which is built first as
// `ramus build FILE --lod N --wind --compress meshopt` would build it (docs/mesh.md).
#include <filesystem>
#include <memory>
#include <regex>

#include "backends/mesh/gltf_container.h"
#include "backends/mesh/gltf_writer.h"
#include "cli/grow_args.h"
#include "cli/output_path.h"
#include "cli/read_file.h"
#include "cli/view_page.h"
#include "core/atomic_file.h"
#include "mesh/tree_mesh.h"

namespace ramus::cli {
namespace {

namespace fs = std::filesystem;

struct ViewArgs {
  GrowArgs grow;
  std::string output;
  int lod = 2;
  std::vector<std::string> grammar_options;  // grammar-only options the command line gave
};

std::string percent_decode(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size()) {
      out += char(std::stoi(s.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

// A .gltf and the files its uris name beside it (data: uris are in the JSON already).
ViewAsset read_gltf(const std::string& path) {
  ViewAsset a;
  a.binary = false;
  a.main = read_file_bytes(path);
  static const std::regex uri(R"re("uri"\s*:\s*"([^"]+)")re");
  for (std::sregex_iterator it(a.main.begin(), a.main.end(), uri), end; it != end; ++it) {
    const std::string u = (*it)[1].str();
    if (u.rfind("data:", 0) == 0) continue;
    a.files[u] = read_file_bytes((fs::path(path).parent_path() / percent_decode(u)).string());
  }
  return a;
}

int run_view(const ViewArgs& a, const GlobalOptions& global) {
  const std::string ext = fs::path(a.grow.file).extension().string();
  const bool grammar = ext != ".glb" && ext != ".gltf";
  if (!grammar && !a.grammar_options.empty())
    throw UserError(a.grammar_options.front() + " applies to grammar inputs only");
  if (grammar && ext != ".ramus")
    throw UserError("ramus view takes a .glb, a .gltf or a grammar (.ramus), not " + a.grow.file);
  const std::string three = three_dir();
  ViewAsset asset;
  asset.name = fs::path(a.grow.file).filename().string();
  if (ext == ".glb") {
    asset.main = read_file_bytes(a.grow.file);
    // The page hands the bytes to the browser's glTF loader: a container whose header or chunks
    // lie about them is refused here, where the byte can be named (gltf_container.h).
    const std::string e = mesh::glb_layout_error(
        reinterpret_cast<const unsigned char*>(asset.main.data()), asset.main.size());
    if (!e.empty()) throw UserError(a.grow.file + " is not a GLB file: " + e);
  } else if (ext == ".gltf") {
    ViewAsset g = read_gltf(a.grow.file);
    g.name = asset.name;
    asset = std::move(g);
  } else {
    const std::optional<Skeleton> skeleton = grow_for_cli(a.grow);
    if (!skeleton) return 1;
    mesh::MeshOptions o;
    o.name = fs::path(a.grow.file).stem().string();
    o.lod_count = a.lod + 1;
    o.wind = true;
    try {
      const std::vector<mesh::TreeMesh> lods = mesh::build_tree_lods(*skeleton, o);
      asset.main = mesh::encode_gltf(lods, true, "", mesh::GltfCompression::kMeshopt).main;
    } catch (const mesh::MeshError& e) {
      throw UserError(e.what());
    }
  }
  write_file_atomically(a.output, view_page(asset, three));
  if (!global.quiet) std::fprintf(stderr, "ramus: wrote %s\n", a.output.c_str());
  return 0;
}

}  // namespace

void add_view(CLI::App& app, const GlobalOptions& global, std::function<int()>& run) {
  auto args = std::make_shared<ViewArgs>();
  CLI::App* sub = app.add_subcommand(
      "view", "write a self-contained HTML page that shows a .glb/.gltf or a grammar's tree");
  add_grow_options(sub, args->grow);
  sub->get_option("file")->description("the asset: .glb, .gltf or a grammar (.ramus)");
  output_path(sub->add_option("-o,--output", args->output, "the page (.html)"))
      ->required()
      ->check(CLI::Validator(
          [](const std::string& p) -> std::string {
            const std::string e = fs::path(p).extension().string();
            return e == ".html" || e == ".htm" ? "" : "the page must end in .html";
          },
          "FILE", "page"));
  sub->add_option("--lod", args->lod, "grammar: levels of detail LOD0..LOD N (default 2)")
      ->check(CLI::Range(0, 7));
  sub->callback([args, sub, &global, &run] {
    for (const char* o : {"--steps", "--seed", "--define", "--system", "--max-modules", "--lod"})
      if (sub->count(o) > 0) args->grammar_options.push_back(o);
    run = [args, &global] { return run_view(*args, global); };
  });
}

}  // namespace ramus::cli
