// A fill-reducing ordering by nested dissection (METIS through CHOLMOD) for KLU's
// sparse LU, as KLU's user ordering (klu_l_common::ordering = 3). On the bearing's
// Jacobian, a 2-D grid of film and temperature nodes bordered by four dense rigid-body
// rows and columns, AMD's minimum-degree order makes the factors grow faster than the
// grid (benchmarks/README.md, "Growth"); a nested-dissection order on the grid's graph
// keeps them near the O(n log n) fill and O(n^1.5) work of a planar graph. Dense rows
// and columns (the rigid body) are left out of the graph and ordered last, as AMD does.
#pragma once

#include <klu.h>

namespace twb {

// KLU's user_order callback: the permutation of the n × n block (column pointers Ap,
// row indices Ai) into perm, by nested dissection of the graph of A + Aᵀ. Returns an
// estimate of the nonzeros in L (KLU's first allocation), 0 on failure (never throws).
SuiteSparse_long nested_dissection_order(SuiteSparse_long n, SuiteSparse_long* Ap, SuiteSparse_long* Ai,
                                         SuiteSparse_long* perm, klu_l_common* common);

}  // namespace twb
