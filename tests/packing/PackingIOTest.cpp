// CSV and HDF5 packing files: bit-exact round trips and reader errors that name the file and
// the line/column (CSV) or the dataset/row (HDF5).
#include "packing/PackingIO.hpp"
#include "packing/RandomSequentialAddition.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using ellipsoids::Ellipsoid;
using ellipsoids::Quat;
using ellipsoids::Vec3;
using packing::Packing;

class PackingIO : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("packingTests-" + std::to_string(::getpid()) + "-" + info->name());
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name), std::ios::binary) << text;
    return path(name);
  }

  fs::path dir_;
};

Packing generated() {
  packing::RsaOptions o;
  o.aspectRatio = 6;
  o.boxLengthRelative = 8;
  o.volumeFraction = 0.15;
  o.seed = std::numeric_limits<std::uint64_t>::max();  // all 64 bits survive the trip
  o.equivalentDiameter = 1e-3;
  return packing::randomSequentialAddition(o);
}

void expectBitExact(const Packing& a, const Packing& b) {
  EXPECT_EQ(a.boxLength, b.boxLength);
  EXPECT_EQ(a.aspectRatio, b.aspectRatio);
  EXPECT_EQ(a.equivalentDiameter, b.equivalentDiameter);
  EXPECT_EQ(a.volumeFraction, b.volumeFraction);
  EXPECT_EQ(a.seed, b.seed);
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t k = 0; k < a.bodies.size(); ++k) {
    ASSERT_EQ(a.bodies[k].semiAxes(), b.bodies[k].semiAxes()) << "body " << k;
    ASSERT_EQ(a.bodies[k].centre(), b.bodies[k].centre()) << "body " << k;
    ASSERT_EQ(a.bodies[k].orientation().coeffs(), b.bodies[k].orientation().coeffs()) << "body " << k;
  }
}

/// the message of the std::runtime_error fn throws ("" and a failure if none)
template <class F>
std::string errorOf(F fn) {
  try {
    fn();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no std::runtime_error";
  return "";
}

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "'" << (text) << "' lacks '" << (part) << "'"

const std::string kGoodHead =
    "# spheroidFoam packing\n# formatVersion 1\n# boxLength 4\n# aspectRatio 1\n"
    "# equivalentDiameter 1\n# volumeFraction 0.1\n# seed 7\n"
    "a,b,c,x,y,z,qw,qx,qy,qz\n";                                       // header: line 8
const std::string kRow1 = "0.5,0.5,0.5,1,1,1,1,0,0,0\n";             // line 9
const std::string kRow2 = "0.5,0.5,0.5,3,3,3,0.5,0.5,0.5,0.5\n";     // line 10

TEST_F(PackingIO, CsvRoundTripIsBitExact) {
  const Packing p = generated();
  ASSERT_GT(p.bodies.size(), 50u);
  packing::writeCsv(p, path("p.csv"));
  expectBitExact(p, packing::readCsv(path("p.csv")));
  // and the file is what the format says
  std::ifstream in(path("p.csv"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_CONTAINS(text, "# formatVersion 1\n");
  EXPECT_CONTAINS(text, "# seed 18446744073709551615\n");
  EXPECT_CONTAINS(text, "# bodies " + std::to_string(p.bodies.size()) + "\n");
  EXPECT_CONTAINS(text, "\na,b,c,x,y,z,qw,qx,qy,qz\n");
}

TEST_F(PackingIO, Hdf5RoundTripIsBitExact) {
  const Packing p = generated();
  packing::writeHdf5(p, path("p.h5"));
  expectBitExact(p, packing::readHdf5(path("p.h5")));
  // by extension, both formats
  packing::writePacking(p, path("q.hdf5"));
  packing::writePacking(p, path("q.CSV"));
  expectBitExact(p, packing::readPacking(path("q.hdf5")));
  expectBitExact(p, packing::readPacking(path("q.CSV")));
  EXPECT_THROW(packing::writePacking(p, path("q.txt")), std::invalid_argument);
  EXPECT_THROW(packing::readPacking(path("q")), std::invalid_argument);
}

TEST_F(PackingIO, Hdf5LayoutAsDocumented) {
  const Packing p = generated();
  packing::writeHdf5(p, path("p.h5"));
  const hid_t file = H5Fopen(path("p.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  for (const auto& [name, columns] : {std::pair<const char*, hsize_t>{"semiAxes", 3},
                                      {"centres", 3}, {"quaternions", 4}}) {
    const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
    ASSERT_GE(set, 0) << name;
    const hid_t space = H5Dget_space(set);
    hsize_t dims[2] = {0, 0};
    EXPECT_EQ(H5Sget_simple_extent_ndims(space), 2);
    H5Sget_simple_extent_dims(space, dims, nullptr);
    EXPECT_EQ(dims[0], p.bodies.size()) << name;
    EXPECT_EQ(dims[1], columns) << name;
    H5Sclose(space);
    H5Dclose(set);
  }
  std::vector<double> q(4 * p.bodies.size());
  const hid_t set = H5Dopen2(file, "quaternions", H5P_DEFAULT);
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, q.data());
  H5Dclose(set);
  EXPECT_EQ(q[0], p.bodies[0].orientation().w());  // w x y z
  EXPECT_EQ(q[3], p.bodies[0].orientation().z());
  std::uint64_t seed = 0;
  const hid_t attr = H5Aopen(file, "seed", H5P_DEFAULT);
  H5Aread(attr, H5T_NATIVE_UINT64, &seed);
  H5Aclose(attr);
  EXPECT_EQ(seed, p.seed);
  H5Fclose(file);
}

TEST_F(PackingIO, EmptyPackingRoundTrips) {
  Packing p;
  p.boxLength = 3;
  packing::writeCsv(p, path("e.csv"));
  packing::writeHdf5(p, path("e.h5"));
  expectBitExact(p, packing::readCsv(path("e.csv")));
  expectBitExact(p, packing::readHdf5(path("e.h5")));
}

TEST_F(PackingIO, CsvReaderAcceptsAHandWrittenFile) {
  const std::string f = write("hand.csv", "# a comment\n\n" + kGoodHead + kRow1 + "  " + kRow2 + "\r\n");
  const Packing p = packing::readCsv(f);
  EXPECT_EQ(p.boxLength, 4);
  EXPECT_EQ(p.seed, 7u);
  ASSERT_EQ(p.bodies.size(), 2u);
  EXPECT_EQ(p.bodies[1].centre(), Vec3(3, 3, 3));
  EXPECT_EQ(p.bodies[1].orientation().coeffs(), Quat(0.5, 0.5, 0.5, 0.5).coeffs());
}

TEST_F(PackingIO, CsvBadValueNamesFileLineAndColumn) {
  const std::string f = write("bad.csv", kGoodHead + kRow1 + "0.5,0.5,0.5,3,abc,3,1,0,0,0\n");
  const std::string e = errorOf([&] { packing::readCsv(f); });
  EXPECT_CONTAINS(e, f);
  EXPECT_CONTAINS(e, ":10");
  EXPECT_CONTAINS(e, "column 5 (y)");
  EXPECT_CONTAINS(e, "'abc'");
}

TEST_F(PackingIO, CsvMissingColumnNamesFileAndLine) {
  const std::string f = write("short.csv", kGoodHead + kRow1 + "0.5,0.5,0.5,3,3,3,1,0,0\n");
  const std::string e = errorOf([&] { packing::readCsv(f); });
  EXPECT_CONTAINS(e, f);
  EXPECT_CONTAINS(e, ":10");
  EXPECT_CONTAINS(e, "expected 10 columns");
  EXPECT_CONTAINS(e, "got 9");
  // an empty field is a bad value, not a missing column
  const std::string g = write("empty.csv", kGoodHead + "0.5,0.5,0.5,1,1,,1,0,0,0\n");
  EXPECT_CONTAINS(errorOf([&] { packing::readCsv(g); }), "column 6 (z)");
  // a header that lacks a column
  const std::string h = write("header.csv", "# formatVersion 1\n# boxLength 4\na,b,c,x,y,z,qw,qx,qy\n");
  const std::string eh = errorOf([&] { packing::readCsv(h); });
  EXPECT_CONTAINS(eh, h + ":3");
  EXPECT_CONTAINS(eh, "header");
}

TEST_F(PackingIO, CsvNonUnitQuaternionNamesFileAndLine) {
  const std::string f = write("q.csv", kGoodHead + kRow1 + "0.5,0.5,0.5,3,3,3,1,0.01,0,0\n");
  const std::string e = errorOf([&] { packing::readCsv(f); });
  EXPECT_CONTAINS(e, f + ":10");
  EXPECT_CONTAINS(e, "quaternion");
  EXPECT_CONTAINS(e, "not within 1e-6 of 1");
  // within 1e-6 of unit norm: accepted (and normalised, as Ellipsoid does)
  const std::string g = write("q2.csv", kGoodHead + "0.5,0.5,0.5,3,3,3,1.0000001,0,0,0\n");
  EXPECT_EQ(packing::readCsv(g).bodies[0].orientation().w(), 1);
}

TEST_F(PackingIO, CsvOtherErrors) {
  auto expectError = [&](const std::string& name, const std::string& text, const std::string& part) {
    const std::string f = write(name, text);
    const std::string e = errorOf([&] { packing::readCsv(f); });
    EXPECT_CONTAINS(e, f);
    EXPECT_CONTAINS(e, part);
  };
  expectError("semi.csv", kGoodHead + "0.5,-0.5,0.5,1,1,1,1,0,0,0\n", "semi-axis b");
  expectError("out.csv", kGoodHead + "0.5,0.5,0.5,1,4,1,1,0,0,0\n", "centre y");
  expectError("nan.csv", kGoodHead + "0.5,0.5,0.5,1,nan,1,1,0,0,0\n", "centre y");
  expectError("nobox.csv", "# formatVersion 1\na,b,c,x,y,z,qw,qx,qy,qz\n", "boxLength");
  expectError("badbox.csv", "# formatVersion 1\n# boxLength -3\na,b,c,x,y,z,qw,qx,qy,qz\n", "boxLength");
  expectError("noversion.csv", "# boxLength 3\na,b,c,x,y,z,qw,qx,qy,qz\n", "formatVersion");
  expectError("version2.csv", "# formatVersion 2\n# boxLength 3\na,b,c,x,y,z,qw,qx,qy,qz\n",
              "formatVersion 2 is not supported");
  expectError("seed.csv", "# formatVersion 1\n# boxLength 3\n# seed -1\na,b,c,x,y,z,qw,qx,qy,qz\n", "seed");
  expectError("noheader.csv", "# formatVersion 1\n# boxLength 3\n", "no header");
  expectError("count.csv", "# formatVersion 1\n# boxLength 4\n# bodies 3\na,b,c,x,y,z,qw,qx,qy,qz\n" + kRow1,
              "truncated");
  expectError("twice.csv", "# formatVersion 1\n# boxLength 4\n# boxLength 5\na,b,c,x,y,z,qw,qx,qy,qz\n",
              "given twice");
  const std::string missing = path("does-not-exist.csv");
  EXPECT_CONTAINS(errorOf([&] { packing::readCsv(missing); }), missing);
}

/// rewrites one dataset of an HDF5 file (same shape)
void overwrite(const std::string& file, const char* name, const std::vector<double>& data) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t set = H5Dopen2(f, name, H5P_DEFAULT);
  ASSERT_GE(set, 0);
  ASSERT_GE(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), 0);
  H5Dclose(set);
  H5Fclose(f);
}

std::vector<double> readAll(const std::string& file, const char* name, std::size_t count) {
  std::vector<double> data(count);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t set = H5Dopen2(f, name, H5P_DEFAULT);
  H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  H5Dclose(set);
  H5Fclose(f);
  return data;
}

TEST_F(PackingIO, Hdf5NonUnitQuaternionNamesFileDatasetAndRow) {
  const Packing p = generated();
  const std::string f = path("q.h5");
  packing::writeHdf5(p, f);
  std::vector<double> q = readAll(f, "quaternions", 4 * p.bodies.size());
  q[4 * 5 + 1] += 0.01;  // row 5
  overwrite(f, "quaternions", q);
  const std::string e = errorOf([&] { packing::readHdf5(f); });
  EXPECT_CONTAINS(e, f);
  EXPECT_CONTAINS(e, "'quaternions'");
  EXPECT_CONTAINS(e, "row 5");
}

TEST_F(PackingIO, Hdf5BadValuesNameTheDataset) {
  const Packing p = generated();
  const std::string f = path("v.h5");
  packing::writeHdf5(p, f);
  std::vector<double> s = readAll(f, "semiAxes", 3 * p.bodies.size());
  s[3 * 2] = -1;
  overwrite(f, "semiAxes", s);
  std::string e = errorOf([&] { packing::readHdf5(f); });
  EXPECT_CONTAINS(e, "'semiAxes', row 2");
  packing::writeHdf5(p, f);
  std::vector<double> c = readAll(f, "centres", 3 * p.bodies.size());
  c[3 * 7 + 2] = std::numeric_limits<double>::quiet_NaN();
  overwrite(f, "centres", c);
  e = errorOf([&] { packing::readHdf5(f); });
  EXPECT_CONTAINS(e, f);
  EXPECT_CONTAINS(e, "'centres', row 7");
}

TEST_F(PackingIO, Hdf5StructuralErrors) {
  // not there, not HDF5
  const std::string missing = path("none.h5");
  EXPECT_CONTAINS(errorOf([&] { packing::readHdf5(missing); }), missing);
  const std::string text = write("text.h5", kGoodHead);
  EXPECT_CONTAINS(errorOf([&] { packing::readHdf5(text); }), "not an HDF5 file");
  // a dataset missing, inconsistent counts, a missing attribute
  const std::string f = path("s.h5");
  const hid_t file = H5Fcreate(f.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  const hid_t scalar = H5Screate(H5S_SCALAR);
  const int version = 1;
  const double box = 4;
  hid_t a = H5Acreate2(file, "formatVersion", H5T_STD_I32LE, scalar, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_INT, &version);
  H5Aclose(a);
  a = H5Acreate2(file, "boxLength", H5T_IEEE_F64LE, scalar, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(a, H5T_NATIVE_DOUBLE, &box);
  H5Aclose(a);
  auto dataset = [&](const char* name, hsize_t rows, hsize_t columns) {
    const hsize_t dims[2] = {rows, columns};
    const hid_t space = H5Screate_simple(2, dims, nullptr);
    const hid_t set = H5Dcreate2(file, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    std::vector<double> ones(rows * columns, 1.0);
    H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, ones.data());
    H5Dclose(set);
    H5Sclose(space);
  };
  dataset("semiAxes", 2, 3);
  dataset("centres", 2, 3);
  H5Sclose(scalar);
  H5Fclose(file);
  std::string e = errorOf([&] { packing::readHdf5(f); });
  EXPECT_CONTAINS(e, f);
  EXPECT_CONTAINS(e, "'quaternions' is missing");
  {
    const hid_t g = H5Fopen(f.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const hsize_t dims[2] = {3, 4};
    const hid_t space = H5Screate_simple(2, dims, nullptr);
    const hid_t set = H5Dcreate2(g, "quaternions", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const std::vector<double> unit = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, unit.data());
    H5Dclose(set);
    H5Sclose(space);
    H5Fclose(g);
  }
  e = errorOf([&] { packing::readHdf5(f); });
  EXPECT_CONTAINS(e, "as many rows, got 2, 2 and 3");
  {
    const hid_t g = H5Fopen(f.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Adelete(g, "boxLength");
    H5Fclose(g);
  }
  e = errorOf([&] { packing::readHdf5(f); });
  EXPECT_CONTAINS(e, f);
  EXPECT_CONTAINS(e, "'boxLength' is missing");
}

TEST_F(PackingIO, WritersReportUnwritablePaths) {
  const Packing p = generated();
  const std::string bad = path("no-such-dir/p");
  EXPECT_CONTAINS(errorOf([&] { packing::writeCsv(p, bad + ".csv"); }), bad + ".csv");
  EXPECT_CONTAINS(errorOf([&] { packing::writeHdf5(p, bad + ".h5"); }), bad + ".h5");
}

}  // namespace
