// A study type as the runner sees it: how it runs, the tables it writes after
// states.csv, and what its work is made of. Each type is one file in study/types/
// (its runner and its descriptor), registered in study_kinds.cpp; the scene side of a
// type (its keys, their checks, its written-back section) is the scene reader's.
#pragma once

#include <vector>

#include "model/bearing_model.h"
#include "study/searches/study_searches.h"
#include "twb/study/study_outcome.h"

namespace twb {

// What a study is run with, as run_study resolved it.
struct StudyRun {
  const ProgressReport& progress;
  int threads = 1;  // at least one
  Running how;      // threads, resume journal, scheduler, stop: for independent searches (and
                    // the scheduler for a reliability study's Monte Carlo batches)
  const CycleState* cycle_start = nullptr;  // a duty cycle continued from an earlier one's end
};

// A trait no settings of the type have.
inline bool for_no_settings(const Study&) { return false; }
inline bool for_all_settings(const Study&) { return true; }

struct StudyKind {
  void (*run)(BearingModel& model, StudyOutcome& out, const StudyRun& run) = nullptr;
  // The tables the type writes after states.csv, in the order the results directory
  // and Python list them (a trajectory the type leaves out is added after them where
  // the study has one: study_tables).
  void (*add_tables)(const StudyOutcome& out, std::vector<NamedTable>& tables) = nullptr;
  // Its searches run on worker threads (run_searches, a family's curves) and count their
  // own factorizations, and its Newton iterations are those that solved the reported
  // states; the other types are counted round the whole run.
  bool searches_count_their_work = false;
  // Made of independent distress searches: what threads, MPI ranks and the slices of a
  // job array share out, and what RunOptions::stop can stop between.
  bool (*independent_searches)(const Study& study) = for_no_settings;
  // Its work spreads over the ranks of an MPI job beyond its independent searches (a
  // reliability study's Monte Carlo batches, which the slices of a job array cannot take).
  bool (*spreads_over_ranks)(const Study& study) = for_no_settings;
  // It can go on from where an earlier run of its type ended (RunOptions::cycle_start).
  bool continues_from = false;
};

const StudyKind& study_kind(StudyType type);

// Tables more than one type writes, with their type's columns.
void add_distress_table(const StudyOutcome& out, std::vector<NamedTable>& tables);
void add_distress_table_if_any(const StudyOutcome& out, std::vector<NamedTable>& tables);

}  // namespace twb
