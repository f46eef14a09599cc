// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Long C++ work called from Python without holding the interpreter, and stoppable with Ctrl-C.
//
// The work runs on a worker thread; the calling thread gives up the GIL (other Python threads
// run meanwhile) and waits in short slices, taking the GIL back after each one to run Python's
// signal handlers (PyErr_CheckSignals needs the GIL and runs handlers on the main thread only,
// so this is where Ctrl-C becomes KeyboardInterrupt). On an exception from a handler the worker's
// StopRequest is set: the library polls it between stages and in its long loops. A stage that
// cannot be interrupted (one SuiteSparseQR or LAPACK call) may outlast the grace period; then the
// call returns with the exception at once and the worker finishes its stage in the background,
// owning everything it uses. The interpreter waits for such workers at exit (they may be inside
// BLAS, whose buffers exit would free), after asking every running one to stop.
//
// The work must not touch Python objects: it runs without the GIL. One piece of work runs at a
// time (LibraryTurn), as when the GIL serialised every call: parts of the library share process
// state (METIS's rand() for orderings), and a result must not depend on what another thread
// analyses meanwhile.

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>
#include <utility>

#include "kinestat/stop_request.hpp"

namespace kinestat::python {

/// How often the waiting caller looks for signals.
inline constexpr std::chrono::milliseconds kSignalCheckInterval{50};
/// How long an interrupted call waits for its worker to reach a stage boundary before returning
/// without it.
inline constexpr std::chrono::milliseconds kStopGrace{300};

/// The stop flags of the workers still running, so that the interpreter's exit can stop them
/// and wait for them. Never destroyed: a worker may end after static destruction has begun.
class RunningWork {
 public:
  static RunningWork& instance() {
    static auto* running = new RunningWork;
    return *running;
  }
  void add(std::atomic<bool>* flag) {
    const std::lock_guard lock(mutex_);
    flags_.insert(flag);
  }
  void remove(std::atomic<bool>* flag) {
    {
      const std::lock_guard lock(mutex_);
      flags_.erase(flag);
    }
    changed_.notify_all();
  }
  /// Sets every running worker's stop flag and waits until all have ended (call without the GIL).
  void stop_all_and_wait() {
    std::unique_lock lock(mutex_);
    for (std::atomic<bool>* flag : flags_) flag->store(true);
    changed_.wait(lock, [this] { return flags_.empty(); });
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::set<std::atomic<bool>*> flags_;
};

/// The library's work, one call at a time. Never destroyed (see RunningWork).
inline std::mutex& library_turn() {
  static auto* turn = new std::mutex;
  return *turn;
}

/// Runs `work(stop)` on a worker thread as described above and returns its value, or rethrows
/// its exception (with the GIL held, so pybind11's translators apply), or raises the exception a
/// signal handler raised (KeyboardInterrupt). Call with the GIL held.
template <class Result>
Result call_interruptibly(std::function<Result(const StopRequest& stop)> work) {
  struct Job {
    std::atomic<bool> stop{false};
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    std::optional<Result> value;
    std::exception_ptr error;

    bool wait_for(std::chrono::milliseconds interval) {
      std::unique_lock lock(mutex);
      return finished.wait_for(lock, interval, [this] { return done; });
    }
  };
  auto job = std::make_shared<Job>();
  auto shared_work = std::make_shared<std::function<Result(const StopRequest&)>>(std::move(work));
  RunningWork::instance().add(&job->stop);
  std::thread worker;
  try {
    worker = std::thread([job, shared_work] {
      try {
        const std::lock_guard turn(library_turn());
        const StopRequest stop{&job->stop};
        stop.throw_if_requested();  // interrupted while waiting for its turn
        job->value.emplace((*shared_work)(stop));
      } catch (...) {
        job->error = std::current_exception();
      }
      {
        const std::lock_guard lock(job->mutex);
        job->done = true;
      }
      job->finished.notify_all();
      RunningWork::instance().remove(&job->stop);
    });
  } catch (...) {  // no thread to be had: the work in this thread, without interruption
    RunningWork::instance().remove(&job->stop);
    const pybind11::gil_scoped_release release;
    const std::lock_guard turn(library_turn());
    return (*shared_work)(StopRequest{});
  }
  bool interrupted = false;
  {
    pybind11::gil_scoped_release release;
    while (!job->wait_for(kSignalCheckInterval)) {
      const pybind11::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {  // a handler raised: its exception is set on this thread
        interrupted = true;
        break;
      }
    }
    if (interrupted) {
      job->stop.store(true);
      if (job->wait_for(kStopGrace)) worker.join();
      else worker.detach();  // finishes its stage in the background (RunningWork)
    } else {
      worker.join();
    }
  }
  if (interrupted) throw pybind11::error_already_set();
  if (job->error) std::rethrow_exception(job->error);
  return std::move(*job->value);
}

/// Makes the interpreter's exit stop running workers and wait for them (once, at import).
inline void stop_work_at_exit() {
  pybind11::module_::import("atexit").attr("register")(pybind11::cpp_function([] {
    const pybind11::gil_scoped_release release;
    RunningWork::instance().stop_all_and_wait();
  }));
}

}  // namespace kinestat::python
