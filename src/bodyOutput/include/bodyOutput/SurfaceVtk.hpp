/**
 * @file SurfaceVtk.hpp
 * @brief Body surfaces for ParaView: binary legacy-VTK polydata of triangulated ellipsoids, and
 *        ParaView's ".series" files that give each surface file its time.
 *
 * Both functions write to a temporary file (name + ".tmp") and rename it, so a reader (ParaView
 * watching a running case) sees either the old or the new file, never a partial one. Times in
 * the series are written with the shortest text that reads back to the same double
 * (locale-independent).
 */
#ifndef BODYOUTPUT_SURFACEVTK_HPP
#define BODYOUTPUT_SURFACEVTK_HPP

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace bodyoutput {

/// Shape and pose of one body; orientation is the quaternion (w, x, y, z) rotating body axes to
/// world axes (normalised before use).
struct BodyShape {
  std::array<double, 3> semiAxes{}, centre{};
  std::array<double, 4> orientation{1, 0, 0, 0};
  /// the index written in the cell data `body` (several shapes may be one body's images in a
  /// periodic box); negative: the shape's position in the list
  int id = -1;
};

/// Largest `subdivisions` accepted by writeSurfacesVtk (20 * 4^8 = 1.3 million triangles a body).
constexpr int kMaxSurfaceSubdivisions = 8;

/// The unit sphere of the surfaces: an icosahedron subdivided `subdivisions` times (each
/// triangle into four, the new points pushed onto the sphere), points shared, triangles
/// counter-clockwise seen from outside.
struct UnitSphereMesh {
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};
UnitSphereMesh unitSphereMesh(int subdivisions);

/// The rotation matrix (row-major) of the quaternion (w, x, y, z), normalised first.
std::array<double, 9> rotationMatrix(const std::array<double, 4>& q);

/// The point of the body's surface for the unit-sphere point u: centre + R diag(a, b, c) u,
/// R = rotationMatrix(body.orientation).
std::array<double, 3> surfacePoint(const BodyShape& body, const std::array<double, 9>& R,
                                   const std::array<double, 3>& u);

/// The outward unit normal there: R diag(1/a, 1/b, 1/c) u normalised.
std::array<double, 3> surfaceNormal(const BodyShape& body, const std::array<double, 9>& R,
                                    const std::array<double, 3>& u);

/// Points (10 * 4^s + 2) and triangles (20 * 4^s) of one body's surface with s subdivisions.
std::size_t surfacePointCount(int subdivisions);
std::size_t surfaceTriangleCount(int subdivisions);

/// Legacy-VTK polydata in binary ("# vtk DataFile Version 3.0", "BINARY": big-endian 32-bit
/// floats and ints, which ParaView and every VTK reader accept) of the bodies' surfaces: each
/// ellipsoid triangulated from a subdivided icosahedron (subdivisions >= 0: 20 * 4^subdivisions
/// triangles, 10 * 4^subdivisions + 2 points, shared within a body), mapped to
/// x = centre + R(q) diag(a, b, c) u for the unit vectors u of the sphere's mesh. Triangles are
/// oriented outwards (counter-clockwise seen from outside). Body i's points and triangles follow
/// those of bodies 0..i-1. Cell data: "body" (int, the body's index); point data: "Normals"
/// (unit outward normals of the exact ellipsoid, R(q) diag(1/a, 1/b, 1/c) u normalised).
/// Points and normals are computed in double and stored as float: the surfaces are for viewing
/// (the exact state is in the time series), and float32 (relative precision 6e-8) keeps the
/// file at 24 bytes a point and 20 a triangle; a body far from the origin compared to its size
/// (|centre| / semi-axis above about 1e4) shows the rounding as a faceted surface.
/// Creates parent folders. An empty list writes a valid file with no points.
/// @throws std::invalid_argument for subdivisions outside [0, kMaxSurfaceSubdivisions], a
///         semi-axis not finite and > 0, a centre not finite, a quaternion not finite or zero,
///         or more bodies than the file's 32-bit counts hold (4 * triangles <= 2^31 - 1)
/// @throws std::runtime_error naming the file if it cannot be written
void writeSurfacesVtk(const std::string& path, const std::vector<BodyShape>& bodies,
                      int subdivisions);

/// ParaView's file series (JSON, "file-series-version": "1.0"): rewrites seriesPath listing every
/// (file name relative to the series file, time), in the order given; call after each new file.
/// Names are written as given (JSON-escaped). ParaView opens the series when the file name ends
/// in ".series", e.g. "surfaces.vtk.series". Creates parent folders.
/// @throws std::invalid_argument for an empty name or a time that is not finite
/// @throws std::runtime_error naming the file if it cannot be written
void writeVtkSeries(const std::string& seriesPath,
                    const std::vector<std::pair<std::string, double>>& files);

// ---- additions

/// Reads a series file (as written by writeVtkSeries; any JSON with a "files" array of objects
/// with "name" (string) and "time" (number) members).
/// @throws std::runtime_error naming the file (and the position) on problems
std::vector<std::pair<std::string, double>> readVtkSeries(const std::string& seriesPath);

/// A series file kept across restarts: reads seriesPath if it exists (dropping entries with
/// time > restartTime*(1+1e-12)+1e-300, as TimeSeriesWriter does with rows), and rewrites it on
/// every add(). Without this a restarted run would list only its own files.
class VtkSeries {
 public:
  /// @throws std::runtime_error if seriesPath exists but cannot be read;
  ///         std::invalid_argument if restartTime is NaN
  VtkSeries(std::string seriesPath, double restartTime);
  /// Adds (or, for a name already listed, moves to the end with the new time) an entry and
  /// rewrites the series file. @throws as writeVtkSeries
  void add(const std::string& fileName, double time);
  const std::vector<std::pair<std::string, double>>& files() const { return files_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<std::pair<std::string, double>> files_;
};

}  // namespace bodyoutput

#endif  // BODYOUTPUT_SURFACEVTK_HPP
