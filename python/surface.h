// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// KSetTilableSurface: the stateful core K_set_tilable_surface for Python.

#ifndef TILABLE_SURFACES_PYTHON_SURFACE_H
#define TILABLE_SURFACES_PYTHON_SURFACE_H

#include "progress.h"

#include <CGAL/Tilable_surfaces/K_set_tilable_surface.h>

#include <boost/property_map/property_map.hpp>

#include <mutex>
#include <utility>

namespace tilable_surfaces_python {

// Owns the mesh the core refers to. Every step runs without the GIL and
// under the object's lock, so that two Python threads cannot edit the
// state at once (the GIL is released before the lock is taken: a progress
// callback needs the GIL while the lock is held). A step called from the
// progress callable of a running one raises instead of waiting forever.
class Surface
{
  typedef TS::K_set_tilable_surface<CGAL::Parallel_if_available_tag, Mesh> Core;

public:
  explicit Surface(Mesh&& mesh) : m_mesh(std::move(mesh)), m_core(m_mesh) {}
  Surface(const Surface&) = delete;
  Surface& operator=(const Surface&) = delete;

  // f() under the lock, without the GIL.
  template <typename F>
  auto locked(const F& f)
  {
    if(m_guard.in_callback)
      invalid("KSetTilableSurface: the progress callable of a step cannot use the object; "
              "keep what it receives, and look at the object once the step returns");
    py::gil_scoped_release release;
    std::lock_guard<std::mutex> lock(m_guard.mutex);
    return f();
  }

  // The options of a step: those of the last cluster() (seed, orientation
  // policy, ...), then the keywords; the clustering's policy always.
  Options step_options(const py::kwargs& keywords, unsigned groups, const char* function)
  {
    Options o = m_options;
    o.orientation_policy = name_of(policy_names(), locked([&] { return m_core.orientation_policy(); }));
    read_options(o, keywords, groups, function);
    return o;
  }

  // f(np) under the lock, without the GIL (run_without_gil()).
  template <typename F>
  auto run(const Options& o, const F& f)
  {
    return run_without_gil(o, m_mesh.number_of_faces(), &m_guard, f);
  }

  // A step that starts a clustering with K = k: f(np) with K in np. Its
  // options are kept for the steps that follow.
  template <typename F>
  auto start_clustering(int k, const py::kwargs& keywords, const char* function, const F& f)
  {
    Options o = m_options;
    read_options(o, keywords, CLUSTERING | RUN, function);
    const int tiles = int(tile_count(k));
    auto result = run(o, [&](const auto& np) { return f(np.number_of_tiles(tiles)); });
    m_options = o;
    m_options.progress = py::none();
    m_options.threads = 0;
    return result;
  }

  // set_clustering(): the ids and orientations of arrays, by face.
  std::size_t set_clustering(const py::object& clusters, const py::object& orientations, const std::string& policy)
  {
    const TS::Orientation_policy p = named_value(policy_names(), policy, "orientation_policy");
    const std::vector<int> c = ids_per_face(clusters, "cluster"), o = ids_per_face(orientations, "orientation");
    return locked([&] {
      const auto index = get(boost::face_index, m_mesh);
      m_core.set_clustering(boost::make_iterator_property_map(c.begin(), index),
                            boost::make_iterator_property_map(o.begin(), index), p);
      return m_core.degree_of_flexibility();
    });
  }

  Mesh& mesh() { return m_mesh; }
  Core& core() { return m_core; }

private:
  // One id per face, from an (m,) array.
  std::vector<int> ids_per_face(const py::object& values, const char* what) const
  {
    const auto a = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(values);
    if(!a || a.ndim() != 1 || std::size_t(a.shape(0)) != m_mesh.number_of_faces())
      invalid(std::string(what) + "s must be an (m,) array of integers, one per face (m = " +
              std::to_string(m_mesh.number_of_faces()) + ")");
    return std::vector<int>(a.data(), a.data() + a.shape(0));
  }

  Step_guard m_guard;
  Mesh m_mesh;  // before m_core, which refers to it
  Core m_core;
  Options m_options;  // of the last cluster(), which the later steps reuse
};

} // namespace tilable_surfaces_python

#endif // TILABLE_SURFACES_PYTHON_SURFACE_H
