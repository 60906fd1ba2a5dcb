/**
 * ellipsoidDistance: minimal distance between pairs of ellipsoids from the
 * command line, with every method of the geometry core.
 *
 * Usage: ellipsoidDistance [options] <pairs.csv | ->    (see -help)
 */
#include "PairTable.hpp"

#include "ellipsoids/AutoDistance.hpp"
#include "ellipsoids/DistanceMethod.hpp"
#include "ellipsoids/ExteriorPenalty.hpp"
#include "ellipsoids/JainDistance.hpp"
#include "ellipsoids/NewtonCoulomb.hpp"
#include "ellipsoids/OverlapTest.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace ellipsoids;

namespace {

const char* kUsage = R"(Usage: ellipsoidDistance [options] <pairs.csv | ->

Minimal distance between ellipsoid pairs, one pair a CSV row with the header
  a1,b1,c1,x1,y1,z1,qw1,qx1,qy1,qz1,a2,b2,c2,x2,y2,z2,qw2,qx2,qy2,qz2
(semi-axes, centre, unit quaternion w,x,y,z of each body; '-' reads standard input).

Options:
  -method NAME     movingBalls | gjk | newtonCoulomb | exteriorPenalty | jain |
                   dual | auto | paper | all                      (default auto)
                   auto: the measured table (dual); paper: the founding
                   paper's choice, Moving Balls for 1/3 < Ar < 3, GJK
                   otherwise (both certified, with a fallback method)
  -eps E           absolute tolerance on the distance
  -epsRel E        tolerance as a fraction of the smaller equal-volume radius
                   of each pair (not with -eps)                   (default 1e-5)
  -stop RULE       paper | certified: stopping test of movingBalls,
                   newtonCoulomb and jain (auto and paper are always
                   certified)                                     (default paper)
  -adaptiveEpsTheta  eps_theta from the local curvature (eq. F.6) in movingBalls
  -maxIter N       iteration limit (default: each method's own)
  -Cmax X          newtonCoulomb C_max                            (default 0.01)
  -tau X           newtonCoulomb tau                              (default 1)
  -backtrack X     newtonCoulomb backtracking factor lambda       (default 0.5)
  -penalty X       exteriorPenalty lambda / D^2                   (default 1e3)
  -epsG X          exteriorPenalty eps_G / D                      (default 1e-4)
  -jainC X         jain C_m / C_m^Jain                            (default 1)
  -zeroTolerance X Jia overlap test: relative zero of sr0, sr11   (default 1e-12)
  -o FILE          write the result CSV to FILE (default standard output)
  -help            this text

Supported bodies (the geometry core's range): semi-axes in [1e-35, 1e35],
largest/smallest semi-axis at most 100, centre coordinates at most 1e35 in
magnitude.

Output CSV, a row per pair and method:
  row,method,status,distance,lower,upper,iterations,p1x,p1y,p1z,p2x,p2y,p2z,overlap
row: 1-based data row of the input; status: converged | overlapping |
max-iterations | failed; [lower, upper]: certified bracket of the distance;
distance is signed for the dual method (minus the penetration depth when the
bodies overlap); overlap: Jia et al.'s test (separated | touching | overlapping).

Exit status: 0 done; 1 bad options or input (a message on standard error
names the option, or the row and column) or an error while computing.
)";

[[noreturn]] void usageError(const std::string& message) {
  std::cerr << "ellipsoidDistance: " << message << "\n(ellipsoidDistance -help for the options)\n";
  std::exit(1);
}

double number(const std::string& option, const std::string& text, bool positive) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v) ||
      (positive && !(v > 0))) {
    usageError("option " + option + ": '" + text + "' is not a " +
               (positive ? "positive " : "") + "number");
  }
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  std::string methodName = "auto", input, output;
  double eps = -1, epsRel = 1e-5;
  bool epsGiven = false, epsRelGiven = false;
  DistanceOptions base;
  NewtonCoulomb::Parameters nc;
  ExteriorPenalty::Parameters ep;
  JainDistance::Parameters jain;
  double zeroTolerance = JiaOverlapTest::kDefaultZeroTolerance;

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
    } else if (a == "-method") {
      methodName = value();
    } else if (a == "-eps") {
      eps = number(a, value(), true);
      epsGiven = true;
    } else if (a == "-epsRel") {
      epsRel = number(a, value(), true);
      epsRelGiven = true;
    } else if (a == "-stop") {
      const std::string s = value();
      if (s == "paper") base.stopRule = StopRule::paper;
      else if (s == "certified") base.stopRule = StopRule::certified;
      else usageError("option -stop: '" + s + "'; allowed: paper, certified");
    } else if (a == "-adaptiveEpsTheta") {
      base.adaptiveEpsTheta = true;
    } else if (a == "-maxIter") {
      const double n = number(a, value(), true);
      if (n != std::floor(n) || n > 1e9) usageError("option -maxIter: a positive integer");
      base.maxIterations = static_cast<int>(n);
    } else if (a == "-Cmax") {
      nc.cMax = number(a, value(), true);
    } else if (a == "-tau") {
      nc.tau = number(a, value(), true);
    } else if (a == "-backtrack") {
      nc.lambda = number(a, value(), true);
    } else if (a == "-penalty") {
      ep.lambdaRelative = number(a, value(), true);
    } else if (a == "-epsG") {
      ep.epsGRelative = number(a, value(), true);
    } else if (a == "-jainC") {
      jain.cFactor = number(a, value(), true);
    } else if (a == "-zeroTolerance") {
      zeroTolerance = number(a, value(), false);
    } else if (a == "-o") {
      output = value();
    } else if (a.size() > 1 && a[0] == '-') {
      usageError("unknown option '" + a + "'");
    } else if (input.empty()) {
      input = a;
    } else {
      usageError("more than one input file ('" + input + "' and '" + a + "')");
    }
  }
  if (input.empty()) usageError("no input: give a CSV file or '-' for standard input");
  if (epsGiven && epsRelGiven) {
    usageError("options -eps and -epsRel exclude each other: give the absolute or the relative tolerance");
  }

  // methods
  std::vector<std::unique_ptr<DistanceMethod>> methods;
  std::vector<std::string> names;
  if (methodName == "all") {
    names = distanceMethodNames();
  } else {
    names = {methodName};
  }
  try {
    for (const auto& n : names) {
      if (n == "newtonCoulomb") methods.push_back(std::make_unique<NewtonCoulomb>(nc));
      else if (n == "exteriorPenalty") methods.push_back(std::make_unique<ExteriorPenalty>(ep));
      else if (n == "jain") methods.push_back(std::make_unique<JainDistance>(jain));
      else methods.push_back(makeDistanceMethod(n));
    }
  } catch (const std::invalid_argument& e) {
    usageError(std::string(e.what()) + (methodName == "all" ? "" : " (or all)"));
  }
  std::unique_ptr<JiaOverlapTest> jia;
  try {
    jia = std::make_unique<JiaOverlapTest>(zeroTolerance);
  } catch (const std::invalid_argument& e) {
    usageError(e.what());
  }

  // input
  std::vector<pairtable::Pair> pairs;
  try {
    if (input == "-") {
      pairs = pairtable::read(std::cin, "standard input");
    } else {
      std::ifstream in(input);
      if (!in) {
        std::cerr << "ellipsoidDistance: cannot open '" << input << "'\n";
        return 1;
      }
      pairs = pairtable::read(in, input);
    }
  } catch (const pairtable::InputError& e) {
    std::cerr << "ellipsoidDistance: " << e.what() << "\n";
    return 1;
  }

  std::ofstream file;
  if (!output.empty()) {
    file.open(output);
    if (!file) {
      std::cerr << "ellipsoidDistance: cannot write '" << output << "'\n";
      return 1;
    }
  }
  std::ostream& out = output.empty() ? std::cout : file;
  out.precision(17);
  out << "row,method,status,distance,lower,upper,iterations,p1x,p1y,p1z,p2x,p2y,p2z,overlap\n";
  for (const auto& p : pairs) {
    DistanceOptions o = base;
    o.epsD = eps > 0 ? eps : epsRel * std::min(p.e1.equivalentRadius(), p.e2.equivalentRadius());
    std::string method;
    try {
      const char* overlap = toString(jia->test(p.e1, p.e2));
      for (const auto& m : methods) {
        method = m->name();
        o.validate();
        const DistanceResult r = m->distance(p.e1, p.e2, o);
        out << p.row << ',' << m->name() << ',' << toString(r.status) << ',' << r.distance << ','
            << r.lower << ',' << r.upper << ',' << r.iterations << ',' << r.point1.x() << ','
            << r.point1.y() << ',' << r.point1.z() << ',' << r.point2.x() << ',' << r.point2.y()
            << ',' << r.point2.z() << ',' << overlap << '\n';
      }
    } catch (const std::exception& e) {
      // e.g. -epsRel times a tiny body's radius rounding to 0 (DistanceOptions::validate);
      // whatever it is, a message and exit status 1, never an abort
      std::cerr << "ellipsoidDistance: row " << p.row << (method.empty() ? "" : ", method " + method)
                << ": " << e.what() << "\n";
      return 1;
    }
  }
  if (!out) {
    std::cerr << "ellipsoidDistance: error writing the output\n";
    return 1;
  }
  return 0;
}
