// The error family (twb/error_family.h, the base layer): each kind of error ends a run
// with its own exit status and words, and an internal error raised where twb hands
// control to SUNDIALS comes back out as itself, not as a failed solve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <string>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "solver/ida_transient.h"
#include "solver/kinsol_newton.h"
#include "study/parallel/parallel.h"
#include "../support/model_problems.h"
#include "twb/error_family.h"
#include "twb/input_error.h"
#include "twb/solver_failure.h"

namespace twb {
namespace {

template <class E>
ErrorReport report_of(const E& error) {
  try {
    throw error;
  } catch (...) {
    return report_error(std::current_exception());
  }
}

TEST(ErrorFamily, EachKindHasItsExitStatusAndWords) {
  const ErrorReport input = report_of(InputError("scene.yaml", 3, 5, "a load must be positive", "  load: -1 N"));
  EXPECT_EQ(input.exit_status(), 2);
  EXPECT_NE(input.message.find("scene.yaml:3:5"), std::string::npos) << input.message;

  const ErrorReport argument = report_of(std::invalid_argument("--slice '0/2': write K/N"));
  EXPECT_EQ(argument.exit_status(), 2);
  EXPECT_EQ(argument.message, "twb: error: --slice '0/2': write K/N");

  const ErrorReport solver = report_of(SolverFailure("no steady state at 300 N", -6));
  EXPECT_EQ(solver.exit_status(), 3);
  EXPECT_EQ(solver.message, "twb: solver failure: no steady state at 300 N");

  // A broken precondition is twb's bug: its own status and the request to report it.
  const ErrorReport internal = report_of(InternalError("FoldSystem: borders of another size"));
  EXPECT_EQ(internal.exit_status(), 4);
  EXPECT_NE(internal.message.find("FoldSystem: borders of another size"), std::string::npos);
  EXPECT_NE(internal.message.find("please report"), std::string::npos) << internal.message;

  // An input or output the system refused is neither the user's nor a bug: its own status,
  // what failed and why, and no request to report it.
  const ErrorReport io = report_of(IoError("cannot write", "out/states.csv", ENOSPC));
  EXPECT_EQ(io.kind, ErrorKind::io);
  EXPECT_EQ(io.exit_status(), 5);
  EXPECT_EQ(io.message, "twb: I/O error: cannot write 'out/states.csv': No space left on device");
  const ErrorReport mpi = report_of(IoError("MPI: MPI_Send failed: MPI_ERR_COMM: invalid communicator"));
  EXPECT_EQ(mpi.exit_status(), 5);
  EXPECT_EQ(mpi.message, "twb: I/O error: MPI: MPI_Send failed: MPI_ERR_COMM: invalid communicator");
  const ErrorReport filesystem = report_of(std::filesystem::filesystem_error(
      "cannot remove all", "out/.twb-journal", std::make_error_code(std::errc::permission_denied)));
  EXPECT_EQ(filesystem.exit_status(), 5);
  EXPECT_NE(filesystem.message.find("out/.twb-journal"), std::string::npos) << filesystem.message;
  for (const ErrorReport* r : {&io, &mpi, &filesystem})
    EXPECT_EQ(r->message.find("report"), std::string::npos) << r->message;

  // Anything else thrown is internal too, whatever its type.
  EXPECT_EQ(report_of(std::out_of_range("index")).exit_status(), 4);
  EXPECT_EQ(report_of(42).exit_status(), 4);
}

// Semenov's problem whose residual throws once it has been evaluated `clean` times: an
// internal error at that one call only (so that nothing after it, outside the C solver,
// throws it again), any other error at every call from then on.
class ThrowingProblem final : public SteadySystem {
 public:
  ThrowingProblem(int clean, bool internal) : problem_(0.2), clean_(clean), internal_(internal) {}
  Index size() const override { return problem_.size(); }
  const SparsePattern& pattern() const override { return problem_.pattern(); }
  void evaluate(std::span<const double> u, std::span<double> r, std::span<double> jac) const override {
    const int call = calls_++;
    if (internal_ && call == clean_) throw InternalError("a broken precondition inside the residual");
    if (!internal_ && call >= clean_) throw std::runtime_error("a recoverable failure inside the residual");
    problem_.evaluate(u, r, jac);
  }
  double parameter() const override { return problem_.parameter(); }
  void set_parameter(double v) override { problem_.set_parameter(v); }
  void parameter_derivative(std::span<const double> u, std::span<double> d) const override {
    problem_.parameter_derivative(u, d);
  }
  std::vector<double> capacities() const override { return problem_.capacities(); }

 private:
  testing::SemenovProblem problem_;
  int clean_;
  bool internal_;
  mutable int calls_ = 0;
};

TEST(ErrorFamily, AnInternalErrorInANewtonCallbackComesBackOutOfKinsol) {
  ThrowingProblem problem(1, true);
  KinsolNewton newton(problem);
  std::vector<double> u{0.5, 1.0};
  EXPECT_THROW(newton.solve(u, NewtonSettings{}), InternalError);
}

TEST(ErrorFamily, AnyOtherErrorInANewtonCallbackIsAFailedSolveWithItsReason) {
  ThrowingProblem problem(1, false);
  KinsolNewton newton(problem);
  std::vector<double> u{0.5, 1.0};
  const NewtonReport rep = newton.solve(u, NewtonSettings{});
  EXPECT_FALSE(rep.converged);
  EXPECT_NE(rep.message.find("a recoverable failure inside the residual"), std::string::npos) << rep.message;
}

TEST(ErrorFamily, AnInternalErrorInATransientCallbackComesBackOutOfIda) {
  ThrowingProblem problem(3, true);
  IdaTransient transient(problem, TransientSettings{});
  const std::vector<double> u{0.25, std::exp(0.25)};
  EXPECT_THROW(
      {
        TransientStatus s = transient.start(0.0, u);
        for (int k = 0; k < 100 && s.ok; ++k) s = transient.step(transient.time() + 1.0);
      },
      InternalError);
}

// A study's searches run on worker threads: an internal error one of them throws must
// reach the caller (an exception leaving a thread ends the process), the lowest piece's
// first, after every piece has run.
TEST(ErrorFamily, AnInternalErrorOnAWorkerThreadReachesTheCaller) {
  std::vector<int> ran(6, 0);
  try {
    run_in_parallel(ran.size(), 2, [&](std::size_t i) {
      ran[i] = 1;
      if (i == 3 || i == 5) throw InternalError("piece " + std::to_string(i));
    });
    ADD_FAILURE() << "no error came back";
  } catch (const InternalError& e) {
    EXPECT_STREQ(e.what(), "piece 3");
  }
  EXPECT_EQ(std::count(ran.begin(), ran.end(), 1), 6);
}

}  // namespace
}  // namespace twb
