// What `ramus preview` was given: a grammar, a binary grammar, a skeleton, a mesh or a scan.
// The extension decides where it is unambiguous; the content decides the rest: a PLY with faces
// is a mesh and one without is a point cloud, a GLB or .rmb signature wins over the name, and a
// file with an unknown extension is a scan when its first bytes announce a point cloud format.
#pragma once

#include <string>

namespace ramus::cli {

enum class PreviewInput { kGrammar, kBinaryGrammar, kSkeleton, kMesh, kScan };

// "grammar", "binary grammar", "skeleton", "mesh", "scan": for messages.
const char* preview_input_name(PreviewInput kind);

// Throws UserError when the file cannot be opened or is none of these.
PreviewInput classify_preview_input(const std::string& path);

}  // namespace ramus::cli
