#include "packing/RandomSequentialAddition.hpp"

#include "ellipsoids/OverlapTest.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>

#include <unistd.h>

namespace packing {

using ellipsoids::Ellipsoid;
using ellipsoids::OverlapStatus;
using ellipsoids::Quat;
using ellipsoids::Vec3;

namespace {

/// largest semi-axis over D_eq/2: max(Ar^(2/3), Ar^(-1/3))
double maxSemiAxisRelative(double ar) {
  return std::max(std::cbrt(ar * ar), 1 / std::cbrt(ar));
}

/// relative margin of the cutoff: pairs farther apart than 2 a_max (1 + kMargin)
/// are separated by a relative gap the Jia test resolves without doubt
constexpr double kMargin = 1e-6;

/// bodies allowed (memory and int indices)
constexpr double kMaxBodies = 1e8;

std::string fmt(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

}  // namespace

namespace random {

ellipsoids::Quat orientation(std::mt19937_64& engine) {
  auto disc = [&](double& u, double& v, double& s, bool excludeCentre) {
    for (int tries = 0; tries < 64; ++tries) {
      u = 2 * uniform01(engine) - 1;
      v = 2 * uniform01(engine) - 1;
      s = u * u + v * v;
      if (s < 1 && (!excludeCentre || s > 0)) return;
    }
    throw std::runtime_error(
        "packing::random::orientation: 64 draws in a row outside the unit disc (broken engine?)");
  };
  double x1, x2, s1, x3, x4, s2;
  disc(x1, x2, s1, false);
  disc(x3, x4, s2, true);
  const double t = std::sqrt((1 - s1) / s2);
  return Quat(x1, x2, x3 * t, x4 * t);
}

}  // namespace random

double minimumBoxLengthRelative(double aspectRatio) {
  return 4 * maxSemiAxisRelative(aspectRatio) / 2 * (1 + kMargin);
}

std::size_t rsaBodyCount(const RsaOptions& o) {
  const double l = o.boxLengthRelative;
  const double n = std::round(o.volumeFraction * l * l * l * 6 / kPi);
  if (!(n >= 0) || n > kMaxBodies) return static_cast<std::size_t>(kMaxBodies) + 1;
  return static_cast<std::size_t>(n);
}

void validate(const RsaOptions& o) {
  if (!(o.aspectRatio > 0) || !std::isfinite(o.aspectRatio)) {
    throw InvalidRsaOption("aspectRatio",
                           "aspectRatio must be finite and > 0, got " + fmt(o.aspectRatio));
  }
  if (!(o.equivalentDiameter > 0) || !std::isfinite(o.equivalentDiameter)) {
    throw InvalidRsaOption("equivalentDiameter", "equivalentDiameter must be finite and > 0, got " +
                                                     fmt(o.equivalentDiameter));
  }
  if (!(o.volumeFraction > 0) || !(o.volumeFraction <= 0.3)) {
    throw InvalidRsaOption("volumeFraction", "volumeFraction must be in (0, 0.3], got " +
                                                 fmt(o.volumeFraction));
  }
  const double lMin = minimumBoxLengthRelative(o.aspectRatio);
  if (!(o.boxLengthRelative > lMin) || !std::isfinite(o.boxLengthRelative)) {
    throw InvalidRsaOption(
        "boxLengthRelative",
        "boxLengthRelative (L/D_eq) must be finite and > " + fmt(lMin) + " for aspectRatio " +
            fmt(o.aspectRatio) +
            " (the box must exceed twice the longest body length, 4 a_max/D_eq, so that only the"
            " minimum image of a body can touch another), got " + fmt(o.boxLengthRelative));
  }
  const std::size_t n = rsaBodyCount(o);
  if (n == 0) {
    throw InvalidRsaOption("volumeFraction",
                           "volumeFraction " + fmt(o.volumeFraction) + " with boxLengthRelative " +
                               fmt(o.boxLengthRelative) +
                               " gives N = round(alpha l^3 6/pi) = 0 bodies; raise either");
  }
  if (static_cast<double>(n) > kMaxBodies) {
    throw InvalidRsaOption("boxLengthRelative",
                           "boxLengthRelative " + fmt(o.boxLengthRelative) + " with volumeFraction " +
                               fmt(o.volumeFraction) + " gives more than 1e8 bodies; lower either");
  }
  if (!(o.wallClearance >= 0) || !std::isfinite(o.wallClearance)) {
    throw InvalidRsaOption("wallClearance",
                           "wallClearance must be finite and >= 0, got " + fmt(o.wallClearance));
  }
  if (o.walls && !(2 * (maxSemiAxisRelative(o.aspectRatio) / 2 + o.wallClearance) < o.boxLengthRelative)) {
    throw InvalidRsaOption("wallClearance",
                           "wallClearance " + fmt(o.wallClearance) + " leaves no room for a body between the walls"
                           " of a box of boxLengthRelative " + fmt(o.boxLengthRelative) +
                           ": it must be < l/2 - a_max/D_eq = " +
                           fmt(o.boxLengthRelative / 2 - maxSemiAxisRelative(o.aspectRatio) / 2));
  }
  if (o.maxAttemptsPerBody < 1) {
    throw InvalidRsaOption("maxAttemptsPerBody", "maxAttemptsPerBody must be >= 1, got " +
                                                     std::to_string(o.maxAttemptsPerBody));
  }
}

Packing randomSequentialAddition(const RsaOptions& options) {
  return randomSequentialAddition(options, nullptr);
}

namespace {

/// a placed body as the cell scan sees it
struct Entry {
  double x, y, z;
  int index;
};

/**
 * Bodies by cell, each cell a fixed-capacity block of one flat array (cells
 * next to each other along z are next to each other in memory). A full cell
 * doubles every capacity.
 */
class CellStore {
 public:
  CellStore() = default;
  CellStore(std::size_t cells, std::size_t expectedBodies)
      : counts_(cells, 0),
        capacity_(std::max<std::size_t>(4, 2 * expectedBodies / std::max<std::size_t>(cells, 1) + 2)),
        entries_(cells * capacity_) {}

  void add(std::size_t cell, const Entry& e) {
    if (counts_[cell] == capacity_) grow();
    entries_[cell * capacity_ + counts_[cell]++] = e;
  }
  const Entry* begin(std::size_t cell) const { return entries_.data() + cell * capacity_; }
  const Entry* end(std::size_t cell) const { return begin(cell) + counts_[cell]; }

 private:
  void grow() {
    const std::size_t newCapacity = 2 * capacity_;
    std::vector<Entry> grown(counts_.size() * newCapacity);
    for (std::size_t c = 0; c < counts_.size(); ++c) {
      std::copy(begin(c), end(c), grown.data() + c * newCapacity);
    }
    entries_.swap(grown);
    capacity_ = newCapacity;
  }

  std::vector<std::uint32_t> counts_;
  std::size_t capacity_ = 0;
  std::vector<Entry> entries_;
};

/**
 * The RSA run. What decides is the Jia et al. test on the minimum image; all
 * the rest only saves work, and each shortcut decides a pair only with a
 * relative margin kMargin that the Jia test resolves without doubt, so the
 * packing is the one of a plain loop "draw, Jia-test against every body,
 * keep or redraw" with the same draws (tests/packing checks this):
 *  - a cell list (cells >= cutoff), own cell first, cells farther than the
 *    cutoff from the candidate skipped;
 *  - centre distance > cutoff = 2 a_max (1 + kMargin): separated;
 *  - centre distance < 2 a_min: the inscribed balls overlap;
 *  - the candidate's centre inside a body inflated by a_min along each axis
 *    (which lies within a_min of the body, so the candidate's inscribed ball
 *    reaches it): not separated whatever the orientation; then the same with
 *    the roles swapped;
 *  - a plane normal to the centre line separates the two: separated;
 *  - blocked voxels: when a body is placed, every voxel (side a_min / 2)
 *    entirely inside its inflated ellipsoid (8 corners inside, convexity) is
 *    flagged, and a later candidate whose centre falls in a flagged voxel is
 *    rejected at once (the draws are still made: the stream of candidates
 *    does not depend on the voxels).
 */
class Placement {
 public:
  explicit Placement(const RsaOptions& o) : o_(o) {
    n_ = rsaBodyCount(o);
    D_ = o.equivalentDiameter;
    L_ = o.boxLengthRelative * D_;
    wallClearance_ = o.wallClearance * D_;
    const Ellipsoid reference =
        Ellipsoid::spheroid(o.aspectRatio, D_, Vec3::Zero(), Quat::Identity());
    semiAxes_ = reference.semiAxes();  // exactly as Ellipsoid::spheroid computes them
    const double aMax = reference.maxSemiAxis();
    aMin_ = reference.minSemiAxis();
    cutoff_ = 2 * aMax * (1 + kMargin);
    cutoff2_ = cutoff_ * cutoff_;
    inner2_ = 4 * aMin_ * aMin_ * (1 - kMargin) * (1 - kMargin);
    inflatedReach2_ = (aMax + aMin_) * (aMax + aMin_);
    const Vec3 inflated = semiAxes_ + Vec3::Constant(aMin_);
    inflatedInverse2_ = inflated.cwiseProduct(inflated).cwiseInverse();
    semiAxes2_ = semiAxes_.cwiseProduct(semiAxes_);

    // cells: side >= cutoff, so that the bodies within the cutoff of a point are in its cell
    // and the 26 around; fewer than 3 cells a side (a small box): every body is scanned
    const int maxPerSide =
        std::min(1024, std::max(3, 2 * static_cast<int>(std::ceil(std::cbrt(double(n_))))));
    int m = static_cast<int>(std::min(std::floor(L_ / cutoff_), double(maxPerSide)));
    while (m > 1 && L_ / m < cutoff_) --m;
    useCells_ = m >= 3;
    m_ = useCells_ ? m : 1;
    h_ = L_ / m_;
    cellScale_ = m_ / L_;
    cells_ = CellStore(static_cast<std::size_t>(m_) * m_ * m_, n_);

    // voxels: side about a_min / 2, at most kMaxVoxelsPerSide a side (32 MB of flags)
    voxelsPerSide_ = static_cast<int>(
        std::clamp(std::floor(L_ / (aMin_ / kVoxelsPerAMin)), 1.0, double(kMaxVoxelsPerSide)));
    voxelScale_ = voxelsPerSide_ / L_;
    voxelSide_ = L_ / voxelsPerSide_;
    const std::size_t voxels =
        static_cast<std::size_t>(voxelsPerSide_) * voxelsPerSide_ * voxelsPerSide_;
    dead_.assign((voxels + 63) / 64, 0);

    bodies_.reserve(n_);
    shapes_.reserve(n_);
    near_.reserve(256);
  }

  Packing run(RsaStatistics* statistics) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    auto lastReport = t0;
    stats_ = RsaStatistics{};
    stats_.bodies = n_;
    // the progress line of the project's long runs: done/total, seconds, time left (from the
    // rate so far: an underestimate, as each body takes more attempts than the last); rewritten
    // in place on a terminal, one line per report otherwise
    const bool terminal = isatty(fileno(stderr));
    auto report = [&](std::size_t placed, bool final) {
      const double s = std::chrono::duration<double>(Clock::now() - t0).count();
      const double left = placed > 0 ? s * double(n_ - placed) / double(placed) : 0;
      std::cerr << (terminal ? "\r" : "") << "packSpheroids: " << placed << "/" << n_
                << " bodies (alpha " << std::fixed << std::setprecision(4)
                << volumeFractionOf(placed, D_, L_) << "), " << stats_.attempts << " attempts, "
                << std::setprecision(0) << s << " s";
      if (!final) std::cerr << ", about " << left << " s left";
      std::cerr << (terminal && !final ? "      " : "\n") << std::defaultfloat << std::setprecision(6)
                << std::flush;
    };

    std::mt19937_64 engine(o_.seed);
    for (std::size_t k = 0; k < n_; ++k) {
      long attempt = 0;
      while (true) {
        if (attempt == o_.maxAttemptsPerBody) {
          stats_.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
          if (statistics) *statistics = stats_;
          std::ostringstream os;
          os << "randomSequentialAddition: body " << k << " (0-based) of " << n_
             << " could not be placed after " << attempt << " attempts; volume fraction reached "
             << volumeFractionOf(k, D_, L_) << " of the requested " << o_.volumeFraction
             << " (aspectRatio " << o_.aspectRatio << ", boxLengthRelative "
             << o_.boxLengthRelative << ", seed " << o_.seed
             << "): lower volumeFraction or raise maxAttemptsPerBody";
          throw std::runtime_error(os.str());
        }
        ++attempt;
        ++stats_.attempts;
        // candidate: position, then orientation (always both: a fixed stream of draws)
        Vec3 c;
        for (int d = 0; d < 3; ++d) {
          double x = L_ * random::uniform01(engine);
          if (x >= L_) x = std::nextafter(L_, 0.0);  // cannot happen (L (1 - 2^-53) < L): a guard
          c[d] = x;
        }
        const Quat q = random::orientation(engine);
        if (tryPlace(c, q)) break;
      }
      stats_.maxAttemptsForOneBody = std::max(stats_.maxAttemptsForOneBody, attempt);
      if (o_.progress) {
        const auto now = Clock::now();
        if (now - lastReport >= std::chrono::seconds(terminal ? 1 : 10)) {
          lastReport = now;
          report(k + 1, false);
        }
      }
    }
    if (o_.progress) report(n_, true);

    Packing packing;
    packing.boxLength = L_;
    packing.aspectRatio = o_.aspectRatio;
    packing.equivalentDiameter = D_;
    packing.volumeFraction = volumeFractionOf(n_, D_, L_);
    packing.seed = o_.seed;
    packing.bodies = std::move(bodies_);
    stats_.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    if (statistics) *statistics = stats_;
    return packing;
  }

 private:
  static constexpr int kMaxVoxelsPerSide = 640;    // 640^3 bits = 32 MB
  static constexpr double kVoxelsPerAMin = 2;     // voxel side a_min / 2

  /// upper triangle (xx, xy, xz, yy, yz, zz) of a symmetric matrix
  struct Sym {
    double a[6];
    explicit Sym(const ellipsoids::Mat3& m = ellipsoids::Mat3::Zero())
        : a{m(0, 0), m(0, 1), m(0, 2), m(1, 1), m(1, 2), m(2, 2)} {}
    /// d^T A d
    double form(double x, double y, double z) const {
      return a[0] * x * x + a[3] * y * y + a[5] * z * z + 2 * (a[1] * x * y + a[2] * x * z + a[4] * y * z);
    }
    double form(const Vec3& d) const { return form(d.x(), d.y(), d.z()); }
  };
  struct Shape {
    Sym inflated;  ///< U diag(1/(a_i + a_min)^2) U^T
    Sym shape;     ///< P = U diag(a_i^2) U^T
  };
  struct Near {
    int index;
    Vec3 d;  ///< candidate centre - body centre (the image nearest to the candidate)
  };

  int cellCoordinate(double x) const {
    return std::clamp(static_cast<int>(x * cellScale_), 0, m_ - 1);
  }
  std::size_t cellOf(const Vec3& c) const {
    return static_cast<std::size_t>((cellCoordinate(c.x()) * m_ + cellCoordinate(c.y())) * m_ +
                                    cellCoordinate(c.z()));
  }
  int voxelCoordinate(double x) const {
    return std::clamp(static_cast<int>(x * voxelScale_), 0, voxelsPerSide_ - 1);
  }
  std::size_t voxelOf(const Vec3& c, int v[3]) const {
    for (int a = 0; a < 3; ++a) v[a] = voxelCoordinate(c[a]);
    return (static_cast<std::size_t>(v[0]) * voxelsPerSide_ + static_cast<std::size_t>(v[1])) *
               voxelsPerSide_ + static_cast<std::size_t>(v[2]);
  }
  bool isDead(std::size_t voxel) const { return (dead_[voxel >> 6] >> (voxel & 63)) & 1u; }

  /// orientation-independent tests of one neighbour; false: the candidate cannot fit
  bool consider(const Vec3& d, int index) {
    const double r2 = d.squaredNorm();
    if (r2 > cutoff2_) return true;
    if (r2 <= inner2_ ||
        (r2 <= inflatedReach2_ && shapes_[static_cast<std::size_t>(index)].inflated.form(d) <= 1 - kMargin)) {
      return false;
    }
    near_.push_back(Near{index, d});
    return true;
  }

  /// the neighbours of c within the cutoff into near_; false if one surely blocks c
  bool gather(const Vec3& c) {
    near_.clear();
    if (!useCells_) {
      for (std::size_t j = 0; j < bodies_.size(); ++j) {
        if (!consider(minimumImage(c - bodies_[j].centre(), L_), static_cast<int>(j))) return false;
      }
      return true;
    }
    // per axis and offset (own cell, below, above): squared gap to that slab of cells, the
    // wrapped cell index and the periodic shift of the bodies in it
    double gap2[3][3], shift[3][3];
    int index[3][3];
    for (int a = 0; a < 3; ++a) {
      const int cc = cellCoordinate(c[a]);
      const double below = c[a] - cc * h_, above = (cc + 1) * h_ - c[a];
      gap2[a][0] = 0;
      gap2[a][1] = below > 0 ? below * below : 0;
      gap2[a][2] = above > 0 ? above * above : 0;
      index[a][0] = cc;
      shift[a][0] = 0;
      index[a][1] = cc > 0 ? cc - 1 : m_ - 1;
      shift[a][1] = cc > 0 ? 0 : -L_;
      index[a][2] = cc < m_ - 1 ? cc + 1 : 0;
      shift[a][2] = cc < m_ - 1 ? 0 : L_;
    }
    // own cell first: a rejection (the usual outcome when the box fills up) comes sooner
    for (int kx = 0; kx < 3; ++kx) {
      const double gx = gap2[0][kx];
      if (gx > cutoff2_) continue;
      for (int ky = 0; ky < 3; ++ky) {
        const double gxy = gx + gap2[1][ky];
        if (gxy > cutoff2_) continue;
        const std::size_t row = static_cast<std::size_t>((index[0][kx] * m_ + index[1][ky]) * m_);
        for (int kz = 0; kz < 3; ++kz) {
          if (gxy + gap2[2][kz] > cutoff2_) continue;
          const double sx = c.x() - shift[0][kx], sy = c.y() - shift[1][ky], sz = c.z() - shift[2][kz];
          const std::size_t cell = row + static_cast<std::size_t>(index[2][kz]);
          for (const Entry *e = cells_.begin(cell), *end = cells_.end(cell); e != end; ++e) {
            if (!consider(Vec3(sx - e->x, sy - e->y, sz - e->z), e->index)) return false;
          }
        }
      }
    }
    return true;
  }

  /**
   * Flags every voxel that lies inside the inflated ellipsoid x^T Q x <= 1 - kMargin of a body
   * placed at c (Q = inflated, P = its inverse): a voxel is inside iff its 8 corners are
   * (convexity). For each vertical line of voxel corners through the ellipsoid's bounding box,
   * the z interval inside; a voxel column is inside over the intersection of its 4 lines.
   */
  void killVoxels(const Vec3& c, const Sym& Q, const ellipsoids::Mat3& P) {
    const double t = 1 - kMargin;
    const double ex = std::sqrt(P(0, 0) * t), ey = std::sqrt(P(1, 1) * t);
    const double v = voxelSide_;
    const long i0 = static_cast<long>(std::floor((c.x() - ex) / v)),
               i1 = static_cast<long>(std::ceil((c.x() + ex) / v));
    const long j0 = static_cast<long>(std::floor((c.y() - ey) / v)),
               j1 = static_cast<long>(std::ceil((c.y() + ey) / v));
    const long nx = i1 - i0 + 1, ny = j1 - j0 + 1;
    lineLo_.assign(static_cast<std::size_t>(nx * ny), 0);
    lineHi_.assign(static_cast<std::size_t>(nx * ny), -1);  // empty: lo > hi
    const double qxx = Q.a[0], qxy = Q.a[1], qxz = Q.a[2], qyy = Q.a[3], qyz = Q.a[4], qzz = Q.a[5];
    for (long i = i0; i <= i1; ++i) {
      const double x = i * v - c.x();
      for (long j = j0; j <= j1; ++j) {
        const double y = j * v - c.y();
        // qzz z^2 + 2 beta z + gamma <= 0
        const double beta = qxz * x + qyz * y;
        const double gamma = qxx * x * x + 2 * qxy * x * y + qyy * y * y - t;
        const double disc = beta * beta - qzz * gamma;
        if (!(disc > 0)) continue;
        const double root = std::sqrt(disc);
        const std::size_t at = static_cast<std::size_t>((i - i0) * ny + (j - j0));
        lineLo_[at] = (-beta - root) / qzz;
        lineHi_[at] = (-beta + root) / qzz;
      }
    }
    const long M = voxelsPerSide_;
    auto wrap = [M](long i) { return ((i % M) + M) % M; };
    for (long i = i0; i < i1; ++i) {
      for (long j = j0; j < j1; ++j) {
        const std::size_t a = static_cast<std::size_t>((i - i0) * ny + (j - j0));
        const std::size_t b = a + static_cast<std::size_t>(ny);
        const double lo = std::max(std::max(lineLo_[a], lineLo_[a + 1]), std::max(lineLo_[b], lineLo_[b + 1]));
        const double hi = std::min(std::min(lineHi_[a], lineHi_[a + 1]), std::min(lineHi_[b], lineHi_[b + 1]));
        if (!(hi - lo >= v)) continue;
        // voxels k with k v - c_z >= lo and (k + 1) v - c_z <= hi
        const long k0 = static_cast<long>(std::ceil((lo + c.z()) / v));
        const long k1 = static_cast<long>(std::floor((hi + c.z()) / v)) - 1;
        const std::size_t base =
            (static_cast<std::size_t>(wrap(i)) * static_cast<std::size_t>(M) + static_cast<std::size_t>(wrap(j))) *
            static_cast<std::size_t>(M);
        for (long k = k0; k <= k1; ++k) {
          const std::size_t voxel = base + static_cast<std::size_t>(wrap(k));
          std::uint64_t& word = dead_[voxel >> 6];
          const std::uint64_t bit = std::uint64_t(1) << (voxel & 63);
          if (!(word & bit)) {
            word |= bit;
            ++stats_.deadVoxels;
          }
        }
      }
    }
  }

  bool tryPlace(const Vec3& c, const Quat& q) {
    int v[3];
    const std::size_t voxel = voxelOf(c, v);
    if (isDead(voxel)) {
      ++stats_.voxelRejections;
      return false;
    }
    if (!gather(c)) return false;
    // orientation-dependent: the body's centre near the candidate, a separating plane, Jia
    const ellipsoids::Mat3 R = q.toRotationMatrix();
    Shape shape{Sym(R * inflatedInverse2_.asDiagonal() * R.transpose()),
                Sym(R * semiAxes2_.asDiagonal() * R.transpose())};
    if (o_.walls) {
      // the support along each axis, sqrt(P_dd), within the clearance of the faces
      const double reach[3] = {shape.shape.a[0], shape.shape.a[3], shape.shape.a[5]};
      for (int a = 0; a < 3; ++a) {
        const double h = std::sqrt(reach[a]) + wallClearance_;
        if (!(c[a] - h > 0) || !(c[a] + h < L_)) {
          ++stats_.wallRejections;
          return false;
        }
      }
    }
    for (const Near& nb : near_) {
      if (nb.d.squaredNorm() <= inflatedReach2_ && shape.inflated.form(nb.d) <= 1 - kMargin) return false;
    }
    std::optional<Ellipsoid> candidate;
    for (const Near& nb : near_) {
      // h_c(u) + h_j(u) < r, u = d / r: sqrt(d^T Pc d) + sqrt(d^T Pj d) < r^2
      const double r2 = nb.d.squaredNorm();
      const Shape& sj = shapes_[static_cast<std::size_t>(nb.index)];
      if (std::sqrt(shape.shape.form(nb.d)) + std::sqrt(sj.shape.form(nb.d)) < r2 * (1 - kMargin)) {
        continue;
      }
      // Jia et al. as the check of a finished packing does it: the earlier body first, the
      // later one moved to its image nearest to it (the same shift expression), with the
      // orientation it will be stored with
      if (!candidate) candidate.emplace(storableBody(semiAxes_, c, q));
      const Ellipsoid& body = bodies_[static_cast<std::size_t>(nb.index)];
      const Vec3 s = periodicShift(c - body.centre(), L_);
      ++stats_.jiaTests;
      const OverlapStatus status =
          s.isZero(0) ? jia_.test(body, *candidate)
                      : jia_.test(body, Ellipsoid(semiAxes_, c + s, candidate->orientation()));
      if (status != OverlapStatus::separated) return false;
    }
    if (!candidate) candidate.emplace(storableBody(semiAxes_, c, q));
    const int index = static_cast<int>(bodies_.size());
    bodies_.push_back(*candidate);
    shapes_.push_back(shape);
    const Vec3 inflated2 = (semiAxes_ + Vec3::Constant(aMin_)).cwiseProduct(semiAxes_ + Vec3::Constant(aMin_));
    killVoxels(c, shape.inflated, R * inflated2.asDiagonal() * R.transpose());
    cells_.add(cellOf(c), Entry{c.x(), c.y(), c.z(), index});
    return true;
  }

  const RsaOptions& o_;
  std::size_t n_ = 0;
  double D_ = 1, L_ = 1, wallClearance_ = 0;
  Vec3 semiAxes_, semiAxes2_, inflatedInverse2_;
  double aMin_ = 0, cutoff_ = 0, cutoff2_ = 0, inner2_ = 0, inflatedReach2_ = 0;
  bool useCells_ = false;
  int m_ = 1;
  double h_ = 1, cellScale_ = 1;
  CellStore cells_;
  int voxelsPerSide_ = 1;
  double voxelScale_ = 1, voxelSide_ = 1;
  std::vector<std::uint64_t> dead_;
  std::vector<double> lineLo_, lineHi_;  ///< scratch of killVoxels

  std::vector<Ellipsoid> bodies_;
  std::vector<Shape> shapes_;
  std::vector<Near> near_;
  const ellipsoids::JiaOverlapTest jia_;
  RsaStatistics stats_;
};

}  // namespace

Packing randomSequentialAddition(const RsaOptions& o, RsaStatistics* statistics) {
  validate(o);
  Placement placement(o);
  return placement.run(statistics);
}

}  // namespace packing
