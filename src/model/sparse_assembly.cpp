#include "model/sparse_assembly.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace twb {

Assembler::Assembler(Index n) : mode_(Mode::structure), n_(n) {}

Assembler::Assembler(const SparsePattern* pattern, std::span<double> residual, std::span<double> jacobian,
                     const std::vector<Index>* slot_tape)
    : mode_(Mode::values), n_(pattern->rows), pattern_(pattern), residual_(residual), jacobian_(jacobian),
      tape_(jacobian.empty() ? nullptr : slot_tape) {
  std::fill(residual_.begin(), residual_.end(), 0.0);
  std::fill(jacobian_.begin(), jacobian_.end(), 0.0);
}

void Assembler::record_slots(std::vector<Index>* tape) {
  tape_ = nullptr;
  recording_ = tape;
  if (recording_) recording_->clear();
}

void Assembler::add_derivative_searched(Index row, Index col, double value) {
  if (mode_ == Mode::structure) {
    entries_.emplace_back(row, col);
    return;
  }
  if (jacobian_.empty()) return;
  const Index k = pattern_->find(row, col);
  if (k < 0)
    throw std::logic_error("Jacobian entry (" + std::to_string(row) + ", " + std::to_string(col) +
                           ") is outside the structural pattern");
  jacobian_[k] += value;
  if (recording_) recording_->push_back(k);
}

void Assembler::add_form(Index row, double scale, const LinearForm& form) {
  for (const auto& [col, c] : form.terms) add_derivative(row, col, scale * c);
}

void Assembler::scale_row(Index row, double a) {
  if (mode_ != Mode::values || jacobian_.empty()) return;
  for (Index k = pattern_->row_start[row]; k < pattern_->row_start[row + 1]; ++k) jacobian_[k] *= a;
}

SparsePattern Assembler::finish_structure() const {
  auto entries = entries_;
  // Every diagonal is kept: KLU needs no structurally singular rows, and the
  // pseudo-time solver adds c_j on the diagonal of differential unknowns.
  for (Index i = 0; i < n_; ++i) entries.emplace_back(i, i);
  std::sort(entries.begin(), entries.end());
  entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
  SparsePattern p;
  p.rows = p.cols = n_;
  p.row_start.assign(n_ + 1, 0);
  p.column.reserve(entries.size());
  for (const auto& [r, c] : entries) {
    ++p.row_start[r + 1];
    p.column.push_back(c);
  }
  for (Index r = 0; r < n_; ++r) p.row_start[r + 1] += p.row_start[r];
  return p;
}

}  // namespace twb
