#include "cli/compare_shape.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli/command.h"
#include "infer/shape/envelope.h"
#include "infer/shape/shape_error.h"
#include "infer/shape/tree_shape.h"

namespace ramus::cli {

namespace {

// A tree measured against a reference envelope, height and lean.
ShapeRow row_of(const std::string& label, const shape::Envelope& ref, double ref_lean,
                const Skeleton& tree) {
  const shape::TreeShape t = shape::measure_tree_shape(tree);
  ShapeRow r;
  r.label = label;
  r.iou = shape::envelope_iou(ref, tree);
  r.pieces = t.pieces;
  r.largest_piece_share = t.largest_piece_share;
  r.axis_locked_share = t.axis_locked_share;
  r.height_ratio = t.height / ref.base.height;
  r.lean_degrees = t.lean_degrees;
  r.lean_difference = t.lean_degrees - ref_lean;  // NaN propagates: "n/a"
  return r;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

std::string number_or_na(double v, const char* format) {
  if (!std::isfinite(v)) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string file_name(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

}  // namespace

ShapeReport measure_shapes(const CompareSide& a, const CompareSide& b) {
  ShapeReport report;
  try {
    std::vector<double> ious;
    if (a.cloud) {
      const shape::Envelope ref = shape::scan_envelope(*a.cloud);
      const double lean = shape::lean_degrees(*a.cloud);
      char buf[256];
      std::snprintf(buf, sizeof buf, "A = scan %s: height %.4g, cell %.4g, trunk lean %s deg",
                    file_name(a.path).c_str(), ref.base.height, ref.cell,
                    number_or_na(lean, "%.2f").c_str());
      report.reference = buf;
      report.rows.push_back(row_of("A reconstruction", ref, lean, a.trees.front()));
      report.has_reconstruction = true;
      for (std::size_t i = 0; i < b.trees.size(); ++i) {
        report.rows.push_back(row_of("B " + b.labels[i], ref, lean, b.trees[i]));
        ious.push_back(report.rows.back().iou);
      }
    } else {
      // A's trees are the references; each gets its own cell (its height / 32).
      std::vector<shape::Envelope> refs;
      std::vector<double> leans;
      for (const Skeleton& t : a.trees) {
        refs.push_back(shape::reference_envelope(t));
        leans.push_back(shape::lean_degrees(t));
      }
      const std::size_t rows = std::max(a.trees.size(), b.trees.size());
      for (std::size_t i = 0; i < rows; ++i) {
        const std::size_t ia = i % a.trees.size(), ib = i % b.trees.size();
        std::string label = "B " + b.labels[ib];
        if (a.trees.size() > 1) label += " vs A " + a.labels[ia];
        report.rows.push_back(row_of(label, refs[ia], leans[ia], b.trees[ib]));
        ious.push_back(report.rows.back().iou);
      }
      char buf[256];
      if (a.trees.size() == 1) {
        std::snprintf(buf, sizeof buf, "A = %s %s: height %.4g, cell %.4g, trunk lean %s deg",
                      a.labels[0].c_str(), file_name(a.path).c_str(), refs[0].base.height,
                      refs[0].cell, number_or_na(leans[0], "%.2f").c_str());
      } else {
        std::snprintf(buf, sizeof buf, "A = grammar %s: each row against A's tree of its seed",
                      file_name(a.path).c_str());
      }
      report.reference = buf;
    }
    report.median_iou = median(ious);
  } catch (const shape::ShapeError& e) {
    throw UserError(std::string("shape measures: ") + e.what());
  }
  return report;
}

void print_shape_report(const ShapeReport& r) {
  std::printf("envelope IoU and tree shape against %s\n", r.reference.c_str());
  std::printf("%-28s %7s %6s %13s %11s %12s %8s %9s\n", "tree", "IoU", "pieces", "largest-piece",
              "axis-locked", "height-ratio", "lean-deg", "lean-diff");
  for (const ShapeRow& row : r.rows) {
    std::printf("%-28s %7.4f %6zu %13.4f %11.4f %12.4f %8s %9s\n", row.label.c_str(), row.iou,
                row.pieces, row.largest_piece_share, row.axis_locked_share, row.height_ratio,
                number_or_na(row.lean_degrees, "%.2f").c_str(),
                number_or_na(row.lean_difference, "%+.2f").c_str());
  }
  const std::size_t n = r.rows.size() - (r.has_reconstruction ? 1 : 0);
  std::printf("envelope IoU: B median %.4f over %zu tree%s", r.median_iou, n, n == 1 ? "" : "s");
  if (r.has_reconstruction) std::printf(" vs A reconstruction %.4f", r.rows.front().iou);
  std::printf("\n\n");
}

}  // namespace ramus::cli
