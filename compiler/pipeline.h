// The front half of the pipeline as one call: load (with imports) -> check -> lower. Shared by
// grow_file() (compiler/grow.h), `ramus derive` and the benchmarks.
#pragma once

#include <string>

#include "compiler/grow.h"
#include "compiler/ir.h"
#include "grammar/diagnostic.h"
#include "grammar/source.h"

namespace ramus {

// Throws GrowError when the grammar has errors (they are in `diagnostics`; the message repeats
// the first) or the options name no lsystem / no param.
ir::Grammar lower_file(const std::string& path, const GrowOptions& options, SourceManager& sources,
                       DiagnosticSink& diagnostics);

// The same for grammar text already in memory (`name` is what diagnostics print).
ir::Grammar lower_text(const std::string& name, const std::string& text, const GrowOptions& options,
                       SourceManager& sources, DiagnosticSink& diagnostics);

}  // namespace ramus
