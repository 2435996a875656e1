#include "python/bindings/cancellable_call.h"

#include <chrono>
#include <exception>
#include <future>
#include <optional>
#include <thread>

namespace py = pybind11;

namespace landsim::python {

void CallState::report(const std::string& image, double fraction) {
  const std::lock_guard lock(mutex_);
  image_ = image;
  fraction_ = fraction;
  fresh_ = true;
}

void call_cancellable(const std::function<void(CallState&)>& work, const py::object& progress) {
  CallState state;
  std::packaged_task<void()> task([&] { work(state); });
  std::future<void> done = task.get_future();
  std::thread worker(std::move(task));
  std::optional<py::error_already_set> stopped_by;  // KeyboardInterrupt or the callback's error
  for (bool finished = false; !finished;) {
    {
      py::gil_scoped_release release;
      finished = done.wait_for(std::chrono::milliseconds(50)) == std::future_status::ready;
    }
    if (stopped_by) continue;
    try {
      std::optional<std::pair<std::string, double>> news;
      {
        const std::lock_guard lock(state.mutex_);
        if (state.fresh_) news.emplace(state.image_, state.fraction_);
        state.fresh_ = false;
      }
      if (news && !progress.is_none()) progress(news->first, news->second);
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    } catch (py::error_already_set& e) {
      stopped_by.emplace(std::move(e));
      state.cancelled_ = true;
    }
  }
  worker.join();
  if (stopped_by) throw std::move(*stopped_by);
  done.get();  // rethrows the worker's exception
}

}  // namespace landsim::python
