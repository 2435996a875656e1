#pragma once
// Long calls (render, render_set) run on a worker thread with the GIL released, while the
// calling Python thread waits for it: it passes the worker's progress to the user's callback
// and checks for signals, so Ctrl-C (KeyboardInterrupt) or an exception in the callback asks
// the worker to stop at its next chance (between waves of tiles, before building a scene)
// and is raised once the worker has stopped. Python code only ever runs on the calling
// thread.
#include <pybind11/pybind11.h>

#include <atomic>
#include <functional>
#include <mutex>
#include <string>

namespace landsim::python {

// What the worker shares with the waiting thread.
class CallState {
 public:
  // From the worker: the image being rendered and its fraction done.
  void report(const std::string& image, double fraction);
  // Whether the caller asked the worker to stop.
  bool cancelled() const { return cancelled_.load(); }

 private:
  friend void call_cancellable(const std::function<void(CallState&)>&, const pybind11::object&);
  std::atomic<bool> cancelled_{false};
  std::mutex mutex_;
  std::string image_;
  double fraction_ = 0.0;
  bool fresh_ = false;
};

// Runs `work` on a worker thread; `progress` (None or a callable taking the image's name and
// the fraction done) is called on this thread. Raises what `work` throws, or the
// KeyboardInterrupt / callback exception that stopped it.
void call_cancellable(const std::function<void(CallState&)>& work,
                      const pybind11::object& progress);

}  // namespace landsim::python
