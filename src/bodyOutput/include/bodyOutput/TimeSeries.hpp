/**
 * @file TimeSeries.hpp
 * @brief HDF5 time series of rigid bodies (positions, orientations, velocities, forces), one row
 *        per time, written on the master rank and kept across restarts.
 *
 * File layout, format version 2 (serial HDF5 C API, all numbers 64-bit IEEE floats, little endian);
 * N = rows (times), B = bodies (B >= 1):
 *
 *   /time             N           simulation time of each row
 *   /centre           N x B x 3   centre of mass                       (world frame)
 *   /velocity         N x B x 3   velocity of the centre               (world frame)
 *   /angularVelocity  N x B x 3   angular velocity                     (world frame)
 *   /hydroForce       N x B x 3   hydrodynamic force                   (world frame)
 *   /hydroTorque      N x B x 3   hydrodynamic torque about the centre (world frame)
 *   /collisionForce   N x B x 3   collision (contact/lubrication) force (world frame)
 *   /collisionTorque  N x B x 3   collision torque about the centre    (world frame)
 *   /unwrappedCentre  N x B x 3   the centre as if never moved by whole periods into a periodic
 *                                 box (equal to centre without periodic axes): the path to
 *                                 measure dispersion with
 *   /orientation      N x B x 4   unit quaternion (w, x, y, z) rotating body axes to world axes:
 *                                 x_world = centre + R(q) x_body
 *   /bodyNames        B           variable-length UTF-8 strings
 *   /semiAxes         B x 3       a, b, c along the body x, y, z axes (a spheroid's symmetry
 *                                 axis is its body x axis)
 *   /density          B           body density
 *   attributes of /:  formatVersion (int32) = 1, description (string, this layout in brief)
 *
 * The N-datasets are chunked (64 rows per chunk, fewer if a chunk would exceed 1 MiB) and
 * extendible along N (maximum size unlimited), the B-datasets are contiguous. Units are those of
 * the caller (the solver's). A row exists when every N-dataset has it: readers take N as the
 * smallest length of the N-datasets (a run killed in the middle of append() may have extended
 * some of them); the writer extends `time` last.
 *
 * Crash safety: append() flushes the file (HDF5 metadata and data, H5Fflush), so a run killed at
 * any time after append() returned leaves a readable file with every row (the operating system
 * still has to write its page cache to the disk: no fsync, a machine crash can lose the last
 * rows). The file uses HDF5's earliest (1.8-compatible) format: no "file open for writing" flag
 * that would make a killed run's file unreadable without h5clear.
 *
 * Concurrency: the writer holds HDF5's file lock (flock, exclusive) while open, so a second run
 * cannot write the same file; HDF5 tools that lock (h5dump, h5py by default) cannot open it
 * meanwhile (set HDF5_USE_FILE_LOCKING=FALSE for them). readTimeSeries() and plotBodies.py read
 * without locking, so they can monitor a running case; a read that overlaps an append() may fail
 * (try again) but never disturbs the writer. A file system without flock support is tolerated.
 * Two writers on one file in one process are refused as well.
 *
 * HDF5 is used through its serial C library, which is not thread-safe: call from one thread.
 */
#ifndef BODYOUTPUT_TIMESERIES_HPP
#define BODYOUTPUT_TIMESERIES_HPP

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace bodyoutput {

/// The format version written (and the only one read).
constexpr int kTimeSeriesFormatVersion = 2;

/// One body at one time. Vectors in the world frame; orientation is the unit quaternion
/// (w, x, y, z) rotating body axes to world axes.
struct BodyRecord {
  std::array<double, 3> centre{}, velocity{}, angularVelocity{}, hydroForce{}, hydroTorque{},
      collisionForce{}, collisionTorque{}, unwrappedCentre{};
  std::array<double, 4> orientation{1, 0, 0, 0};
};

/// What does not change: names, semi-axes (a, b, c along the body x, y, z axes), densities.
struct BodyInfo {
  std::string name;
  std::array<double, 3> semiAxes{};
  double density = 0;
};

/// HDF5 time series of every body, one row per call to append(); survives restarts.
class TimeSeriesWriter {
 public:
  /// Opens path, creating it (and its parent folders) if needed. A new file is written under a
  /// temporary name (path + ".creating") and renamed when complete, so `path` is either absent or
  /// a valid series.
  ///
  /// If it exists (a restarted run), its bodies must match `bodies` (same names in the same order,
  /// same semi-axes and densities to 1e-12 relative), else std::runtime_error naming the file and
  /// the difference (the file is left unchanged); rows with time > restartTime*(1+1e-12)+1e-300
  /// (for restartTime < 0: restartTime*(1-1e-12)+1e-300) are dropped, together with every row
  /// after the first such one (the run continues from restartTime); earlier rows are kept.
  ///
  /// @throws std::invalid_argument if bodies is empty, a name is empty or repeated, a semi-axis is
  ///         not finite and > 0, a density is not finite, or restartTime is NaN
  /// @throws std::runtime_error naming the file: cannot create/open it (also: already open by
  ///         another writer), not an HDF5 file, not a valid series, different bodies
  TimeSeriesWriter(const std::string& path, const std::vector<BodyInfo>& bodies,
                   double restartTime);

  /// Appends one row and flushes the file so that a killed run keeps every row written.
  /// Values are stored as given (not checked: NaN is recorded); the quaternion is not normalised.
  /// @throws std::invalid_argument if records.size() != number of bodies, time is not finite, or
  ///         time is before the last row's time by more than the restart tolerance (1e-12
  ///         relative: a row at 0.30000000000000004 kept by a restart from 0.3 may be followed by
  ///         a row at 0.3); equal times are allowed
  /// @throws std::runtime_error naming the file and dataset if HDF5 fails (rows() unchanged: a
  ///         later append() writes the same row again)
  /// @throws std::logic_error if the writer was closed or moved from
  void append(double time, const std::vector<BodyRecord>& records);

  /// Rows in the file (kept from a previous run + appended); 0 when closed or moved from.
  std::size_t rows() const;

  // ---- additions
  /// Time of the last row; NaN if there is none.
  double lastTime() const;
  /// The file's path as given to the constructor ("" when closed or moved from).
  const std::string& path() const;
  /// The bodies as given to the constructor (empty when closed or moved from).
  const std::vector<BodyInfo>& bodies() const;
  /// False once closed or moved from.
  bool isOpen() const;
  /// Closes the file now; unlike the destructor it reports a failure (std::runtime_error).
  /// Closing twice is a no-op.
  void close();

  ~TimeSeriesWriter();  ///< closes; no-throw
  TimeSeriesWriter(const TimeSeriesWriter&) = delete;
  TimeSeriesWriter& operator=(const TimeSeriesWriter&) = delete;
  TimeSeriesWriter(TimeSeriesWriter&&) noexcept;
  TimeSeriesWriter& operator=(TimeSeriesWriter&&) noexcept;  ///< closes the file it had

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Contents of a file written by TimeSeriesWriter.
struct TimeSeries {
  std::vector<BodyInfo> bodies;
  std::vector<double> time;
  std::vector<std::vector<BodyRecord>> records;  ///< [row][body]
};

/// Reads a file written by TimeSeriesWriter (for tests and tools), also while a writer has it open
/// (no file lock). @throws std::runtime_error naming the file (and dataset/attribute) on problems.
TimeSeries readTimeSeries(const std::string& path);

}  // namespace bodyoutput

#endif  // BODYOUTPUT_TIMESERIES_HPP
