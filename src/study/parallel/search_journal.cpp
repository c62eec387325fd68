#include "study/parallel/search_journal.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

#include "results/atomic_file.h"

namespace twb {

namespace {

namespace fs = std::filesystem;

// A field added to a state must be journaled too, or a resumed run would write it as
// zero: the size fails to compile until fields_of_state is extended (the other structs'
// sizes are in kMagic, so an entry of another layout is never read).
static_assert(sizeof(BearingState) == 8 * 31 + 3 * sizeof(std::optional<double>) + sizeof(std::optional<FilmFlows>) +
                  sizeof(std::vector<LimitExcess>),
              "journal every BearingState field (search_journal.cpp)");

// The format, the program's version and the journaled structs' layout: an entry written
// by another build is not read (its search runs again) rather than misread.
const std::string kMagic = fmt::format("twb-search-journal 10 {} {} {} {} {} {}\n", TWB_VERSION, sizeof(BearingState),
                                       sizeof(SolvedState), sizeof(DistressRow), sizeof(TrajectorySample),
                                       sizeof(SearchCounts));

// The resolved scene without its comments: they name the file as typed, which may
// differ between a run and its resume (a relative path, another directory).
std::string without_comments(const std::string& scene) {
  std::stringstream in(scene);
  std::string out;
  for (std::string line; std::getline(in, line);)
    if (line.find_first_not_of(' ') == std::string::npos || line[line.find_first_not_of(' ')] != '#') out += line + "\n";
  return out;
}

// One list of the fields of each journaled struct, for writing and reading alike: a
// field is written and read in the same place or not at all. S is const when writing.
template <class A, class S>
void fields_of_limit(A& a, S& e) {
  a(e.kind), a(e.value), a(e.limit);
}
template <class A, class S>
void fields_of_state(A& a, S& s) {
  a(s.load), a(s.speed), a(s.washer_mean_temperature), a(s.max_film_temperature), a(s.oil_peak_temperature);
  a(s.hmin_over_sigma);
  a(s.carrier_max_temperature), a(s.washer_max_temperature), a(s.gear_max_temperature);
  a(s.gamma_x_ratio), a(s.gamma_y_ratio), a(s.fluid_force), a(s.contact_force), a(s.fluid_share), a(s.stop_reaction);
  a(s.contact_share), a(s.torque), a(s.f_eff), a(s.stribeck), a(s.friction_coefficient), a(s.friction_clamped);
  a(s.heat_generated), a(s.heat_to_ambient), a(s.energy_error), a(s.heat_carried), a(s.force_balance_error);
  a(s.moment_balance_error), a(s.complementarity_error), a(s.max_contact_pressure), a(s.contact_temperature);
  a(s.position.c1), a(s.position.gamma_x), a(s.position.gamma_y), a(s.position.c2), a(s.flows), a(s.limits);
}
template <class A, class S>
void fields_of_flows(A& a, S& q) {
  a(q.supplied), a(q.inner), a(q.outer), a(q.grooves);
}
template <class A, class S>
void fields_of_film(A& a, S& f) {
  a(f.film), a(f.sliding), a(f.mesh), a(f.gap), a(f.pressure), a(f.contact_pressure), a(f.film_temperature);
  a(f.surface_temperature), a(f.viscosity);
}
template <class A, class S>
void fields_of_solved(A& a, S& s) {
  a(s.state), a(s.converged), a(s.iterations), a(s.residual), a(s.wall_ms), a(s.parameters), a(s.sliding);
  a(s.branch), a(s.mesh_errors), a(s.fields);
}
template <class A, class S>
void fields_of_sample(A& a, S& t) {
  a(t.time), a(t.state), a(t.parameters), a(t.sliding), a(t.ambient), a(t.tilt), a(t.least_margin),
      a(t.least_criterion);
}
template <class A, class S>
void fields_of_row(A& a, S& r) {
  a(r.speed), a(r.parameters), a(r.distress_load), a(r.bracket_low), a(r.bracket_high), a(r.fold_load);
  a(r.fine_fold_load), a(r.extrapolated_load), a(r.discretization_error), a(r.method), a(r.sliding);
  a(r.failure_load), a(r.criterion), a(r.failure);
  for (auto& load : r.criterion_loads) a(load);
  for (auto& error : r.criterion_errors) a(error);
  a(r.failure_extrapolated), a(r.failure_error), a(r.verdict);
  for (auto& load : r.criterion_extrapolated) a(load);
  a(r.fold_convergence), a(r.failure_convergence);
}
template <class A, class S>
void fields_of_convergence(A& a, S& c) {
  a(c.meshes), a(c.order), a(c.tolerance_met), a(c.why_unmet);
}
template <class A, class S>
void fields_of_search(A& a, S& j) {
  auto& f = j.found;
  a(f.states), a(f.cool_states), a(f.row), a(f.runaway), a(f.failed), a(f.start_past_distress), a(f.fold_proven);
  a(f.message), a(f.counts.stability_tests), a(f.counts.transients), a(f.counts.ida_steps);
  a(f.counts.ida_factorizations), a(f.counts.klu_factorizations), a(f.diagnostics), a(j.klu_factorizations);
}

class Out {
 public:
  template <class T>
    requires std::is_arithmetic_v<T> || std::is_enum_v<T>
  void operator()(T v) { bytes_.append(reinterpret_cast<const char*>(&v), sizeof v); }
  void operator()(const std::string& s) {
    (*this)(std::uint64_t(s.size()));
    bytes_.append(s);
  }
  template <class T>
  void operator()(const std::optional<T>& v) {
    (*this)(v.has_value());
    if (v) (*this)(*v);
  }
  void operator()(const FailureCriterion& c) { (*this)(c.distress), (*this)(c.limit); }
  template <class T>
  void operator()(const std::vector<T>& v) {
    (*this)(std::uint64_t(v.size()));
    for (const T& x : v) (*this)(x);
  }
  void operator()(const FilmMesh& m) {
    (*this)(m.inner_radius()), (*this)(m.outer_radius()), (*this)(m.radial_nodes()), (*this)(m.circumferential_nodes());
  }
  void operator()(const LimitExcess& e) { fields_of_limit(*this, e); }
  void operator()(const FilmFlows& q) { fields_of_flows(*this, q); }
  void operator()(const BearingState& s) { fields_of_state(*this, s); }
  void operator()(const FilmFields& f) { fields_of_film(*this, f); }
  void operator()(const SolvedState& s) { fields_of_solved(*this, s); }
  void operator()(const TrajectorySample& t) { fields_of_sample(*this, t); }
  void operator()(const DistressRow& r) { fields_of_row(*this, r); }
  void operator()(const LoadConvergence& c) { fields_of_convergence(*this, c); }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

// A value to read into (a film's fields have no default mesh).
template <class T>
T blank() {
  return T{};
}
template <>
FilmFields blank<FilmFields>() {
  return FilmFields{1, false, FilmMesh(0.0, 1.0, 3, 8), {}, {}, {}, {}, {}, {}};
}

class In {
 public:
  explicit In(std::string bytes) : bytes_(std::move(bytes)) {}
  template <class T>
    requires std::is_arithmetic_v<T> || std::is_enum_v<T>
  void operator()(T& v) { raw(&v, sizeof v); }
  void operator()(std::string& s) {
    std::uint64_t n = 0;
    (*this)(n);
    if (n > bytes_.size() - at_) throw std::runtime_error("a journal entry ends early");
    s.assign(bytes_.data() + at_, n);
    at_ += n;
  }
  template <class T>
  void operator()(std::optional<T>& v) {
    bool has = false;
    (*this)(has);
    v.reset();
    if (has) (*this)(v.emplace());
  }
  void operator()(FailureCriterion& c) { (*this)(c.distress), (*this)(c.limit); }
  template <class T>
  void operator()(std::vector<T>& v) {
    std::uint64_t n = 0;
    (*this)(n);
    if (n > bytes_.size()) throw std::runtime_error("a journal entry is damaged");
    v.clear();
    for (std::uint64_t k = 0; k < n; ++k) {
      T x = blank<T>();
      (*this)(x);
      v.push_back(std::move(x));
    }
  }
  void operator()(FilmMesh& m) {
    double r_in = 0, r_out = 0;
    int nr = 0, nt = 0;
    (*this)(r_in), (*this)(r_out), (*this)(nr), (*this)(nt);
    m = FilmMesh(r_in, r_out, nr, nt);
  }
  void operator()(LimitExcess& e) { fields_of_limit(*this, e); }
  void operator()(FilmFlows& q) { fields_of_flows(*this, q); }
  void operator()(BearingState& s) { fields_of_state(*this, s); }
  void operator()(FilmFields& f) { fields_of_film(*this, f); }
  void operator()(SolvedState& s) { fields_of_solved(*this, s); }
  void operator()(TrajectorySample& t) { fields_of_sample(*this, t); }
  void operator()(DistressRow& r) { fields_of_row(*this, r); }
  void operator()(LoadConvergence& c) { fields_of_convergence(*this, c); }
  bool done() const { return at_ == bytes_.size(); }

 private:
  void raw(void* p, std::size_t n) {
    if (at_ + n > bytes_.size()) throw std::runtime_error("a journal entry ends early");
    std::memcpy(p, bytes_.data() + at_, n);
    at_ += n;
  }
  std::string bytes_;
  std::size_t at_ = 0;
};

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path entry_path(const fs::path& dir, std::size_t search) { return dir / fmt::format("search-{:05d}", search); }

}  // namespace

SearchJournal::SearchJournal(const fs::path& results, const std::string& scene, bool resume)
    : dir_(results / ".twb-journal") {
  const fs::path name = dir_ / "scene.yaml";
  if (resume && fs::exists(name)) {
    if (without_comments(read_file(name)) != without_comments(scene))
      throw std::invalid_argument(fmt::format("cannot resume: the journal in '{}' belongs to another scene (or other "
                                              "--set values); run without --resume to start afresh",
                                              results.string()));
    return;
  }
  fs::remove_all(dir_);
  write_file_atomically(name, scene);
}

std::string journal_entry(const DistressSearch& found, long klu_factorizations) {
  Out out;
  out(std::string(kMagic));
  const struct {
    const DistressSearch& found;
    long klu_factorizations;
  } entry{found, klu_factorizations};
  fields_of_search(out, entry);
  return out.bytes();
}

std::optional<JournaledSearch> read_journal_entry(const std::string& bytes) {
  try {
    In in(bytes);
    std::string magic;
    in(magic);
    if (magic != kMagic) return std::nullopt;  // another version's: run the search again
    JournaledSearch j;
    fields_of_search(in, j);
    if (!in.done()) return std::nullopt;
    return j;
  } catch (const std::exception&) {
    return std::nullopt;  // damaged: run the search again
  }
}

std::optional<JournaledSearch> SearchJournal::read(std::size_t search) const {
  try {
    const fs::path p = entry_path(dir_, search);
    if (!fs::exists(p)) return std::nullopt;
    return read_journal_entry(read_file(p));
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable: run the search again
  }
}

void SearchJournal::write(std::size_t search, const DistressSearch& found, long klu_factorizations) const {
  write_entry(search, journal_entry(found, klu_factorizations));
}

void SearchJournal::write_entry(std::size_t search, const std::string& entry) const {
  try {
    write_file_atomically(entry_path(dir_, search), entry);
  } catch (const std::exception&) {
    // The journal only spares a resume work: a full disk must not end the study (its
    // results are written at the end, and fail there with the reason if it is still full).
  }
}

std::vector<std::size_t> SearchJournal::entries() const {
  std::vector<std::size_t> found;
  if (!fs::is_directory(dir_)) return found;
  for (const fs::directory_entry& e : fs::directory_iterator(dir_)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("search-", 0) == 0 && name.size() > 7 && name.find_first_not_of("0123456789", 7) == std::string::npos)
      found.push_back(std::size_t(std::stoull(name.substr(7))));
  }
  std::sort(found.begin(), found.end());
  return found;
}

bool SearchJournal::same_scene(const std::string& a, const std::string& b) {
  return without_comments(a) == without_comments(b);
}

std::string SearchJournal::entry_bytes(std::size_t search) const { return read_file(entry_path(dir_, search)); }

std::optional<std::string> SearchJournal::scene_of(const fs::path& results) {
  const fs::path name = results / ".twb-journal" / "scene.yaml";
  if (!fs::exists(name)) return std::nullopt;
  return read_file(name);
}

void SearchJournal::finish() const { fs::remove_all(dir_); }

}  // namespace twb
