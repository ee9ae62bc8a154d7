// The self-contained HTML page of `ramus view`: three.js (its ES modules, from the npm package in
// tools/node_modules/three, inlined as data: URLs behind an import map, with three's MIT licence
// in a comment) and the asset itself (base64), so the page needs no network and no server.
#pragma once

#include <map>
#include <string>

namespace ramus::cli {

struct ViewAsset {
  std::string name;  // shown in the page's title
  std::string main;  // a GLB, or the JSON of a .gltf
  bool binary = true;
  // Files a .gltf names by relative uri (its .bin, images), by that uri.
  std::map<std::string, std::string> files;
};

// The folder of the three npm package: $RAMUS_THREE_DIR, else the checkout's
// tools/node_modules/three. Throws UserError when three.js is not there.
std::string three_dir();

// The page's module of 2.5D foliage impostors (cli/view_impostors.cpp), imported as
// 'ramus/impostors.js'.
const char* view_impostors_module();

// The page. Throws UserError when a module of three.js cannot be read.
std::string view_page(const ViewAsset& asset, const std::string& three);

}  // namespace ramus::cli
