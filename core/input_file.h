// Whole-file input with the limits every reader shares: the largest file ramus will read, and the
// most points a scan reader keeps.
//
// Scans, grammars, skeletons, manifests and binary grammars come from anyone; a reader that
// slurps a file must not be led into reading 500 GB because a path pointed at the wrong disk.
// The limits are process-wide (the CLI sets them once from `--max-file-size` and `--max-points`,
// docs/robustness.md) so every stage's reader applies the same ones without threading them
// through each call.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace ramus {

// 64 GiB: above any single scan tile a workstation processes, below what would exhaust a disk.
inline constexpr std::uint64_t kDefaultMaxInputFileBytes = std::uint64_t(64) << 30;

std::uint64_t max_input_file_bytes();
void set_max_input_file_bytes(std::uint64_t bytes);

// The most points a scan reader keeps in a cloud (after --thin, when given): 10^9 points hold
// 12 GB of positions alone, more than a workstation processes in one piece (tile it instead).
inline constexpr std::uint64_t kDefaultMaxInputPoints = 1'000'000'000;

std::uint64_t max_input_points();
void set_max_input_points(std::uint64_t points);

// The complaint about a file of `bytes` bytes when it is over the limit ("has N bytes, more than
// the limit of M (--max-file-size)"), else "".
std::string input_file_size_error(std::uint64_t bytes);

// The same for the file at `path`, for readers that hand the path to a library; "" also when the
// size cannot be read (opening the file then fails with its own message).
std::string input_file_size_error(const std::filesystem::path& path);

// Reads the whole file at `path` into `bytes`. On failure returns false and puts the reason in
// `error` without the path: "is a directory", "cannot open the file (No such file ...)", the size
// limit's complaint (checked before anything is read), or "cannot read the file".
bool read_input_file(const std::filesystem::path& path, std::string& bytes, std::string& error);

}  // namespace ramus
