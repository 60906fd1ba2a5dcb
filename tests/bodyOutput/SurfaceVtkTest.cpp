// VTK surfaces (structure, counts, every point on its ellipsoid, normals, outward closed meshes)
// and ParaView series files (content, escaping, restarts).
#include "TestUtil.hpp"
#include "bodyOutput/SurfaceVtk.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace bodyoutput_test;
using bodyoutput::BodyShape;
using bodyoutput::readVtkSeries;
using bodyoutput::VtkSeries;
using bodyoutput::writeSurfacesVtk;
using bodyoutput::writeVtkSeries;

using SurfaceVtkTest = TempDirTest;
using VtkSeriesTest = TempDirTest;
using Vec = std::array<double, 3>;
using Series = std::vector<std::pair<std::string, double>>;

/// A legacy-VTK polydata file as this library writes it, parsed strictly.
struct PolyData {
  std::vector<std::string> header;  // the first four lines
  std::vector<Vec> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  std::vector<int> body;  // cell data
  std::vector<Vec> normals;
};

/// Reads a binary legacy-VTK file: text lines and blocks of big-endian 32-bit numbers.
class BinaryVtkReader {
 public:
  explicit BinaryVtkReader(std::string bytes) : s_(std::move(bytes)) {}

  /// The text up to the next newline (consumed); empty at the end of the data.
  std::string line() {
    const std::size_t end = s_.find('\n', pos_);
    if (end == std::string::npos) {
      ADD_FAILURE() << "missing newline after byte " << pos_;
      pos_ = s_.size();
      return {};
    }
    std::string l = s_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return l;
  }

  /// A 4-byte big-endian value (float or int32); 0 past the end (and a failure)
  template <class T>
  T number() {
    static_assert(sizeof(T) == 4, "4-byte values only");
    if (pos_ + 4 > s_.size()) {
      if (!truncated_) ADD_FAILURE() << "binary data truncated at byte " << pos_;
      truncated_ = true;
      return T{};
    }
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i) bits = (bits << 8) | static_cast<unsigned char>(s_[pos_ + i]);
    pos_ += 4;
    T v;
    std::memcpy(&v, &bits, 4);
    return v;
  }

  bool atEnd() const { return pos_ == s_.size(); }
  std::size_t position() const { return pos_; }

 private:
  std::string s_;
  std::size_t pos_ = 0;
  bool truncated_ = false;
};

/// The words of a line
std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string word; in >> word;) w.push_back(word);
  return w;
}

std::size_t count(const std::string& word) { return std::stoul(word); }

PolyData parseVtk(const std::string& file) {
  BinaryVtkReader in(readFile(file));
  PolyData p;
  for (int i = 0; i < 4; ++i) p.header.push_back(in.line());
  auto w = words(in.line());
  EXPECT_EQ(w.size(), 3u);
  w.resize(3);
  EXPECT_EQ(w[0], "POINTS");
  EXPECT_EQ(w[2], "float");
  std::size_t n = count(w[1]);
  p.points.resize(n);
  for (Vec& v : p.points) {
    for (double& x : v) x = in.number<float>();
  }
  EXPECT_EQ(in.line(), "") << "the points end with a newline";
  w = words(in.line());
  w.resize(3);
  EXPECT_EQ(w[0], "POLYGONS");
  n = count(w[1]);
  EXPECT_EQ(count(w[2]), 4 * n);
  p.triangles.resize(n);
  for (auto& t : p.triangles) {
    EXPECT_EQ(in.number<std::int32_t>(), 3);
    for (std::size_t& i : t) i = static_cast<std::size_t>(in.number<std::int32_t>());
  }
  EXPECT_EQ(in.line(), "") << "the polygons end with a newline";
  w = words(in.line());
  w.resize(2);
  EXPECT_EQ(w[0], "CELL_DATA");
  n = count(w[1]);
  EXPECT_EQ(n, p.triangles.size());
  EXPECT_EQ(in.line(), "SCALARS body int 1");
  EXPECT_EQ(in.line(), "LOOKUP_TABLE default");
  p.body.resize(n);
  for (int& b : p.body) b = in.number<std::int32_t>();
  EXPECT_EQ(in.line(), "") << "the cell data end with a newline";
  w = words(in.line());
  w.resize(2);
  EXPECT_EQ(w[0], "POINT_DATA");
  n = count(w[1]);
  EXPECT_EQ(n, p.points.size());
  EXPECT_EQ(in.line(), "NORMALS Normals float");
  p.normals.resize(n);
  for (Vec& v : p.normals) {
    for (double& x : v) x = in.number<float>();
  }
  EXPECT_EQ(in.line(), "") << "the normals end with a newline";
  EXPECT_TRUE(in.atEnd()) << "unexpected data after byte " << in.position();
  return p;
}

/// rotation matrix of a quaternion (w, x, y, z), normalised here: R[i][j]
std::array<Vec, 3> rotationOf(std::array<double, 4> q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (double& c : q) c /= n;
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {{{w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
           {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
           {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}}};
}

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

std::vector<BodyShape> twoBodies() {
  BodyShape prolate;
  prolate.semiAxes = {0.3, 0.1, 0.1};
  prolate.centre = {1.5, -2.0, 0.25};
  prolate.orientation = {0.9, 0.1, -0.3, 0.2};  // not normalised: the writer normalises
  BodyShape oblate;
  oblate.semiAxes = {0.05, 0.2, 0.2};
  oblate.centre = {-3.0, 0.5, 7.0};
  oblate.orientation = {std::cos(0.4), 0, std::sin(0.4), 0};
  return {prolate, oblate};
}

void checkSurfaces(const std::string& file, const std::vector<BodyShape>& bodies, int s) {
  const PolyData p = parseVtk(file);
  ASSERT_EQ(p.header.size(), 4u);
  EXPECT_EQ(p.header[0], "# vtk DataFile Version 3.0");
  EXPECT_EQ(p.header[2], "BINARY");
  EXPECT_EQ(p.header[3], "DATASET POLYDATA");

  const std::size_t pointsPerBody = 10 * (std::size_t(1) << (2 * s)) + 2;
  const std::size_t trianglesPerBody = 20 * (std::size_t(1) << (2 * s));
  EXPECT_EQ(bodyoutput::surfacePointCount(s), pointsPerBody);
  EXPECT_EQ(bodyoutput::surfaceTriangleCount(s), trianglesPerBody);
  ASSERT_EQ(p.points.size(), pointsPerBody * bodies.size());
  ASSERT_EQ(p.triangles.size(), trianglesPerBody * bodies.size());

  // Points and normals are stored as float (rounded to nearest, relative error <= 2^-24 a
  // component): each point is on its ellipsoid, and its normal along the ellipsoid's gradient,
  // to within the error that rounding allows. With d the point's error (|d| <= sqrt(3) 2^-24
  // max|x_k|): |f - 1| <= 6 |d| / a_min, and the gradient turns by at most
  // |d| a_max / a_min^2 (1 - cos of that, plus the normal's own rounding).
  const double unit = std::ldexp(1.0, -24);
  double worstSurface = 0, worstNormal = 0;  // as fractions of the allowed error
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    const BodyShape& body = bodies[i / pointsPerBody];
    const auto r = rotationOf(body.orientation);
    const Vec d = sub(p.points[i], body.centre);
    // (x - c)^T R diag(1/a^2, 1/b^2, 1/c^2) R^T (x - c) = 1, and the normal along the gradient
    Vec local{}, gradient{};
    for (int k = 0; k < 3; ++k) local[k] = r[0][k] * d[0] + r[1][k] * d[1] + r[2][k] * d[2];
    double f = 0;
    for (int k = 0; k < 3; ++k) {
      f += local[k] * local[k] / (body.semiAxes[k] * body.semiAxes[k]);
    }
    const double aMin = std::min({body.semiAxes[0], body.semiAxes[1], body.semiAxes[2]});
    const double aMax = std::max({body.semiAxes[0], body.semiAxes[1], body.semiAxes[2]});
    const double xMax =
        std::max({std::abs(p.points[i][0]), std::abs(p.points[i][1]), std::abs(p.points[i][2])});
    const double pointError = std::sqrt(3.0) * unit * xMax;
    worstSurface = std::max(worstSurface, std::abs(f - 1) / (6 * pointError / aMin + 1e-12));
    for (int k = 0; k < 3; ++k) {
      gradient[k] = 0;
      for (int j = 0; j < 3; ++j) {
        gradient[k] += r[k][j] * local[j] / (body.semiAxes[j] * body.semiAxes[j]);
      }
    }
    const Vec& n = p.normals[i];
    EXPECT_NEAR(dot(n, n), 1, 4 * unit) << "point " << i;
    const double g = std::sqrt(dot(gradient, gradient));
    const double turn = pointError * aMax / (aMin * aMin);
    // 0 when parallel, outward
    worstNormal = std::max(worstNormal, (1 - dot(n, gradient) / g) / (4 * unit + turn * turn));
  }
  EXPECT_LE(worstSurface, 1);
  EXPECT_LE(worstNormal, 1);

  // triangles: the body's own points, outward, and each body's mesh closed (every edge used
  // twice, once in each direction) with V - E + F = 2
  std::map<std::pair<std::size_t, std::size_t>, int> edges;
  for (std::size_t t = 0; t < p.triangles.size(); ++t) {
    const std::size_t b = t / trianglesPerBody;
    EXPECT_EQ(p.body[t], static_cast<int>(b)) << "triangle " << t;
    const auto& tri = p.triangles[t];
    for (std::size_t i : tri) {
      ASSERT_GE(i, b * pointsPerBody);
      ASSERT_LT(i, (b + 1) * pointsPerBody);
    }
    const Vec centroid{(p.points[tri[0]][0] + p.points[tri[1]][0] + p.points[tri[2]][0]) / 3,
                       (p.points[tri[0]][1] + p.points[tri[1]][1] + p.points[tri[2]][1]) / 3,
                       (p.points[tri[0]][2] + p.points[tri[1]][2] + p.points[tri[2]][2]) / 3};
    const Vec n =
        cross(sub(p.points[tri[1]], p.points[tri[0]]), sub(p.points[tri[2]], p.points[tri[0]]));
    EXPECT_GT(dot(n, sub(centroid, bodies[b].centre)), 0) << "triangle " << t << " faces inwards";
    for (int k = 0; k < 3; ++k) ++edges[{tri[k], tri[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(edges.count({edge.second, edge.first}), 1u) << "open edge";
  }
  const std::size_t e = edges.size() / 2 / bodies.size();
  EXPECT_EQ(pointsPerBody + trianglesPerBody - e, 2u);
}

TEST_F(SurfaceVtkTest, SubdivisionsZeroAndTwo) {
  const auto bodies = twoBodies();
  for (int s : {0, 2}) {
    const std::string file = path("VTK/surfaces_" + std::to_string(s) + ".vtk");  // new folder
    writeSurfacesVtk(file, bodies, s);
    SCOPED_TRACE("subdivisions " + std::to_string(s));
    checkSurfaces(file, bodies, s);
    EXPECT_FALSE(fs::exists(file + ".tmp"));
  }
}

TEST_F(SurfaceVtkTest, ManyOrientations) {
  std::vector<BodyShape> bodies;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> size(0.01, 3);
  for (int i = 0; i < 20; ++i) {
    BodyShape b;
    b.semiAxes = {size(rng), size(rng), size(rng)};
    b.centre = {100 * normal(rng), 100 * normal(rng), normal(rng)};
    b.orientation = {normal(rng), normal(rng), normal(rng), normal(rng)};
    bodies.push_back(b);
  }
  const std::string file = path("many.vtk");
  writeSurfacesVtk(file, bodies, 1);
  checkSurfaces(file, bodies, 1);
}

TEST_F(SurfaceVtkTest, NoBodiesGivesAnEmptyValidFile) {
  const std::string file = path("none.vtk");
  writeSurfacesVtk(file, {}, 3);
  const PolyData p = parseVtk(file);
  EXPECT_TRUE(p.points.empty());
  EXPECT_TRUE(p.triangles.empty());
}

TEST_F(SurfaceVtkTest, InvalidArguments) {
  const std::string file = path("bad.vtk");
  auto bodies = twoBodies();
  EXPECT_THROW(writeSurfacesVtk(file, bodies, -1), std::invalid_argument);
  EXPECT_THROW(writeSurfacesVtk(file, bodies, bodyoutput::kMaxSurfaceSubdivisions + 1),
               std::invalid_argument);
  bodies[1].semiAxes[2] = 0;
  EXPECT_THROW(writeSurfacesVtk(file, bodies, 0), std::invalid_argument);
  bodies = twoBodies();
  bodies[0].orientation = {0, 0, 0, 0};
  EXPECT_THROW(writeSurfacesVtk(file, bodies, 0), std::invalid_argument);
  bodies = twoBodies();
  bodies[0].centre[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(writeSurfacesVtk(file, bodies, 0), std::invalid_argument);
  // more bodies than the 32-bit counts of the file hold (4 * 20 * 4^8 * 410 > 2^31 - 1)
  bodies.assign(410, twoBodies()[0]);
  try {
    writeSurfacesVtk(file, bodies, 8);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("410 bodies exceed the 32-bit counts of the file; at "
                                         "most 409 with 8 subdivisions"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(file));
  // a path that cannot be written: error naming it
  fs::create_directories(path("dir.vtk"));
  try {
    writeSurfacesVtk(path("dir.vtk"), twoBodies(), 0);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path("dir.vtk")), std::string::npos) << e.what();
  }
}

TEST_F(VtkSeriesTest, ContentIsParaViewsFileSeries) {
  const std::string file = path("VTK/surfaces.vtk.series");  // new folder
  writeVtkSeries(file, {{"surfaces_0.vtk", 0.0},
                        {"surfaces_1.vtk", 0.1},
                        {"sub/surfaces_2.vtk", 1e-5},
                        {"say \"hi\"\\.vtk", 2.5}});
  EXPECT_EQ(readFile(file),
            "{\n"
            "  \"file-series-version\" : \"1.0\",\n"
            "  \"files\" : [\n"
            "    { \"name\" : \"surfaces_0.vtk\", \"time\" : 0 },\n"
            "    { \"name\" : \"surfaces_1.vtk\", \"time\" : 0.1 },\n"
            "    { \"name\" : \"sub/surfaces_2.vtk\", \"time\" : 1e-05 },\n"
            "    { \"name\" : \"say \\\"hi\\\"\\\\.vtk\", \"time\" : 2.5 }\n"
            "  ]\n"
            "}\n");
  const Series back = readVtkSeries(file);
  ASSERT_EQ(back.size(), 4u);
  EXPECT_EQ(back[3].first, "say \"hi\"\\.vtk");
  EXPECT_EQ(back[2].second, 1e-5);

  // rewritten, not appended; an empty list
  writeVtkSeries(file, {});
  EXPECT_EQ(readFile(file), "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : []\n}\n");
  EXPECT_TRUE(readVtkSeries(file).empty());

  // times round-trip exactly
  const double t = 0.1 + 0.2;
  writeVtkSeries(file, {{"a.vtk", t}, {"b.vtk", -1.0 / 3}});
  EXPECT_EQ(readVtkSeries(file), (Series{{"a.vtk", t}, {"b.vtk", -1.0 / 3}}));
}

TEST_F(VtkSeriesTest, InvalidEntries) {
  const std::string file = path("s.series");
  EXPECT_THROW(writeVtkSeries(file, {{"a.vtk", std::numeric_limits<double>::infinity()}}),
               std::invalid_argument);
  EXPECT_THROW(writeVtkSeries(file, {{"a.vtk", std::numeric_limits<double>::quiet_NaN()}}),
               std::invalid_argument);
  EXPECT_THROW(writeVtkSeries(file, {{"", 1.0}}), std::invalid_argument);
  EXPECT_FALSE(fs::exists(file));
}

TEST_F(VtkSeriesTest, ReadsOtherJsonLayoutsAndReportsErrors) {
  const std::string file = path("s.series");
  writeFile(file, R"({"files":[{"time":1.5,"name":"a\u00e4.vtk","extra":[1,{"x":null}]}],
                     "file-series-version":"1.0","other":true})");
  EXPECT_EQ(readVtkSeries(file), (Series{{"a\xc3\xa4.vtk", 1.5}}));
  writeFile(file, "{\n  \"files\" : [ { \"name\" : \"a.vtk\", \"time\" : } ]\n}\n");
  try {
    readVtkSeries(file);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file + "', line 2, column 44: expected a number"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(readVtkSeries(path("missing.series")), std::runtime_error);
}

TEST_F(VtkSeriesTest, KeptAcrossRestarts) {
  const std::string file = path("surfaces.vtk.series");
  {
    VtkSeries series(file, 0.0);
    EXPECT_TRUE(series.files().empty());
    EXPECT_FALSE(fs::exists(file));
    series.add("s_1.vtk", 0.1);
    series.add("s_2.vtk", 0.2);
    series.add("s_3.vtk", 0.3);
  }
  VtkSeries restarted(file, 0.2);
  EXPECT_EQ(restarted.files(), (Series{{"s_1.vtk", 0.1}, {"s_2.vtk", 0.2}}));
  restarted.add("s_2.vtk", 0.2);  // the same file written again: listed once
  restarted.add("s_3.vtk", 0.3);
  EXPECT_EQ(readVtkSeries(file), (Series{{"s_1.vtk", 0.1}, {"s_2.vtk", 0.2}, {"s_3.vtk", 0.3}}));
  EXPECT_THROW(restarted.add("s_4.vtk", std::numeric_limits<double>::infinity()),
               std::invalid_argument);
  EXPECT_EQ(restarted.files().size(), 3u);
}

}  // namespace
