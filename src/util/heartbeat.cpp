#include "vibrotherm/util/heartbeat.hpp"

#include <chrono>
#include <cstdio>

namespace vibrotherm {

namespace {

/// Seconds on a steady clock (the thread makes no MPI call).
double Now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

}  // namespace

Heartbeat::Heartbeat(MPI_Comm comm, std::string what, double every) : what_(std::move(what)), every_(every) {
  start_ = Now();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank != 0) return;
  thread_ = std::thread([this] {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::duration<double>(every_), [this] { return done_; })) {
      std::fprintf(stderr, "%s, %.0f s so far\n", what_.c_str(), Now() - start_);
      std::fflush(stderr);
    }
  });
}

Heartbeat::~Heartbeat() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  wake_.notify_one();
  thread_.join();
  const double seconds = Now() - start_;
  if (seconds >= every_) std::fprintf(stderr, "%s: done in %.0f s\n", what_.c_str(), seconds);
}

}  // namespace vibrotherm
