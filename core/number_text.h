// Numbers as text in their shortest round-trip form (std::to_chars): the one spelling every
// text output of ramus uses (derived strings, dumps, JSON, XYZ), so a value printed anywhere
// reads back to the same double and prints identically on every machine.
#pragma once

#include <charconv>
#include <string>

namespace ramus {

template <typename T>
void append_shortest(std::string& out, T value) {
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, ec == std::errc() ? end : buf);
}

template <typename T>
std::string shortest_text(T value) {
  std::string s;
  append_shortest(s, value);
  return s;
}

}  // namespace ramus
