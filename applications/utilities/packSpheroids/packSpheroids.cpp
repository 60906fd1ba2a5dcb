/**
 * packSpheroids: a random periodic packing of mono-dispersed spheroids by random
 * sequential addition (founding paper, section 4.1.1), written as a packing file.
 *
 * Usage: packSpheroids -Ar 6 -l 30 -alpha 0.25 -seed 1 -o packing.h5   (see -help)
 */
#include "packing/PackingIO.hpp"
#include "packing/RandomSequentialAddition.hpp"

#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <system_error>
#include <vector>

namespace {

const char* kUsage = R"(Usage: packSpheroids [options]

Random periodic packing of mono-dispersed spheroids by random sequential
addition (RSA): equal-volume spheroids, a = Ar^(2/3) D/2 along the body x axis,
b = c = Ar^(-1/3) D/2, positions uniform in the periodic cube [0, L)^3,
orientations uniform on SO(3); a candidate is kept only if the Jia et al. test
finds it separated from every body placed before (minimum images; touching is
rejected). N = round(alpha l^3 6/pi) bodies. The same seed gives the same
packing.

Options:
  -Ar X            aspect ratio a/b, > 0; a fraction p/q is accepted (1/6)  (default 1)
  -l X             box side over the equivalent diameter, L/D; must exceed
                   2 max(Ar^(2/3), Ar^(-1/3)) (twice the longest body)    (default 10)
  -alpha X         volume fraction, in (0, 0.3]; 0.25 is the practical limit (default 0.1)
  -seed N          seed of the random generator, 0 .. 2^64-1              (default 1)
  -D X             equivalent diameter D, > 0 (sets the length unit)      (default 1)
  -maxAttempts N   candidates tried for one body before giving up, >= 1   (default 1000000)
  -walls           the cube has walls: every body lies entirely inside it (the
                   initial state of a column or a closed box; still separated
                   across the periodic images as well)                   (default off)
  -wallClearance X with -walls: the smallest gap between a body and a face,
                   over D, >= 0 and < l/2 - a_max/D                       (default 0)
  -o FILE          write the packing to FILE: .csv (text) or .h5/.hdf5 (HDF5);
                   may be given more than once (e.g. once of each)
  -quiet           no progress on stderr
  -help            this text

Prints a summary on stdout (N, actual volume fraction, attempts, wall time).
Exit status: 0 done; 1 a body could not be placed or a file not written;
2 bad options.
)";

[[noreturn]] void usageError(const std::string& message) {
  std::cerr << "packSpheroids: " << message << "\n(packSpheroids -help for the options)\n";
  std::exit(2);
}

bool parseDouble(const std::string& s, double& v) {
  if (s.empty()) return false;
  const char* first = s.data();
  if (*first == '+') ++first;
  const auto r = std::from_chars(first, s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(v);
}

/// a number, or p/q for the aspect ratio
double number(const std::string& option, const std::string& text, const std::string& allowed,
              bool fraction = false) {
  double v = 0;
  if (parseDouble(text, v)) return v;
  if (fraction) {
    const std::size_t slash = text.find('/');
    double p = 0, q = 0;
    if (slash != std::string::npos && parseDouble(text.substr(0, slash), p) &&
        parseDouble(text.substr(slash + 1), q) && q != 0) {
      return p / q;
    }
  }
  usageError("option " + option + ": '" + text + "' is not a number; allowed: " + allowed);
}

template <class Int>
Int integer(const std::string& option, const std::string& text, const std::string& allowed) {
  Int v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size()) {
    usageError("option " + option + ": '" + text + "' is not allowed; allowed: " + allowed);
  }
  return v;
}

bool knownExtension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos) return false;
  std::string ext = path.substr(dot);
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext == ".csv" || ext == ".h5" || ext == ".hdf5";
}

}  // namespace

int main(int argc, char** argv) {
  packing::RsaOptions options;
  options.progress = true;
  std::vector<std::string> outputs;

  std::vector<std::string> args(argv + 1, argv + argc);
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) usageError("option " + a + " needs a value");
      return args[++i];
    };
    if (a == "-help" || a == "--help" || a == "-h") {
      std::cout << kUsage;
      return 0;
    } else if (a == "-Ar") {
      options.aspectRatio = number(a, value(), "a number > 0 or a fraction p/q", true);
    } else if (a == "-l") {
      options.boxLengthRelative = number(a, value(), "a number > 2 max(Ar^(2/3), Ar^(-1/3))");
    } else if (a == "-alpha") {
      options.volumeFraction = number(a, value(), "a number in (0, 0.3]");
    } else if (a == "-seed") {
      options.seed = integer<std::uint64_t>(a, value(), "an integer in [0, 2^64 - 1]");
    } else if (a == "-D") {
      options.equivalentDiameter = number(a, value(), "a number > 0");
    } else if (a == "-maxAttempts") {
      options.maxAttemptsPerBody = integer<long>(a, value(), "an integer >= 1");
    } else if (a == "-walls") {
      options.walls = true;
    } else if (a == "-wallClearance") {
      options.wallClearance = number(a, value(), "a number >= 0 and < l/2 - a_max/D");
    } else if (a == "-o") {
      const std::string path = value();
      if (!knownExtension(path)) {
        usageError("option -o: '" + path + "' has an unknown extension; allowed: .csv, .h5, .hdf5");
      }
      outputs.push_back(path);
    } else if (a == "-quiet") {
      options.progress = false;
    } else {
      usageError("unknown option '" + a + "'");
    }
  }

  static const std::map<std::string, std::string> flag = {
      {"aspectRatio", "-Ar"},          {"boxLengthRelative", "-l"},
      {"volumeFraction", "-alpha"},    {"equivalentDiameter", "-D"},
      {"maxAttemptsPerBody", "-maxAttempts"}, {"wallClearance", "-wallClearance"}};
  try {
    packing::validate(options);
  } catch (const packing::InvalidRsaOption& e) {
    const auto f = flag.find(e.option());
    usageError("option " + (f == flag.end() ? e.option() : f->second) + ": " + e.what());
  }
  if (options.wallClearance > 0 && !options.walls) {
    usageError("option -wallClearance: needs -walls");
  }
  if (outputs.empty() && options.progress) {
    std::cerr << "packSpheroids: no -o given: the packing is generated but not written\n";
  }

  const auto t0 = std::chrono::steady_clock::now();
  packing::RsaStatistics stats;
  packing::Packing result;
  try {
    result = packing::randomSequentialAddition(options, &stats);
  } catch (const std::exception& e) {
    std::cerr << "packSpheroids: " << e.what() << "\n";
    return 1;
  }
  for (const std::string& path : outputs) {
    try {
      packing::writePacking(result, path);
    } catch (const std::exception& e) {
      std::cerr << "packSpheroids: " << e.what() << "\n";
      return 1;
    }
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  const ellipsoids::Vec3 s = result.bodies.front().semiAxes();
  std::cout << std::setprecision(6);
  std::cout << "packSpheroids: Ar " << options.aspectRatio << ", l " << options.boxLengthRelative
            << ", D " << options.equivalentDiameter << ", seed " << options.seed << "\n"
            << "  box length L      " << result.boxLength
            << (options.walls ? " (walls: every body inside the box)" : " (periodic)") << "\n"
            << "  semi-axes         a " << s.x() << ", b = c " << s.y() << "\n"
            << "  bodies N          " << result.bodies.size() << "\n"
            << "  volume fraction   " << result.volumeFraction << " (requested "
            << options.volumeFraction << ")\n"
            << "  attempts          " << stats.attempts << " (" << std::setprecision(4)
            << double(stats.attempts) / double(result.bodies.size()) << " per body, at most "
            << stats.maxAttemptsForOneBody << " for one body)\n"
            << "  Jia tests         " << stats.jiaTests << "\n"
            << "  blocked voxels    " << stats.deadVoxels << " (" << stats.voxelRejections
            << " candidates rejected there at once)\n"
            << (options.walls ? "  wall rejections   " + std::to_string(stats.wallRejections) + "\n" : "")
            << std::fixed << std::setprecision(3) << "  wall time         " << stats.seconds
            << " s placing, " << total << " s in all\n";
  for (const std::string& path : outputs) std::cout << "  wrote             " << path << "\n";
  return 0;
}
