// Private helpers of the HDF5 code: RAII handles, silenced error printing, error text.
#ifndef BODYOUTPUT_HDF5UTIL_HPP
#define BODYOUTPUT_HDF5UTIL_HPP

#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace bodyoutput {
namespace detail {

/// Owns an HDF5 identifier and closes it with its closer (H5Fclose, H5Dclose, ...).
class H5Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  H5Handle() = default;
  H5Handle(hid_t id, Closer closer) noexcept : id_(id), closer_(closer) {}
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  H5Handle(H5Handle&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), closer_(o.closer_) {}
  H5Handle& operator=(H5Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, H5I_INVALID_HID);
      closer_ = o.closer_;
    }
    return *this;
  }
  ~H5Handle() { reset(); }

  hid_t get() const noexcept { return id_; }
  bool valid() const noexcept { return id_ >= 0; }
  /// closes now (errors ignored)
  void reset() noexcept {
    if (id_ >= 0 && closer_ != nullptr) closer_(id_);
    id_ = H5I_INVALID_HID;
  }
  /// closes now; false if closing failed (a write error may show only here)
  bool close() noexcept {
    const hid_t id = std::exchange(id_, H5I_INVALID_HID);
    return id < 0 || closer_ == nullptr || closer_(id) >= 0;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

/// Silences HDF5's automatic error-stack printing for the scope (failures are thrown instead).
class H5Quiet {
 public:
  H5Quiet() noexcept {
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

/// The innermost message of HDF5's current error stack as " (HDF5: ...)", or "". Call right
/// after the failing HDF5 call: any other HDF5 call (closing a handle too) clears the stack.
std::string hdf5Detail();

/// throws std::runtime_error(what + hdf5Detail())
[[noreturn]] void fail(const std::string& what);

/// "'path'" for messages
inline std::string inQuotes(const std::string& s) { return "'" + s + "'"; }

}  // namespace detail
}  // namespace bodyoutput

#endif  // BODYOUTPUT_HDF5UTIL_HPP
