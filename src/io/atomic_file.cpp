#include "vibrotherm/io/atomic_file.hpp"

#include <cstdio>
#include <stdexcept>

namespace vibrotherm::io {

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), out_(partial_name(path_)) {
  if (!out_) throw std::runtime_error("cannot write '" + partial_name(path_) + "'");
  out_.precision(17);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(partial_name(path_).c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  if (!out_) throw std::runtime_error("write error on '" + partial_name(path_) + "'");
  out_.close();
  publish(path_);
  committed_ = true;
}

void AtomicFile::publish(const std::string& path) {
  if (std::rename(partial_name(path).c_str(), path.c_str()) != 0)
    throw std::runtime_error("cannot rename '" + partial_name(path) + "' to '" + path + "'");
}

}  // namespace vibrotherm::io
