// The journal of a study's finished distress searches, so that a run killed outright
// (kill -9, a node lost) resumes where it stopped: `twb run SCENE --out DIR --resume`.
// Each search the study hands over (run_searches: one per speed and parameter value or
// sliding film) is written at once, atomically, to DIR/.twb-journal/search-K, with
// every field the study's files are made of, doubles bit for bit. On resume the
// journaled searches are read instead of run and the others run, so the files end as an
// uninterrupted run's (its measured times aside). The journal names the scene it
// belongs to and is refused for another; it is removed once the run's files are
// written. Studies of one search (point, transient, curve) have nothing to resume and
// run again.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "study/searches/distress_search.h"
#include "twb/scene/worn_washer.h"

namespace twb {

struct JournaledSearch {
  DistressSearch found;  // states, cool_states, row, runaway, failed, flags, message, counts, diagnostics
  long klu_factorizations = 0;
};

// A search as one journal entry: every field, doubles bit for bit, with the format's and
// the build's signature; what an MPI rank sends the rank that writes. Read back: none for
// another build's entry or a damaged one.
std::string journal_entry(const DistressSearch& found, long klu_factorizations);
std::optional<JournaledSearch> read_journal_entry(const std::string& entry);

class SearchJournal {
 public:
  // The journal in `results`; `scene` (the resolved scene's text) names the run, and
  // `worn` the worn washer it holds (worn_identity(); empty for a new one: the scene's
  // text only names it in a comment). With resume, an existing journal of this scene and
  // washer is kept and read (std::invalid_argument for another's); without, any journal
  // there is discarded.
  SearchJournal(const std::filesystem::path& results, const std::string& scene, bool resume,
                const std::string& worn = {});
  // A worn washer (--continue-from) as the journal tells runs apart: every depth to 17
  // digits, with its time, film and grid.
  static std::string worn_identity(const WornWasher& worn);

  std::optional<JournaledSearch> read(std::size_t search) const;
  void write(std::size_t search, const DistressSearch& found, long klu_factorizations) const;
  // An entry as journal_entry() made it (another process's search).
  void write_entry(std::size_t search, const std::string& entry) const;
  // The searches journaled so far, and one's entry as it is stored (twb merge).
  std::vector<std::size_t> entries() const;
  std::string entry_bytes(std::size_t search) const;
  // The searches journaled in a results directory (none without a journal).
  static std::vector<std::size_t> entries_in(const std::filesystem::path& results);
  // The resolved scene a results directory's journal belongs to; none without a journal.
  static std::optional<std::string> scene_of(const std::filesystem::path& results);
  // Whether two resolved scenes are the same run's (their comments, which name the file as
  // typed, aside).
  static bool same_scene(const std::string& a, const std::string& b);
  // The run's files are written: nothing left to resume.
  void finish() const;

 private:
  std::filesystem::path dir_;
};

}  // namespace twb
