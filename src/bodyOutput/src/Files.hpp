// Private helpers: folders, atomic text files, numbers as text.
#ifndef BODYOUTPUT_FILES_HPP
#define BODYOUTPUT_FILES_HPP

#include <functional>
#include <ostream>
#include <string>

namespace bodyoutput {
namespace detail {

/// Creates the folders above `path` if missing. @throws std::runtime_error "<who>: ..."
void createParentDirectories(const std::string& path, const std::string& who);

/// Writes text to path + ".tmp" and renames it to path (readers never see a partial file).
/// @throws std::runtime_error "<who>: ..." naming the file
void writeFileAtomically(const std::string& path, const std::string& text, const std::string& who);

/// The same with the content written by `fill` into the open temporary file (for content too
/// large to hold in memory at once). An exception from `fill` removes the temporary file and
/// propagates.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& fill,
                         const std::string& who);

/// Shortest text that reads back as the same double (locale-independent; "nan", "inf", "-inf").
std::string shortest(double v);

}  // namespace detail
}  // namespace bodyoutput

#endif  // BODYOUTPUT_FILES_HPP
