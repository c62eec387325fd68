#include "model/sparse_assembly.h"
#include "twb/error_family.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace twb {

Assembler::Assembler(Index n) : mode_(Mode::structure), n_(n) {
  if (n > std::numeric_limits<std::int32_t>::max()) throw InternalError("Assembler: more unknowns than 32-bit rows hold");
  // The bearing's passes make about 60 contributions per unknown (519 k for the 8750
  // unknowns of 17×132): room for them at once instead of growing through copies.
  entries_.reserve(std::size_t(64 * n));
}

Assembler::Assembler(const SparsePattern* pattern, std::span<double> residual, std::span<double> jacobian,
                     const SlotTape* slot_tape, SlotTape* retaped)
    : mode_(Mode::values), n_(pattern->rows), pattern_(pattern), residual_(residual), jacobian_(jacobian),
      tape_(jacobian.empty() ? nullptr : slot_tape), retaped_(jacobian.empty() ? nullptr : retaped) {
  std::fill(residual_.begin(), residual_.end(), 0.0);
  std::fill(jacobian_.begin(), jacobian_.end(), 0.0);
  if (retaped_) {
    retaped_->clear();
    if (!tape_) recording_ = retaped_;
  }
}

void Assembler::leave_tape() {
  if (retaped_) {
    retaped_->assign(tape_->begin(), tape_->begin() + std::ptrdiff_t(cursor_));
    recording_ = retaped_;
  }
  tape_ = nullptr;
}

void Assembler::add_derivative_searched(Index row, Index col, double value) {
  if (mode_ == Mode::structure) {
    entries_.emplace_back(std::int32_t(row), std::int32_t(col));
    return;
  }
  if (jacobian_.empty()) return;
  const Index k = pattern_->find(row, col);
  if (k < 0)
    throw InternalError("Jacobian entry (" + std::to_string(row) + ", " + std::to_string(col) +
                           ") is outside the structural pattern");
  jacobian_[k] += value;
  if (recording_) recording_->push_back(std::int32_t(k));
}

void Assembler::add_form(Index row, double scale, const LinearForm& form) {
  for (const auto& [col, c] : form.terms) add_derivative(row, col, scale * c);
}

void Assembler::scale_row(Index row, double a) {
  if (mode_ != Mode::values || jacobian_.empty()) return;
  for (Index k = pattern_->row_start[row]; k < pattern_->row_start[row + 1]; ++k) jacobian_[k] *= a;
}

SparsePattern Assembler::finish_structure(SlotTape* tape) const {
  // The entries bucketed by row (a counting sort: the structure pass records every
  // contribution, some 500 k on 17×132, mostly repeats), each behind its row's diagonal,
  // then each row's columns made unique by marking the columns seen (a row's bucket holds
  // its repeats, so the sort after it is of the few distinct columns). Every diagonal is
  // kept: KLU needs no structurally singular rows, and the pseudo-time solver adds c_j on
  // the diagonal of differential unknowns.
  std::vector<Index> start(std::size_t(n_) + 1, 0);
  for (const auto& e : entries_) ++start[std::size_t(e.first) + 1];
  for (Index i = 0; i < n_; ++i) start[std::size_t(i) + 1] += start[std::size_t(i)] + 1;
  if (start.back() > std::numeric_limits<std::int32_t>::max())
    throw InternalError("Assembler: more contributions than a 32-bit slot tape holds");
  std::vector<std::int32_t> bucket(std::size_t(start.back()));
  std::vector<Index> fill(start.begin(), start.end() - 1);
  for (Index i = 0; i < n_; ++i) bucket[std::size_t(fill[std::size_t(i)]++)] = std::int32_t(i);
  for (const auto& [r, c] : entries_) bucket[std::size_t(fill[std::size_t(r)]++)] = c;
  SparsePattern p;
  p.rows = p.cols = n_;
  p.row_start.assign(std::size_t(n_) + 1, 0);
  std::vector<Index> seen_in_row(std::size_t(n_), -1);
  std::vector<std::int32_t> slot_of_column(tape ? std::size_t(n_) : 0);
  for (Index r = 0; r < n_; ++r) {
    const std::size_t first = p.column.size();
    for (Index k = start[std::size_t(r)]; k < start[std::size_t(r) + 1]; ++k) {
      const Index c = bucket[std::size_t(k)];
      if (seen_in_row[std::size_t(c)] == r) continue;
      seen_in_row[std::size_t(c)] = r;
      p.column.push_back(c);
    }
    std::sort(p.column.begin() + std::ptrdiff_t(first), p.column.end());
    p.row_start[std::size_t(r) + 1] = Index(p.column.size());
    if (!tape) continue;
    // The bucket's columns become the slots they land in.
    for (std::size_t k = first; k < p.column.size(); ++k) slot_of_column[std::size_t(p.column[k])] = std::int32_t(k);
    for (Index k = start[std::size_t(r)]; k < start[std::size_t(r) + 1]; ++k)
      bucket[std::size_t(k)] = slot_of_column[std::size_t(bucket[std::size_t(k)])];
  }
  if (tape) {
    // The contributions again in the order they came, each to its place in its bucket
    // (behind the row's diagonal): the slots in the pass's order.
    tape->resize(entries_.size());
    for (Index i = 0; i < n_; ++i) fill[std::size_t(i)] = start[std::size_t(i)] + 1;
    for (std::size_t e = 0; e < entries_.size(); ++e)
      (*tape)[e] = bucket[std::size_t(fill[std::size_t(entries_[e].first)]++)];
  }
  return p;
}

}  // namespace twb
