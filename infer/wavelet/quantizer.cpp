#include "infer/wavelet/quantizer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace ramus::wavelet {

std::uint8_t CoefficientQuantizer::quantize(double c) const {
  const int h = half();
  double k = std::round(c / step());
  if (!(k >= -h)) k = -h;  // also catches NaN
  if (k > h) k = h;
  return std::uint8_t(h + int(k));
}

CoefficientQuantizer make_quantizer(double range, int classes) {
  if (classes < 3 || classes > kMaxClasses || classes % 2 == 0) {
    throw std::invalid_argument("the number of classes must be odd and in [3, " +
                                std::to_string(kMaxClasses) + "], not " + std::to_string(classes));
  }
  CoefficientQuantizer q;
  q.classes = classes;
  q.range = range > 0 && std::isfinite(range) ? range : 1.0;
  return q;
}

}  // namespace ramus::wavelet
