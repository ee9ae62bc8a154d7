// What the C++20 sources of the runtime use from the standard library and the libc++ 13 of
// Debian's emscripten 3.1.6 lacks: std::bit_cast (libc++ 14) and std::to_chars /
// std::from_chars for floating point (libc++ 14 and 20). Force-included (-include) into every
// source of the WebAssembly build only (runtime/wasm/CMakeLists.txt); the native builds use
// the standard library's own. Each piece is compiled only where that libc++ lacks it, so a
// newer emscripten ignores this file.
//
// Same results as GCC's libstdc++: from_chars goes through musl's strtod, which rounds
// correctly (as from_chars must), so decoded reals (formats/rmb/rmb_io.cpp decimal_value) are
// bit-identical; to_chars writes the shortest digits that read back to the same value in the
// shorter of the fixed and scientific forms, fixed on a tie ([charconv.to.chars]/2), which
// is what the messages and the dumps print natively (core/number_text.h).
#pragma once

#include <version>  // defines _LIBCPP_VERSION

#if defined(__EMSCRIPTEN__) && defined(_LIBCPP_VERSION) && _LIBCPP_VERSION < 14000

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <type_traits>

namespace std {

template <class To, class From>
requires(sizeof(To) == sizeof(From) && is_trivially_copyable_v<To> &&
         is_trivially_copyable_v<From>) constexpr To bit_cast(const From& from) noexcept {
  return __builtin_bit_cast(To, from);
}

namespace ramus_compat {

// The shortest-round-trip spelling of v (finite, not 0) in the form to_chars(first, last, v)
// chooses: the digits d1 d2 ... dn and decimal exponent e of v = 0.d1...dn * 10^e, then fixed
// or scientific, whichever is shorter.
template <class T>
to_chars_result shortest(char* first, char* last, T v) {
  char sci[40];
  int precision = 1;
  const int max_precision = is_same_v<T, float> ? 9 : 17;
  for (;; ++precision) {
    snprintf(sci, sizeof sci, "%.*e", precision - 1, double(v));
    if (precision == max_precision) break;
    if constexpr (is_same_v<T, float>) {
      if (strtof(sci, nullptr) == v) break;
    } else {
      if (strtod(sci, nullptr) == v) break;
    }
  }
  // sci is "[-]D.DDDe[+-]XX": split into sign, digits and exponent.
  const char* p = sci;
  const bool negative = *p == '-';
  if (negative) ++p;
  char digits[24];
  int n = 0;
  for (; *p != 'e'; ++p) {
    if (*p != '.') digits[n++] = *p;
  }
  while (n > 1 && digits[n - 1] == '0') --n;  // "%.*e" pads; the shortest has no trailing zeros
  const int exp10 = atoi(p + 1);              // v = D.DDD * 10^exp10
  // Scientific: D[.DDD]e[+-]XX with at least two exponent digits.
  char s_text[40];
  int s_len = 0;
  if (negative) s_text[s_len++] = '-';
  s_text[s_len++] = digits[0];
  if (n > 1) {
    s_text[s_len++] = '.';
    for (int i = 1; i < n; ++i) s_text[s_len++] = digits[i];
  }
  s_len += snprintf(s_text + s_len, sizeof s_text - size_t(s_len), "e%c%02d", exp10 < 0 ? '-' : '+',
                    exp10 < 0 ? -exp10 : exp10);
  // Fixed: the digits with the point moved, zeros filled in.
  char f_text[400];
  int f_len = 0;
  if (negative) f_text[f_len++] = '-';
  if (exp10 < 0) {
    f_text[f_len++] = '0';
    f_text[f_len++] = '.';
    for (int i = 0; i < -exp10 - 1; ++i) f_text[f_len++] = '0';
    for (int i = 0; i < n; ++i) f_text[f_len++] = digits[i];
  } else if (exp10 + 1 >= n) {
    // An integer: its exact value ("%.0f"), as long as the shortest digits padded with zeros
    // and the closest of the spellings of that length ([charconv.to.chars]/2).
    f_len += snprintf(f_text + f_len, sizeof f_text - size_t(f_len), "%.0f", fabs(double(v)));
  } else {
    for (int i = 0; i < n; ++i) {
      if (i == exp10 + 1) f_text[f_len++] = '.';
      f_text[f_len++] = digits[i];
    }
  }
  const char* text = f_len <= s_len ? f_text : s_text;
  const int len = f_len <= s_len ? f_len : s_len;
  if (last - first < len) return {last, errc::value_too_large};
  memcpy(first, text, size_t(len));
  return {first + len, errc()};
}

template <class T>
to_chars_result to_chars_float(char* first, char* last, T v) {
  const char* special = nullptr;
  if (isnan(v))
    special = signbit(v) ? "-nan" : "nan";
  else if (isinf(v))
    special = v < 0 ? "-inf" : "inf";
  else if (v == 0)
    special = signbit(v) ? "-0" : "0";
  if (!special) return shortest(first, last, v);
  const size_t len = strlen(special);
  if (size_t(last - first) < len) return {last, errc::value_too_large};
  memcpy(first, special, len);
  return {first + len, errc()};
}

}  // namespace ramus_compat

inline to_chars_result to_chars(char* first, char* last, double v) {
  return ramus_compat::to_chars_float(first, last, v);
}
inline to_chars_result to_chars(char* first, char* last, float v) {
  return ramus_compat::to_chars_float(first, last, v);
}

// The general format of from_chars (decimal, optional exponent, no leading '+', no hex), read
// with strtod over a bounded copy.
inline from_chars_result from_chars(const char* first, const char* last, double& value) {
  char buf[128];
  const size_t n = size_t(last - first) < sizeof buf - 1 ? size_t(last - first) : sizeof buf - 1;
  memcpy(buf, first, n);
  buf[n] = '\0';
  const char* p = buf + (buf[0] == '-');
  if (!(('0' <= *p && *p <= '9') || *p == '.') || (p[0] == '0' && (p[1] == 'x' || p[1] == 'X')))
    return {first, errc::invalid_argument};
  char* end = nullptr;
  const double v = strtod(buf, &end);
  if (end == buf) return {first, errc::invalid_argument};
  if (isinf(v)) return {first + (end - buf), errc::result_out_of_range};
  value = v;
  return {first + (end - buf), errc()};
}

}  // namespace std

#endif
