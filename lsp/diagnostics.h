// The checker's diagnostics as LSP diagnostics of the document: code (E0101), severity, range,
// and each note with a place as relatedInformation (notes without one join the message). A
// diagnostic in an imported file is shown at the document's `import` that reads that file
// (directly or through other imports), with the place in that file as related information,
// since the client publishes diagnostics per document.
#pragma once

#include <vector>

#include "lsp/analysis.h"

namespace ramus::lsp {

std::vector<LspDiagnostic> document_diagnostics(const Analysis& analysis);

}  // namespace ramus::lsp
