#include "vibrotherm/store/atomic_file.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "vibrotherm/util/write_failure.hpp"

namespace vibrotherm::store {
namespace {

/// "write error on 'path': <why>" (a full disk named as such).
std::string WriteError(const std::string& path) {
  const std::string reason = WriteFailureReason(path);
  return "write error on '" + path + "'" + (reason.empty() ? "" : ": " + reason);
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), out_(partial_name(path_)) {
  if (!out_) throw std::runtime_error("cannot write '" + partial_name(path_) + "'");
  out_.precision(17);
}

AtomicFile::AtomicFile(std::string path, long long resume_bytes) : path_(std::move(path)) {
  const std::string partial = partial_name(path_);
  std::error_code ec;
  const auto size = std::filesystem::file_size(partial, ec);
  if (ec || static_cast<long long>(size) < resume_bytes)
    throw std::runtime_error("-restart: cannot resume '" + partial + "': " +
                             (ec ? std::string("missing") : std::to_string(size) + " bytes") + ", the checkpoint expects " +
                             std::to_string(resume_bytes));
  std::filesystem::resize_file(partial, static_cast<std::uintmax_t>(resume_bytes), ec);
  if (!ec) out_.open(partial, std::ios::app);
  if (ec || !out_) throw std::runtime_error("-restart: cannot append to '" + partial + "'");
  out_.precision(17);
}

long long AtomicFile::bytes() {
  out_.flush();
  if (!out_) throw std::runtime_error(WriteError(partial_name(path_)));
  return static_cast<long long>(std::filesystem::file_size(partial_name(path_)));
}

void AtomicFile::keep() {
  out_.flush();
  out_.close();
  committed_ = true;  // nothing to remove
}

std::unique_ptr<AtomicFile> OpenAtomicFile(const std::string& path, long long resume_bytes) {
  return resume_bytes < 0 ? std::make_unique<AtomicFile>(path) : std::make_unique<AtomicFile>(path, resume_bytes);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(partial_name(path_).c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw std::runtime_error(WriteError(published_ ? path_ : partial_name(path_)));
  out_.close();
  if (!published_) publish(path_);
  committed_ = true;
}

void AtomicFile::publish_open() {
  out_.flush();
  if (!out_) throw std::runtime_error(WriteError(partial_name(path_)));
  publish(path_);
  published_ = committed_ = true;  // nothing under the .partial name to remove any more
}

void AtomicFile::publish(const std::string& path) {
  if (std::rename(partial_name(path).c_str(), path.c_str()) != 0)
    throw std::runtime_error("cannot rename '" + partial_name(path) + "' to '" + path + "'");
}

}  // namespace vibrotherm::store
