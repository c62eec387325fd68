// The threads a study's searches leave idle (study/spare_threads.h): none while every
// thread has a search to run, one more with each search that finishes, and lent ones
// come back.
#include <gtest/gtest.h>

#include "study/parallel/spare_threads.h"

namespace twb {
namespace {

TEST(SpareThreads, NoneWhileEveryThreadHasASearch) {
  SpareThreads spare(2, 3);  // three searches on two threads
  EXPECT_EQ(spare.borrow(1), 0);
  spare.search_finished();  // two left: both threads busy
  EXPECT_EQ(spare.borrow(1), 0);
  spare.search_finished();  // one left: one thread idles
  EXPECT_EQ(spare.borrow(4), 1);
  EXPECT_EQ(spare.borrow(1), 0);  // already lent
  spare.give_back(1);
  EXPECT_EQ(spare.borrow(1), 1);
}

TEST(SpareThreads, BorrowedThreadsComeBackWithTheirHolder) {
  SpareThreads spare(4, 1);  // one search on four threads: three idle
  {
    const BorrowedThreads helpers(&spare, 2);
    EXPECT_EQ(helpers.count(), 2);
    EXPECT_EQ(spare.borrow(5), 1);
    spare.give_back(1);
  }
  EXPECT_EQ(spare.borrow(5), 3);
  const BorrowedThreads none(nullptr, 3);  // no pool: no threads
  EXPECT_EQ(none.count(), 0);
}

}  // namespace
}  // namespace twb
