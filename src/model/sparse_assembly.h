// Residual and Jacobian assembly with a fixed sparsity pattern.
//
// The Jacobian pattern is found once by a structural pass of the same assembly code
// (every term registers every entry it could ever touch, whatever the state), so
// KLU's symbolic analysis stays valid for the life of the model. Numeric passes then
// add into that pattern; an entry outside it is a programming error and throws.
//
// Finding an entry's position in the CSR arrays is a binary search in its row. The
// assembly visits mostly the same entries in the same order at every state (which terms
// exist depends on the scene and the grids; a few, such as the contact of cells far
// from it, on the state), so the positions of one pass, kept as a slot tape, serve the
// later ones: each entry then costs one load and two checks (the slot's column and row)
// instead of a search. The first tape is the structure pass's own sequence (that pass
// visits every entry a value pass can: the same sequence wherever the state leaves
// every term in place). A pass that leaves the tape (a check fails) searches for the
// rest and can hand back the tape it should have had (the part it replayed, then what
// it found), so a stale tape costs one searched pass, never correctness.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "system/sparse_pattern.h"

namespace twb {

// Positions in a pattern's entries, in the order a pass adds them (the slot tape above):
// 32 bits, half the memory a pass streams through (a pattern of 2^31 entries would
// outgrow any mesh twb refines on; finish_structure refuses one).
using SlotTape = std::vector<std::int32_t>;

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
  // With a slot tape (see above) entries are placed by it; without, by search. A pass
  // given `retaped` that leaves its tape (or has none) writes there the tape of its own
  // sequence, complete once the pass is.
  Assembler(const SparsePattern* pattern, std::span<double> residual, std::span<double> jacobian,
            const SlotTape* slot_tape = nullptr, SlotTape* retaped = nullptr);

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
      leave_tape();  // search from here on
    }
    add_derivative_searched(row, col, value);
  }
  // d(row) += scale · form
  void add_form(Index row, double scale, const LinearForm& form);
  // Multiply every Jacobian entry of a row by a: used to turn an accumulated flow
  // balance into the complementarity row that wraps it.
  void scale_row(Index row, double a);

  // The pattern of the entries recorded, and, given `tape`, the slot tape of the
  // structure pass's sequence in it.
  SparsePattern finish_structure(SlotTape* tape = nullptr) const;
  // True while every entry so far has been placed by the slot tape.
  bool on_tape() const { return tape_ != nullptr; }

 private:
  void add_derivative_searched(Index row, Index col, double value);
  void leave_tape();

  Mode mode_;
  Index n_ = 0;
  std::vector<std::pair<std::int32_t, std::int32_t>> entries_;  // (row, column), as added
  const SparsePattern* pattern_ = nullptr;
  std::span<double> residual_, jacobian_;
  const SlotTape* tape_ = nullptr;  // replayed: positions in call order
  std::size_t cursor_ = 0;
  SlotTape* recording_ = nullptr;
  SlotTape* retaped_ = nullptr;  // where a pass off its tape records (the constructor's)
};

}  // namespace twb
