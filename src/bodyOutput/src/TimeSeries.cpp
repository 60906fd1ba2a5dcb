#include "bodyOutput/TimeSeries.hpp"

#include "Files.hpp"
#include "Hdf5Util.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

// H5Pset_file_locking exists from HDF5 1.10.7 (1.12.1 in the 1.12 series)
#if (H5_VERS_MAJOR > 1) || (H5_VERS_MAJOR == 1 && H5_VERS_MINOR > 12) ||   \
    (H5_VERS_MAJOR == 1 && H5_VERS_MINOR == 12 && H5_VERS_RELEASE >= 1) || \
    (H5_VERS_MAJOR == 1 && H5_VERS_MINOR == 10 && H5_VERS_RELEASE >= 7)
#define BODYOUTPUT_HAVE_FILE_LOCKING_PROPERTY 1
#else
#define BODYOUTPUT_HAVE_FILE_LOCKING_PROPERTY 0
#endif

namespace bodyoutput {

namespace detail {

std::string hdf5Detail() {
  std::string innermost;
  // H5E_WALK_UPWARD starts with the innermost entry (where the error was detected), which
  // carries the useful text (errno, object name); H5Ewalk2 does not clear the stack.
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned n, const H5E_error2_t* e, void* data) -> herr_t {
        if (n == 0 && e != nullptr && e->desc != nullptr) {
          *static_cast<std::string*>(data) = e->desc;
        }
        return 0;
      },
      &innermost);
  return innermost.empty() ? std::string() : " (HDF5: " + innermost + ")";
}

void fail(const std::string& what) { throw std::runtime_error(what + hdf5Detail()); }

}  // namespace detail

using detail::fail;
using detail::H5Handle;
using detail::H5Quiet;
using detail::inQuotes;

namespace {

namespace fs = std::filesystem;

// ------------------------------------------------------------------ layout

constexpr int kFieldCount = 9;  // the N x B x k datasets; `time` is separate
constexpr const char* kFieldNames[kFieldCount] = {
    "centre",         "velocity",        "angularVelocity", "hydroForce",     "hydroTorque",
    "collisionForce", "collisionTorque", "unwrappedCentre", "orientation"};
constexpr std::array<double, 3> BodyRecord::*kVectorMembers[kFieldCount - 1] = {
    &BodyRecord::centre,         &BodyRecord::velocity,       &BodyRecord::angularVelocity,
    &BodyRecord::hydroForce,     &BodyRecord::hydroTorque,    &BodyRecord::collisionForce,
    &BodyRecord::collisionTorque, &BodyRecord::unwrappedCentre};
constexpr int kOrientationField = kFieldCount - 1;
constexpr const char* kTimeName = "time";

constexpr const char* kDescription =
    "spheroidFoam rigid-body time series (bodyOutput). N rows, B bodies. time (N); centre, "
    "velocity, angularVelocity, hydroForce, hydroTorque, collisionForce, collisionTorque, "
    "unwrappedCentre (N x B x 3, world frame, torques about the centre; the unwrapped centre is "
    "the centre before wrapping into a periodic box); orientation (N x B x 4, unit quaternion "
    "w, x, y, z rotating body axes to world axes); bodyNames (B strings); semiAxes (B x 3, a, b, "
    "c along the body x, y, z axes); density (B). A row exists when every N-dataset has it.";

constexpr hsize_t fieldWidth(int f) { return f == kOrientationField ? 4 : 3; }

void pack(int f, const std::vector<BodyRecord>& records, std::vector<double>& out) {
  const std::size_t w = fieldWidth(f);
  out.resize(records.size() * w);
  for (std::size_t b = 0; b < records.size(); ++b) {
    const double* v = f == kOrientationField ? records[b].orientation.data()
                                             : (records[b].*kVectorMembers[f]).data();
    std::copy(v, v + w, out.data() + b * w);
  }
}

void unpack(int f, const double* in, std::vector<BodyRecord>& records) {
  const std::size_t w = fieldWidth(f);
  for (std::size_t b = 0; b < records.size(); ++b) {
    double* v = f == kOrientationField ? records[b].orientation.data()
                                       : (records[b].*kVectorMembers[f]).data();
    std::copy(in + b * w, in + (b + 1) * w, v);
  }
}

/// 64 rows a chunk, fewer if a chunk would exceed 1 MiB (many bodies)
hsize_t rowsPerChunk(hsize_t bodies, hsize_t width) {
  const hsize_t rowBytes = std::max<hsize_t>(1, bodies * width * sizeof(double));
  return std::clamp<hsize_t>((hsize_t(1) << 20) / rowBytes, 1, 64);
}

/// the last time kept on a restart from t
double keepThreshold(double t) {
  if (std::isinf(t)) return t;
  return (t >= 0 ? t * (1 + 1e-12) : t * (1 - 1e-12)) + 1e-300;
}

std::string numberText(double v) {
  std::ostringstream os;
  os.precision(17);
  os << v;
  return os.str();
}

// ------------------------------------------------------------------ property lists

/// lock: take HDF5's file lock (writer); otherwise read without (monitoring a running case).
/// Either way a file system without flock support is tolerated.
H5Handle fileAccess(bool lock, const std::string& where) {
  H5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!fapl.valid()) fail(where + ": cannot create a file-access property list");
#if BODYOUTPUT_HAVE_FILE_LOCKING_PROPERTY
  if (H5Pset_file_locking(fapl.get(), lock ? 1 : 0, 1) < 0) {
    fail(where + ": cannot set the file-locking property");
  }
#else
  (void)lock;
#endif
  return fapl;
}

/// The writer's dataset access: no chunk cache, so that each append writes its row straight to
/// the file instead of flushing (rewriting) whole cached chunks on every H5Fflush.
H5Handle writerDatasetAccess(const std::string& where) {
  H5Handle dapl(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose);
  if (!dapl.valid() ||
      H5Pset_chunk_cache(dapl.get(), H5D_CHUNK_CACHE_NSLOTS_DEFAULT, 0,
                         H5D_CHUNK_CACHE_W0_DEFAULT) < 0) {
    fail(where + ": cannot create a dataset-access property list");
  }
  return dapl;
}

// ------------------------------------------------------------------ creating

void writeIntAttribute(hid_t object, const char* name, int value, const std::string& where) {
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (!space.valid()) fail(where + ": cannot create the dataspace of attribute '" + name + "'");
  H5Handle attr(H5Acreate2(object, name, H5T_STD_I32LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                H5Aclose);
  if (!attr.valid()) fail(where + ": cannot create attribute '" + name + "'");
  if (H5Awrite(attr.get(), H5T_NATIVE_INT, &value) < 0) {
    fail(where + ": cannot write attribute '" + name + "'");
  }
}

void writeStringAttribute(hid_t object, const char* name, const std::string& value,
                          const std::string& where) {
  H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (!type.valid() || H5Tset_size(type.get(), value.size() + 1) < 0 ||
      H5Tset_strpad(type.get(), H5T_STR_NULLTERM) < 0) {
    fail(where + ": cannot create the string type of attribute '" + name + "'");
  }
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  if (!space.valid()) fail(where + ": cannot create the dataspace of attribute '" + name + "'");
  H5Handle attr(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                H5Aclose);
  if (!attr.valid()) fail(where + ": cannot create attribute '" + name + "'");
  if (H5Awrite(attr.get(), type.get(), value.c_str()) < 0) {
    fail(where + ": cannot write attribute '" + name + "'");
  }
}

/// fixed-size dataset of doubles, written at once
void writeFixedDataset(hid_t file, const char* name, const std::vector<hsize_t>& dims,
                       const std::vector<double>& data, const std::string& where) {
  H5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  if (!space.valid()) fail(where + ": cannot create the dataspace of dataset '" + name + "'");
  H5Handle set(H5Dcreate2(file, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                          H5P_DEFAULT),
               H5Dclose);
  if (!set.valid()) fail(where + ": cannot create dataset '" + name + "'");
  if (H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0) {
    fail(where + ": cannot write dataset '" + name + "'");
  }
}

/// empty dataset of doubles, extendible along its first dimension
void createSeriesDataset(hid_t file, const char* name, hsize_t bodies, hsize_t width,
                         const std::string& where) {
  const bool scalar = width == 0;  // `time`
  const int rank = scalar ? 1 : 3;
  const hsize_t dims[3] = {0, bodies, width};
  const hsize_t maxDims[3] = {H5S_UNLIMITED, bodies, width};
  const hsize_t chunk[3] = {rowsPerChunk(scalar ? 1 : bodies, scalar ? 1 : width), bodies, width};
  H5Handle space(H5Screate_simple(rank, dims, maxDims), H5Sclose);
  if (!space.valid()) fail(where + ": cannot create the dataspace of dataset '" + name + "'");
  H5Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (!dcpl.valid() || H5Pset_chunk(dcpl.get(), rank, chunk) < 0) {
    fail(where + ": cannot set the chunks of dataset '" + name + "'");
  }
  H5Handle set(
      H5Dcreate2(file, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
      H5Dclose);
  if (!set.valid()) fail(where + ": cannot create dataset '" + name + "'");
}

/// Writes an empty series to path + ".creating" and renames it to path.
void createSeriesFile(const std::string& path, const std::vector<BodyInfo>& bodies,
                      const std::string& who) {
  const std::string tmp = path + ".creating";
  const std::string where = who + ": " + inQuotes(tmp);
  try {
    H5Handle fapl = fileAccess(true, where);
    H5Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
    if (!file.valid()) fail(where + ": cannot create the file");

    const hsize_t b = bodies.size();
    {
      H5Handle root(H5Gopen2(file.get(), "/", H5P_DEFAULT), H5Gclose);
      if (!root.valid()) fail(where + ": cannot open the root group");
      writeIntAttribute(root.get(), "formatVersion", kTimeSeriesFormatVersion, where);
      writeStringAttribute(root.get(), "description", kDescription, where);
    }
    {  // bodyNames: variable-length UTF-8 strings
      H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
      if (!type.valid() || H5Tset_size(type.get(), H5T_VARIABLE) < 0 ||
          H5Tset_cset(type.get(), H5T_CSET_UTF8) < 0) {
        fail(where + ": cannot create the string type of dataset 'bodyNames'");
      }
      H5Handle space(H5Screate_simple(1, &b, nullptr), H5Sclose);
      if (!space.valid()) fail(where + ": cannot create the dataspace of dataset 'bodyNames'");
      H5Handle set(H5Dcreate2(file.get(), "bodyNames", type.get(), space.get(), H5P_DEFAULT,
                              H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose);
      if (!set.valid()) fail(where + ": cannot create dataset 'bodyNames'");
      std::vector<const char*> names;
      for (const BodyInfo& body : bodies) names.push_back(body.name.c_str());
      if (H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, names.data()) < 0) {
        fail(where + ": cannot write dataset 'bodyNames'");
      }
    }
    std::vector<double> semi, density;
    for (const BodyInfo& body : bodies) {
      semi.insert(semi.end(), body.semiAxes.begin(), body.semiAxes.end());
      density.push_back(body.density);
    }
    writeFixedDataset(file.get(), "semiAxes", {b, 3}, semi, where);
    writeFixedDataset(file.get(), "density", {b}, density, where);

    createSeriesDataset(file.get(), kTimeName, b, 0, where);
    for (int f = 0; f < kFieldCount; ++f) {
      createSeriesDataset(file.get(), kFieldNames[f], b, fieldWidth(f), where);
    }
    if (!file.close()) fail(where + ": error while closing the new file");
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error(who + ": cannot rename " + inQuotes(tmp) + " to " + inQuotes(path) +
                             ": " + ec.message());
  }
}

// ------------------------------------------------------------------ reading

H5Handle openDataset(hid_t file, const char* name, hid_t dapl, const std::string& where) {
  const htri_t exists = H5Lexists(file, name, H5P_DEFAULT);
  if (exists < 0) fail(where + ": cannot look up dataset '" + name + "'");
  if (exists == 0) {
    throw std::runtime_error(where + ": dataset '" + name +
                             "' is missing: not a body time series written by bodyOutput");
  }
  H5Handle set(H5Dopen2(file, name, dapl), H5Dclose);
  if (!set.valid()) fail(where + ": '" + name + "' cannot be opened as a dataset");
  return set;
}

/// dims and maximum dims of a dataset's dataspace
void extent(hid_t set, std::vector<hsize_t>& dims, std::vector<hsize_t>& maxDims,
            const std::string& what) {
  H5Handle space(H5Dget_space(set), H5Sclose);
  if (!space.valid()) fail(what + ": cannot get its dataspace");
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail(what + ": cannot get its rank");
  dims.assign(static_cast<std::size_t>(rank), 0);
  maxDims.assign(static_cast<std::size_t>(rank), 0);
  if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), maxDims.data()) < 0) {
    fail(what + ": cannot get its dimensions");
  }
}

std::string dimsText(const std::vector<hsize_t>& dims) {
  if (dims.empty()) return "a scalar";
  std::string s;
  for (std::size_t i = 0; i < dims.size(); ++i) {
    if (i) s += " x ";
    s += std::to_string(dims[i]);
  }
  return s;
}

void requireFloat(hid_t set, const std::string& what) {
  H5Handle type(H5Dget_type(set), H5Tclose);
  if (!type.valid()) fail(what + ": cannot get its type");
  if (H5Tget_class(type.get()) != H5T_FLOAT) {
    throw std::runtime_error(what + " must hold floating-point numbers");
  }
}

/// reads `count` elements (a hyperslab from the origin) as doubles
std::vector<double> readDoubles(hid_t set, const std::vector<hsize_t>& count,
                                const std::string& what) {
  hsize_t total = 1;
  for (hsize_t c : count) total *= c;
  std::vector<double> data(static_cast<std::size_t>(total));
  if (total == 0) return data;
  H5Handle fileSpace(H5Dget_space(set), H5Sclose);
  if (!fileSpace.valid()) fail(what + ": cannot get its dataspace");
  const std::vector<hsize_t> start(count.size(), 0);
  if (H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, start.data(), nullptr, count.data(),
                          nullptr) < 0) {
    fail(what + ": cannot select its elements");
  }
  H5Handle memSpace(H5Screate_simple(static_cast<int>(count.size()), count.data(), nullptr),
                    H5Sclose);
  if (!memSpace.valid()) fail(what + ": cannot create a memory dataspace");
  if (H5Dread(set, H5T_NATIVE_DOUBLE, memSpace.get(), fileSpace.get(), H5P_DEFAULT, data.data()) <
      0) {
    fail(what + " cannot be read");
  }
  return data;
}

void checkFormatVersion(hid_t file, const std::string& where) {
  const std::string what = where + ": attribute 'formatVersion' of the root group";
  const htri_t exists = H5Aexists_by_name(file, "/", "formatVersion", H5P_DEFAULT);
  if (exists < 0) fail(what + " cannot be looked up");
  if (exists == 0) {
    throw std::runtime_error(what + " is missing: not a body time series written by bodyOutput");
  }
  H5Handle attr(H5Aopen_by_name(file, "/", "formatVersion", H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!attr.valid()) fail(what + " cannot be opened");
  H5Handle type(H5Aget_type(attr.get()), H5Tclose);
  H5Handle space(H5Aget_space(attr.get()), H5Sclose);
  if (!type.valid() || !space.valid()) fail(what + " cannot be inspected");
  if (H5Tget_class(type.get()) != H5T_INTEGER ||
      H5Sget_simple_extent_npoints(space.get()) != 1) {
    throw std::runtime_error(what + " must be a single integer");
  }
  int version = 0;
  if (H5Aread(attr.get(), H5T_NATIVE_INT, &version) < 0) fail(what + " cannot be read");
  if (version != kTimeSeriesFormatVersion) {
    throw std::runtime_error(what + " is " + std::to_string(version) +
                             ": not supported (this library reads and writes version " +
                             std::to_string(kTimeSeriesFormatVersion) + ")");
  }
}

std::vector<std::string> readNames(hid_t file, const std::string& where) {
  const std::string what = where + ": dataset 'bodyNames'";
  H5Handle set = openDataset(file, "bodyNames", H5P_DEFAULT, where);
  std::vector<hsize_t> dims, maxDims;
  extent(set.get(), dims, maxDims, what);
  if (dims.size() != 1) {
    throw std::runtime_error(what + " must be 1-d (one name a body), got " + dimsText(dims));
  }
  const std::size_t n = static_cast<std::size_t>(dims[0]);
  H5Handle fileType(H5Dget_type(set.get()), H5Tclose);
  if (!fileType.valid()) fail(what + ": cannot get its type");
  if (H5Tget_class(fileType.get()) != H5T_STRING) {
    throw std::runtime_error(what + " must hold strings");
  }
  std::vector<std::string> names(n);
  if (n == 0) return names;
  const htri_t variable = H5Tis_variable_str(fileType.get());
  if (variable < 0) fail(what + ": cannot inspect its string type");
  if (variable > 0) {
    H5Handle memType(H5Tcopy(H5T_C_S1), H5Tclose);
    if (!memType.valid() || H5Tset_size(memType.get(), H5T_VARIABLE) < 0 ||
        H5Tset_cset(memType.get(), H5Tget_cset(fileType.get())) < 0) {
      fail(what + ": cannot create the memory string type");
    }
    H5Handle space(H5Dget_space(set.get()), H5Sclose);
    std::vector<char*> buffer(n, nullptr);
    if (!space.valid() ||
        H5Dread(set.get(), memType.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0) {
      fail(what + " cannot be read");
    }
    struct Reclaim {  // frees HDF5's strings whatever happens
      hid_t type, space;
      std::vector<char*>& buffer;
      ~Reclaim() { H5Dvlen_reclaim(type, space, H5P_DEFAULT, buffer.data()); }
    } reclaim{memType.get(), space.get(), buffer};
    for (std::size_t i = 0; i < n; ++i) names[i] = buffer[i] != nullptr ? buffer[i] : "";
  } else {
    const std::size_t size = H5Tget_size(fileType.get());
    if (size == 0) fail(what + ": cannot get its string size");
    std::vector<char> buffer(n * size);
    if (H5Dread(set.get(), fileType.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0) {
      fail(what + " cannot be read");
    }
    for (std::size_t i = 0; i < n; ++i) {
      const char* s = buffer.data() + i * size;
      std::string name(s, strnlen(s, size));
      while (!name.empty() && name.back() == ' ') name.pop_back();  // space-padded strings
      names[i] = name;
    }
  }
  return names;
}

std::vector<BodyInfo> readBodies(hid_t file, const std::string& where) {
  const std::vector<std::string> names = readNames(file, where);
  const hsize_t b = names.size();
  if (b == 0) throw std::runtime_error(where + ": dataset 'bodyNames' is empty (no bodies)");
  std::vector<hsize_t> dims, maxDims;

  H5Handle semiSet = openDataset(file, "semiAxes", H5P_DEFAULT, where);
  const std::string semiWhat = where + ": dataset 'semiAxes'";
  requireFloat(semiSet.get(), semiWhat);
  extent(semiSet.get(), dims, maxDims, semiWhat);
  if (dims != std::vector<hsize_t>{b, 3}) {
    throw std::runtime_error(semiWhat + " must be " + std::to_string(b) +
                             " x 3 (bodies x a, b, c), got " + dimsText(dims));
  }
  const std::vector<double> semi = readDoubles(semiSet.get(), dims, semiWhat);

  H5Handle densitySet = openDataset(file, "density", H5P_DEFAULT, where);
  const std::string densityWhat = where + ": dataset 'density'";
  requireFloat(densitySet.get(), densityWhat);
  extent(densitySet.get(), dims, maxDims, densityWhat);
  if (dims != std::vector<hsize_t>{b}) {
    throw std::runtime_error(densityWhat + " must be " + std::to_string(b) +
                             " (one a body), got " + dimsText(dims));
  }
  const std::vector<double> density = readDoubles(densitySet.get(), dims, densityWhat);

  std::vector<BodyInfo> bodies(names.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    bodies[i].name = names[i];
    std::copy(&semi[3 * i], &semi[3 * i] + 3, bodies[i].semiAxes.begin());
    bodies[i].density = density[i];
  }
  return bodies;
}

/// An N-dataset, checked: floats, `time` N, the others N x B x width.
struct SeriesDataset {
  H5Handle set;
  hsize_t length = 0;
};

SeriesDataset openSeriesDataset(hid_t file, const char* name, hsize_t bodies, hsize_t width,
                                hid_t dapl, bool extendible, const std::string& where) {
  const std::string what = where + ": dataset '" + std::string(name) + "'";
  SeriesDataset d;
  d.set = openDataset(file, name, dapl, where);
  requireFloat(d.set.get(), what);
  std::vector<hsize_t> dims, maxDims;
  extent(d.set.get(), dims, maxDims, what);
  const bool scalar = width == 0;
  const bool ok = scalar ? dims.size() == 1
                         : dims.size() == 3 && dims[1] == bodies && dims[2] == width;
  if (!ok) {
    throw std::runtime_error(
        what + " must be " +
        (scalar ? std::string("1-d (N times)")
                : "N x " + std::to_string(bodies) + " x " + std::to_string(width) +
                      " (times x bodies x components)") +
        ", got " + dimsText(dims));
  }
  if (extendible && maxDims[0] != H5S_UNLIMITED) {
    throw std::runtime_error(what + " cannot grow (its maximum length is not unlimited): "
                             "not a body time series written by bodyOutput");
  }
  d.length = dims[0];
  return d;
}

std::string describeBodies(const std::vector<BodyInfo>& bodies) {
  std::string s = std::to_string(bodies.size()) + (bodies.size() == 1 ? " body (" : " bodies (");
  for (std::size_t i = 0; i < bodies.size() && i < 8; ++i) {
    if (i) s += ", ";
    s += inQuotes(bodies[i].name);
  }
  if (bodies.size() > 8) s += ", ...";
  return s + ")";
}

bool closeEnough(double a, double b) {
  return a == b || std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b));
}

/// "" if the bodies match, else the first difference
std::string bodiesDifference(const std::vector<BodyInfo>& inFile,
                             const std::vector<BodyInfo>& inRun) {
  if (inFile.size() != inRun.size()) {
    return "the file has " + describeBodies(inFile) + ", this run has " + describeBodies(inRun);
  }
  static const char* const axis[3] = {"a", "b", "c"};
  for (std::size_t i = 0; i < inFile.size(); ++i) {
    const BodyInfo& f = inFile[i];
    const BodyInfo& r = inRun[i];
    const std::string body = "body " + std::to_string(i);
    if (f.name != r.name) {
      return body + " is named " + inQuotes(f.name) + " in the file but " + inQuotes(r.name) +
             " in this run";
    }
    for (int k = 0; k < 3; ++k) {
      if (!closeEnough(f.semiAxes[k], r.semiAxes[k])) {
        return body + " (" + inQuotes(f.name) + "): semi-axis " + axis[k] + " is " +
               numberText(f.semiAxes[k]) + " in the file but " + numberText(r.semiAxes[k]) +
               " in this run";
      }
    }
    if (!closeEnough(f.density, r.density)) {
      return body + " (" + inQuotes(f.name) + "): density is " + numberText(f.density) +
             " in the file but " + numberText(r.density) + " in this run";
    }
  }
  return "";
}

void validateBodies(const std::vector<BodyInfo>& bodies, const std::string& who) {
  if (bodies.empty()) throw std::invalid_argument(who + ": no bodies (at least one is needed)");
  std::set<std::string> seen;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const BodyInfo& b = bodies[i];
    const std::string body = who + ": body " + std::to_string(i);
    if (b.name.empty()) throw std::invalid_argument(body + " has an empty name");
    if (!seen.insert(b.name).second) {
      throw std::invalid_argument(body + ": the name " + inQuotes(b.name) + " is used twice");
    }
    for (int k = 0; k < 3; ++k) {
      if (!(b.semiAxes[k] > 0) || !std::isfinite(b.semiAxes[k])) {
        throw std::invalid_argument(body + " (" + inQuotes(b.name) +
                                    "): semi-axes must be finite and > 0, got " +
                                    numberText(b.semiAxes[0]) + ", " + numberText(b.semiAxes[1]) +
                                    ", " + numberText(b.semiAxes[2]));
      }
    }
    if (!std::isfinite(b.density)) {
      throw std::invalid_argument(body + " (" + inQuotes(b.name) + "): density must be finite, got " +
                                  numberText(b.density));
    }
  }
}

// ------------------------------------------------------------------ one writer a file

std::mutex& registryMutex() {
  static std::mutex m;
  return m;
}
std::set<std::string>& openFiles() {
  static std::set<std::string> files;
  return files;
}

std::string registryKey(const std::string& path) {
  std::error_code ec;
  std::string key = fs::weakly_canonical(fs::absolute(path), ec).string();
  if (ec) key = fs::absolute(path).lexically_normal().string();
  return key;
}

/// true if a TimeSeriesWriter of this process has the file open
bool isOpenForWriting(const std::string& path) {
  const std::string key = registryKey(path);
  std::lock_guard<std::mutex> lock(registryMutex());
  return openFiles().count(key) > 0;
}

/// Registers a file as open for writing in this process (HDF5 would share the open file between
/// two writers of one process instead of refusing the second).
class Registration {
 public:
  Registration(const std::string& path, const std::string& who) {
    key_ = registryKey(path);
    std::lock_guard<std::mutex> lock(registryMutex());
    if (!openFiles().insert(key_).second) {
      key_.clear();
      throw std::runtime_error(who + ": " + inQuotes(path) +
                               " is already open by another TimeSeriesWriter of this process");
    }
  }
  Registration(const Registration&) = delete;
  Registration& operator=(const Registration&) = delete;
  ~Registration() {
    if (key_.empty()) return;
    std::lock_guard<std::mutex> lock(registryMutex());
    openFiles().erase(key_);
  }

 private:
  std::string key_;
};

}  // namespace

// ------------------------------------------------------------------ TimeSeriesWriter

struct TimeSeriesWriter::Impl {
  Impl(const std::string& p, const std::string& who) : registration(p, who), path(p) {}
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() { closeAll(); }

  /// closes the datasets, then the file; false if something failed
  bool closeAll() noexcept {
    H5Quiet quiet;
    bool ok = time.close();
    for (H5Handle& f : fields) ok = f.close() && ok;
    return file.close() && ok;
  }

  Registration registration;  // first: unregistered after the file is closed
  std::string path;
  std::vector<BodyInfo> bodies;
  H5Handle file;
  H5Handle time;
  std::array<H5Handle, kFieldCount> fields;
  std::size_t rows = 0;
  double lastTime = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> buffer;
};

TimeSeriesWriter::TimeSeriesWriter(const std::string& path, const std::vector<BodyInfo>& bodies,
                                   double restartTime) {
  const std::string who = "TimeSeriesWriter";
  if (path.empty()) throw std::invalid_argument(who + ": empty file name");
  validateBodies(bodies, who + " " + inQuotes(path));
  if (std::isnan(restartTime)) {
    throw std::invalid_argument(who + " " + inQuotes(path) + ": restartTime is NaN");
  }
  auto impl = std::make_unique<Impl>(path, who);
  impl->bodies = bodies;
  const std::string where = who + ": " + inQuotes(path);
  H5Quiet quiet;

  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::exists(status)) {
    if (!fs::is_regular_file(status)) {
      throw std::runtime_error(where + " exists but is not a regular file");
    }
  } else {
    detail::createParentDirectories(path, who);
    createSeriesFile(path, bodies, who);
  }

  const htri_t isHdf5 = H5Fis_hdf5(path.c_str());
  if (isHdf5 <= 0) {
    throw std::runtime_error(where + (isHdf5 == 0 ? " exists but is not an HDF5 file"
                                                  : " cannot be read") +
                             ": it was left unchanged (move it away or choose another file)" +
                             (isHdf5 < 0 ? detail::hdf5Detail() : std::string()));
  }
  {
    H5Handle fapl = fileAccess(true, where);
    impl->file = H5Handle(H5Fopen(path.c_str(), H5F_ACC_RDWR, fapl.get()), H5Fclose);
    if (!impl->file.valid()) {
      fail(where + ": cannot open it for writing (no permission, or is it open in another run or "
                   "in a program that locks HDF5 files, such as h5py or HDFView?)");
    }
  }
  const hid_t file = impl->file.get();
  std::vector<BodyInfo> inFile;
  try {
    checkFormatVersion(file, where);
    inFile = readBodies(file, where);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string(e.what()) + " (" + inQuotes(path) +
                             " is not a valid body time series; it was left unchanged)");
  }
  const std::string difference = bodiesDifference(inFile, bodies);
  if (!difference.empty()) {
    throw std::runtime_error(where + " was written for other bodies than this run's (a restart "
                                     "must keep the bodies; the file was left unchanged: move it "
                                     "away to start a new series): " + difference);
  }

  // the N-datasets; rows kept = the shortest length (a killed append may have extended some)
  const hsize_t b = bodies.size();
  H5Handle dapl = writerDatasetAccess(where);
  std::array<hsize_t, kFieldCount> lengths{};
  SeriesDataset timeSet = openSeriesDataset(file, kTimeName, b, 0, dapl.get(), true, where);
  hsize_t n = timeSet.length;
  impl->time = std::move(timeSet.set);
  for (int f = 0; f < kFieldCount; ++f) {
    SeriesDataset d =
        openSeriesDataset(file, kFieldNames[f], b, fieldWidth(f), dapl.get(), true, where);
    lengths[static_cast<std::size_t>(f)] = d.length;
    n = std::min(n, d.length);
    impl->fields[static_cast<std::size_t>(f)] = std::move(d.set);
  }
  const std::vector<double> times =
      readDoubles(impl->time.get(), {n}, where + ": dataset '" + kTimeName + "'");

  // restart: keep the rows before the first one after restartTime
  const double threshold = keepThreshold(restartTime);
  const auto firstLater =
      std::find_if(times.begin(), times.end(), [&](double t) { return !(t <= threshold); });
  const hsize_t keep = static_cast<hsize_t>(firstLater - times.begin());

  bool changed = false;
  auto shrink = [&](hid_t set, const char* name, hsize_t length, hsize_t width) {
    if (length == keep) return;
    const hsize_t dims[3] = {keep, b, width};  // H5Dset_extent reads `rank` of them
    if (H5Dset_extent(set, dims) < 0) {
      fail(where + ": cannot truncate dataset '" + name + "' to " + std::to_string(keep) +
           " rows");
    }
    changed = true;
  };
  shrink(impl->time.get(), kTimeName, timeSet.length, 0);
  for (int f = 0; f < kFieldCount; ++f) {
    shrink(impl->fields[static_cast<std::size_t>(f)].get(), kFieldNames[f],
           lengths[static_cast<std::size_t>(f)], fieldWidth(f));
  }
  if (changed && H5Fflush(file, H5F_SCOPE_LOCAL) < 0) {
    fail(where + ": cannot flush the file after truncating it to " + std::to_string(keep) +
         " rows");
  }
  impl->rows = static_cast<std::size_t>(keep);
  if (keep > 0) impl->lastTime = times[static_cast<std::size_t>(keep - 1)];
  impl_ = std::move(impl);
}

TimeSeriesWriter::~TimeSeriesWriter() = default;
TimeSeriesWriter::TimeSeriesWriter(TimeSeriesWriter&&) noexcept = default;
TimeSeriesWriter& TimeSeriesWriter::operator=(TimeSeriesWriter&&) noexcept = default;

void TimeSeriesWriter::append(double time, const std::vector<BodyRecord>& records) {
  if (!impl_) throw std::logic_error("TimeSeriesWriter::append: the writer is closed");
  Impl& m = *impl_;
  const std::string where = "TimeSeriesWriter::append: " + inQuotes(m.path);
  if (records.size() != m.bodies.size()) {
    throw std::invalid_argument(where + ": got " + std::to_string(records.size()) +
                                " records for " + std::to_string(m.bodies.size()) +
                                " bodies (one record a body, in the order of the bodies)");
  }
  if (!std::isfinite(time)) {
    throw std::invalid_argument(where + ": time must be finite, got " + numberText(time));
  }
  // earlier than the last row beyond the restart tolerance: a restart at `time` would keep that
  // row (e.g. a kept row at 0.30000000000000004 and the run restarted from 0.3 appends at 0.3)
  if (m.rows > 0 && keepThreshold(time) < m.lastTime) {
    throw std::invalid_argument(where + ": time " + numberText(time) +
                                " is before the last row's time " + numberText(m.lastTime) +
                                " (times must not decrease; after a restart pass the time the run "
                                "restarts from as restartTime)");
  }
  H5Quiet quiet;
  const hsize_t b = m.bodies.size();
  const hsize_t row = m.rows;

  auto writeRow = [&](hid_t set, const char* name, int rank, hsize_t width, const double* data) {
    const std::string what = where + ": dataset '" + std::string(name) + "'";
    const hsize_t dims[3] = {row + 1, b, width};
    if (H5Dset_extent(set, dims) < 0) fail(what + ": cannot extend it to " +
                                           std::to_string(row + 1) + " rows");
    H5Handle fileSpace(H5Dget_space(set), H5Sclose);
    if (!fileSpace.valid()) fail(what + ": cannot get its dataspace");
    const hsize_t start[3] = {row, 0, 0};
    const hsize_t count[3] = {1, b, width};
    if (H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0) {
      fail(what + ": cannot select row " + std::to_string(row));
    }
    H5Handle memSpace(H5Screate_simple(rank, count, nullptr), H5Sclose);
    if (!memSpace.valid()) fail(what + ": cannot create a memory dataspace");
    if (H5Dwrite(set, H5T_NATIVE_DOUBLE, memSpace.get(), fileSpace.get(), H5P_DEFAULT, data) < 0) {
      fail(what + ": cannot write row " + std::to_string(row));
    }
  };
  for (int f = 0; f < kFieldCount; ++f) {
    pack(f, records, m.buffer);
    writeRow(m.fields[static_cast<std::size_t>(f)].get(), kFieldNames[f], 3, fieldWidth(f),
             m.buffer.data());
  }
  writeRow(m.time.get(), kTimeName, 1, 0, &time);  // last: the row exists once `time` has it
  if (H5Fflush(m.file.get(), H5F_SCOPE_LOCAL) < 0) fail(where + ": cannot flush the file");
  m.rows = static_cast<std::size_t>(row + 1);
  m.lastTime = time;
}

std::size_t TimeSeriesWriter::rows() const { return impl_ ? impl_->rows : 0; }

double TimeSeriesWriter::lastTime() const {
  return impl_ ? impl_->lastTime : std::numeric_limits<double>::quiet_NaN();
}

const std::string& TimeSeriesWriter::path() const {
  static const std::string none;
  return impl_ ? impl_->path : none;
}

const std::vector<BodyInfo>& TimeSeriesWriter::bodies() const {
  static const std::vector<BodyInfo> none;
  return impl_ ? impl_->bodies : none;
}

bool TimeSeriesWriter::isOpen() const { return impl_ != nullptr; }

void TimeSeriesWriter::close() {
  if (!impl_) return;
  const std::string path = impl_->path;
  const bool ok = impl_->closeAll();
  impl_.reset();
  if (!ok) {
    throw std::runtime_error("TimeSeriesWriter::close: " + inQuotes(path) +
                             ": error while closing the file (disk full?)");
  }
}

// ------------------------------------------------------------------ reading

TimeSeries readTimeSeries(const std::string& path) {
  const std::string where = "readTimeSeries: " + inQuotes(path);
  std::error_code ec;
  if (!fs::exists(path, ec)) throw std::runtime_error(where + " does not exist");
  if (fs::is_directory(path, ec)) throw std::runtime_error(where + " is a folder");
  H5Quiet quiet;
  const htri_t isHdf5 = H5Fis_hdf5(path.c_str());
  if (isHdf5 == 0) throw std::runtime_error(where + " is not an HDF5 file");
  if (isHdf5 < 0) fail(where + " cannot be read");
  // Without a lock, so that a running case can be read. HDF5 shares a file opened twice in one
  // process, and refuses the second opening if its locking flag differs: a file a writer of this
  // process has open is opened with the writer's flag.
  const bool writerHere = isOpenForWriting(path);
  H5Handle file;
  {
    H5Handle fapl = fileAccess(writerHere, where);
    file = H5Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get()), H5Fclose);
  }
  if (!file.valid()) {
    const std::string first = detail::hdf5Detail();
    H5Handle fapl = fileAccess(!writerHere, where);  // opened elsewhere in this process?
    file = H5Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get()), H5Fclose);
    if (!file.valid()) throw std::runtime_error(where + ": cannot open it" + first);
  }

  TimeSeries series;
  checkFormatVersion(file.get(), where);
  series.bodies = readBodies(file.get(), where);
  const hsize_t b = series.bodies.size();

  SeriesDataset timeSet =
      openSeriesDataset(file.get(), kTimeName, b, 0, H5P_DEFAULT, false, where);
  hsize_t n = timeSet.length;
  std::array<SeriesDataset, kFieldCount> fields;
  for (int f = 0; f < kFieldCount; ++f) {
    fields[static_cast<std::size_t>(f)] =
        openSeriesDataset(file.get(), kFieldNames[f], b, fieldWidth(f), H5P_DEFAULT, false, where);
    n = std::min(n, fields[static_cast<std::size_t>(f)].length);
  }
  series.time = readDoubles(timeSet.set.get(), {n}, where + ": dataset '" + kTimeName + "'");
  series.records.assign(static_cast<std::size_t>(n), std::vector<BodyRecord>(b));
  for (int f = 0; f < kFieldCount; ++f) {
    const std::vector<double> data =
        readDoubles(fields[static_cast<std::size_t>(f)].set.get(), {n, b, fieldWidth(f)},
                    where + ": dataset '" + kFieldNames[f] + "'");
    const std::size_t rowSize = static_cast<std::size_t>(b * fieldWidth(f));
    for (std::size_t r = 0; r < series.records.size(); ++r) {
      unpack(f, data.data() + r * rowSize, series.records[r]);
    }
  }
  return series;
}

}  // namespace bodyoutput
