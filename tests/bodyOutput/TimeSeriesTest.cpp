// HDF5 time series: bit-exact round trips, restarts (truncation, body checks), reading while the
// writer is open, argument and file errors.
#include "TestUtil.hpp"
#include "bodyOutput/TimeSeries.hpp"

#include <hdf5.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace bodyoutput_test;
using bodyoutput::readTimeSeries;
using bodyoutput::TimeSeries;
using bodyoutput::TimeSeriesWriter;

using TimeSeriesTest = TempDirTest;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// the message of the exception `statement` throws (as type E), "" if none
template <class E, class F>
std::string messageOf(F&& statement) {
  try {
    statement();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

/// length of one dataset of a file (HDF5 C API, independent of the library)
hsize_t datasetLength(const std::string& path, const char* name) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(file, 0);
  const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  hsize_t dims[3] = {0, 0, 0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(file);
  return dims[0];
}

TEST_F(TimeSeriesTest, RoundTripIsBitExact) {
  const std::string file = path("run/output/bodies.h5");  // parent folders created
  const auto bodies = threeBodies();
  std::vector<double> times;
  std::vector<std::vector<BodyRecord>> rows;
  {
    TimeSeriesWriter writer(file, bodies, 0.0);
    EXPECT_EQ(writer.rows(), 0u);
    EXPECT_TRUE(std::isnan(writer.lastTime()));
    EXPECT_EQ(writer.path(), file);
    for (int i = 0; i < 70; ++i) {  // more than one chunk of 64 rows
      times.push_back(1e-3 * i + 1e-17 * i * i);
      rows.push_back(randomRecords(bodies.size(), 1000 + static_cast<unsigned>(i)));
    }
    // values HDF5 must not alter: -0, subnormal, extremes, infinities, NaN with a payload
    double payloadNaN;
    const std::uint64_t nanBits = 0x7ff8dead0000beefULL;
    std::memcpy(&payloadNaN, &nanBits, sizeof payloadNaN);
    rows[3][0].centre = {-0.0, 4.9406564584124654e-324, std::numeric_limits<double>::max()};
    rows[3][1].velocity = {kInf, -kInf, payloadNaN};
    rows[3][2].orientation = {std::numeric_limits<double>::min(), -1e-310, 0.0, -0.0};
    for (std::size_t i = 0; i < rows.size(); ++i) {
      writer.append(times[i], rows[i]);
      EXPECT_EQ(writer.rows(), i + 1);
    }
    EXPECT_EQ(writer.lastTime(), times.back());
  }
  const TimeSeries series = readTimeSeries(file);
  expectSameBodies(series.bodies, bodies);
  ASSERT_EQ(series.time.size(), times.size());
  ASSERT_EQ(series.records.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(bits(series.time[i]), bits(times[i])) << "row " << i;
    ASSERT_EQ(series.records[i].size(), bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      expectSameBits(series.records[i][b], rows[i][b],
                     "row " + std::to_string(i) + " body " + std::to_string(b));
    }
  }
  EXPECT_FALSE(fs::exists(file + ".creating"));
}

TEST_F(TimeSeriesTest, FileLayoutIsAsDocumented) {
  const std::string file = path("bodies.h5");
  const auto bodies = threeBodies();
  {
    TimeSeriesWriter writer(file, bodies, 0.0);
    writer.append(0.5, randomRecords(3, 1));
    writer.append(1.0, randomRecords(3, 2));
  }
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  auto shape = [&](const char* name, std::vector<hsize_t>& dims, std::vector<hsize_t>& maxDims,
                   bool& chunked) {
    const hid_t set = H5Dopen2(f, name, H5P_DEFAULT);
    ASSERT_GE(set, 0) << name;
    const hid_t space = H5Dget_space(set);
    const int rank = H5Sget_simple_extent_ndims(space);
    dims.assign(static_cast<std::size_t>(rank), 0);
    maxDims.assign(static_cast<std::size_t>(rank), 0);
    H5Sget_simple_extent_dims(space, dims.data(), maxDims.data());
    const hid_t type = H5Dget_type(set);
    if (std::string(name) != "bodyNames") {
      EXPECT_EQ(H5Tequal(type, H5T_IEEE_F64LE), 1) << name << " must be 64-bit floats";
    } else {
      EXPECT_EQ(H5Tget_class(type), H5T_STRING);
      EXPECT_GT(H5Tis_variable_str(type), 0);
    }
    const hid_t dcpl = H5Dget_create_plist(set);
    chunked = H5Pget_layout(dcpl) == H5D_CHUNKED;
    H5Pclose(dcpl);
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(set);
  };
  std::vector<hsize_t> dims, maxDims;
  bool chunked = false;
  shape("time", dims, maxDims, chunked);
  EXPECT_EQ(dims, (std::vector<hsize_t>{2}));
  EXPECT_EQ(maxDims, (std::vector<hsize_t>{H5S_UNLIMITED}));
  EXPECT_TRUE(chunked);
  for (const char* name : {"centre", "velocity", "angularVelocity", "hydroForce", "hydroTorque",
                           "collisionForce", "collisionTorque", "unwrappedCentre", "orientation"}) {
    shape(name, dims, maxDims, chunked);
    const hsize_t width = std::string(name) == "orientation" ? 4 : 3;
    EXPECT_EQ(dims, (std::vector<hsize_t>{2, 3, width})) << name;
    EXPECT_EQ(maxDims, (std::vector<hsize_t>{H5S_UNLIMITED, 3, width})) << name;
    EXPECT_TRUE(chunked) << name;
  }
  shape("bodyNames", dims, maxDims, chunked);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3}));
  shape("semiAxes", dims, maxDims, chunked);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3, 3}));
  shape("density", dims, maxDims, chunked);
  EXPECT_EQ(dims, (std::vector<hsize_t>{3}));

  int version = 0;
  const hid_t attr = H5Aopen_by_name(f, "/", "formatVersion", H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(attr, 0);
  EXPECT_GE(H5Aread(attr, H5T_NATIVE_INT, &version), 0);
  EXPECT_EQ(version, 2);
  H5Aclose(attr);
  H5Fclose(f);
}

TEST_F(TimeSeriesTest, RestartDropsTheRowsAfterTheRestartTime) {
  const std::string file = path("bodies.h5");
  const auto bodies = threeBodies();
  const auto r1 = randomRecords(3, 1), r2 = randomRecords(3, 2), r3 = randomRecords(3, 3);
  const auto r3b = randomRecords(3, 33);
  {
    TimeSeriesWriter writer(file, bodies, 0.0);
    writer.append(0.1, r1);
    writer.append(0.2, r2);
    writer.append(0.3, r3);
  }
  {
    TimeSeriesWriter writer(file, bodies, 0.2);  // the run restarts from 0.2
    EXPECT_EQ(writer.rows(), 2u);
    EXPECT_EQ(writer.lastTime(), 0.2);
    const TimeSeries meanwhile = readTimeSeries(file);  // already truncated on disk
    EXPECT_EQ(meanwhile.time, (std::vector<double>{0.1, 0.2}));
    writer.append(0.3, r3b);  // the new 0.3
    EXPECT_EQ(writer.rows(), 3u);
  }
  const TimeSeries series = readTimeSeries(file);
  ASSERT_EQ(series.time, (std::vector<double>{0.1, 0.2, 0.3}));
  for (std::size_t b = 0; b < 3; ++b) {
    expectSameBits(series.records[0][b], r1[b], "row 0");
    expectSameBits(series.records[1][b], r2[b], "row 1");
    expectSameBits(series.records[2][b], r3b[b], "row 2 (written after the restart)");
  }
}

TEST_F(TimeSeriesTest, RestartTimeToleranceAndLimits) {
  const std::string file = path("bodies.h5");
  const auto bodies = threeBodies();
  {
    TimeSeriesWriter writer(file, bodies, 0.0);
    writer.append(0.1, randomRecords(3, 1));
    writer.append(0.1 + 0.2, randomRecords(3, 2));  // 0.30000000000000004
    writer.append(0.5, randomRecords(3, 3));
  }
  {  // restartTime 0.3 as read from a time folder name keeps the row at 0.1 + 0.2
    TimeSeriesWriter writer(file, bodies, 0.3);
    EXPECT_EQ(writer.rows(), 2u);
    EXPECT_EQ(writer.lastTime(), 0.1 + 0.2);
    writer.append(0.3, randomRecords(3, 9));  // the restarted run's first row: not "before"
    EXPECT_EQ(writer.rows(), 3u);
  }
  {  // but not a row clearly after it
    TimeSeriesWriter writer(file, bodies, 0.29999);
    EXPECT_EQ(writer.rows(), 1u);
    EXPECT_THROW(writer.append(0.0999, randomRecords(3, 9)), std::invalid_argument);
  }
  {  // infinity keeps everything, and an earlier restart time than every row keeps nothing
    TimeSeriesWriter writer(file, bodies, kInf);
    EXPECT_EQ(writer.rows(), 1u);
  }
  {
    TimeSeriesWriter writer(file, bodies, 0.0);
    EXPECT_EQ(writer.rows(), 0u);
    EXPECT_TRUE(std::isnan(writer.lastTime()));
    writer.append(0.0, randomRecords(3, 4));
  }
  EXPECT_EQ(readTimeSeries(file).time, (std::vector<double>{0.0}));
  {  // negative times: the tolerance is relative to |restartTime|
    TimeSeriesWriter writer(file, bodies, -1.0);
    EXPECT_EQ(writer.rows(), 0u);
    writer.append(-2.0, randomRecords(3, 5));
    writer.append(-1.0 * (1 + 1e-14), randomRecords(3, 6));
    writer.append(-0.5, randomRecords(3, 7));
  }
  {
    TimeSeriesWriter writer(file, bodies, -1.0);
    EXPECT_EQ(writer.rows(), 2u);
  }
}

TEST_F(TimeSeriesTest, ReopeningWithOtherBodiesThrowsAndLeavesTheFile) {
  const std::string file = path("bodies.h5");
  const auto bodies = threeBodies();
  {
    TimeSeriesWriter writer(file, bodies, 0.0);
    writer.append(0.1, randomRecords(3, 1));
  }
  const std::string before = readFile(file);

  auto reopen = [&](std::vector<BodyInfo> other) {
    return messageOf<std::runtime_error>([&] { TimeSeriesWriter writer(file, other, 0.0); });
  };
  auto expectMessage = [&](const std::string& message, const std::string& detail) {
    EXPECT_NE(message.find(file), std::string::npos) << message;
    EXPECT_NE(message.find("other bodies"), std::string::npos) << message;
    EXPECT_NE(message.find(detail), std::string::npos) << message;
    EXPECT_EQ(readFile(file), before) << "the file must be left unchanged";
  };

  auto renamed = bodies;
  renamed[1].name = "prolate 4:1";
  expectMessage(reopen(renamed), "body 1 is named 'prolate 3:1' in the file but 'prolate 4:1'");

  auto swapped = bodies;
  std::swap(swapped[0], swapped[2]);
  expectMessage(reopen(swapped), "body 0 is named 'sphere' in the file but 'oblate-");

  auto fewer = bodies;
  fewer.pop_back();
  expectMessage(reopen(fewer), "the file has 3 bodies ('sphere', 'prolate 3:1', 'oblate-");
  expectMessage(reopen(fewer), "this run has 2 bodies");

  auto longer = bodies;
  longer[1].semiAxes[2] *= 1 + 1e-9;
  expectMessage(reopen(longer), "body 1 ('prolate 3:1'): semi-axis c is 0.10000000000000001 in "
                                "the file but 0.10000000010000001 in this run");

  auto heavier = bodies;
  heavier[2].density = 2e-3;
  expectMessage(reopen(heavier), "body 2 ('oblate-\xc3\xa4'): density is 0.001 in the file but "
                                 "0.002 in this run");

  // within 1e-12 relative: the same bodies
  auto close = bodies;
  close[0].semiAxes[0] *= 1 + 1e-13;
  close[1].density *= 1 - 1e-13;
  TimeSeriesWriter writer(file, close, 1.0);
  EXPECT_EQ(writer.rows(), 1u);
}

TEST_F(TimeSeriesTest, WrongRecordCountThrowsAndChangesNothing) {
  const std::string file = path("bodies.h5");
  TimeSeriesWriter writer(file, threeBodies(), 0.0);
  writer.append(0.1, randomRecords(3, 1));
  const std::string message =
      messageOf<std::invalid_argument>([&] { writer.append(0.2, randomRecords(2, 2)); });
  EXPECT_NE(message.find("got 2 records for 3 bodies"), std::string::npos) << message;
  EXPECT_NE(message.find(file), std::string::npos) << message;
  EXPECT_THROW(writer.append(0.2, {}), std::invalid_argument);
  EXPECT_THROW(writer.append(0.2, randomRecords(4, 2)), std::invalid_argument);
  EXPECT_EQ(writer.rows(), 1u);
  writer.append(0.2, randomRecords(3, 2));
  EXPECT_EQ(readTimeSeries(file).time, (std::vector<double>{0.1, 0.2}));
}

TEST_F(TimeSeriesTest, TimesMustBeFiniteAndNotDecrease) {
  const std::string file = path("bodies.h5");
  TimeSeriesWriter writer(file, threeBodies(), 0.0);
  writer.append(0.1, randomRecords(3, 1));
  EXPECT_THROW(writer.append(kNaN, randomRecords(3, 2)), std::invalid_argument);
  EXPECT_THROW(writer.append(kInf, randomRecords(3, 2)), std::invalid_argument);
  const std::string message =
      messageOf<std::invalid_argument>([&] { writer.append(0.05, randomRecords(3, 2)); });
  EXPECT_NE(message.find("before the last row's time 0.1"), std::string::npos) << message;
  writer.append(0.1, randomRecords(3, 3));  // equal: allowed
  EXPECT_EQ(writer.rows(), 2u);
}

TEST_F(TimeSeriesTest, InvalidArgumentsOfTheConstructor) {
  const std::string file = path("bodies.h5");
  EXPECT_THROW(TimeSeriesWriter(file, {}, 0.0), std::invalid_argument);
  auto unnamed = threeBodies();
  unnamed[1].name.clear();
  EXPECT_THROW(TimeSeriesWriter(file, unnamed, 0.0), std::invalid_argument);
  auto twice = threeBodies();
  twice[2].name = twice[0].name;
  const std::string message =
      messageOf<std::invalid_argument>([&] { TimeSeriesWriter writer(file, twice, 0.0); });
  EXPECT_NE(message.find("'sphere' is used twice"), std::string::npos) << message;
  auto flat = threeBodies();
  flat[0].semiAxes[1] = 0;
  EXPECT_THROW(TimeSeriesWriter(file, flat, 0.0), std::invalid_argument);
  auto infinite = threeBodies();
  infinite[0].semiAxes[2] = kInf;
  EXPECT_THROW(TimeSeriesWriter(file, infinite, 0.0), std::invalid_argument);
  auto nanDensity = threeBodies();
  nanDensity[0].density = kNaN;
  EXPECT_THROW(TimeSeriesWriter(file, nanDensity, 0.0), std::invalid_argument);
  EXPECT_THROW(TimeSeriesWriter(file, threeBodies(), kNaN), std::invalid_argument);
  EXPECT_FALSE(fs::exists(file)) << "no file for invalid arguments";
}

TEST_F(TimeSeriesTest, RowsAreReadableWhileTheWriterIsOpen) {
  // a killed run: the writer is never destroyed; a second reader sees every appended row
  const std::string file = path("bodies.h5");
  const auto bodies = threeBodies();
  auto writer = std::make_unique<TimeSeriesWriter>(file, bodies, 0.0);
  std::vector<std::vector<BodyRecord>> rows;
  for (int i = 0; i < 5; ++i) {
    rows.push_back(randomRecords(3, 50 + static_cast<unsigned>(i)));
    writer->append(0.01 * i, rows.back());
    const TimeSeries series = readTimeSeries(file);
    ASSERT_EQ(series.time.size(), static_cast<std::size_t>(i + 1));
    for (std::size_t b = 0; b < 3; ++b) {
      expectSameBits(series.records.back()[b], rows.back()[b], "last row");
    }
  }
  // a second writer on the same file in this process is refused
  const std::string message =
      messageOf<std::runtime_error>([&] { TimeSeriesWriter second(file, bodies, 1.0); });
  EXPECT_NE(message.find("already open"), std::string::npos) << message;
  EXPECT_EQ(writer->rows(), 5u);
  writer->append(0.05, randomRecords(3, 60));
  EXPECT_EQ(readTimeSeries(file).time.size(), 6u);
}

TEST_F(TimeSeriesTest, MoveAndClose) {
  const std::string file = path("bodies.h5");
  TimeSeriesWriter a(file, threeBodies(), 0.0);
  a.append(0.1, randomRecords(3, 1));
  TimeSeriesWriter b(std::move(a));
  EXPECT_FALSE(a.isOpen());  // NOLINT(bugprone-use-after-move): moved-from state is specified
  EXPECT_EQ(a.rows(), 0u);
  EXPECT_EQ(a.path(), "");
  EXPECT_THROW(a.append(0.2, randomRecords(3, 2)), std::logic_error);
  EXPECT_TRUE(b.isOpen());
  EXPECT_EQ(b.rows(), 1u);
  b.append(0.2, randomRecords(3, 2));

  // move assignment closes the file the target had: it can be opened again
  const std::string other = path("other.h5");
  TimeSeriesWriter c(other, threeBodies(), 0.0);
  c = std::move(b);
  EXPECT_EQ(c.path(), file);
  EXPECT_EQ(c.rows(), 2u);
  TimeSeriesWriter reopened(other, threeBodies(), 0.0);
  EXPECT_EQ(reopened.rows(), 0u);

  c.close();
  EXPECT_FALSE(c.isOpen());
  c.close();  // twice: no-op
  TimeSeriesWriter again(file, threeBodies(), 1.0);
  EXPECT_EQ(again.rows(), 2u);
}

TEST_F(TimeSeriesTest, ManyBodies) {
  const std::string file = path("bodies.h5");
  std::vector<BodyInfo> bodies;
  for (int i = 0; i < 3000; ++i) {
    bodies.push_back({"p" + std::to_string(i), {0.3, 0.1, 0.1}, 1000.0 + i});
  }
  std::vector<std::vector<BodyRecord>> rows;
  {
    TimeSeriesWriter writer(file, bodies, 0.0);
    for (int i = 0; i < 4; ++i) {
      rows.push_back(randomRecords(bodies.size(), static_cast<unsigned>(i)));
      writer.append(i, rows.back());
    }
  }
  const TimeSeries series = readTimeSeries(file);
  expectSameBodies(series.bodies, bodies);
  ASSERT_EQ(series.records.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    expectSameBits(series.records[i][2999], rows[i][2999], "last body");
    expectSameBits(series.records[i][1234], rows[i][1234], "a body");
  }
}

TEST_F(TimeSeriesTest, PartlyAppendedRowIsIgnoredAndRepaired) {
  // a run killed inside append(): some datasets one row longer than `time`
  const std::string file = path("bodies.h5");
  const auto bodies = threeBodies();
  {
    TimeSeriesWriter writer(file, bodies, 0.0);
    writer.append(0.1, randomRecords(3, 1));
    writer.append(0.2, randomRecords(3, 2));
  }
  {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    for (const char* name : {"centre", "velocity"}) {
      const hid_t set = H5Dopen2(f, name, H5P_DEFAULT);
      const hsize_t dims[3] = {3, 3, 3};
      ASSERT_GE(H5Dset_extent(set, dims), 0);
      H5Dclose(set);
    }
    H5Fclose(f);
  }
  EXPECT_EQ(readTimeSeries(file).time.size(), 2u);
  {
    TimeSeriesWriter writer(file, bodies, kInf);
    EXPECT_EQ(writer.rows(), 2u);
    EXPECT_EQ(datasetLength(file, "centre"), 2u);  // repaired on open
    writer.append(0.3, randomRecords(3, 3));
  }
  EXPECT_EQ(readTimeSeries(file).time, (std::vector<double>{0.1, 0.2, 0.3}));
  EXPECT_EQ(datasetLength(file, "velocity"), 3u);
}

TEST_F(TimeSeriesTest, ExistingFileThatIsNotASeries) {
  const auto bodies = threeBodies();
  // a text file: not overwritten
  const std::string text = path("notes.h5");
  writeFile(text, "not HDF5\n");
  std::string message = messageOf<std::runtime_error>([&] { TimeSeriesWriter w(text, bodies, 0); });
  EXPECT_NE(message.find(text), std::string::npos) << message;
  EXPECT_NE(message.find("not an HDF5 file"), std::string::npos) << message;
  EXPECT_EQ(readFile(text), "not HDF5\n");
  message = messageOf<std::runtime_error>([&] { readTimeSeries(text); });
  EXPECT_NE(message.find(text), std::string::npos) << message;
  EXPECT_NE(message.find("not an HDF5 file"), std::string::npos) << message;

  // an empty file
  const std::string empty = path("empty.h5");
  writeFile(empty, "");
  EXPECT_THROW(TimeSeriesWriter(empty, bodies, 0), std::runtime_error);

  // an HDF5 file of something else
  const std::string other = path("other.h5");
  {
    const hid_t f = H5Fcreate(other.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const hsize_t n = 4;
    const hid_t space = H5Screate_simple(1, &n, nullptr);
    const hid_t set = H5Dcreate2(f, "pressure", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT,
                                 H5P_DEFAULT);
    H5Dclose(set);
    H5Sclose(space);
    H5Fclose(f);
  }
  const std::string before = readFile(other);
  message = messageOf<std::runtime_error>([&] { TimeSeriesWriter w(other, bodies, 0); });
  EXPECT_NE(message.find(other), std::string::npos) << message;
  EXPECT_NE(message.find("formatVersion"), std::string::npos) << message;
  EXPECT_NE(message.find("not a valid body time series"), std::string::npos) << message;
  EXPECT_EQ(readFile(other), before);
  message = messageOf<std::runtime_error>([&] { readTimeSeries(other); });
  EXPECT_NE(message.find(other), std::string::npos) << message;
  EXPECT_NE(message.find("formatVersion"), std::string::npos) << message;

  // a series with a missing dataset
  const std::string damaged = path("damaged.h5");
  { TimeSeriesWriter w(damaged, bodies, 0); }
  {
    const hid_t f = H5Fopen(damaged.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(H5Ldelete(f, "hydroTorque", H5P_DEFAULT), 0);
    H5Fclose(f);
  }
  message = messageOf<std::runtime_error>([&] { readTimeSeries(damaged); });
  EXPECT_NE(message.find(damaged), std::string::npos) << message;
  EXPECT_NE(message.find("dataset 'hydroTorque' is missing"), std::string::npos) << message;
  message = messageOf<std::runtime_error>([&] { TimeSeriesWriter w(damaged, bodies, 0); });
  EXPECT_NE(message.find("dataset 'hydroTorque' is missing"), std::string::npos) << message;

  // a folder
  fs::create_directories(path("folder.h5"));
  EXPECT_THROW(TimeSeriesWriter(path("folder.h5"), bodies, 0), std::runtime_error);

  // missing file
  message = messageOf<std::runtime_error>([&] { readTimeSeries(path("missing.h5")); });
  EXPECT_NE(message.find(path("missing.h5")), std::string::npos) << message;
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
}

/// open HDF5 files and objects in them (datasets, groups, attributes, named types), all files
std::vector<ssize_t> openIdentifiers() {
  std::vector<ssize_t> counts;
  for (unsigned kind : {H5F_OBJ_FILE, H5F_OBJ_DATASET, H5F_OBJ_GROUP, H5F_OBJ_DATATYPE,
                        H5F_OBJ_ATTR}) {
    counts.push_back(H5Fget_obj_count(H5F_OBJ_ALL, kind));
  }
  return counts;
}

TEST_F(TimeSeriesTest, NoHandleLeaks) {
  const std::string file = path("bodies.h5");
  const auto bodies = threeBodies();
  { TimeSeriesWriter warmUp(path("warmUp.h5"), bodies, 0); }  // HDF5 initialised
  readTimeSeries(path("warmUp.h5"));
  const std::vector<ssize_t> before = openIdentifiers();
  {
    TimeSeriesWriter writer(file, bodies, 0);
    writer.append(0.1, randomRecords(3, 1));
    EXPECT_THROW(writer.append(0.2, randomRecords(2, 1)), std::invalid_argument);
    readTimeSeries(file);  // while open
    EXPECT_THROW(TimeSeriesWriter(file, bodies, 0), std::runtime_error);
  }
  auto other = bodies;
  other[0].density = 1;
  EXPECT_THROW(TimeSeriesWriter(file, other, 0), std::runtime_error);
  {
    TimeSeriesWriter writer(file, bodies, 0.05);
    writer.append(0.1, randomRecords(3, 2));
    TimeSeriesWriter moved(std::move(writer));
    moved.close();
  }
  writeFile(path("text.h5"), "text");
  EXPECT_THROW(TimeSeriesWriter(path("text.h5"), bodies, 0), std::runtime_error);
  EXPECT_THROW(readTimeSeries(path("text.h5")), std::runtime_error);
  EXPECT_THROW(readTimeSeries(path("missing.h5")), std::runtime_error);
  {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(H5Ldelete(f, "orientation", H5P_DEFAULT), 0);
    H5Fclose(f);
  }
  EXPECT_THROW(readTimeSeries(file), std::runtime_error);
  EXPECT_THROW(TimeSeriesWriter(file, bodies, 0), std::runtime_error);
  EXPECT_EQ(openIdentifiers(), before)
      << "open files, datasets, groups, named types, attributes";
  for (ssize_t n : before) EXPECT_EQ(n, 0);
}

TEST_F(TimeSeriesTest, ParentThatIsAFileGivesAClearError) {
  writeFile(path("plain"), "a file, not a folder");
  const std::string file = path("plain/output/bodies.h5");
  const std::string message =
      messageOf<std::runtime_error>([&] { TimeSeriesWriter w(file, threeBodies(), 0); });
  EXPECT_NE(message.find(file), std::string::npos) << message;
  EXPECT_NE(message.find("cannot create the folder"), std::string::npos) << message;
}

TEST_F(TimeSeriesTest, UnwritableFolderGivesAClearError) {
  if (::geteuid() == 0) GTEST_SKIP() << "root can write anywhere";
  fs::create_directories(path("locked"));
  fs::permissions(path("locked"), fs::perms::owner_read | fs::perms::owner_exec);
  const std::string file = path("locked/bodies.h5");
  const std::string message =
      messageOf<std::runtime_error>([&] { TimeSeriesWriter w(file, threeBodies(), 0); });
  fs::permissions(path("locked"), fs::perms::owner_all);
  EXPECT_NE(message.find(file), std::string::npos) << message;
}

}  // namespace
