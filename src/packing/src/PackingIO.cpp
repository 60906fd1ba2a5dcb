#include "packing/PackingIO.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace packing {

using ellipsoids::Ellipsoid;
using ellipsoids::Quat;
using ellipsoids::Vec3;

namespace {

const char* const kHeader = "a,b,c,x,y,z,qw,qx,qy,qz";
const char* const kColumns[10] = {"a", "b", "c", "x", "y", "z", "qw", "qx", "qy", "qz"};

/// 17 significant digits, locale-independent ("%.17g")
std::string number(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  return std::string(buf, r.ptr);
}

std::string shortNumber(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

std::string trim(const std::string& s) {
  std::size_t b = 0, e = s.size();
  while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
  return s.substr(b, e - b);
}

/// whole string as a double (from_chars: locale-independent, exact round trip)
bool parseDouble(const std::string& s, double& v) {
  if (s.empty()) return false;
  const char* first = s.data();
  if (*first == '+') ++first;  // from_chars rejects a leading '+'
  const auto r = std::from_chars(first, s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

template <class Int>
bool parseInteger(const std::string& s, Int& v) {
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

/// What is wrong with a body read from a file ("" if nothing): semi-axes finite and > 0,
/// centre finite and in [0, L)^3, quaternion within 1e-6 of unit norm (as Ellipsoid requires).
std::string bodyProblem(const double* semi, const double* centre, const double* q, double L) {
  std::ostringstream os;
  os.precision(17);
  for (int k = 0; k < 3; ++k) {
    if (!(semi[k] > 0) || !std::isfinite(semi[k])) {
      os << "semi-axis " << kColumns[k] << " must be finite and > 0, got " << semi[k];
      return os.str();
    }
  }
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(centre[k]) || centre[k] < 0 || centre[k] >= L) {
      os << "centre " << kColumns[3 + k] << " must be finite and in [0, boxLength = " << L
         << "), got " << centre[k];
      return os.str();
    }
  }
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!std::isfinite(norm) || std::abs(norm - 1) > 1e-6) {
    os << "quaternion (qw, qx, qy, qz) = (" << q[0] << ", " << q[1] << ", " << q[2] << ", " << q[3]
       << ") has norm " << norm << ", not within 1e-6 of 1";
    return os.str();
  }
  return "";
}

Ellipsoid makeBody(const double* semi, const double* centre, const double* q) {
  return Ellipsoid(Vec3(semi[0], semi[1], semi[2]), Vec3(centre[0], centre[1], centre[2]),
                   Quat(q[0], q[1], q[2], q[3]));
}

void checkBoxLength(double L, const std::string& where) {
  if (!(L > 0) || !std::isfinite(L)) {
    throw std::runtime_error(where + ": boxLength must be finite and > 0, got " + shortNumber(L));
  }
}

std::string lowerExtension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return ext;
}

}  // namespace

// ---------------------------------------------------------------- CSV

void writeCsv(const Packing& p, const std::string& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("writeCsv: cannot open '" + path + "' for writing");
  std::string text;
  text.reserve(200 * p.bodies.size() + 512);
  text += "# spheroidFoam packing (random sequential addition of spheroids)\n";
  text += "# formatVersion " + std::to_string(kPackingFormatVersion) + "\n";
  text += "# boxLength " + number(p.boxLength) + "\n";
  text += "# aspectRatio " + number(p.aspectRatio) + "\n";
  text += "# equivalentDiameter " + number(p.equivalentDiameter) + "\n";
  text += "# volumeFraction " + number(p.volumeFraction) + "\n";
  text += "# seed " + std::to_string(p.seed) + "\n";
  text += "# bodies " + std::to_string(p.bodies.size()) + "\n";
  text += kHeader;
  text += '\n';
  for (const Ellipsoid& e : p.bodies) {
    const Vec3& s = e.semiAxes();
    const Vec3& c = e.centre();
    const Quat& q = e.orientation();
    const double v[10] = {s.x(), s.y(), s.z(), c.x(), c.y(), c.z(), q.w(), q.x(), q.y(), q.z()};
    for (int k = 0; k < 10; ++k) {
      if (k) text += ',';
      text += number(v[k]);
    }
    text += '\n';
  }
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::runtime_error("writeCsv: error while writing '" + path + "'");
}

Packing readCsv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("readCsv: cannot open '" + path + "'");
  Packing p;
  std::map<std::string, std::string> meta;  // key -> value text
  std::map<std::string, long> metaLine;
  bool headerSeen = false;
  long lineNo = 0, headerLine = 0;
  std::string line;
  auto where = [&](long l) { return "readCsv: " + path + ":" + std::to_string(l); };

  auto metaDouble = [&](const std::string& key, double& v) {
    auto it = meta.find(key);
    if (it == meta.end()) return false;
    if (!parseDouble(it->second, v)) {
      throw std::runtime_error(where(metaLine[key]) + ": metadata '" + key + "': cannot parse '" +
                               it->second + "' as a number");
    }
    return true;
  };

  while (std::getline(in, line)) {
    ++lineNo;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t[0] == '#') {
      std::istringstream ls(t.substr(1));
      std::string key, value, extra;
      ls >> key >> value;
      static const char* const known[] = {"formatVersion", "boxLength",      "aspectRatio",
                                          "equivalentDiameter", "volumeFraction", "seed",
                                          "bodies"};
      if (std::find_if(std::begin(known), std::end(known),
                       [&](const char* k) { return key == k; }) == std::end(known)) {
        continue;  // a free comment
      }
      if (headerSeen) {
        throw std::runtime_error(where(lineNo) + ": metadata '" + key +
                                 "' after the header line (line " + std::to_string(headerLine) +
                                 "); metadata must come first");
      }
      if (value.empty() || (ls >> extra)) {
        throw std::runtime_error(where(lineNo) + ": metadata '" + key +
                                 "' needs exactly one value: '# " + key + " <value>'");
      }
      if (meta.count(key)) {
        throw std::runtime_error(where(lineNo) + ": metadata '" + key + "' given twice (lines " +
                                 std::to_string(metaLine[key]) + " and " + std::to_string(lineNo) +
                                 ")");
      }
      meta[key] = value;
      metaLine[key] = lineNo;
      continue;
    }

    if (!headerSeen) {
      std::string compact;
      for (char ch : t)
        if (!std::isspace(static_cast<unsigned char>(ch))) compact += ch;
      if (compact != kHeader) {
        throw std::runtime_error(where(lineNo) + ": expected the header line '" + kHeader +
                                 "', got '" + t + "'");
      }
      headerSeen = true;
      headerLine = lineNo;
      // metadata: required ones first
      auto v = meta.find("formatVersion");
      if (v == meta.end()) {
        throw std::runtime_error(where(lineNo) + ": no '# formatVersion' line before the header");
      }
      int version = 0;
      if (!parseInteger(v->second, version)) {
        throw std::runtime_error(where(metaLine["formatVersion"]) +
                                 ": metadata 'formatVersion': cannot parse '" + v->second +
                                 "' as an integer");
      }
      if (version != kPackingFormatVersion) {
        throw std::runtime_error(where(metaLine["formatVersion"]) + ": formatVersion " +
                                 v->second + " is not supported (this reader reads version " +
                                 std::to_string(kPackingFormatVersion) + ")");
      }
      if (!metaDouble("boxLength", p.boxLength)) {
        throw std::runtime_error(where(lineNo) + ": no '# boxLength' line before the header");
      }
      checkBoxLength(p.boxLength, where(metaLine["boxLength"]));
      metaDouble("aspectRatio", p.aspectRatio);
      metaDouble("equivalentDiameter", p.equivalentDiameter);
      metaDouble("volumeFraction", p.volumeFraction);
      if (meta.count("seed") && !parseInteger(meta["seed"], p.seed)) {
        throw std::runtime_error(where(metaLine["seed"]) + ": metadata 'seed': cannot parse '" +
                                 meta["seed"] + "' as an unsigned 64-bit integer");
      }
      if (meta.count("bodies")) {
        std::size_t count = 0;
        if (!parseInteger(meta["bodies"], count)) {
          throw std::runtime_error(where(metaLine["bodies"]) +
                                   ": metadata 'bodies': cannot parse '" + meta["bodies"] +
                                   "' as a count");
        }
        p.bodies.reserve(std::min<std::size_t>(count, 100000000));
      }
      continue;
    }

    // a body
    double v[10];
    std::size_t column = 0, begin = 0;
    while (true) {
      const std::size_t comma = t.find(',', begin);
      const std::string field = trim(t.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin));
      if (column < 10 && !parseDouble(field, v[column])) {
        throw std::runtime_error(where(lineNo) + ", column " + std::to_string(column + 1) + " (" +
                                 kColumns[column] + "): cannot parse '" + field +
                                 "' as a number");
      }
      ++column;
      if (comma == std::string::npos) break;
      begin = comma + 1;
    }
    if (column != 10) {
      throw std::runtime_error(where(lineNo) + ": expected 10 columns (" + kHeader + "), got " +
                               std::to_string(column));
    }
    const std::string problem = bodyProblem(v, v + 3, v + 6, p.boxLength);
    if (!problem.empty()) throw std::runtime_error(where(lineNo) + ": " + problem);
    try {
      p.bodies.push_back(makeBody(v, v + 3, v + 6));
    } catch (const std::exception& e) {
      throw std::runtime_error(where(lineNo) + ": " + e.what());
    }
  }
  if (in.bad()) throw std::runtime_error("readCsv: error while reading '" + path + "'");
  if (!headerSeen) {
    throw std::runtime_error("readCsv: " + path + ": no header line '" + kHeader + "'");
  }
  if (meta.count("bodies")) {
    std::size_t count = 0;
    parseInteger(meta["bodies"], count);
    if (count != p.bodies.size()) {
      throw std::runtime_error(where(metaLine["bodies"]) + ": metadata 'bodies' says " +
                               meta["bodies"] + " but the file has " +
                               std::to_string(p.bodies.size()) + " body rows (truncated file?)");
    }
  }
  return p;
}

// ---------------------------------------------------------------- HDF5

namespace {

/// closes an HDF5 identifier on scope exit
class H5Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  H5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  ~H5Handle() {
    if (id_ >= 0) closer_(id_);
  }
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  /// closes now, returns false if closing failed (a write error may show only here)
  bool close() {
    const hid_t id = id_;
    id_ = -1;
    return id < 0 || closer_(id) >= 0;
  }

 private:
  hid_t id_;
  Closer closer_;
};

/// silences HDF5's automatic error-stack printing for the scope (errors are thrown instead)
class H5Quiet {
 public:
  H5Quiet() {
    H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  H5Quiet(const H5Quiet&) = delete;
  H5Quiet& operator=(const H5Quiet&) = delete;
  ~H5Quiet() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }

 private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

void writeDataset(hid_t file, const char* name, const std::vector<double>& data, hsize_t rows,
                  hsize_t columns, const std::string& path) {
  const hsize_t dims[2] = {rows, columns};
  H5Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose);
  if (!space.valid()) throw std::runtime_error("writeHdf5: '" + path + "': cannot create the dataspace of '" + name + "'");
  H5Handle set(H5Dcreate2(file, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               H5Dclose);
  if (!set.valid()) throw std::runtime_error("writeHdf5: '" + path + "': cannot create dataset '" + name + "'");
  if (rows > 0 &&
      H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0) {
    throw std::runtime_error("writeHdf5: '" + path + "': cannot write dataset '" + name + "'");
  }
}

void writeAttribute(hid_t object, const char* name, hid_t fileType, hid_t memType, const void* value,
                    const std::string& path) {
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  H5Handle attr(H5Acreate2(object, name, fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!space.valid() || !attr.valid() || H5Awrite(attr.get(), memType, value) < 0) {
    throw std::runtime_error("writeHdf5: '" + path + "': cannot write attribute '" + name + "'");
  }
}

/// reads a rank-2 float dataset with `columns` columns; returns the row count
std::vector<double> readDataset(hid_t file, const char* name, hsize_t columns, hsize_t& rows,
                                const std::string& path) {
  const std::string where = "readHdf5: '" + path + "': dataset '" + std::string(name) + "'";
  if (H5Lexists(file, name, H5P_DEFAULT) <= 0) throw std::runtime_error(where + " is missing");
  H5Handle set(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose);
  if (!set.valid()) throw std::runtime_error(where + " cannot be opened as a dataset");
  H5Handle type(H5Dget_type(set.get()), H5Tclose);
  if (!type.valid() || H5Tget_class(type.get()) != H5T_FLOAT) {
    throw std::runtime_error(where + " must hold floating-point numbers");
  }
  H5Handle space(H5Dget_space(set.get()), H5Sclose);
  hsize_t dims[2] = {0, 0};
  if (!space.valid() || H5Sget_simple_extent_ndims(space.get()) != 2 ||
      H5Sget_simple_extent_dims(space.get(), dims, nullptr) != 2 || dims[1] != columns) {
    throw std::runtime_error(where + " must be a 2-d array N x " + std::to_string(columns));
  }
  rows = dims[0];
  std::vector<double> data(static_cast<std::size_t>(rows * columns));
  if (rows > 0 &&
      H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0) {
    throw std::runtime_error(where + " cannot be read");
  }
  return data;
}

/// reads a scalar (or 1-element) attribute of the root group; false if absent
bool readAttribute(hid_t root, const char* name, H5T_class_t typeClass, hid_t memType, void* value,
                   const std::string& path) {
  const std::string where = "readHdf5: '" + path + "': attribute '" + std::string(name) + "'";
  const htri_t exists = H5Aexists(root, name);
  if (exists < 0) throw std::runtime_error(where + " cannot be queried");
  if (exists == 0) return false;
  H5Handle attr(H5Aopen(root, name, H5P_DEFAULT), H5Aclose);
  if (!attr.valid()) throw std::runtime_error(where + " cannot be opened");
  H5Handle type(H5Aget_type(attr.get()), H5Tclose);
  if (!type.valid() || H5Tget_class(type.get()) != typeClass) {
    throw std::runtime_error(where + (typeClass == H5T_FLOAT ? " must be a floating-point number"
                                                             : " must be an integer"));
  }
  H5Handle space(H5Aget_space(attr.get()), H5Sclose);
  if (!space.valid() || H5Sget_simple_extent_npoints(space.get()) != 1) {
    throw std::runtime_error(where + " must be a single value");
  }
  if (H5Aread(attr.get(), memType, value) < 0) throw std::runtime_error(where + " cannot be read");
  return true;
}

}  // namespace

void writeHdf5(const Packing& p, const std::string& path) {
  H5Quiet quiet;
  H5Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw std::runtime_error("writeHdf5: cannot create '" + path + "'");
  const std::size_t n = p.bodies.size();
  std::vector<double> semi(3 * n), centres(3 * n), quats(4 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Ellipsoid& e = p.bodies[i];
    for (int k = 0; k < 3; ++k) {
      semi[3 * i + static_cast<std::size_t>(k)] = e.semiAxes()[k];
      centres[3 * i + static_cast<std::size_t>(k)] = e.centre()[k];
    }
    const Quat& q = e.orientation();
    quats[4 * i + 0] = q.w();
    quats[4 * i + 1] = q.x();
    quats[4 * i + 2] = q.y();
    quats[4 * i + 3] = q.z();
  }
  writeDataset(file.get(), "semiAxes", semi, n, 3, path);
  writeDataset(file.get(), "centres", centres, n, 3, path);
  writeDataset(file.get(), "quaternions", quats, n, 4, path);

  H5Handle root(H5Gopen2(file.get(), "/", H5P_DEFAULT), H5Gclose);
  if (!root.valid()) throw std::runtime_error("writeHdf5: '" + path + "': cannot open the root group");
  const int version = kPackingFormatVersion;
  writeAttribute(root.get(), "formatVersion", H5T_STD_I32LE, H5T_NATIVE_INT, &version, path);
  writeAttribute(root.get(), "boxLength", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &p.boxLength, path);
  writeAttribute(root.get(), "aspectRatio", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &p.aspectRatio, path);
  writeAttribute(root.get(), "equivalentDiameter", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                 &p.equivalentDiameter, path);
  writeAttribute(root.get(), "volumeFraction", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &p.volumeFraction,
                 path);
  writeAttribute(root.get(), "seed", H5T_STD_U64LE, H5T_NATIVE_UINT64, &p.seed, path);
  root.close();
  if (!file.close()) throw std::runtime_error("writeHdf5: error while closing '" + path + "'");
}

Packing readHdf5(const std::string& path) {
  H5Quiet quiet;
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    throw std::runtime_error("readHdf5: '" + path + "' does not exist or is not an HDF5 file");
  }
  H5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw std::runtime_error("readHdf5: cannot open '" + path + "'");
  H5Handle root(H5Gopen2(file.get(), "/", H5P_DEFAULT), H5Gclose);
  if (!root.valid()) throw std::runtime_error("readHdf5: '" + path + "': cannot open the root group");

  Packing p;
  int version = 0;
  if (!readAttribute(root.get(), "formatVersion", H5T_INTEGER, H5T_NATIVE_INT, &version, path)) {
    throw std::runtime_error("readHdf5: '" + path + "': attribute 'formatVersion' is missing");
  }
  if (version != kPackingFormatVersion) {
    throw std::runtime_error("readHdf5: '" + path + "': attribute 'formatVersion' = " +
                             std::to_string(version) + " is not supported (this reader reads " +
                             std::to_string(kPackingFormatVersion) + ")");
  }
  if (!readAttribute(root.get(), "boxLength", H5T_FLOAT, H5T_NATIVE_DOUBLE, &p.boxLength, path)) {
    throw std::runtime_error("readHdf5: '" + path + "': attribute 'boxLength' is missing");
  }
  checkBoxLength(p.boxLength, "readHdf5: '" + path + "': attribute 'boxLength'");
  readAttribute(root.get(), "aspectRatio", H5T_FLOAT, H5T_NATIVE_DOUBLE, &p.aspectRatio, path);
  readAttribute(root.get(), "equivalentDiameter", H5T_FLOAT, H5T_NATIVE_DOUBLE,
                &p.equivalentDiameter, path);
  readAttribute(root.get(), "volumeFraction", H5T_FLOAT, H5T_NATIVE_DOUBLE, &p.volumeFraction, path);
  readAttribute(root.get(), "seed", H5T_INTEGER, H5T_NATIVE_UINT64, &p.seed, path);

  hsize_t nSemi = 0, nCentres = 0, nQuats = 0;
  const std::vector<double> semi = readDataset(file.get(), "semiAxes", 3, nSemi, path);
  const std::vector<double> centres = readDataset(file.get(), "centres", 3, nCentres, path);
  const std::vector<double> quats = readDataset(file.get(), "quaternions", 4, nQuats, path);
  if (nSemi != nCentres || nSemi != nQuats) {
    throw std::runtime_error("readHdf5: '" + path + "': datasets 'semiAxes', 'centres' and "
                             "'quaternions' must have as many rows, got " + std::to_string(nSemi) +
                             ", " + std::to_string(nCentres) + " and " + std::to_string(nQuats));
  }
  const std::size_t n = static_cast<std::size_t>(nSemi);
  p.bodies.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* s = &semi[3 * i];
    const double* c = &centres[3 * i];
    const double* q = &quats[4 * i];
    const std::string problem = bodyProblem(s, c, q, p.boxLength);
    if (!problem.empty()) {
      // name the dataset the problem is in
      const char* dataset = problem.rfind("semi-axis", 0) == 0 ? "semiAxes"
                            : problem.rfind("centre", 0) == 0  ? "centres"
                                                               : "quaternions";
      throw std::runtime_error("readHdf5: '" + path + "': dataset '" + dataset + "', row " +
                               std::to_string(i) + " (body index): " + problem);
    }
    try {
      p.bodies.push_back(makeBody(s, c, q));
    } catch (const std::exception& e) {
      throw std::runtime_error("readHdf5: '" + path + "': row " + std::to_string(i) + ": " + e.what());
    }
  }
  return p;
}

// ---------------------------------------------------------------- by extension

void writePacking(const Packing& packing, const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".csv") return writeCsv(packing, path);
  if (ext == ".h5" || ext == ".hdf5") return writeHdf5(packing, path);
  throw std::invalid_argument("writePacking: '" + path +
                              "': unknown extension; allowed: .csv, .h5, .hdf5");
}

Packing readPacking(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".csv") return readCsv(path);
  if (ext == ".h5" || ext == ".hdf5") return readHdf5(path);
  throw std::invalid_argument("readPacking: '" + path +
                              "': unknown extension; allowed: .csv, .h5, .hdf5");
}

}  // namespace packing
