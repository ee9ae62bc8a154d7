// Measuring the trees an inferred grammar grows: growing it over seeds, the mean total length
// its calibration aims at, and the distance of the grown trees from the input that chooses
// between candidate grammars.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "core/skeleton.h"
#include "infer/skeleton/fidelity.h"

namespace ramus::skeleton_infer {

// A calibration growth with more modules than this is taken as far too long.
constexpr std::uint64_t kMaxCalibrationModules = 20'000'000;

// Grows `text` with seeds 1..n and hands every tree to `use`; false when a growth goes over
// kMaxCalibrationModules (far too long). Throws InferError when the text does not grow.
bool grow_seeds(const std::string& text, int seeds, const std::function<void(const Skeleton&)>& use);

// Mean total length of trees grown from `text` with seeds 1..n (infinity when far too long).
double mean_grown_length(const std::string& text, int seeds);

// The tip hazard shift for which the grammar `write(shift)` grows trees of total length
// `target` over `seeds` seeds (bisection; see grown_trees.cpp).
double calibrate_tip_shift(const std::function<std::string(double)>& write, double target,
                           int seeds);

// grown_distance (skeleton_grammar.h) against the input's measures, taken once.
double grown_distance(const std::string& text, const Distributions& input, int seeds);

}  // namespace ramus::skeleton_infer
