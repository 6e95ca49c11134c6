// A minimal streaming JSON writer (objects, arrays, numbers, strings, bools).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace vibrotherm::io {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) { out_.precision(17); }
  JsonWriter& begin_object(const char* key = nullptr);
  JsonWriter& end_object();
  JsonWriter& begin_array(const char* key = nullptr);
  JsonWriter& end_array();
  JsonWriter& value(const char* key, double v);
  JsonWriter& value(const char* key, long long v);
  JsonWriter& value(const char* key, int v) { return value(key, static_cast<long long>(v)); }
  JsonWriter& value(const char* key, const std::string& v);
  JsonWriter& value(const char* key, bool v);
  JsonWriter& value(const char* key, const char* v) { return value(key, std::string(v)); }
  JsonWriter& boolean(const char* key, bool v);

 private:
  void prefix(const char* key);
  static std::string quote(const std::string& s);
  std::ostream& out_;
  std::vector<bool> first_;  ///< per open container: nothing written yet
};

}  // namespace vibrotherm::io
