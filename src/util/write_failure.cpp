#include "vibrotherm/util/write_failure.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace vibrotherm {

std::string WriteFailureReason(const std::string& path) {
  const int error = errno;  // of the failed write, before anything here changes it
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  const std::filesystem::space_info space = std::filesystem::space(dir.empty() ? "." : dir, ec);
  constexpr std::uintmax_t kNearlyFull = 1 << 20;  // bytes: less than a dataset or a CSV block more
  if (!ec && space.available < kNearlyFull)
    return "no space left on device (" + std::to_string(space.available / 1024) + " kB free)";
  for (int known : {ENOSPC, EDQUOT, EFBIG, EIO, EROFS, EACCES})
    if (error == known) return std::strerror(error);
  return "";
}

}  // namespace vibrotherm
