// Records as bytes, doubles bit for bit: what one process of a study writes and another,
// or a later run, reads back. The search journal's entries (study/parallel/search_journal.cpp),
// the searches MPI ranks send back (src/cli/mpi_searches.cpp: the same entries), and a
// reliability study's Monte Carlo samples and the states every rank must hold alike
// (study/uncertainty/reliability.cpp) are all made of them.
//
// Each record's fields are listed once, in a `record_fields(a, r)` that the writer and the
// reader both call: a field is written and read in the same place or not at all. The
// bytes are the machine's own (byte order, sizes), for the same build to read: the
// journal's header names the build and the layout, MPI ranks run one program.
#pragma once

#include <concepts>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "twb/results/distress_table.h"
#include "twb/results/states_table.h"
#include "twb/results/trajectory_table.h"

namespace twb {

template <class T>
concept Number = std::is_arithmetic_v<T> || std::is_enum_v<T>;
// S is R, const when written.
template <class S, class R>
concept RecordOf = std::same_as<std::remove_const_t<S>, R>;

// A field added to a state must be listed too, or a resumed run would write it as zero:
// the size fails to compile until its list is extended (the other records' sizes are
// in the journal's header, so an entry of another layout is never read).
static_assert(sizeof(BearingState) == 8 * 31 + 2 * sizeof(std::optional<double>) + sizeof(std::optional<FilmFlows>) +
                  sizeof(std::vector<LimitExcess>) + sizeof(std::vector<ReportedValue>),
              "list every BearingState field (record_bytes.h)");

// Each record's fields, for the writer (S const) and the reader alike.
template <class A, RecordOf<LimitExcess> S>
void record_fields(A& a, S& e) {
  a(e.kind), a(e.value), a(e.limit);
}
template <class A, RecordOf<ReportedValue> S>
void record_fields(A& a, S& v) {
  a(v.column), a(v.value);
}
template <class A, RecordOf<FilmFlows> S>
void record_fields(A& a, S& q) {
  a(q.supplied), a(q.inner), a(q.outer), a(q.grooves);
}
template <class A, RecordOf<BearingState> S>
void record_fields(A& a, S& s) {
  a(s.load), a(s.speed), a(s.washer_mean_temperature), a(s.max_film_temperature), a(s.oil_peak_temperature);
  a(s.hmin_over_sigma);
  a(s.carrier_max_temperature), a(s.washer_max_temperature), a(s.gear_max_temperature);
  a(s.gamma_x_ratio), a(s.gamma_y_ratio), a(s.fluid_force), a(s.contact_force), a(s.fluid_share), a(s.stop_reaction);
  a(s.contact_share), a(s.torque), a(s.f_eff), a(s.stribeck), a(s.friction_coefficient), a(s.friction_clamped);
  a(s.heat_generated), a(s.heat_to_ambient), a(s.energy_error), a(s.force_balance_error);
  a(s.moment_balance_error), a(s.complementarity_error), a(s.max_contact_pressure), a(s.contact_temperature);
  a(s.position.c1), a(s.position.gamma_x), a(s.position.gamma_y), a(s.position.c2), a(s.flows), a(s.limits);
  a(s.reported);
}
template <class A, RecordOf<FilmFields> S>
void record_fields(A& a, S& f) {
  a(f.film), a(f.sliding), a(f.mesh), a(f.gap), a(f.pressure), a(f.contact_pressure), a(f.film_temperature);
  a(f.surface_temperature), a(f.viscosity), a(f.washer_deflection);
}
template <class A, RecordOf<SolvedState> S>
void record_fields(A& a, S& s) {
  a(s.state), a(s.converged), a(s.iterations), a(s.residual), a(s.wall_ms), a(s.parameters), a(s.sliding);
  a(s.branch), a(s.mesh_errors), a(s.fields);
}
template <class A, RecordOf<TrajectorySample> S>
void record_fields(A& a, S& t) {
  a(t.time), a(t.state), a(t.parameters), a(t.sliding), a(t.ambient), a(t.tilt), a(t.least_margin),
      a(t.least_criterion);
}
template <class A, RecordOf<FailureCriterion> S>
void record_fields(A& a, S& c) {
  a(c.distress), a(c.limit);
}
template <class A, RecordOf<LoadConvergence> S>
void record_fields(A& a, S& c) {
  a(c.meshes), a(c.order), a(c.tolerance_met), a(c.why_unmet);
}
template <class A, RecordOf<DistressRow> S>
void record_fields(A& a, S& r) {
  a(r.speed), a(r.parameters), a(r.distress_load), a(r.bracket_low), a(r.bracket_high), a(r.fold_load);
  a(r.fine_fold_load), a(r.extrapolated_load), a(r.discretization_error), a(r.method), a(r.sliding);
  a(r.failure_load), a(r.criterion), a(r.failure);
  for (auto& load : r.criterion_loads) a(load);
  for (auto& error : r.criterion_errors) a(error);
  a(r.failure_extrapolated), a(r.failure_error), a(r.verdict);
  for (auto& load : r.criterion_extrapolated) a(load);
  a(r.fold_convergence), a(r.failure_convergence);
}

// A value to read a record into: a film's fields have no default mesh.
template <class T>
T blank_record() {
  return T{};
}
template <>
FilmFields blank_record<FilmFields>();

class RecordWriter {
 public:
  template <Number T>
  void operator()(T v) {
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void operator()(const std::string& s);
  void operator()(const FilmMesh& m);
  template <class T>
  void operator()(const std::optional<T>& v) {
    (*this)(v.has_value());
    if (v) (*this)(*v);
  }
  template <class T>
  void operator()(const std::vector<T>& v) {
    count(v.size());
    for (const T& x : v) (*this)(x);
  }
  template <class T>
    requires requires(RecordWriter& a, const T& r) { record_fields(a, r); }
  void operator()(const T& r) {
    record_fields(*this, r);
  }
  // How many of something follow (a container's length).
  void count(std::size_t n) { (*this)(std::uint64_t(n)); }
  const std::string& bytes() const { return bytes_; }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

// Reads what a RecordWriter wrote, in the same order. Bytes that end early or cannot be
// what was written throw std::runtime_error naming `what` ("a journal entry ends early").
class RecordReader {
 public:
  // `bytes` are not copied: they outlive the reader.
  RecordReader(std::string_view bytes, std::string what) : bytes_(bytes), what_(std::move(what)) {}
  RecordReader(std::string&& bytes, std::string what) = delete;
  template <Number T>
  void operator()(T& v) {
    raw(&v, sizeof v);
  }
  void operator()(bool& v);
  void operator()(std::string& s);
  void operator()(FilmMesh& m);
  template <class T>
  void operator()(std::optional<T>& v) {
    bool has = false;
    (*this)(has);
    v.reset();
    if (has) (*this)(v.emplace());
  }
  template <class T>
  void operator()(std::vector<T>& v) {
    const std::size_t n = count();
    v.clear();
    for (std::size_t k = 0; k < n; ++k) {
      T x = blank_record<T>();
      (*this)(x);
      v.push_back(std::move(x));
    }
  }
  template <class T>
    requires requires(RecordReader& a, T& r) { record_fields(a, r); }
  void operator()(T& r) {
    record_fields(*this, r);
  }
  // A count RecordWriter::count wrote; refused where more would follow than the bytes left.
  std::size_t count();
  bool done() const { return at_ == bytes_.size(); }
  // Every byte read: refused where some are left over.
  void finish() const;
  // `what`, damaged: the error to throw for a value read that cannot be.
  [[noreturn]] void damaged() const;

 private:
  void raw(void* p, std::size_t n);
  std::string_view bytes_;
  std::string what_;
  std::size_t at_ = 0;
};

}  // namespace twb
