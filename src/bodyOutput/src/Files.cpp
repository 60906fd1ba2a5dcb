#include "Files.hpp"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace bodyoutput {
namespace detail {

namespace fs = std::filesystem;

void createParentDirectories(const std::string& path, const std::string& who) {
  const fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec || !fs::is_directory(parent)) {
    throw std::runtime_error(who + ": cannot create the folder '" + parent.string() + "' for '" +
                             path + "'" + (ec ? ": " + ec.message() : std::string()));
  }
}

void writeFileAtomically(const std::string& path, const std::string& text, const std::string& who) {
  writeFileAtomically(
      path,
      [&](std::ostream& out) { out.write(text.data(), static_cast<std::streamsize>(text.size())); },
      who);
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& fill,
                         const std::string& who) {
  createParentDirectories(path, who);
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw std::runtime_error(who + ": cannot open '" + tmp + "' for writing: " +
                               std::strerror(errno));
    }
    try {
      fill(out);
    } catch (...) {
      out.close();
      std::error_code ec;
      fs::remove(tmp, ec);
      throw;
    }
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw std::runtime_error(who + ": error while writing '" + tmp + "' (disk full?)");
    }
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error(who + ": cannot rename '" + tmp + "' to '" + path + "': " +
                             ec.message());
  }
}

std::string shortest(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

}  // namespace detail
}  // namespace bodyoutput
