// Why writing a file failed, in words a user can act on (plain C++: vibrotherm-contact
// writes its CSV through store/atomic_file without PETSc).
#pragma once

#include <string>

namespace vibrotherm {

/// Why writing `path` may have failed: "no space left on device (N kB free)" when the file
/// system that holds it is (nearly) full, else the system's text for errno after a failed
/// write (EFBIG, EIO, EDQUOT, EROFS, EACCES), else "".
std::string WriteFailureReason(const std::string& path);

}  // namespace vibrotherm
