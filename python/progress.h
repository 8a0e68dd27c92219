// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The package's visitor for Python: passes phases and solver iterations to a
// Python callable, and stops the solvers when it returns False, raises, or
// the user presses Ctrl-C.

#ifndef TILABLE_SURFACES_PYTHON_PROGRESS_H
#define TILABLE_SURFACES_PYTHON_PROGRESS_H

#include "options.h"

#include <CGAL/Tilable_surfaces/visitor.h>

#include <atomic>
#include <exception>
#include <mutex>
#include <utility>

namespace tilable_surfaces_python {

// Called from the computation, which runs without the GIL (on the calling
// thread, or on a TBB thread for the candidate solves): each call takes the
// GIL for the time of the Python call. An exception of the callable (or a
// KeyboardInterrupt) is kept, stops the solvers, and is raised by
// `raise_pending()` once the computation returns.
class Progress_visitor : public TS::Default_visitor
{
public:
  // `in_callback`, if given, is true while the callable runs.
  Progress_visitor(py::object callback, std::atomic<bool>* in_callback)
    : m_callback(std::move(callback)), m_in_callback(in_callback)
  {}
  Progress_visitor(const Progress_visitor&) = delete;
  Progress_visitor& operator=(const Progress_visitor&) = delete;

  bool iteration(int iteration, double congruence_error, double objective)
  {
    return report([&] { return m_callback("iteration", iteration, congruence_error, objective); });
  }

  // A phase cannot be interrupted: False stops the next solver iteration.
  void phase(const char* name, double seconds)
  {
    report([&] { return m_callback("phase", name, seconds); });
  }

  // With the GIL held, after the computation.
  void raise_pending() const
  {
    if(m_error) std::rethrow_exception(m_error);
  }

private:
  template <typename Call>
  bool report(const Call& call)
  {
    if(m_failed) return false;
    py::gil_scoped_acquire gil;
    try
    {
      if(PyErr_CheckSignals() != 0) throw py::error_already_set();
      if(!m_callback.is_none())
      {
        const Flag_scope scope(m_in_callback);
        const py::object answer = call();
        const int go_on = answer.is_none() ? 1 : PyObject_IsTrue(answer.ptr());
        if(go_on < 0) throw py::error_already_set();
        if(go_on == 0) m_stop = true;
      }
    }
    catch(...)
    {
      m_error = std::current_exception();
      m_failed = true;
      m_stop = true;
    }
    return !m_stop;
  }

  // Sets a flag for its lifetime.
  struct Flag_scope
  {
    explicit Flag_scope(std::atomic<bool>* flag) : flag(flag) { if(flag) *flag = true; }
    ~Flag_scope() { if(flag) *flag = false; }
    std::atomic<bool>* flag;
  };

  py::object m_callback;
  std::atomic<bool>* m_in_callback;
  std::atomic<bool> m_stop{false};
  std::atomic<bool> m_failed{false};  // the callable is not called again
  std::exception_ptr m_error;         // written under the GIL
};

// What keeps the steps of one object apart: a step holds `mutex`, and
// `in_callback` tells that its progress callable is running (a step it
// called would wait for the mutex forever).
struct Step_guard
{
  std::mutex mutex;
  std::atomic<bool> in_callback{false};
};

// f(np), np the named parameters of `o` for a mesh of `faces` faces, run
// without the GIL (under `guard` if given), with o's threads and progress;
// the progress callable's exception, if any, is raised after.
template <typename F>
auto run_without_gil(const Options& o, std::size_t faces, Step_guard* guard, const F& f)
{
  Progress_visitor progress(o.progress, guard != nullptr ? &guard->in_callback : nullptr);
  auto result = [&] {
    py::gil_scoped_release release;
    std::unique_lock<std::mutex> lock;
    if(guard != nullptr) lock = std::unique_lock<std::mutex>(guard->mutex);
    Thread_cap cap(o.threads);
    return f(step_parameters(o, faces, progress));
  }();
  progress.raise_pending();
  return result;
}

} // namespace tilable_surfaces_python

#endif // TILABLE_SURFACES_PYTHON_PROGRESS_H
