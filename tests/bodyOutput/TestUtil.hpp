// Helpers shared by the body-output tests: a temporary folder per test, bodies and records,
// bit-exact comparisons.
#ifndef BODYOUTPUT_TESTS_TESTUTIL_HPP
#define BODYOUTPUT_TESTS_TESTUTIL_HPP

#include "bodyOutput/TimeSeries.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace bodyoutput_test {

namespace fs = std::filesystem;
using bodyoutput::BodyInfo;
using bodyoutput::BodyRecord;

/// A fresh folder per test (pid + test name: ctest may run tests in parallel), removed afterwards.
class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("bodyOutputTests-" + std::to_string(::getpid()) + "-" +
                                        info->test_suite_name() + "-" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

/// A child process that tells the parent it is ready (one byte on a pipe) and waits for its go
/// (the parent closing the other pipe). Whatever happens in the parent (a failed ASSERT, an exception), the destructor lets the
/// child go and reaps it before the test's folder is removed.
class ChildProcess {
 public:
  ChildProcess() {
    if (::pipe(toParent_) != 0 || ::pipe(toChild_) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::close(toParent_[0]);
      ::close(toChild_[1]);
    } else {
      ::close(toParent_[1]);
      ::close(toChild_[0]);
    }
  }
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ~ChildProcess() {
    if (pid_ > 0) release();
    if (pid_ > 0 && !reaped_) wait();
  }
  bool started() const { return pid_ >= 0; }
  bool inChild() const { return pid_ == 0; }

  // in the child
  void ready() const {
    const char c = 'r';
    if (::write(toParent_[1], &c, 1) != 1) ::_exit(90);
  }
  /// returns when the parent calls release() (closes its end of the pipe) or ends
  void waitForGo() const {
    char c = 0;
    while (::read(toChild_[0], &c, 1) > 0) {
    }
  }

  // in the parent
  bool waitUntilReady() const {
    char c = 0;
    return ::read(toParent_[0], &c, 1) == 1;
  }
  /// lets the child go on (end of file on its pipe: no write, so no SIGPIPE if it is gone)
  void release() {
    if (toChild_[1] < 0) return;
    ::close(toChild_[1]);
    toChild_[1] = -1;
    ::close(toParent_[0]);
  }
  /// exit status, or -signal
  int wait() {
    int status = 0;
    if (::waitpid(pid_, &status, 0) != pid_) return 1000;
    reaped_ = true;
    if (WIFSIGNALED(status)) return -WTERMSIG(status);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1001;
  }

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
  int toParent_[2] = {-1, -1}, toChild_[2] = {-1, -1};
};

inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

inline void writeFile(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::vector<BodyInfo> threeBodies() {
  return {{"sphere", {0.5, 0.5, 0.5}, 1050.0},
          {"prolate 3:1", {0.3, 0.1, 0.1}, 2500.0},
          {"oblate-\xc3\xa4", {0.05, 0.2, 0.2}, 1e-3}};  // UTF-8 name
}

/// bits of a double (NaN payloads and -0 compared exactly)
inline std::uint64_t bits(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

/// records for `bodies` bodies with values from a seeded generator (wide range of magnitudes)
inline std::vector<BodyRecord> randomRecords(std::size_t bodies, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-300, 300);
  auto value = [&] { return std::ldexp(mantissa(rng), exponent(rng)); };
  std::vector<BodyRecord> records(bodies);
  for (BodyRecord& r : records) {
    for (auto* v : {&r.centre, &r.velocity, &r.angularVelocity, &r.hydroForce, &r.hydroTorque,
                    &r.collisionForce, &r.collisionTorque, &r.unwrappedCentre}) {
      for (double& x : *v) x = value();
    }
    for (double& x : r.orientation) x = mantissa(rng);
  }
  return records;
}

inline void expectSameBits(const BodyRecord& a, const BodyRecord& b, const std::string& where) {
  auto same = [&](const auto& x, const auto& y, const char* name) {
    for (std::size_t k = 0; k < x.size(); ++k) {
      EXPECT_EQ(bits(x[k]), bits(y[k])) << where << " " << name << "[" << k << "]: " << x[k]
                                        << " vs " << y[k];
    }
  };
  same(a.centre, b.centre, "centre");
  same(a.velocity, b.velocity, "velocity");
  same(a.angularVelocity, b.angularVelocity, "angularVelocity");
  same(a.hydroForce, b.hydroForce, "hydroForce");
  same(a.hydroTorque, b.hydroTorque, "hydroTorque");
  same(a.collisionForce, b.collisionForce, "collisionForce");
  same(a.collisionTorque, b.collisionTorque, "collisionTorque");
  same(a.unwrappedCentre, b.unwrappedCentre, "unwrappedCentre");
  same(a.orientation, b.orientation, "orientation");
}

inline void expectSameBodies(const std::vector<BodyInfo>& a, const std::vector<BodyInfo>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].name, b[i].name);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(bits(a[i].semiAxes[k]), bits(b[i].semiAxes[k]));
    EXPECT_EQ(bits(a[i].density), bits(b[i].density));
  }
}

}  // namespace bodyoutput_test

#endif  // BODYOUTPUT_TESTS_TESTUTIL_HPP
