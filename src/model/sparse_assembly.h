// Residual and Jacobian assembly with a fixed sparsity pattern.
//
// The Jacobian pattern is found once by a structural pass of the same assembly code
// (every term registers every entry it could ever touch, whatever the state), so
// KLU's symbolic analysis stays valid for the life of the model. Numeric passes then
// add into that pattern; an entry outside it is a programming error and throws.
//
// Finding an entry's position in the CSR arrays is a binary search in its row. The
// assembly visits the same entries in the same order at every state (which terms exist
// depends on the scene and the grids, never on the unknowns), so the positions of one
// Jacobian pass, recorded once as a slot tape, serve every later pass: each entry then
// costs one load and two checks (the slot's column and row) instead of a search. A pass
// that ever leaves the tape (a check fails) drops it and searches for the rest, so a
// stale tape costs speed, never correctness.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "system/sparse_pattern.h"

namespace twb {

// One sparse linear combination: the gradient of a local quantity with respect to
// the global unknowns, e.g. dh/du at a quadrature point.
struct LinearForm {
  std::vector<std::pair<Index, double>> terms;
  void add(Index col, double coefficient) { if (col >= 0) terms.emplace_back(col, coefficient); }
  void clear() { terms.clear(); }
};

class Assembler {
 public:
  enum class Mode { structure, values };

  // Structure mode: records entries of an n×n matrix.
  explicit Assembler(Index n);
  // Value mode into an existing pattern; jacobian may be empty for residual-only passes.
  // With a slot tape (see above) entries are placed by it; without, by search.
  Assembler(const SparsePattern* pattern, std::span<double> residual, std::span<double> jacobian,
            const std::vector<Index>* slot_tape = nullptr);

  Mode mode() const { return mode_; }
  bool wants_jacobian() const { return mode_ == Mode::structure || !jacobian_.empty(); }

  void add_residual(Index row, double value) {
    if (mode_ == Mode::values && row >= 0) residual_[row] += value;
  }
  double residual_value(Index row) const { return mode_ == Mode::values ? residual_[row] : 0.0; }
  void set_residual(Index row, double value) {
    if (mode_ == Mode::values) residual_[row] = value;
  }
  void add_derivative(Index row, Index col, double value) {
    if (row < 0 || col < 0) return;
    if (tape_) {
      const std::size_t c = cursor_;
      if (c < tape_->size()) {
        const Index k = (*tape_)[c];
        if (pattern_->column[std::size_t(k)] == col && k >= pattern_->row_start[std::size_t(row)] &&
            k < pattern_->row_start[std::size_t(row) + 1]) {
          cursor_ = c + 1;
          jacobian_[std::size_t(k)] += value;
          return;
        }
      }
      tape_ = nullptr;  // off the tape: search from here on
    }
    add_derivative_searched(row, col, value);
  }
  // d(row) += scale · form
  void add_form(Index row, double scale, const LinearForm& form);
  // Multiply every Jacobian entry of a row by a: used to turn an accumulated flow
  // balance into the complementarity row that wraps it.
  void scale_row(Index row, double a);

  SparsePattern finish_structure() const;
  // Records the slot tape of this (value, searching) pass into *tape, cleared first.
  void record_slots(std::vector<Index>* tape);
  // True while every entry so far has been placed by the slot tape.
  bool on_tape() const { return tape_ != nullptr; }

 private:
  void add_derivative_searched(Index row, Index col, double value);

  Mode mode_;
  Index n_ = 0;
  std::vector<std::pair<Index, Index>> entries_;
  const SparsePattern* pattern_ = nullptr;
  std::span<double> residual_, jacobian_;
  const std::vector<Index>* tape_ = nullptr;  // replayed: positions in call order
  std::size_t cursor_ = 0;
  std::vector<Index>* recording_ = nullptr;
};

}  // namespace twb
