#include "solver/sparse_lu.h"

#include <klu.h>

#include "solver/nested_dissection.h"
#include "twb/error_family.h"

#include <stdexcept>
#include <string>

namespace twb {

namespace {
// Every SparseLu of this thread together (a search's work, whatever solver it was in).
thread_local SparseLu::Counts tally;
}  // namespace

const SparseLu::Counts& SparseLu::thread_counts() { return tally; }

// KLU reads column-compressed arrays; handed our row-compressed ones it factors Aᵀ, so
// klu_l_tsolve solves with A and klu_l_solve with Aᵀ.
struct SparseLu::Klu {
  klu_l_common common{};
  klu_l_symbolic* symbolic = nullptr;
  klu_l_numeric* numeric = nullptr;
  std::vector<SuiteSparse_long> row_start, column;
  std::vector<double> values;  // KLU's factor takes a non-const pointer
  SuiteSparse_long n = 0;
  double growth_at_factor = 0.0;  // KLU's reciprocal pivot growth of the last full factorization
  Counts counts;
  ~Klu() {
    if (numeric) klu_l_free_numeric(&numeric, &common);
    if (symbolic) klu_l_free_symbolic(&symbolic, &common);
  }
  // KLU's reciprocal pivot growth of the current factors (small: large growth), or 0.
  double growth() {
    return klu_l_rgrowth(row_start.data(), column.data(), values.data(), symbolic, numeric, &common) ? common.rgrowth
                                                                                                      : 0.0;
  }
  bool full_factorization() {
    if (numeric) klu_l_free_numeric(&numeric, &common);
    numeric = klu_l_factor(row_start.data(), column.data(), values.data(), symbolic, &common);
    ++counts.factorizations;
    ++tally.factorizations;
    if (!numeric) return false;
    growth_at_factor = growth();
    return true;
  }
};

SparseLu::SparseLu(const SparsePattern& p, Ordering ordering) : klu_(std::make_unique<Klu>()) {
  if (p.rows != p.cols) throw InternalError("SparseLu: the matrix must be square");
  klu_l_defaults(&klu_->common);
  if (ordering == Ordering::by_size && (p.rows > kNestedDissectionAbove || p.prefers_nested_dissection)) {
    klu_->common.ordering = 3;
    klu_->common.user_order = nested_dissection_order;
  } else {
    klu_->common.ordering = 0;  // AMD
  }
  klu_->n = p.rows;
  klu_->row_start.assign(p.row_start.begin(), p.row_start.end());
  klu_->column.assign(p.column.begin(), p.column.end());
  klu_->symbolic = klu_l_analyze(klu_->n, klu_->row_start.data(), klu_->column.data(), &klu_->common);
  if (!klu_->symbolic && klu_->common.ordering == 3) {
    // Nested dissection failed (METIS out of memory, say): AMD orders it instead.
    klu_->common.ordering = 0;
    klu_->symbolic = klu_l_analyze(klu_->n, klu_->row_start.data(), klu_->column.data(), &klu_->common);
  }
  ++klu_->counts.analyses;
  ++tally.analyses;
  if (!klu_->symbolic)
    throw std::runtime_error("KLU symbolic analysis failed (status " + std::to_string(klu_->common.status) + ")");
}

SparseLu::~SparseLu() = default;

bool SparseLu::factor(std::span<const double> values) {
  klu_->values.assign(values.begin(), values.end());
  return klu_->full_factorization();
}

bool SparseLu::refactor(std::span<const double> values) {
  Klu& k = *klu_;
  k.values.assign(values.begin(), values.end());
  if (k.numeric) {
    ++k.counts.refactorizations;
    ++tally.refactorizations;
    if (klu_l_refactor(k.row_start.data(), k.column.data(), k.values.data(), k.symbolic, k.numeric, &k.common) &&
        k.growth() >= 1e-2 * k.growth_at_factor)
      return true;
  }
  return k.full_factorization();
}

bool SparseLu::factored() const { return klu_->numeric != nullptr; }

void SparseLu::solve(std::span<double> b) const {
  if (!klu_->numeric) throw InternalError("SparseLu::solve without a factorization");
  klu_l_tsolve(klu_->symbolic, klu_->numeric, klu_->n, 1, b.data(), &klu_->common);
}

void SparseLu::solve_transposed(std::span<double> b) const {
  if (!klu_->numeric) throw InternalError("SparseLu::solve_transposed without a factorization");
  klu_l_solve(klu_->symbolic, klu_->numeric, klu_->n, 1, b.data(), &klu_->common);
}

double SparseLu::pivot_ratio() const {
  if (!klu_->numeric) return 0.0;
  klu_l_rcond(klu_->symbolic, klu_->numeric, &klu_->common);
  return klu_->common.rcond;
}

const SparseLu::Counts& SparseLu::counts() const { return klu_->counts; }

long SparseLu::factor_entries() const { return klu_->numeric ? long(klu_->numeric->lnz + klu_->numeric->unz) : 0; }

}  // namespace twb
