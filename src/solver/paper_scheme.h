// The paper's own algorithm (Jackson & Green 2006, "Integrated Numerical Scheme and
// Convergence", Fig. 5) on twb's discretization, as a selectable solver
// (`solver.method: paper`) and the baseline twb's monolithic Newton is raced against.
//
//  - Outer: Newton–Raphson on the four rigid-body unknowns (z_w, γx, γy, z_g) for the
//    force and moment balances [34]-[37], their derivatives by the centred five-point
//    differences of eq. [38], from the paper's initial state (h_min/σ = 3, ambient
//    temperature, p = 0).
//  - Inner, at each rigid-body position the outer iteration asks about: the coupled loop
//    of the flow chart until pressures and temperatures have converged: the Reynolds
//    equation by Gauss–Seidel over-relaxation with the Reynolds cavitation condition
//    (projected SOR: p ≥ 0 kept by projection at every node update), the heat balance by
//    Gauss–Seidel; each field's coefficients (conductances, viscosities, heat sources)
//    frozen while it is swept, and updated between sweeps of the loop.
//
// The fields are swept on the same equations twb's Newton solves (the system's rows and
// their exact Jacobian; the pressure rows as plain flow balances, linear in p for a given
// film and viscosity, so the sweeps are SOR on the discretized Reynolds equation itself),
// so both schemes converge to the same state, to the tolerance.
#pragma once

#include <string>
#include <vector>

#include "system/segregated_system.h"

namespace twb {

// How the heat field is solved inside the coupled loop. The paper's Gauss–Seidel
// converges node by node only while every film is open: where a film closes (on the
// paper's case film 2, washer on gear, carries its load by contact), its film-node
// temperature links the two surfaces through a resistance of the average gap alone
// (heat_balance.cpp), the link's conductance grows to 1e8 times the row's scale, and
// point Gauss–Seidel's rate tends to one: on the 5×24 mesh at 545 rad/s it stalled at a
// residual of 2 K after 20000 sweeps. The direct solve factors the same conduction
// matrix instead: a baseline faster than the paper's own, never slower.
enum class PaperHeatSolver { gauss_seidel, direct };

struct PaperSchemeSettings {
  // Converged when every row is within this: the same max-norm of the scaled residual as
  // twb's Newton (the pressure rows as the complementarity min(p̂, ŵ)).
  double residual_tolerance = 1e-10;
  // ω of the pressure's projected SOR, and of the heat's Gauss–Seidel (1: the paper's).
  double pressure_over_relaxation = 1.7;
  double heat_over_relaxation = 1.0;
  PaperHeatSolver heat_solver = PaperHeatSolver::direct;
  // A field's sweeps stop once its linearized residual has fallen by this factor (or
  // below a tenth of the tolerance): the loop updates the coefficients anyway.
  double sweep_reduction = 1e-3;
  int max_sweeps = 2000;
  int max_coupled_iterations = 500;
  int max_newton_iterations = 100;
  // Δx of eq. [38], in the rigid unknowns' scaled units (clearances in σ, tilts in γ_ref).
  // 1e-3 crosses the cavitation boundary's kinks and Newton–Raphson converges only
  // linearly (27 iterations at 136 rad/s, 300 N on 5×24); 1e-5 keeps it quadratic (7),
  // with a differencing error of the coupled loop's tolerance over Δx, 1e-5 relative.
  double difference_step = 1e-5;
  // The largest Newton–Raphson step in any rigid unknown, in the same units (as twb's
  // Newton's); longer steps are scaled down, and a step whose coupled loop does not
  // converge or that does not lower the balances is halved.
  double max_rigid_step = 20.0;
};

struct PaperSchemeReport {
  bool converged = false;
  std::string message;
  double residual_norm = 0.0;   // max-norm of the scaled residual (complementarity rows) at the end
  long newton_iterations = 0;   // outer iterations
  long inner_solves = 0;        // coupled loops run to convergence (17 per outer iteration)
  long coupled_iterations = 0;  // passes of the loop over both fields
  long pressure_sweeps = 0, heat_sweeps = 0;
  long evaluations = 0;         // residual and Jacobian assemblies of the system
};

// From u (on entry the start, the paper's cold start for its algorithm) to a steady
// state at the system's parameter; u holds the last iterate either way.
PaperSchemeReport solve_by_paper_scheme(SegregatedSystem& system, std::vector<double>& u,
                                        const PaperSchemeSettings& settings = {});

}  // namespace twb
