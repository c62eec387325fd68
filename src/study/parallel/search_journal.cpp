#include "study/parallel/search_journal.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "results/atomic_file.h"
#include "results/record_bytes.h"

namespace twb {

namespace {

namespace fs = std::filesystem;

// The format, the program's version and the journaled structs' layout: an entry written
// by another build is not read (its search runs again) rather than misread.
const std::string kMagic = fmt::format("twb-search-journal 12 {} {} {} {} {} {}\n", TWB_VERSION, sizeof(BearingState),
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

// The entry's fields after its header, for writing and reading alike (S is const when
// writing); the records' own are record_bytes.h's.
template <class A, class S>
void fields_of_search(A& a, S& j) {
  auto& f = j.found;
  a(f.states), a(f.cool_states), a(f.row), a(f.runaway), a(f.failed), a(f.start_past_distress), a(f.fold_proven);
  a(f.message), a(f.counts.stability_tests), a(f.counts.transients), a(f.counts.ida_steps);
  a(f.counts.ida_factorizations), a(f.counts.klu_factorizations), a(f.diagnostics), a(j.klu_factorizations);
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path entry_path(const fs::path& dir, std::size_t search) { return dir / fmt::format("search-{:05d}", search); }

}  // namespace

SearchJournal::SearchJournal(const fs::path& results, const std::string& scene, bool resume, const std::string& worn)
    : dir_(results / ".twb-journal") {
  const fs::path name = dir_ / "scene.yaml", washer = dir_ / "worn_washer.txt";
  if (resume && fs::exists(name)) {
    if (without_comments(read_file(name)) != without_comments(scene))
      throw std::invalid_argument(fmt::format("cannot resume: the journal in '{}' belongs to another scene (or other "
                                              "--set values); run without --resume to start afresh",
                                              results.string()));
    // (a journal from before worn washers were journaled has none: a new washer's)
    const std::string journaled = fs::exists(washer) ? read_file(washer) : std::string();
    if (journaled != worn)
      throw std::invalid_argument(fmt::format(
          "cannot resume: the journal in '{}' was written for {} and this run is of {}: give the same "
          "--continue-from as the run it resumes, or run without --resume to start afresh",
          results.string(), journaled.empty() ? "a new washer" : "a worn washer (--continue-from)",
          worn.empty() ? "a new washer" : journaled.empty() ? "a worn washer" : "another worn washer"));
    return;
  }
  fs::remove_all(dir_);
  write_file_atomically(name, scene);
  if (!worn.empty()) write_file_atomically(washer, worn);
}

std::string SearchJournal::worn_identity(const WornWasher& worn) {
  std::string text = fmt::format("{:.17g} {} {:.17g} {:.17g} {} {}\n", worn.time, worn.film, worn.inner_radius,
                                 worn.outer_radius, worn.radial_nodes, worn.circumferential_nodes);
  for (const double d : worn.rest) text += fmt::format("{:.17g}\n", d);
  for (const double d : worn.turn) text += fmt::format("{:.17g}\n", d);
  return text;
}

std::string journal_entry(const DistressSearch& found, long klu_factorizations) {
  RecordWriter out;
  out(kMagic);
  const struct {
    const DistressSearch& found;
    long klu_factorizations;
  } entry{found, klu_factorizations};
  fields_of_search(out, entry);
  return out.take();
}

std::optional<JournaledSearch> read_journal_entry(const std::string& bytes) {
  try {
    RecordReader in(bytes, "a journal entry");
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

std::vector<std::size_t> SearchJournal::entries() const { return entries_in(dir_.parent_path()); }

std::vector<std::size_t> SearchJournal::entries_in(const fs::path& results) {
  const fs::path dir = results / ".twb-journal";
  std::vector<std::size_t> found;
  if (!fs::is_directory(dir)) return found;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
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
