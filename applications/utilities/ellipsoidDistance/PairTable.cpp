#include "PairTable.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace pairtable {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::string number(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream is(line);
  while (std::getline(is, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

}  // namespace

const std::vector<std::string>& columns() {
  static const std::vector<std::string> c = {"a1", "b1", "c1", "x1", "y1", "z1", "qw1",
                                             "qx1", "qy1", "qz1", "a2", "b2", "c2", "x2",
                                             "y2", "z2", "qw2", "qx2", "qy2", "qz2"};
  return c;
}

std::vector<Pair> read(std::istream& in, const std::string& source) {
  std::vector<Pair> pairs;
  std::string line;
  int lineNo = 0;
  // header: the first non-blank line
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    ++lineNo;
    if (!trim(line).empty()) {
      header = split(trim(line));
      break;
    }
  }
  std::string expected;
  for (const auto& c : columns()) expected += (expected.empty() ? "" : ",") + c;
  if (header != columns()) {
    throw InputError(source + ", line " + std::to_string(lineNo) +
                     ": the header must be exactly\n    " + expected +
                     (header.empty() ? "\n  (the input is empty)" : ""));
  }

  int row = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (trim(line).empty()) continue;
    ++row;
    const std::string where = source + ", row " + std::to_string(row) + " (line " +
                              std::to_string(lineNo) + ")";
    const std::vector<std::string> fields = split(trim(line));
    if (fields.size() != columns().size()) {
      throw InputError(where + ": " + std::to_string(fields.size()) + " fields, expected " +
                       std::to_string(columns().size()) + " (" + expected + ")");
    }
    double v[20];
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const char* begin = fields[i].c_str();
      char* end = nullptr;
      errno = 0;
      v[i] = std::strtod(begin, &end);
      if (fields[i].empty() || end != begin + fields[i].size() || errno == ERANGE ||
          !std::isfinite(v[i])) {
        throw InputError(where + ": column " + columns()[i] + ": '" + fields[i] +
                         "' is not a finite number");
      }
    }
    using Range = ellipsoids::SupportedRange;
    const std::string lengths = "[" + number(Range::kMinLength) + ", " + number(Range::kMaxLength) + "]";
    for (int body = 0; body < 2; ++body) {
      const int o = 10 * body;
      for (int k = 0; k < 3; ++k) {
        if (!(v[o + k] > 0)) {
          throw InputError(where + ": semi-axis " + columns()[o + k] + " = " + fields[o + k] +
                           " must be > 0");
        }
        if (!(v[o + k] >= Range::kMinLength && v[o + k] <= Range::kMaxLength)) {
          throw InputError(where + ": semi-axis " + columns()[o + k] + " = " + fields[o + k] +
                           " must be in " + lengths + " (the range the geometry core supports)");
        }
        if (!(std::abs(v[o + 3 + k]) <= Range::kMaxLength)) {
          throw InputError(where + ": centre " + columns()[o + 3 + k] + " = " + fields[o + 3 + k] +
                           " must be at most " + number(Range::kMaxLength) + " in magnitude");
        }
      }
      const double longest = std::max({v[o], v[o + 1], v[o + 2]});
      const double shortest = std::min({v[o], v[o + 1], v[o + 2]});
      if (!(longest <= Range::kMaxElongation * (1 + 1e-12) * shortest)) {
        throw InputError(where + ": semi-axes (" + columns()[o] + "," + columns()[o + 1] + "," +
                         columns()[o + 2] + ") = (" + fields[o] + "," + fields[o + 1] + "," +
                         fields[o + 2] + "): the largest over the smallest must be at most " +
                         number(Range::kMaxElongation) + " (aspect ratio 1/" +
                         number(Range::kMaxElongation) + " to " + number(Range::kMaxElongation) + ")");
      }
      const double qn = std::sqrt(v[o + 6] * v[o + 6] + v[o + 7] * v[o + 7] +
                                  v[o + 8] * v[o + 8] + v[o + 9] * v[o + 9]);
      if (std::abs(qn - 1) > 1e-6) {
        std::ostringstream os;
        os.precision(17);
        os << where << ": quaternion (qw" << body + 1 << ",qx" << body + 1 << ",qy" << body + 1
           << ",qz" << body + 1 << ") has norm " << qn
           << "; it must be a unit quaternion (norm within 1e-6 of 1)";
        throw InputError(os.str());
      }
    }
    using ellipsoids::Quat;
    using ellipsoids::Vec3;
    try {
      pairs.push_back(Pair{row,
                           ellipsoids::Ellipsoid(Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]),
                                                 Quat(v[6], v[7], v[8], v[9])),
                           ellipsoids::Ellipsoid(Vec3(v[10], v[11], v[12]), Vec3(v[13], v[14], v[15]),
                                                 Quat(v[16], v[17], v[18], v[19]))});
    } catch (const std::invalid_argument& e) {
      throw InputError(where + ": " + e.what());
    }
  }
  return pairs;
}

}  // namespace pairtable
