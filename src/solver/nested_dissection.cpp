#include "solver/nested_dissection.h"

#include <cholmod.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

namespace twb {

namespace {

// METIS (libmetis 5.1 as Debian packages it, its GKlib without a generator of its own)
// draws its random numbers from the C library's rand(), whose state is the process's.
// It seeds it again (srand of a fixed seed) at every call, so one call at a time finds
// the same order every time; two at once on two threads share one stream and find
// other orders, and every factorization after carries other round-off (a study's
// results would depend on its thread count). One METIS call at a time, whatever the
// thread: about 80 ms per new structure, most of which are kept (KeptOrders).
std::mutex& metis_lock() {
  static std::mutex lock;
  return lock;
}

SuiteSparse_long order(SuiteSparse_long n, SuiteSparse_long* Ap, SuiteSparse_long* Ai, SuiteSparse_long* perm) {
  using Long = SuiteSparse_long;
  // The graph of A + Aᵀ without self-loops.
  std::vector<std::vector<Long>> adjacent(static_cast<std::size_t>(n));
  for (Long j = 0; j < n; ++j)
    for (Long e = Ap[j]; e < Ap[j + 1]; ++e) {
      const Long i = Ai[e];
      if (i == j) continue;
      adjacent[std::size_t(i)].push_back(j);
      adjacent[std::size_t(j)].push_back(i);
    }
  // AMD's rule for a dense node: more than 10·√n neighbours (at least 16).
  const Long dense_degree = std::max<Long>(16, Long(10.0 * std::sqrt(double(n))));
  std::vector<Long> kept_index(std::size_t(n), -1), kept, dense;
  for (Long i = 0; i < n; ++i) {
    auto& a = adjacent[std::size_t(i)];
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    if (Long(a.size()) > dense_degree) {
      dense.push_back(i);
    } else {
      kept_index[std::size_t(i)] = Long(kept.size());
      kept.push_back(i);
    }
  }

  const Long m = Long(kept.size());
  cholmod_common cc;
  cholmod_l_start(&cc);
  Long nnz = 0;
  for (Long i : kept)
    for (Long j : adjacent[std::size_t(i)]) nnz += kept_index[std::size_t(j)] >= 0;
  cholmod_sparse* graph = cholmod_l_allocate_sparse(std::size_t(m), std::size_t(m), std::size_t(nnz), true, true,
                                                    /*stype: symmetric, both triangles given*/ 1, CHOLMOD_PATTERN,
                                                    &cc);
  Long lnz = 0;
  if (graph) {
    auto* gp = static_cast<Long*>(graph->p);
    auto* gi = static_cast<Long*>(graph->i);
    Long e = 0;
    for (Long c = 0; c < m; ++c) {
      gp[c] = e;
      for (Long j : adjacent[std::size_t(kept[std::size_t(c)])])
        if (kept_index[std::size_t(j)] >= 0) gi[e++] = kept_index[std::size_t(j)];
    }
    gp[m] = e;
    std::vector<Long> order(std::size_t(std::max<Long>(m, 1)));
    bool ordered = m == 0;
    if (!ordered) {
      const std::lock_guard<std::mutex> hold(metis_lock());
      ordered = cholmod_l_metis(graph, nullptr, 0, /*postorder*/ true, order.data(), &cc);
    }
    if (ordered) {
      for (Long k = 0; k < m; ++k) perm[k] = kept[std::size_t(order[std::size_t(k)])];
      for (std::size_t k = 0; k < dense.size(); ++k) perm[m + Long(k)] = dense[k];
      // KLU sizes its first allocation of L by this; it grows the factors when short.
      lnz = std::max<Long>(n, 4 * (Ap[n] + n));
    }
    cholmod_l_free_sparse(&graph, &cc);
  }
  cholmod_l_finish(&cc);
  return lnz;
}

// The orders found so far, by the block they order. A pattern is ordered again and
// again (every Newton solver, fold system and bordered matrix built on a mesh's
// Jacobian), and METIS costs about 80 ms on 17×132 against 6 ms for a refactorization;
// METIS called one at a time (metis_lock) is deterministic, so a kept order is the order
// it would find again. Keyed by the block's whole structure (compared, not only hashed); the first
// kKept blocks are kept, which covers a run's few meshes and their bordered systems.
class KeptOrders {
 public:
  using Long = SuiteSparse_long;
  // The order of the block and its fill estimate, if kept.
  bool find(Long n, const Long* Ap, const Long* Ai, Long* perm, Long& lnz) {
    const std::lock_guard<std::mutex> hold(lock_);
    for (const Entry& e : kept_)
      if (e.same(n, Ap, Ai)) {
        std::copy(e.perm.begin(), e.perm.end(), perm);
        lnz = e.lnz;
        return true;
      }
    return false;
  }
  void keep(Long n, const Long* Ap, const Long* Ai, const Long* perm, Long lnz) {
    const std::lock_guard<std::mutex> hold(lock_);
    if (kept_.size() >= kKept) return;
    kept_.push_back({std::vector<Long>(Ap, Ap + n + 1), std::vector<Long>(Ai, Ai + Ap[n]),
                     std::vector<Long>(perm, perm + n), lnz});
  }

 private:
  static constexpr std::size_t kKept = 16;
  struct Entry {
    std::vector<Long> p, i, perm;
    Long lnz = 0;
    bool same(Long n, const Long* Ap, const Long* Ai) const {
      return Long(p.size()) == n + 1 && std::equal(p.begin(), p.end(), Ap) && std::equal(i.begin(), i.end(), Ai);
    }
  };
  std::mutex lock_;
  std::vector<Entry> kept_;
};

KeptOrders& kept_orders() {
  static KeptOrders orders;
  return orders;
}

}  // namespace

SuiteSparse_long nested_dissection_order(SuiteSparse_long n, SuiteSparse_long* Ap, SuiteSparse_long* Ai,
                                         SuiteSparse_long* perm, klu_l_common* /*common*/) {
  // Called from KLU's C code: nothing may be thrown through it (0 makes KLU report a
  // failed analysis, and SparseLu falls back to AMD).
  try {
    SuiteSparse_long lnz = 0;
    if (kept_orders().find(n, Ap, Ai, perm, lnz)) return lnz;
    lnz = order(n, Ap, Ai, perm);
    if (lnz > 0) kept_orders().keep(n, Ap, Ai, perm, lnz);
    return lnz;
  } catch (...) {
    return 0;
  }
}

}  // namespace twb
