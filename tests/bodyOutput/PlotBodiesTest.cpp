// plotBodies.py on a file written by TimeSeriesWriter: a PNG appears; clear errors for a missing
// file and unknown body names; the symmetry-axis angle. Skipped if Debian's /usr/bin/python3
// cannot import h5py, numpy and matplotlib.
#include "TestUtil.hpp"
#include "bodyOutput/TimeSeries.hpp"

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#ifndef PLOT_BODIES_SCRIPT
#error "PLOT_BODIES_SCRIPT (path of plotBodies.py) must be defined by CMake"
#endif

namespace {

using namespace bodyoutput_test;
using bodyoutput::TimeSeriesWriter;

const char* const kPython = "/usr/bin/python3";

std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

class PlotBodiesTest : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    if (run(std::string(kPython) + " -c 'import h5py, numpy, matplotlib'") != 0) {
      GTEST_SKIP() << kPython << " cannot import h5py, numpy and matplotlib";
    }
  }

  /// runs a shell command with output to out.txt / err.txt; its exit status
  int run(const std::string& command) {
    const std::string full = "MPLBACKEND=Agg PYTHONDONTWRITEBYTECODE=1 MPLCONFIGDIR=" + shellQuote(path("mpl")) + " " +
                             command + " >" + shellQuote(path("out.txt")) + " 2>" +
                             shellQuote(path("err.txt"));
    const int status = std::system(full.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1000;
  }
  std::string out() const { return readFile(path("out.txt")); }
  std::string err() const { return readFile(path("err.txt")); }

  int plot(const std::string& arguments) {
    return run(std::string(kPython) + " " + shellQuote(PLOT_BODIES_SCRIPT) + " " + arguments);
  }

  /// two bodies spinning about y, moving and pushed
  std::string writeSeries() {
    const std::string file = path("bodies.h5");
    TimeSeriesWriter writer(file, {{"p0", {0.3, 0.1, 0.1}, 1000}, {"p1", {0.2, 0.1, 0.1}, 2000}},
                            0.0);
    for (int i = 0; i < 50; ++i) {
      const double t = 0.02 * i;
      std::vector<BodyRecord> r(2);
      for (std::size_t b = 0; b < 2; ++b) {
        const double phi = (1.0 + static_cast<double>(b)) * t;
        r[b].centre = {t, 0.5 * t * t, -static_cast<double>(b)};
        r[b].velocity = {1, t, 0};
        r[b].orientation = {std::cos(phi / 2), 0, std::sin(phi / 2), 0};
        r[b].hydroForce = {0, 0, 3.0 + t};
      }
      writer.append(t, r);
    }
    return file;
  }
};

TEST_F(PlotBodiesTest, WritesAPng) {
  const std::string file = writeSeries();
  const std::string png = path("plots/all.png");  // new folder
  ASSERT_EQ(plot(shellQuote(file) + " -o " + shellQuote(png)), 0) << err();
  ASSERT_TRUE(fs::exists(png)) << out() << err();
  const std::string bytes = readFile(png);
  EXPECT_GT(bytes.size(), 10000u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));

  // default output name, a subset of bodies, another axis, folded angle
  ASSERT_EQ(plot(shellQuote(file) + " --bodies p1 --axis x --fold"), 0) << err();
  EXPECT_TRUE(fs::exists(path("bodies.png")));
  EXPECT_NE(out().find("bodies.png"), std::string::npos) << out();
}

TEST_F(PlotBodiesTest, PlotsARunningCase) {
  // the writer (another process) holds the file and its lock while the script reads it
  const std::string file = path("running.h5");
  ChildProcess child;
  ASSERT_TRUE(child.started());
  if (child.inChild()) {
    try {
      TimeSeriesWriter writer(file, {{"only", {0.3, 0.1, 0.1}, 1000}}, 0.0);
      for (int i = 0; i < 10; ++i) {
        std::vector<BodyRecord> r(1);
        r[0].centre = {0.1 * i, 0, 0};
        writer.append(0.1 * i, r);
      }
      child.ready();
      child.waitForGo();
    } catch (...) {
      ::_exit(3);
    }
    ::_exit(0);
  }
  ASSERT_TRUE(child.waitUntilReady());
  const int status = plot(shellQuote(file) + " -o " + shellQuote(path("running.png")));
  child.release();
  EXPECT_EQ(child.wait(), 0);
  EXPECT_EQ(status, 0) << err();
  EXPECT_TRUE(fs::exists(path("running.png")));
  EXPECT_NE(out().find("running.png"), std::string::npos) << out();
}

TEST_F(PlotBodiesTest, ClearErrors) {
  const std::string file = writeSeries();
  EXPECT_EQ(plot(shellQuote(file) + " --bodies p0 nosuchbody -o " + shellQuote(path("x.png"))),
            1);
  EXPECT_NE(err().find("no body named 'nosuchbody'"), std::string::npos) << err();
  EXPECT_NE(err().find("'p0', 'p1'"), std::string::npos) << "must list the names: " << err();
  EXPECT_FALSE(fs::exists(path("x.png")));

  EXPECT_EQ(plot(shellQuote(path("missing.h5"))), 1);
  EXPECT_NE(err().find(path("missing.h5") + ": no such file"), std::string::npos) << err();

  writeFile(path("text.h5"), "not HDF5");
  EXPECT_EQ(plot(shellQuote(path("text.h5"))), 1);
  EXPECT_NE(err().find("cannot open it as an HDF5 file"), std::string::npos) << err();
  EXPECT_EQ(err().find("Traceback"), std::string::npos) << err();

  EXPECT_EQ(plot(shellQuote(file) + " --axis w"), 2);  // usage error (argparse)
  EXPECT_NE(err().find("usage"), std::string::npos) << err();
}

TEST_F(PlotBodiesTest, SymmetryAxisAngle) {
  // rotation by 30 degrees about y: the body x axis becomes (cos 30, 0, -sin 30), at 120 degrees
  // from z (60 folded) and 30 from x; a non-unit quaternion is normalised
  const std::string folder = fs::path(PLOT_BODIES_SCRIPT).parent_path().string();
  const std::string script =
      "import sys, math\n"
      "sys.path.insert(0, sys.argv[1])\n"
      "import plotBodies as p\n"
      "h = math.radians(15)\n"
      "q = [2 * math.cos(h), 0, 2 * math.sin(h), 0]\n"
      "print('%.12f %.12f %.12f' % (p.axis_angle_degrees(q, 'z'), "
      "p.axis_angle_degrees(q, 'z', fold=True), p.axis_angle_degrees(q, 'x')))\n";
  writeFile(path("angle.py"), script);
  ASSERT_EQ(run(std::string(kPython) + " " + shellQuote(path("angle.py")) + " " +
                shellQuote(folder)),
            0)
      << err();
  EXPECT_EQ(out(), "120.000000000000 60.000000000000 30.000000000000\n");
}

}  // namespace
