// Growing a tree from a grammar file in one call: load (with imports) -> check -> lower ->
// derive -> interpret with the turtle -> Skeleton. What `ramus build`, `ramus preview`,
// `ramus scan` and the tests use when they only need the tree.
#pragma once

#include <string>

#include "compiler/pipeline.h"
#include "core/skeleton.h"
#include "grammar/diagnostic.h"
#include "grammar/loader.h"
#include "grammar/source.h"

namespace ramus {

Skeleton grow_file(const std::string& path, const GrowOptions& options, SourceManager& sources,
                   DiagnosticSink& diagnostics);

// The same for a program the caller has loaded and checked (with options.defines) without
// errors: lower -> derive -> interpret, so a command that also needs the program's other blocks
// loads and checks it once.
Skeleton grow_checked(const Program& program, const GrowOptions& options, SourceManager& sources,
                      DiagnosticSink& diagnostics);

// The back half alone, for a grammar already lowered (or decoded from an .rmb): derive ->
// interpret, with options.steps and options.max_modules (the seed is the grammar's own, which
// a caller overriding it sets first, as the runtime does). Throws GrowError when derivation fails.
Skeleton grow_grammar(const ir::Grammar& grammar, const GrowOptions& options);

// The same for grammar text in memory (a decompiled .rmb), named `name` in diagnostics.
Skeleton grow_text(const std::string& name, const std::string& text, const GrowOptions& options,
                   SourceManager& sources, DiagnosticSink& diagnostics);

}  // namespace ramus
