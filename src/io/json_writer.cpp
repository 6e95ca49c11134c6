#include "vibrotherm/io/json_writer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace vibrotherm::io {

std::string JsonWriter::quote(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    switch (c) {
      case '"': q += "\\\""; break;
      case '\\': q += "\\\\"; break;
      case '\n': q += "\\n"; break;
      case '\t': q += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof(buf), "\\u%04x", c);
          q += buf;
        } else {
          q += c;
        }
    }
  }
  return q + "\"";
}

void JsonWriter::prefix(const char* key) {
  if (!first_.empty()) {
    if (!first_.back()) out_ << ",";
    first_.back() = false;
    out_ << "\n" << std::string(2 * first_.size(), ' ');
  }
  if (key) out_ << quote(key) << ": ";
}

JsonWriter& JsonWriter::begin_object(const char* key) {
  prefix(key);
  out_ << "{";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::end_object() {
  first_.pop_back();
  out_ << "\n" << std::string(2 * first_.size(), ' ') << "}";
  if (first_.empty()) out_ << "\n";
  return *this;
}

JsonWriter& JsonWriter::begin_array(const char* key) {
  prefix(key);
  out_ << "[";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::end_array() {
  first_.pop_back();
  out_ << "]";
  return *this;
}

JsonWriter& JsonWriter::value(const char* key, double v) {
  prefix(key);
  if (std::isfinite(v)) {
    char buf[32];  // shortest text that reads back to the same double (no 0.54256294400000005)
    const auto r = std::to_chars(buf, buf + sizeof(buf), v);
    out_.write(buf, r.ptr - buf);
  } else {
    out_ << "null";  // JSON has no NaN/Inf
  }
  return *this;
}

JsonWriter& JsonWriter::value(const char* key, long long v) {
  prefix(key);
  out_ << v;
  return *this;
}

JsonWriter& JsonWriter::value(const char* key, bool v) {
  prefix(key);
  out_ << (v ? "true" : "false");
  return *this;
}

JsonWriter& JsonWriter::value(const char* key, const std::string& v) {
  prefix(key);
  out_ << quote(v);
  return *this;
}

JsonWriter& JsonWriter::boolean(const char* key, bool v) {
  prefix(key);
  out_ << (v ? "true" : "false");
  return *this;
}

}  // namespace vibrotherm::io
