#include "twb/solver/sparse_lu.h"

#include <klu.h>

#include <stdexcept>
#include <string>

namespace twb {

// KLU reads column-compressed arrays; handed our row-compressed ones it factors Aᵀ, so
// klu_l_tsolve solves with A and klu_l_solve with Aᵀ.
struct SparseLu::Klu {
  klu_l_common common{};
  klu_l_symbolic* symbolic = nullptr;
  klu_l_numeric* numeric = nullptr;
  std::vector<SuiteSparse_long> row_start, column;
  std::vector<double> values;  // KLU's factor takes a non-const pointer
  SuiteSparse_long n = 0;
  ~Klu() {
    if (numeric) klu_l_free_numeric(&numeric, &common);
    if (symbolic) klu_l_free_symbolic(&symbolic, &common);
  }
};

SparseLu::SparseLu(const SparsePattern& p) : klu_(std::make_unique<Klu>()) {
  if (p.rows != p.cols) throw std::invalid_argument("SparseLu: the matrix must be square");
  klu_l_defaults(&klu_->common);
  klu_->common.ordering = 0;  // AMD: dense borders are ordered last (kinsol_newton.cpp)
  klu_->n = p.rows;
  klu_->row_start.assign(p.row_start.begin(), p.row_start.end());
  klu_->column.assign(p.column.begin(), p.column.end());
  klu_->symbolic = klu_l_analyze(klu_->n, klu_->row_start.data(), klu_->column.data(), &klu_->common);
  if (!klu_->symbolic)
    throw std::runtime_error("KLU symbolic analysis failed (status " + std::to_string(klu_->common.status) + ")");
}

SparseLu::~SparseLu() = default;

bool SparseLu::factor(std::span<const double> values) {
  if (klu_->numeric) klu_l_free_numeric(&klu_->numeric, &klu_->common);
  klu_->values.assign(values.begin(), values.end());
  klu_->numeric = klu_l_factor(klu_->row_start.data(), klu_->column.data(), klu_->values.data(), klu_->symbolic,
                               &klu_->common);
  return klu_->numeric != nullptr;
}

void SparseLu::solve(std::span<double> b) const {
  if (!klu_->numeric) throw std::logic_error("SparseLu::solve without a factorization");
  klu_l_tsolve(klu_->symbolic, klu_->numeric, klu_->n, 1, b.data(), &klu_->common);
}

void SparseLu::solve_transposed(std::span<double> b) const {
  if (!klu_->numeric) throw std::logic_error("SparseLu::solve_transposed without a factorization");
  klu_l_solve(klu_->symbolic, klu_->numeric, klu_->n, 1, b.data(), &klu_->common);
}

double SparseLu::pivot_ratio() const {
  if (!klu_->numeric) return 0.0;
  klu_l_rcond(klu_->symbolic, klu_->numeric, &klu_->common);
  return klu_->common.rcond;
}

}  // namespace twb
