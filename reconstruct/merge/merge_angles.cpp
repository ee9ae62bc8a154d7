#include "reconstruct/merge/merge_angles.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace ramus::merge {

namespace {

double parse_angle(std::string_view part, const char* name, std::string_view whole) {
  const std::string s(part);
  char* end = nullptr;
  const double v = s.empty() ? NAN : std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v) || v < 0 || v > 180) {
    throw std::invalid_argument("--merge expects ALPHA,BETA in degrees (0 to 180), e.g. 10,15; " +
                                std::string(name) + " in '" + std::string(whole) +
                                "' is not such a number");
  }
  return v;
}

}  // namespace

MergeOptions parse_merge_angles(std::string_view text) {
  const std::size_t comma = text.find(',');
  if (comma == std::string_view::npos) {
    throw std::invalid_argument("--merge expects ALPHA,BETA in degrees, e.g. 10,15 (got '" +
                                std::string(text) + "')");
  }
  MergeOptions o;
  o.alpha_deg = parse_angle(text.substr(0, comma), "alpha", text);
  o.beta_deg = parse_angle(text.substr(comma + 1), "beta", text);
  return o;
}

}  // namespace ramus::merge
