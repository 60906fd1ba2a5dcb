#include "bodyOutput/SurfaceVtk.hpp"

#include "Files.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <string_view>
#include <unordered_map>

namespace bodyoutput {

namespace {

using Vec3 = std::array<double, 3>;
using Triangle = std::array<std::uint32_t, 3>;

std::string numberText(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

Vec3 normalised(const Vec3& v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

/// Unit sphere: an icosahedron subdivided `subdivisions` times (each triangle into four, the new
/// points pushed onto the sphere), points shared, triangles counter-clockwise seen from outside.
void unitSphere(int subdivisions, std::vector<Vec3>& points, std::vector<Triangle>& triangles) {
  const double p = (1 + std::sqrt(5.0)) / 2;
  points = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
            {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
  for (Vec3& v : points) v = normalised(v);
  triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
               {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
               {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
               {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  // orient outwards whatever the table says: (p1 - p0) x (p2 - p0) along the centroid
  for (Triangle& t : triangles) {
    const Vec3& a = points[t[0]];
    const Vec3& b = points[t[1]];
    const Vec3& c = points[t[2]];
    const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const Vec3 v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const Vec3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    if (n[0] * (a[0] + b[0] + c[0]) + n[1] * (a[1] + b[1] + c[1]) + n[2] * (a[2] + b[2] + c[2]) <
        0) {
      std::swap(t[1], t[2]);
    }
  }
  for (int s = 0; s < subdivisions; ++s) {
    std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
    midpoints.reserve(triangles.size() * 2);
    auto midpoint = [&](std::uint32_t i, std::uint32_t j) {
      const std::uint64_t key = (std::uint64_t(std::min(i, j)) << 32) | std::max(i, j);
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      const Vec3& a = points[i];
      const Vec3& b = points[j];
      points.push_back(normalised({a[0] + b[0], a[1] + b[1], a[2] + b[2]}));
      const auto index = static_cast<std::uint32_t>(points.size() - 1);
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<Triangle> finer;
    finer.reserve(triangles.size() * 4);
    for (const Triangle& t : triangles) {
      const std::uint32_t ab = midpoint(t[0], t[1]);
      const std::uint32_t bc = midpoint(t[1], t[2]);
      const std::uint32_t ca = midpoint(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    triangles.swap(finer);
  }
}


void validate(const BodyShape& body, std::size_t index, const std::string& who) {
  const std::string name = who + ": body " + std::to_string(index);
  for (double a : body.semiAxes) {
    if (!(a > 0) || !std::isfinite(a)) {
      throw std::invalid_argument(name + ": semi-axes must be finite and > 0, got " +
                                  numberText(body.semiAxes[0]) + ", " +
                                  numberText(body.semiAxes[1]) + ", " +
                                  numberText(body.semiAxes[2]));
    }
  }
  for (double c : body.centre) {
    if (!std::isfinite(c)) {
      throw std::invalid_argument(name + ": the centre must be finite, got " +
                                  numberText(body.centre[0]) + ", " + numberText(body.centre[1]) +
                                  ", " + numberText(body.centre[2]));
    }
  }
  const auto& q = body.orientation;
  const double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  if (!std::isfinite(n2) || !(n2 > 1e-200)) {
    throw std::invalid_argument(name + ": the quaternion (w, x, y, z) = (" + numberText(q[0]) +
                                ", " + numberText(q[1]) + ", " + numberText(q[2]) + ", " +
                                numberText(q[3]) + ") must be finite and not zero");
  }
}

/// Writes text and 4-byte numbers to a stream through a buffer of about 1 MB: the numbers big
/// endian (legacy VTK binary is big-endian whatever the machine). Neither appending millions of
/// 4-byte pieces to one string nor holding the whole file in memory (first-touch page faults of
/// ~100 MB) is as cheap.
class BigEndianWriter {
 public:
  explicit BigEndianWriter(std::ostream& out) : out_(out) { buffer_.reserve(kSize + 64); }

  template <class T>
  void put(T v) {
    static_assert(sizeof(T) == 4, "4-byte values only");
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, 4);
    const char bytes[4] = {static_cast<char>(bits >> 24), static_cast<char>(bits >> 16),
                           static_cast<char>(bits >> 8), static_cast<char>(bits)};
    buffer_.append(bytes, 4);
    if (buffer_.size() >= kSize) flush();
  }
  void text(const std::string& s) {
    buffer_ += s;
    if (buffer_.size() >= kSize) flush();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kSize = std::size_t(1) << 20;
  std::ostream& out_;
  std::string buffer_;
};

void checkSubdivisions(int subdivisions, const std::string& who) {
  if (subdivisions < 0 || subdivisions > kMaxSurfaceSubdivisions) {
    throw std::invalid_argument(who + ": subdivisions must be in [0, " +
                                std::to_string(kMaxSurfaceSubdivisions) + "], got " +
                                std::to_string(subdivisions));
  }
}

// ------------------------------------------------------------------ JSON

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const auto u = static_cast<unsigned char>(ch);
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      default:
        if (u < 0x20) {
          static const char* const hex = "0123456789abcdef";
          out += "\\u00";
          out += hex[u >> 4];
          out += hex[u & 15];
        } else {
          out += ch;  // UTF-8 bytes as they are
        }
    }
  }
  return out + "\"";
}

/// A small JSON reader for series files: keeps the "name" and "time" of the members of "files".
class SeriesParser {
 public:
  SeriesParser(const std::string& text, const std::string& where) : s_(text), where_(where) {}

  std::vector<std::pair<std::string, double>> parse() {
    skipSpace();
    if (peek() != '{') error("expected a JSON object");
    bool sawFiles = false;
    object([&](const std::string& key) {
      if (key == "files") {
        sawFiles = true;
        files();
      } else {
        skipValue();
      }
    });
    skipSpace();
    if (pos_ != s_.size()) error("unexpected text after the JSON object");
    if (!sawFiles) error("no \"files\" member");
    return files_;
  }

 private:
  [[noreturn]] void error(const std::string& what) const {
    // line and column of pos_
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < pos_ && i < s_.size(); ++i) {
      if (s_[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw std::runtime_error(where_ + ", line " + std::to_string(line) + ", column " +
                             std::to_string(column) + ": " + what);
  }
  char peek() const { return pos_ < s_.size() ? s_[pos_] : '\0'; }
  void skipSpace() {
    while (pos_ < s_.size() &&
           (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\n' || s_[pos_] == '\r')) {
      ++pos_;
    }
  }
  void expect(char c) {
    skipSpace();
    if (peek() != c) error(std::string("expected '") + c + "'");
    ++pos_;
  }

  template <class OnMember>
  void object(OnMember onMember) {
    expect('{');
    skipSpace();
    if (peek() == '}') {
      ++pos_;
      return;
    }
    while (true) {
      skipSpace();
      const std::string key = string();
      expect(':');
      skipSpace();
      onMember(key);
      skipSpace();
      if (peek() == ',') {
        ++pos_;
        continue;
      }
      expect('}');
      return;
    }
  }

  template <class OnElement>
  void array(OnElement onElement) {
    expect('[');
    skipSpace();
    if (peek() == ']') {
      ++pos_;
      return;
    }
    while (true) {
      skipSpace();
      onElement();
      skipSpace();
      if (peek() == ',') {
        ++pos_;
        continue;
      }
      expect(']');
      return;
    }
  }

  void files() {
    if (peek() != '[') error("\"files\" must be an array");
    array([&] {
      if (peek() != '{') error("each member of \"files\" must be an object");
      std::string name;
      double time = 0;
      bool hasName = false, hasTime = false;
      object([&](const std::string& key) {
        if (key == "name") {
          if (peek() != '"') error("\"name\" must be a string");
          name = string();
          hasName = true;
        } else if (key == "time") {
          time = number();
          hasTime = true;
        } else {
          skipValue();
        }
      });
      if (!hasName || !hasTime) error("a member of \"files\" lacks \"name\" or \"time\"");
      files_.emplace_back(name, time);
    });
  }

  static void appendUtf8(std::string& out, unsigned code) {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | (code >> 6));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xE0 | (code >> 12));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (code >> 18));
      out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  unsigned hex4() {
    if (pos_ + 4 > s_.size()) error("truncated \\u escape");
    unsigned v = 0;
    const auto r = std::from_chars(s_.data() + pos_, s_.data() + pos_ + 4, v, 16);
    if (r.ptr != s_.data() + pos_ + 4) error("bad \\u escape");
    pos_ += 4;
    return v;
  }

  std::string string() {
    if (peek() != '"') error("expected a string");
    ++pos_;
    std::string out;
    while (true) {
      if (pos_ >= s_.size()) error("unterminated string");
      const char c = s_[pos_++];
      if (c == '"') return out;
      if (static_cast<unsigned char>(c) < 0x20) error("control character in a string");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (pos_ >= s_.size()) error("unterminated string");
      const char e = s_[pos_++];
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          unsigned code = hex4();
          if (code >= 0xD800 && code < 0xDC00 && s_.compare(pos_, 2, "\\u") == 0) {
            pos_ += 2;
            const unsigned low = hex4();
            if (low < 0xDC00 || low >= 0xE000) error("bad surrogate pair");
            code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
          }
          appendUtf8(out, code);
          break;
        }
        default: error(std::string("bad escape '\\") + e + "'");
      }
    }
  }

  double number() {
    const std::size_t begin = pos_;
    while (pos_ < s_.size() && std::string_view("+-0123456789.eE").find(s_[pos_]) !=
                                   std::string_view::npos) {
      ++pos_;
    }
    double v = 0;
    const auto r = std::from_chars(s_.data() + begin, s_.data() + pos_, v);
    if (begin == pos_ || r.ec != std::errc() || r.ptr != s_.data() + pos_) {
      pos_ = begin;
      error("expected a number");
    }
    return v;
  }

  void literal(const char* word) {
    const std::string w(word);
    if (s_.compare(pos_, w.size(), w) != 0) error("unexpected character");
    pos_ += w.size();
  }

  void skipValue() {
    skipSpace();
    const char c = peek();
    if (c == '{') {
      object([&](const std::string&) { skipValue(); });
    } else if (c == '[') {
      array([&] { skipValue(); });
    } else if (c == '"') {
      string();
    } else if (c == 't') {
      literal("true");
    } else if (c == 'f') {
      literal("false");
    } else if (c == 'n') {
      literal("null");
    } else {
      number();
    }
  }

  const std::string& s_;
  std::string where_;
  std::size_t pos_ = 0;
  std::vector<std::pair<std::string, double>> files_;
};

double keepThreshold(double t) {
  if (std::isinf(t)) return t;
  return (t >= 0 ? t * (1 + 1e-12) : t * (1 - 1e-12)) + 1e-300;
}

}  // namespace

UnitSphereMesh unitSphereMesh(int subdivisions) {
  UnitSphereMesh mesh;
  unitSphere(subdivisions, mesh.points, mesh.triangles);
  return mesh;
}

std::array<double, 9> rotationMatrix(const std::array<double, 4>& q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

std::array<double, 3> surfacePoint(const BodyShape& body, const std::array<double, 9>& r,
                                   const std::array<double, 3>& u) {
  const Vec3& s = body.semiAxes;
  const Vec3 local{s[0] * u[0], s[1] * u[1], s[2] * u[2]};
  Vec3 x;
  for (int k = 0; k < 3; ++k) {
    x[k] = body.centre[k] + (r[3 * k] * local[0] + r[3 * k + 1] * local[1] + r[3 * k + 2] * local[2]);
  }
  return x;
}

std::array<double, 3> surfaceNormal(const BodyShape& body, const std::array<double, 9>& r,
                                    const std::array<double, 3>& u) {
  const Vec3& s = body.semiAxes;
  const Vec3 g{u[0] / s[0], u[1] / s[1], u[2] / s[2]};  // body-frame gradient direction
  return normalised({r[0] * g[0] + r[1] * g[1] + r[2] * g[2], r[3] * g[0] + r[4] * g[1] + r[5] * g[2],
                     r[6] * g[0] + r[7] * g[1] + r[8] * g[2]});
}

std::size_t surfacePointCount(int subdivisions) {
  checkSubdivisions(subdivisions, "surfacePointCount");
  return 10 * (std::size_t(1) << (2 * subdivisions)) + 2;
}

std::size_t surfaceTriangleCount(int subdivisions) {
  checkSubdivisions(subdivisions, "surfaceTriangleCount");
  return 20 * (std::size_t(1) << (2 * subdivisions));
}

void writeSurfacesVtk(const std::string& path, const std::vector<BodyShape>& bodies,
                      int subdivisions) {
  const std::string who = "writeSurfacesVtk: '" + path + "'";
  checkSubdivisions(subdivisions, who);
  for (std::size_t i = 0; i < bodies.size(); ++i) validate(bodies[i], i, who);
  // point indices, counts and the body index are 32-bit signed in the file
  const std::size_t pointsPerBody = surfacePointCount(subdivisions);
  const std::size_t maxBodies = std::size_t(std::numeric_limits<std::int32_t>::max()) /
                                (4 * surfaceTriangleCount(subdivisions));
  if (bodies.size() > maxBodies) {
    throw std::invalid_argument(who + ": " + std::to_string(bodies.size()) +
                                " bodies exceed the 32-bit counts of the file; at most " +
                                std::to_string(maxBodies) + " with " +
                                std::to_string(subdivisions) + " subdivisions");
  }

  const UnitSphereMesh sphere = unitSphereMesh(subdivisions);
  const std::vector<Triangle>& triangles = sphere.triangles;
  const std::size_t np = pointsPerBody * bodies.size();
  const std::size_t nt = triangles.size() * bodies.size();

  auto write = [&](std::ostream& stream) {
    BigEndianWriter out(stream);
    out.text("# vtk DataFile Version 3.0\nspheroidFoam body surfaces\nBINARY\n"
             "DATASET POLYDATA\nPOINTS " + std::to_string(np) + " float\n");
    for (const BodyShape& body : bodies) {
      const std::array<double, 9> r = rotationMatrix(body.orientation);
      for (const Vec3& u : sphere.points) {
        for (double xk : surfacePoint(body, r, u)) out.put(static_cast<float>(xk));
      }
    }
    // each binary block ends with a newline, as VTK's own legacy writer does
    out.text("\nPOLYGONS " + std::to_string(nt) + " " + std::to_string(4 * nt) + "\n");
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const std::size_t offset = b * pointsPerBody;
      for (const Triangle& t : triangles) {
        out.put(std::int32_t{3});
        for (std::uint32_t i : t) out.put(static_cast<std::int32_t>(offset + i));
      }
    }
    out.text("\nCELL_DATA " + std::to_string(nt) +
             "\nSCALARS body int 1\nLOOKUP_TABLE default\n");
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const std::int32_t id = bodies[b].id >= 0 ? bodies[b].id : static_cast<std::int32_t>(b);
      for (std::size_t t = 0; t < triangles.size(); ++t) out.put(id);
    }
    out.text("\nPOINT_DATA " + std::to_string(np) + "\nNORMALS Normals float\n");
    for (const BodyShape& body : bodies) {
      const std::array<double, 9> r = rotationMatrix(body.orientation);
      for (const Vec3& u : sphere.points) {
        for (double nk : surfaceNormal(body, r, u)) out.put(static_cast<float>(nk));
      }
    }
    out.text("\n");
    out.flush();
  };
  detail::writeFileAtomically(path, write, "writeSurfacesVtk");
}

void writeVtkSeries(const std::string& seriesPath,
                    const std::vector<std::pair<std::string, double>>& files) {
  const std::string who = "writeVtkSeries: '" + seriesPath + "'";
  std::string out = "{\n  \"file-series-version\" : \"1.0\",\n  \"files\" : [";
  for (std::size_t i = 0; i < files.size(); ++i) {
    const auto& [name, time] = files[i];
    if (name.empty()) {
      throw std::invalid_argument(who + ": entry " + std::to_string(i) + " has an empty name");
    }
    if (!std::isfinite(time)) {
      throw std::invalid_argument(who + ": entry " + std::to_string(i) + " (" + name +
                                  "): time must be finite, got " + numberText(time));
    }
    out += i ? ",\n" : "\n";
    out += "    { \"name\" : " + jsonString(name) + ", \"time\" : " + detail::shortest(time) + " }";
  }
  out += files.empty() ? "]\n}\n" : "\n  ]\n}\n";
  detail::writeFileAtomically(seriesPath, out, "writeVtkSeries");
}

std::vector<std::pair<std::string, double>> readVtkSeries(const std::string& seriesPath) {
  const std::string where = "readVtkSeries: '" + seriesPath + "'";
  std::ifstream in(seriesPath, std::ios::binary);
  if (!in) throw std::runtime_error(where + ": cannot open it");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error(where + ": error while reading it");
  return SeriesParser(text, where).parse();
}

VtkSeries::VtkSeries(std::string seriesPath, double restartTime) : path_(std::move(seriesPath)) {
  if (std::isnan(restartTime)) {
    throw std::invalid_argument("VtkSeries: '" + path_ + "': restartTime is NaN");
  }
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) return;
  files_ = readVtkSeries(path_);
  const double threshold = keepThreshold(restartTime);
  files_.erase(std::remove_if(files_.begin(), files_.end(),
                              [&](const auto& f) { return !(f.second <= threshold); }),
               files_.end());
}

void VtkSeries::add(const std::string& fileName, double time) {
  std::vector<std::pair<std::string, double>> next = files_;
  next.erase(std::remove_if(next.begin(), next.end(),
                            [&](const auto& f) { return f.first == fileName; }),
             next.end());
  next.emplace_back(fileName, time);
  writeVtkSeries(path_, next);  // throws before files_ changes
  files_.swap(next);
}

}  // namespace bodyoutput
