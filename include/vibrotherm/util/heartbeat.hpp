// A line now and then while one long call runs that reports nothing itself (MUMPS's
// analysis and factorisation, SLEPc's solve): "Harmonic start: factoring, 60 s so far".
// Rank 0 only, from a thread of its own that only prints; it stops when the object
// goes out of scope, saying how long the call took when that was long.
#pragma once

#include <petscsys.h>

#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace vibrotherm {

class Heartbeat {
 public:
  /// what: "Harmonic start: factoring"; a line every `every` seconds while in scope.
  Heartbeat(MPI_Comm comm, std::string what, double every = 30.0);
  ~Heartbeat();
  Heartbeat(const Heartbeat&) = delete;
  Heartbeat& operator=(const Heartbeat&) = delete;

 private:
  std::string what_;
  double every_, start_;
  bool done_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
};

}  // namespace vibrotherm
