/**
 * @file PackingIO.hpp
 * @brief Packing files: CSV (text) and HDF5, read back bit-exactly.
 *
 * CSV, format version 1:
 *   # spheroidFoam packing
 *   # formatVersion 1
 *   # boxLength 30
 *   # aspectRatio 6
 *   # equivalentDiameter 1
 *   # volumeFraction 0.2500...
 *   # seed 1
 *   # bodies 12892
 *   a,b,c,x,y,z,qw,qx,qy,qz
 *   <one body per row, 17 significant digits>
 * Comment lines start with '#'; "# key value" lines with a known key are
 * metadata (formatVersion and boxLength are required, before the header; the
 * others default to the Packing defaults; "bodies", if present, must equal the
 * number of rows); other comments and blank lines are ignored.
 *
 * HDF5, format version 1 (serial HDF5 C API): datasets semiAxes (N x 3),
 * centres (N x 3), quaternions (N x 4, w x y z), all 64-bit floats; root
 * attributes boxLength, aspectRatio, equivalentDiameter, volumeFraction
 * (double), seed (uint64), formatVersion (int32). formatVersion and boxLength
 * are required.
 *
 * Readers validate every body: semi-axes finite and > 0, centre finite and in
 * [0, boxLength)^3, quaternion norm within 1e-6 of 1 (as Ellipsoid requires);
 * errors are std::runtime_error naming the file and the line/column (CSV) or
 * the dataset/attribute and row (HDF5, rows counted from 0 = body index).
 */
#ifndef PACKING_PACKINGIO_HPP
#define PACKING_PACKINGIO_HPP

#include "packing/Packing.hpp"

#include <string>

namespace packing {

/// The format version written (and the only one read).
constexpr int kPackingFormatVersion = 1;

/// @throws std::runtime_error naming the file if it cannot be written
void writeCsv(const Packing& packing, const std::string& path);
/// throws std::runtime_error naming the file, line and column on bad input
Packing readCsv(const std::string& path);

/// @throws std::runtime_error naming the file (and dataset) if it cannot be written
void writeHdf5(const Packing& packing, const std::string& path);
/// throws std::runtime_error naming the file and dataset
Packing readHdf5(const std::string& path);

/// By extension: .csv -> CSV, .h5 / .hdf5 -> HDF5 (case-insensitive).
/// @throws std::invalid_argument for another extension
void writePacking(const Packing& packing, const std::string& path);
/// By extension, as writePacking.
Packing readPacking(const std::string& path);

}  // namespace packing

#endif
