// Skeleton files: a Skeleton as JSON ("ramus-skeleton" version 1), documented in
// docs/skeleton-format.md. Numbers are written in their shortest round-trip form, so
// write -> read gives back the same doubles. The reader is strict: unknown keys, wrong types,
// parents out of range and parent cycles are FormatErrors naming the file, line, column and the
// JSON location (e.g. "nodes[12].parent").
#pragma once

#include <string>
#include <string_view>

#include "core/atomic_file.h"  // WriteError
#include "core/skeleton.h"
#include "formats/point_cloud_io.h"  // FormatError

namespace ramus {

std::string skeleton_to_json(const Skeleton& skeleton);
// `name` is used in messages. Throws FormatError.
Skeleton skeleton_from_json(std::string_view text, const std::string& name);

// File versions; the writer goes through write_file_atomically and throws WriteError (also for
// a skeleton holding NaN or infinity, which JSON cannot express).
void write_skeleton_json(const std::string& path, const Skeleton& skeleton);
Skeleton read_skeleton_json(const std::string& path);

}  // namespace ramus
