// Killed runs, for real: a child process writes rows and is killed (SIGKILL, no destructor, no
// HDF5 shutdown); the file keeps every row appended and a restarted writer continues it. And a
// reader in another process while the writer runs; a second writer there is refused.
#include "TestUtil.hpp"
#include "bodyOutput/TimeSeries.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace bodyoutput_test;
using bodyoutput::readTimeSeries;
using bodyoutput::TimeSeries;
using bodyoutput::TimeSeriesWriter;

using CrashTest = TempDirTest;

TEST_F(CrashTest, KilledWriterKeepsEveryRowAndTheRunContinues) {
  const std::string file = path("bodies.h5");
  const auto bodies = threeBodies();
  const int rows = 7;
  ChildProcess child;
  ASSERT_TRUE(child.started());
  if (child.inChild()) {
    try {
      auto* writer = new TimeSeriesWriter(file, bodies, 0.0);  // never deleted
      for (int i = 0; i < rows; ++i) {
        writer->append(0.1 * i, randomRecords(bodies.size(), static_cast<unsigned>(i)));
      }
    } catch (...) {
      ::_exit(3);
    }
    ::kill(::getpid(), SIGKILL);
    ::_exit(4);  // not reached
  }
  ASSERT_EQ(child.wait(), -SIGKILL);
  ASSERT_FALSE(fs::exists(file + ".creating"));

  const TimeSeries series = readTimeSeries(file);
  expectSameBodies(series.bodies, bodies);
  ASSERT_EQ(series.time.size(), static_cast<std::size_t>(rows));
  for (int i = 0; i < rows; ++i) {
    EXPECT_EQ(series.time[static_cast<std::size_t>(i)], 0.1 * i);
    const auto expected = randomRecords(bodies.size(), static_cast<unsigned>(i));
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      expectSameBits(series.records[static_cast<std::size_t>(i)][b], expected[b],
                     "row " + std::to_string(i));
    }
  }

  // the restarted run (from the last time written out, 0.4) continues the file
  TimeSeriesWriter writer(file, bodies, 0.4);
  EXPECT_EQ(writer.rows(), 5u);
  writer.append(0.5, randomRecords(bodies.size(), 99));
  writer.close();
  const TimeSeries continued = readTimeSeries(file);
  ASSERT_EQ(continued.time.size(), 6u);
  expectSameBits(continued.records[5][1], randomRecords(bodies.size(), 99)[1], "row 5");
}

/// true if this file system supports flock (HDF5 ignores locking where it does not)
bool flockWorks(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT, 0600);
  if (fd < 0) return false;
  const bool ok = ::flock(fd, LOCK_EX | LOCK_NB) == 0;
  ::close(fd);
  return ok;
}

TEST_F(CrashTest, ReaderInAnotherProcessWhileTheWriterRuns) {
  const std::string file = path("bodies.h5");
  const auto bodies = threeBodies();
  ChildProcess child;
  ASSERT_TRUE(child.started());
  if (child.inChild()) {
    try {
      auto* writer = new TimeSeriesWriter(file, bodies, 0.0);  // never deleted
      writer->append(1.0, randomRecords(bodies.size(), 1));
      writer->append(2.0, randomRecords(bodies.size(), 2));
      child.ready();
      child.waitForGo();  // the parent has read
      writer->append(3.0, randomRecords(bodies.size(), 3));
    } catch (...) {
      ::_exit(3);
    }
    ::_exit(0);  // without closing the file
  }
  ASSERT_TRUE(child.waitUntilReady());

  // the writer is running in the child: read without a lock
  const TimeSeries during = readTimeSeries(file);
  EXPECT_EQ(during.time, (std::vector<double>{1.0, 2.0}));
  expectSameBits(during.records[1][2], randomRecords(bodies.size(), 2)[2], "row 1");

  // a second writer (another run on the same case) is refused while the child holds the lock
  if (flockWorks(path("probe"))) {
    std::string message;
    try {
      TimeSeriesWriter second(file, bodies, 10.0);
    } catch (const std::runtime_error& e) {
      message = e.what();
    }
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_NE(message.find("cannot open it for writing"), std::string::npos) << message;
  }

  child.release();
  EXPECT_EQ(child.wait(), 0);
  EXPECT_EQ(readTimeSeries(file).time, (std::vector<double>{1.0, 2.0, 3.0}));
}

}  // namespace
