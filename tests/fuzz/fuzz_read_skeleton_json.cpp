// Fuzz target for the skeleton JSON reader: any input either reads or raises FormatError; a
// skeleton that reads is valid and writes back to the same text it reads from.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "formats/skeleton_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    ramus::Skeleton s = ramus::skeleton_from_json(text, "fuzz.json");
    if (!s.validate().empty()) std::abort();
    std::string once = ramus::skeleton_to_json(s);
    std::string twice = ramus::skeleton_to_json(ramus::skeleton_from_json(once, "again.json"));
    if (once != twice) std::abort();
  } catch (const ramus::FormatError&) {
  }
  return 0;
}
