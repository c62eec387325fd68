// The records' bytes, which the search journal, MPI ranks and a reliability study's
// samples share: every field comes back as written, the layout an existing journal holds
// does not move, and damaged bytes are refused by name.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "results/record_bytes.h"

namespace twb {
namespace {

SolvedState a_solved_state() {
  SolvedState s;
  s.state.load = 115.0;
  s.state.speed = 0.1 + 0.2;  // a double that is not its decimal
  s.state.reported = {{"heat_carried_W", 3.5}, {"toy_um", 0.1 + 0.7}};
  s.state.flows = FilmFlows{1e-6, 2e-6, 3e-6, 4e-6};
  s.state.limits.push_back(LimitExcess{LimitKind::oil_temperature, 420.0, 410.0});
  s.converged = true;
  s.iterations = 7;
  s.parameters = {1.0, -2.5};
  s.sliding = SlidingFilm::washer_gear;
  s.branch = Branch::hot;
  FilmFields f{2, true, FilmMesh(0.01, 0.02, 3, 8), {}, {}, {}, {}, {}, {}, {}};
  f.gap.assign(24, 1e-5);
  f.pressure.assign(24, 2e5);
  f.washer_deflection.assign(24, -1e-6);
  s.fields.push_back(f);
  return s;
}

TEST(RecordBytes, EveryFieldComesBackAsWritten) {
  RecordWriter out;
  out(a_solved_state());
  const std::string bytes = out.take();
  SolvedState back;
  RecordReader in(bytes, "a test record");
  in(back);
  EXPECT_TRUE(in.done());
  EXPECT_EQ(back.state.speed, 0.1 + 0.2);
  ASSERT_TRUE(back.state.flows);
  EXPECT_EQ(back.state.flows->grooves, 4e-6);
  ASSERT_EQ(back.state.limits.size(), 1u);
  EXPECT_EQ(back.state.limits[0].kind, LimitKind::oil_temperature);
  ASSERT_EQ(back.state.reported.size(), 2u);
  EXPECT_EQ(back.state.reported[1].column, "toy_um");
  EXPECT_EQ(back.state.reported_value("toy_um"), 0.1 + 0.7);
  EXPECT_EQ(back.sliding, SlidingFilm::washer_gear);
  EXPECT_EQ(back.branch, Branch::hot);
  ASSERT_EQ(back.fields.size(), 1u);
  EXPECT_EQ(back.fields[0].mesh.circumferential_nodes(), 8);
  EXPECT_EQ(back.fields[0].pressure, std::vector<double>(24, 2e5));
  EXPECT_EQ(back.fields[0].washer_deflection, std::vector<double>(24, -1e-6));
  // Written again, the same bytes: nothing was left out on the way back.
  RecordWriter again;
  again(back);
  EXPECT_EQ(again.bytes(), bytes);
}

// The journal's entries are these bytes: a change here is a change of its format (and of
// kMagic's version in search_journal.cpp).
TEST(RecordBytes, LayoutIsTheJournals) {
  LoadConvergence c;
  c.meshes = "ab";
  c.order = 2.0;
  RecordWriter out;
  out(c);
  std::string expected;
  const std::uint64_t two = 2;
  const double order = 2.0;
  expected.append(reinterpret_cast<const char*>(&two), 8).append("ab");
  expected.append(1, '\1').append(reinterpret_cast<const char*>(&order), 8);
  expected.append(1, '\0');  // tolerance_met: none
  expected.append(8, '\0');  // why_unmet: empty
  EXPECT_EQ(out.bytes(), expected);
}

TEST(RecordBytes, DamagedBytesAreRefusedByName) {
  RecordWriter out;
  out(a_solved_state());
  const std::string bytes = out.bytes();
  SolvedState back;
  RecordReader short_one(std::string_view(bytes).substr(0, bytes.size() - 1), "a journal entry");
  try {
    short_one(back);
    FAIL() << "read past the end";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "a journal entry ends early");
  }
  // A length longer than what follows.
  std::string long_count(8, '\0');
  const std::uint64_t n = 1000;
  std::memcpy(long_count.data(), &n, sizeof n);
  std::vector<double> v;
  RecordReader counted(long_count, "sample 3's message");
  EXPECT_THROW(
      {
        try {
          counted(v);
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "sample 3's message is damaged");
          throw;
        }
      },
      std::runtime_error);
  // A truth value that is neither.
  bool b = false;
  const std::string two(1, '\2'), ones(2, '\1');
  RecordReader flag(two, "a batch's message");
  EXPECT_THROW(flag(b), std::runtime_error);
  RecordReader left_over(ones, "a batch's message");
  left_over(b);
  EXPECT_THROW(left_over.finish(), std::runtime_error);
}

}  // namespace
}  // namespace twb
