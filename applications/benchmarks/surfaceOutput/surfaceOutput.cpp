/**
 * surfaceOutput: size and wall time of one write of the body surfaces (the VTK file written at
 * every write time when `surfaces yes`) for 2000 spheroids, in the binary legacy-VTK format of
 * bodyoutput::writeSurfacesVtk and in the ASCII legacy-VTK format it replaced (its writer is
 * kept here, for this comparison only), in the same run.
 *
 *   surfaceOutput [--bodies N] [--subdivisions S] [--repetitions R] [--dir D]
 *
 * Defaults: 2000 bodies, 3 subdivisions (the default of the `output` dictionary: 642 points and
 * 1280 triangles a body), 5 repetitions, files in /tmp/surfaceOutput-<pid> (removed at the end).
 * Bodies: prolate spheroids (semi-axes 2, 1, 1 mm) at random centres in a 0.1 m cube with random
 * orientations (seeded). Each repetition writes one file of each format (interleaved, so that
 * the load of the shared machine hits both alike); the wall time of a write covers the surface
 * generation, the formatting and the write to the page cache (temporary file + rename), as in
 * a run. Prints a Markdown table: size, median and minimum wall time a write, and the ratios,
 * with the machine (/proc/cpuinfo) and the date.
 */
#include "bodyOutput/SurfaceVtk.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <unordered_map>
#include <vector>

namespace {

namespace fs = std::filesystem;
using bodyoutput::BodyShape;
using Vec3 = std::array<double, 3>;
using Triangle = std::array<std::uint32_t, 3>;

// ---- the ASCII legacy-VTK writer (same surfaces, numbers as shortest round-trip text)

void appendNumber(std::string& out, double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

void appendInteger(std::string& out, std::size_t v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

/// Text to path + ".tmp", renamed to path (as the library writes its files)
void writeFileAtomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw std::runtime_error("cannot write '" + tmp + "'");
  }
  fs::rename(tmp, path);
}

void writeSurfacesAscii(const std::string& path, const std::vector<BodyShape>& bodies,
                       int subdivisions) {
  const bodyoutput::UnitSphereMesh mesh = bodyoutput::unitSphereMesh(subdivisions);
  const std::vector<Vec3>& sphere = mesh.points;
  const std::vector<Triangle>& triangles = mesh.triangles;
  const std::size_t np = sphere.size() * bodies.size();
  const std::size_t nt = triangles.size() * bodies.size();

  std::string out;
  out.reserve(np * 150 + nt * 40 + 512);
  out += "# vtk DataFile Version 3.0\n";
  out += "spheroidFoam body surfaces\n";
  out += "ASCII\n";
  out += "DATASET POLYDATA\n";
  out += "POINTS ";
  appendInteger(out, np);
  out += " double\n";
  std::vector<Vec3> normals;
  normals.reserve(np);
  for (const BodyShape& body : bodies) {
    const std::array<double, 9> r = bodyoutput::rotationMatrix(body.orientation);
    for (const Vec3& u : sphere) {
      const Vec3 x = bodyoutput::surfacePoint(body, r, u);
      for (int k = 0; k < 3; ++k) {
        if (k) out += ' ';
        appendNumber(out, x[k]);
      }
      out += '\n';
      normals.push_back(bodyoutput::surfaceNormal(body, r, u));
    }
  }
  out += "POLYGONS ";
  appendInteger(out, nt);
  out += ' ';
  appendInteger(out, 4 * nt);
  out += '\n';
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const std::size_t offset = b * sphere.size();
    for (const Triangle& t : triangles) {
      out += '3';
      for (std::uint32_t i : t) {
        out += ' ';
        appendInteger(out, offset + i);
      }
      out += '\n';
    }
  }
  out += "CELL_DATA ";
  appendInteger(out, nt);
  out += "\nSCALARS body int 1\nLOOKUP_TABLE default\n";
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      appendInteger(out, b);
      out += '\n';
    }
  }
  out += "POINT_DATA ";
  appendInteger(out, np);
  out += "\nNORMALS Normals double\n";
  for (const Vec3& n : normals) {
    appendNumber(out, n[0]);
    out += ' ';
    appendNumber(out, n[1]);
    out += ' ';
    appendNumber(out, n[2]);
    out += '\n';
  }
  writeFileAtomically(path, out);
}

// ---- the benchmark

std::vector<BodyShape> randomSpheroids(std::size_t n) {
  std::mt19937_64 rng(2000);
  std::uniform_real_distribution<double> position(0, 0.1);
  std::normal_distribution<double> normal;
  std::vector<BodyShape> bodies(n);
  for (BodyShape& b : bodies) {
    b.semiAxes = {2e-3, 1e-3, 1e-3};
    b.centre = {position(rng), position(rng), position(rng)};
    b.orientation = {normal(rng), normal(rng), normal(rng), normal(rng)};
  }
  return bodies;
}

std::string machine() {
  std::ifstream cpu("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpu, line)) {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      return line.substr(line.find(':') + 2);
    }
  }
  return "unknown";
}

std::string today() {
  const std::time_t now = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return buf;
}

struct Result {
  std::uintmax_t bytes = 0;
  std::vector<double> seconds;
  double median() const {
    std::vector<double> s = seconds;
    std::sort(s.begin(), s.end());
    const std::size_t n = s.size();
    return n % 2 ? s[n / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
  }
  double minimum() const { return *std::min_element(seconds.begin(), seconds.end()); }
};

template <class Write>
void timeWrite(Result& r, const std::string& file, Write write) {
  const auto t0 = std::chrono::steady_clock::now();
  write(file);
  const auto t1 = std::chrono::steady_clock::now();
  r.seconds.push_back(std::chrono::duration<double>(t1 - t0).count());
  r.bytes = fs::file_size(file);
}

std::string fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

[[noreturn]] void usage(int status) {
  (status ? std::cerr : std::cout)
      << "usage: surfaceOutput [--bodies N] [--subdivisions S] [--repetitions R] [--dir D]\n";
  std::exit(status);
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t nBodies = 2000;
  int subdivisions = 3;
  int repetitions = 5;
  std::string dir = (fs::temp_directory_path() / ("surfaceOutput-" + std::to_string(::getpid())))
                        .string();
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") usage(0);
    if (i + 1 >= argc) usage(2);
    const std::string value = argv[++i];
    try {
      if (arg == "--bodies") {
        nBodies = std::stoul(value);
      } else if (arg == "--subdivisions") {
        subdivisions = std::stoi(value);
      } else if (arg == "--repetitions") {
        repetitions = std::stoi(value);
      } else if (arg == "--dir") {
        dir = value;
      } else {
        usage(2);
      }
    } catch (const std::logic_error&) {
      std::cerr << "surfaceOutput: bad value '" << value << "' for " << arg << "\n";
      usage(2);
    }
  }
  if (repetitions < 1 || subdivisions < 0 ||
      subdivisions > bodyoutput::kMaxSurfaceSubdivisions) {
    usage(2);
  }

  const std::vector<BodyShape> bodies = randomSpheroids(nBodies);
  fs::create_directories(dir);
  const std::string asciiFile = dir + "/surfaces_ascii.vtk";
  const std::string binaryFile = dir + "/surfaces_binary.vtk";
  Result ascii, binary;
  try {
    for (int r = 0; r < repetitions; ++r) {
      timeWrite(ascii, asciiFile,
                [&](const std::string& f) { writeSurfacesAscii(f, bodies, subdivisions); });
      timeWrite(binary, binaryFile, [&](const std::string& f) {
        bodyoutput::writeSurfacesVtk(f, bodies, subdivisions);
      });
    }
  } catch (const std::exception& e) {
    std::cerr << "surfaceOutput: " << e.what() << "\n";
    return 1;
  }
  fs::remove(asciiFile);
  fs::remove(binaryFile);
  std::error_code ec;
  fs::remove(dir, ec);  // only if empty

  const double mb = 1e6;
  std::cout << "Surfaces of " << nBodies << " spheroids, " << subdivisions << " subdivisions ("
            << bodyoutput::surfacePointCount(subdivisions) * nBodies << " points, "
            << bodyoutput::surfaceTriangleCount(subdivisions) * nBodies << " triangles), "
            << repetitions << " writes of each format\n"
            << "Machine: " << machine() << "; " << today() << "\n\n"
            << "| format | size (MB) | wall time a write, median (s) | minimum (s) |\n"
            << "|---|---:|---:|---:|\n"
            << "| ASCII legacy VTK, double (before) | " << fixed(ascii.bytes / mb, 1) << " | "
            << fixed(ascii.median(), 3) << " | " << fixed(ascii.minimum(), 3) << " |\n"
            << "| binary legacy VTK, float (now) | " << fixed(binary.bytes / mb, 1) << " | "
            << fixed(binary.median(), 3) << " | " << fixed(binary.minimum(), 3) << " |\n"
            << "| ratio before / now | " << fixed(double(ascii.bytes) / binary.bytes, 2)
            << " | " << fixed(ascii.median() / binary.median(), 1) << " | "
            << fixed(ascii.minimum() / binary.minimum(), 1) << " |\n";
  return 0;
}
