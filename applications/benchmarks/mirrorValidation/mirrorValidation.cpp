/**
 * mirrorValidation: the founding paper's analytic validation study (section 3)
 * for every distance method, as CSV.
 *
 *   mirrorValidation [-quick] [-o results.csv]
 *
 * Grid: Lambda in {1e-6, 1e-3, 1, 1e3, 1e6}, d_star/D in {1, 1e-1, ..., 1e-6},
 * Ar in {1/6, 1/3, 2/3, 3/2, 3, 6}, eps_d/D in {1e-4, 1e-5, 1e-6, 1e-8}, for
 * movingBalls (paper stop, eq. 2.9), gjk (from eq. 3.3), newtonCoulomb
 * (C_max 0.01, tau 1, lambda 0.5), jain (C/C^Jain in {1, 1/2, 1/4, 1/10, 1/20}),
 * dual (from the centre line and from eq. 3.3) and auto; exteriorPenalty with
 * its own parameters (eps_G/D in {1e-2, 1e-3, 1e-4}, lambda/D^2 in {1e3, 5e3, 1e4};
 * the paper's Figs. 15-18). -quick: Lambda = 1 only, three distances.
 * Progress on stderr.
 */
#include "MirrorCase.hpp"

#include "ellipsoids/DistanceMethod.hpp"
#include "ellipsoids/ExteriorPenalty.hpp"
#include "ellipsoids/JainDistance.hpp"
#include "ellipsoids/NewtonCoulomb.hpp"

#include <chrono>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

using namespace ellipsoids;

namespace {

struct Variant {
  std::string method;      // column 'method'
  std::string parameter;   // column 'parameter' (name=value or empty)
  std::shared_ptr<DistanceMethod> impl;
  bool eq33Start = false;  // start from eq. 3.3 (GJK as in the paper; dual variant)
  bool usesEps = true;     // exteriorPenalty ignores eps_d: run once per grid point
};

std::string fmt(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  std::string output;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-quick") {
      quick = true;
    } else if (a == "-o" && i + 1 < argc) {
      output = argv[++i];
    } else {
      std::cerr << "Usage: mirrorValidation [-quick] [-o results.csv]\n";
      return 2;
    }
  }

  std::vector<Variant> variants;
  variants.push_back({"movingBalls", "", makeDistanceMethod("movingBalls")});
  variants.push_back({"gjk", "", makeDistanceMethod("gjk"), true});
  variants.push_back({"newtonCoulomb", "Cmax=0.01 tau=1 lambda=0.5", makeDistanceMethod("newtonCoulomb")});
  for (double c : {1.0, 0.5, 0.25, 0.1, 0.05}) {
    JainDistance::Parameters p;
    p.cFactor = c;
    variants.push_back({"jain", "C/CJain=" + fmt(c), std::make_shared<JainDistance>(p)});
  }
  for (double epsG : {1e-2, 1e-3, 1e-4}) {
    for (double lambda : {1e3, 5e3, 1e4}) {
      ExteriorPenalty::Parameters p;
      p.epsGRelative = epsG;
      p.lambdaRelative = lambda;
      variants.push_back({"exteriorPenalty", "epsG=" + fmt(epsG) + " lambda=" + fmt(lambda),
                          std::make_shared<ExteriorPenalty>(p), false, false});
    }
  }
  variants.push_back({"dual", "", makeDistanceMethod("dual")});
  variants.push_back({"dual", "start=eq3.3", makeDistanceMethod("dual"), true});
  variants.push_back({"auto", "", makeDistanceMethod("auto")});

  const std::vector<double> lambdas = quick ? std::vector<double>{1} : std::vector<double>{1e-6, 1e-3, 1, 1e3, 1e6};
  const std::vector<double> distances =
      quick ? std::vector<double>{1, 1e-3, 1e-6} : std::vector<double>{1, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  const std::vector<double> ars = {1.0 / 6, 1.0 / 3, 2.0 / 3, 1.5, 3, 6};
  const std::vector<double> epss = {1e-4, 1e-5, 1e-6, 1e-8};

  std::ofstream file;
  if (!output.empty()) {
    file.open(output);
    if (!file) {
      std::cerr << "mirrorValidation: cannot write " << output << "\n";
      return 1;
    }
  }
  std::ostream& out = output.empty() ? std::cout : file;
  out.precision(10);
  out << "method,parameter,lambda,ar,dStarRel,epsRel,status,iterations,distErrRel,pointErrRel,"
         "lowerRel,upperRel,bracketContains,timeUs\n";

  long total = 0, done = 0;
  for (const auto& v : variants) total += long(lambdas.size() * distances.size() * ars.size() * (v.usesEps ? epss.size() : 1));
  const auto start = std::chrono::steady_clock::now();
  for (const auto& v : variants) {
    for (double lambda : lambdas) {
      for (double ar : ars) {
        for (double dRel : distances) {
          const mirror::Case c = mirror::make(ar, dRel * lambda, lambda);
          for (double eps : v.usesEps ? epss : std::vector<double>{0}) {
            DistanceOptions o;
            o.epsD = (v.usesEps ? eps : 1e-6) * lambda;
            if (v.eq33Start) {
              o.useInitialDirection = true;
              o.initialDirection = mirror::eq33Direction(c);
            }
            const auto t0 = std::chrono::steady_clock::now();
            const DistanceResult r = v.impl->distance(c.e1, c.e2, o);
            const auto t1 = std::chrono::steady_clock::now();
            const double d = c.exactDistance;
            const bool contains = r.lower <= d && d <= r.upper;
            out << v.method << ',' << v.parameter << ',' << lambda << ',' << ar << ',' << dRel << ','
                << (v.usesEps ? fmt(eps) : std::string("")) << ',' << toString(r.status) << ','
                << r.iterations << ',' << std::abs(r.distance - d) / lambda << ','
                << (r.point1 - c.exactPoint1).norm() / lambda << ',' << r.lower / lambda << ','
                << r.upper / lambda << ',' << (contains ? 1 : 0) << ','
                << std::chrono::duration<double, std::micro>(t1 - t0).count() << '\n';
            ++done;
          }
        }
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::cerr << "\rmirrorValidation: " << done << "/" << total << " (" << v.method << " "
                  << v.parameter << "), " << int(elapsed * (total - done) / std::max<long>(done, 1))
                  << " s left   " << std::flush;
        out.flush();
      }
    }
  }
  std::cerr << "\n";
  return out ? 0 : 1;
}
