#pragma once
/// @file AtomicFile.h
/// Writing a file so that it is replaced whole or not at all. The content goes into a new
/// temporary file in the same directory, which is renamed over the file once it is complete: a
/// rename within one directory is atomic, so the file holds either its old content or all of
/// the new one. A failed write leaves an existing file untouched and no temporary file behind.
/// A symbolic link is followed (through a chain, to a target that need not exist yet): the file
/// it points to is replaced, from a temporary file in that file's directory, and the link stays.
/// An existing file that the user may not write (access(2): root may) is refused, not replaced.
///
/// The PNG writer uses it, and so does every program that writes a file it must not half-write
/// (the `rt` program's scene files).

#include <cstdio>
#include <functional>
#include <string>
#include <string_view>

namespace rt {

/// Writes the file at path: fill puts the content into the open temporary file (mode 0644, or
/// the permission bits of the file it replaces; opened for binary writing) and returns an empty
/// string, or why it could not ("PNG encoding failed"). A failed fwrite need not be reported by
/// fill: the stream's error flag is checked after it. Missing directories are not created.
/// @throws std::runtime_error "cannot write 'PATH': REASON" when path names an existing file
///         the user may not write ("Permission denied") or a loop of links, or when the
///         temporary file cannot be created, filled, closed or renamed; any exception fill
///         throws is passed on. In every case the temporary file is removed and an existing
///         file at path is untouched.
void writeFileAtomically(const std::string& path,
                         const std::function<std::string(std::FILE*)>& fill);

/// writeFileAtomically with bytes as the whole content.
void writeFileAtomically(const std::string& path, std::string_view bytes);

/// Creates and removes the temporary file that writeFileAtomically(path, ...) would write
/// (beside a symbolic link's target), after the same refusal of a file the user may not write:
/// the one reliable test that the write can start (permissions, read-only file systems, ACLs
/// and root's privileges defeat any cheaper one).
/// @throws std::runtime_error "cannot write 'PATH': REASON" when it cannot be created.
void checkTemporaryFileBeside(const std::string& path);

}  // namespace rt
