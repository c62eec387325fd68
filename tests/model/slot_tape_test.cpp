// The slot tape of sparse_assembly.h: a recorded pass places entries without searching,
// and a pass that leaves it still lands every entry where the search would.
#include <gtest/gtest.h>

#include <stdexcept>
#include <utility>
#include <vector>

#include "model/sparse_assembly.h"

namespace twb {
namespace {

// A 3×3 pattern with entries (0,0) (0,2) (1,1) (2,0) (2,2).
SparsePattern small_pattern() {
  Assembler structure(3);
  for (auto [r, c] : {std::pair{0, 2}, {2, 0}, {1, 1}}) structure.add_derivative(r, c, 0.0);
  return structure.finish_structure();
}

void add_sequence(Assembler& a) {
  a.add_derivative(0, 2, 1.0);
  a.add_derivative(2, 0, 2.0);
  a.add_derivative(0, 0, 3.0);
  a.add_derivative(2, 0, 4.0);  // repeated entries add up
}

// The sequence's tape, and the values it assembles by search into jacobian.
SlotTape recorded_tape(const SparsePattern& p, std::vector<double>& jacobian) {
  std::vector<double> r(std::size_t(p.rows));
  jacobian.assign(std::size_t(p.nnz()), 0.0);
  SlotTape tape;
  Assembler recorder(&p, r, jacobian, nullptr, &tape);  // no tape: the pass records its own
  add_sequence(recorder);
  return tape;
}

TEST(SlotTape, ReplayPlacesEntriesLikeTheSearch) {
  const SparsePattern p = small_pattern();
  std::vector<double> r(3), searched, replayed(std::size_t(p.nnz()));
  const SlotTape tape = recorded_tape(p, searched);
  EXPECT_EQ(tape.size(), 4u);
  Assembler replay(&p, r, replayed, &tape);
  add_sequence(replay);
  EXPECT_TRUE(replay.on_tape());
  EXPECT_EQ(replayed, searched);
}

TEST(SlotTape, LeavingTheTapeStillPlacesEveryEntry) {
  const SparsePattern p = small_pattern();
  std::vector<double> r(3), expected, got(std::size_t(p.nnz()));
  const SlotTape tape = recorded_tape(p, expected);
  // Another order than recorded: the first mismatch drops the tape.
  Assembler a(&p, r, got, &tape);
  a.add_derivative(0, 2, 1.0);
  a.add_derivative(0, 0, 3.0);  // the tape expected (2, 0) here
  EXPECT_FALSE(a.on_tape());
  a.add_derivative(2, 0, 2.0);
  a.add_derivative(2, 0, 4.0);
  EXPECT_EQ(got, expected);
  EXPECT_THROW(a.add_derivative(1, 0, 1.0), std::logic_error);  // outside the pattern
}

// The structure pass records every contribution, repeats and all: each entry appears
// once in its row, the row's columns in order, every diagonal among them.
TEST(SlotTape, StructureHoldsEachEntryOnceInOrder) {
  Assembler structure(3);
  for (auto [r, c] : {std::pair{0, 2}, {2, 0}, {0, 2}, {2, 1}, {0, 1}, {2, 0}, {0, 2}}) structure.add_derivative(r, c, 0.0);
  const SparsePattern p = structure.finish_structure();
  EXPECT_EQ(p.row_start, (std::vector<Index>{0, 3, 4, 7}));
  EXPECT_EQ(p.column, (std::vector<Index>{0, 1, 2, 1, 0, 1, 2}));
}

// The structure pass's own tape (finish_structure) is the one a searching value pass of
// the same sequence records: repeats, the diagonals the pattern adds, rows out of order.
TEST(SlotTape, TheStructureTapeIsTheSearchedOne) {
  Assembler structure(3);
  add_sequence(structure);
  SlotTape from_structure;
  const SparsePattern p = structure.finish_structure(&from_structure);
  std::vector<double> searched;
  EXPECT_EQ(from_structure, recorded_tape(p, searched));
}

// A pass that leaves its tape hands back the tape of its own sequence: the part it
// replayed, then the slots it searched for. The next pass of that sequence replays it
// whole and assembles what the search did; a pass that stays on its tape hands back
// nothing.
TEST(SlotTape, APassOffItsTapeHandsBackItsOwn) {
  const SparsePattern p = small_pattern();
  std::vector<double> r(3), expected;
  const SlotTape tape = recorded_tape(p, expected);
  auto other_sequence = [](Assembler& a) {
    a.add_derivative(0, 2, 1.0);
    a.add_derivative(0, 0, 3.0);  // the tape expected (2, 0) here
    a.add_derivative(2, 0, 2.0);
    a.add_derivative(2, 0, 4.0);
  };
  std::vector<double> first(std::size_t(p.nnz()));
  SlotTape retaped;
  Assembler off(&p, r, first, &tape, &retaped);
  other_sequence(off);
  EXPECT_FALSE(off.on_tape());
  ASSERT_EQ(retaped.size(), 4u);
  EXPECT_EQ(retaped[0], tape[0]);
  std::vector<double> second(std::size_t(p.nnz()));
  SlotTape unused{42};
  Assembler on(&p, r, second, &retaped, &unused);
  other_sequence(on);
  EXPECT_TRUE(on.on_tape());
  EXPECT_TRUE(unused.empty());
  EXPECT_EQ(second, expected);
  EXPECT_EQ(first, expected);
}

}  // namespace
}  // namespace twb
