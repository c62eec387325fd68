#include "model/sparse_assembly.h"
#include "twb/error_family.h"

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
    throw InternalError("Jacobian entry (" + std::to_string(row) + ", " + std::to_string(col) +
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
  // The entries bucketed by row (a counting sort: the structure pass records every
  // contribution, some million on 17×132, mostly repeats), then each row's columns made
  // unique by marking the columns seen (a row's bucket holds its repeats, so the sort
  // after it is of the few distinct columns). Every diagonal is kept: KLU needs no
  // structurally singular rows, and the pseudo-time solver adds c_j on the diagonal of
  // differential unknowns.
  std::vector<Index> start(std::size_t(n_) + 1, 0);
  for (const auto& e : entries_) ++start[std::size_t(e.first) + 1];
  for (Index i = 0; i < n_; ++i) start[std::size_t(i) + 1] += start[std::size_t(i)] + 1;
  std::vector<Index> columns(std::size_t(start.back()));
  std::vector<Index> fill(start.begin(), start.end() - 1);
  for (Index i = 0; i < n_; ++i) columns[std::size_t(fill[std::size_t(i)]++)] = i;
  for (const auto& [r, c] : entries_) columns[std::size_t(fill[std::size_t(r)]++)] = c;
  SparsePattern p;
  p.rows = p.cols = n_;
  p.row_start.assign(std::size_t(n_) + 1, 0);
  std::vector<Index> seen_in_row(std::size_t(n_), -1);
  for (Index r = 0; r < n_; ++r) {
    const std::size_t first = p.column.size();
    for (Index k = start[std::size_t(r)]; k < start[std::size_t(r) + 1]; ++k) {
      const Index c = columns[std::size_t(k)];
      if (seen_in_row[std::size_t(c)] == r) continue;
      seen_in_row[std::size_t(c)] = r;
      p.column.push_back(c);
    }
    std::sort(p.column.begin() + std::ptrdiff_t(first), p.column.end());
    p.row_start[std::size_t(r) + 1] = Index(p.column.size());
  }
  return p;
}

}  // namespace twb
