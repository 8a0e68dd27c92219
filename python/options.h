// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The keyword arguments of the Python module: one table says which function
// takes which, reads them with the package's message on a bad value, and
// writes their help; the named parameters are made from them in one place.

#ifndef TILABLE_SURFACES_PYTHON_OPTIONS_H
#define TILABLE_SURFACES_PYTHON_OPTIONS_H

#include "arrays.h"

#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace tilable_surfaces_python {

namespace TSP = CGAL::Tilable_surfaces::parameters;

// Their defaults are the package's (defaults.h); a negative value, where
// said, leaves the package's default for the solver or the mesh.
struct Options
{
  int k = 0;                  // 0: not given
  double max_deviation = -1;  // negative: K is given
  unsigned int seed = TS::defaults::random_seed;
  std::size_t number_of_candidates = TS::defaults::number_of_candidates;
  double similarity_threshold = TS::defaults::similarity_threshold;
  double flexibility_penalty = TS::defaults::flexibility_penalty;
  std::string orientation_policy = "proper_rigid_motions";
  double distance_weight = TS::defaults::distance_weight;
  double fairness_weight = -1;
  std::string solver = "gauss-newton";
  int iterations = -1;
  double congruence_tolerance = TS::defaults::congruence_tolerance;
  bool planar_tiles = TS::defaults::planar_tiles;
  double panel_tolerance = TS::defaults::panel_tolerance;
  int optimized_candidates = -1;
  int improvement_rounds = TS::defaults::number_of_improvement_rounds;
  int threads = 0;
  py::object progress = py::none();
};

// Which calls take an option.
enum Option_group : unsigned
{
  TILE_COUNT = 1,    // make_k_set_tilable()
  CLUSTERING = 2,    // and KSetTilableSurface.cluster()
  OPTIMIZATION = 4,  // and the solving steps
  SEARCH = 8,        // optimize_closest() and the pipeline
  RUN = 16,          // every step that computes
  PIPELINE = CLUSTERING | OPTIMIZATION | SEARCH | RUN
};

template <typename Enum>
using Name_table = std::vector<std::pair<const char*, Enum> >;

inline const Name_table<TS::Solver_type>& solver_names()
{
  static const Name_table<TS::Solver_type> names{{"gauss-newton", TS::CONSTRAINED_GAUSS_NEWTON},
                                                 {"paper-cg", TS::PAPER_CONJUGATE_GRADIENT}};
  return names;
}

inline const Name_table<TS::Orientation_policy>& policy_names()
{
  static const Name_table<TS::Orientation_policy> names{{"proper_rigid_motions", TS::PROPER_RIGID_MOTIONS},
                                                        {"no_turned_over_panels", TS::NO_TURNED_OVER_PANELS},
                                                        {"allow_mirrored_panels", TS::ALLOW_MIRRORED_PANELS}};
  return names;
}

template <typename Enum>
Enum named_value(const Name_table<Enum>& table, const std::string& name, const char* what)
{
  std::string known;
  for(const auto& entry : table)
  {
    if(name == entry.first) return entry.second;
    known += std::string(known.empty() ? "" : ", ") + entry.first;
  }
  invalid(std::string("unknown ") + what + " '" + name + "' (" + known + ")");
}

template <typename Enum>
const char* name_of(const Name_table<Enum>& table, Enum value)
{
  for(const auto& entry : table)
    if(entry.second == value) return entry.first;
  return table.front().first;
}

struct Option
{
  const char* name;
  unsigned groups;
  const char* help;
  std::function<void(Options&, py::handle)> read;
  std::function<py::object(const Options&)> default_value;
};

// An option stored in `member`; a value of another type is refused with
// the package's message.
template <typename T>
Option option(const char* name, unsigned groups, T Options::*member, const char* help)
{
  auto read = [name, member](Options& o, py::handle value) {
    try
    {
      o.*member = value.cast<T>();
    }
    catch(const py::cast_error&)
    {
      invalid(std::string(name) + " cannot be " + std::string(py::repr(value)));
    }
  };
  auto default_value = [member](const Options& o) -> py::object {
    if constexpr(std::is_base_of<py::object, T>::value)
      return o.*member;
    else
      return py::cast(o.*member);
  };
  return Option{name, groups, help, read, default_value};
}

inline const std::vector<Option>& option_table()
{
  static const std::vector<Option> table{
    option("k", TILE_COUNT, &Options::k,
           "number K of distinct tiles (S-quads), 1..m; with max_deviation the largest K tried (0: m)"),
    option("max_deviation", TILE_COUNT, &Options::max_deviation,
           "instead of k: the smallest K whose result is tilable, does not cross itself and is within "
           "this symmetric Hausdorff distance of the input (a fraction of its bounding-box diagonal); "
           "< 0: k is given"),
    option("seed", CLUSTERING | SEARCH, &Options::seed, "random seed of the k-means and the splits"),
    option("number_of_candidates", CLUSTERING, &Options::number_of_candidates,
           "configurations kept while clustering"),
    option("similarity_threshold", CLUSTERING, &Options::similarity_threshold,
           "initial clustering threshold over the mean edge length"),
    option("flexibility_penalty", CLUSTERING, &Options::flexibility_penalty,
           "weight of lost degrees of flexibility in the clustering score"),
    option("orientation_policy", CLUSTERING, &Options::orientation_policy,
           "'proper_rigid_motions', 'no_turned_over_panels' or 'allow_mirrored_panels'"),
    option("distance_weight", OPTIMIZATION, &Options::distance_weight, "mu1, closeness to the input"),
    option("fairness_weight", OPTIMIZATION, &Options::fairness_weight,
           "mu2 (< 0: the solver's default, 1e-6 for gauss-newton, 1e-4 for paper-cg)"),
    option("solver", OPTIMIZATION, &Options::solver,
           "'gauss-newton' (exact) or 'paper-cg' (the paper's conjugate gradient)"),
    option("iterations", OPTIMIZATION, &Options::iterations,
           "maximum solver iterations (< 0: the solver's default, 300 or 5000)"),
    option("congruence_tolerance", OPTIMIZATION, &Options::congruence_tolerance,
           "congruence error below which the result is tilable"),
    option("planar_tiles", CLUSTERING | OPTIMIZATION, &Options::planar_tiles,
           "every panel planar as well as congruent (gauss-newton only)"),
    option("panel_tolerance", CLUSTERING | OPTIMIZATION, &Options::panel_tolerance,
           "T in model units: every panel within T of its mold (largest corner distance after the best "
           "rigid fit), panels that fit one mold within T share it; 0: exact congruence"),
    option("optimized_candidates", SEARCH, &Options::optimized_candidates,
           "clusterings of the pool optimized fully (< 0: the package's default for the mesh's size)"),
    option("improvement_rounds", SEARCH, &Options::improvement_rounds,
           "rounds of split-and-merge edits after the candidates"),
    option("threads", RUN, &Options::threads, "threads of the parallel loops (0: all cores); same results"),
    option("progress", RUN, &Options::progress,
           "a callable: progress('phase', name, seconds) when a phase ends, progress('iteration', i, "
           "congruence_error, objective) after solver iteration i (0: the start); returning False "
           "stops the solvers (at the next iteration), None or True goes on"),
  };
  return table;
}

// Docstrings are wrapped at this width, as Python's help() does not wrap.
constexpr std::size_t docstring_width = 92;

// `text` with every line longer than docstring_width broken at spaces; the
// continuation keeps the line's indentation plus `indent`.
inline std::string wrapped(const std::string& text, const std::string& indent = "")
{
  std::string out, line;
  std::istringstream lines(text);
  while(std::getline(lines, line))
  {
    const std::size_t text_start = line.find_first_not_of(' ');
    const std::string margin = line.substr(0, text_start == std::string::npos ? 0 : text_start) + indent;
    for(std::size_t cut = line.rfind(' ', docstring_width);
        line.size() > docstring_width && cut != std::string::npos && cut > margin.size();
        cut = line.rfind(' ', docstring_width))
    {
      out += line.substr(0, cut) + "\n";
      line = margin + line.substr(cut + 1);
    }
    out += line + "\n";
  }
  return out;
}

// A docstring: `text`, then the keyword arguments of `groups` with their
// defaults.
inline std::string docstring(const std::string& text, unsigned groups = 0)
{
  std::string help = wrapped(text);
  if(groups != 0)
  {
    help += "\nKeyword arguments [default]:\n";
    for(const Option& o : option_table())
      if(o.groups & groups)
        help += wrapped("  " + std::string(o.name) + ": " + o.help + " [" +
                          std::string(py::repr(o.default_value(Options()))) + "]",
                        "    ");
  }
  return help;
}

// Reads `keywords` into `o`; None leaves an option at its value. A keyword
// `function` does not take raises TypeError, as Python does.
inline void read_options(Options& o, const py::kwargs& keywords, unsigned groups, const char* function)
{
  for(const auto& item : keywords)
  {
    const std::string key = py::str(item.first);
    const Option* found = nullptr;
    for(const Option& option : option_table())
      if(key == option.name && (option.groups & groups)) found = &option;
    if(found == nullptr)
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + key + "'");
    if(!item.second.is_none())
      found->read(o, item.second);
  }
  if(o.threads < 0)
    invalid("threads must be >= 0 (0: all cores), got " + std::to_string(o.threads));
  if(o.improvement_rounds < 0)
    invalid("improvement_rounds must be >= 0, got " + std::to_string(o.improvement_rounds));
  if(!o.progress.is_none() && !PyCallable_Check(o.progress.ptr()))
    invalid("progress must be callable, not " + std::string(py::repr(o.progress)));
  named_value(solver_names(), o.solver, "solver");
  named_value(policy_names(), o.orientation_policy, "orientation_policy");
}

inline std::size_t tile_count(int k)
{
  if(k < 1)
    invalid("k must be at least 1, got " + std::to_string(k));
  return std::size_t(k);
}

// The named parameters of every step (clustering, solves, the search), with
// `visitor` by reference; the two maps and K are added by the caller.
template <typename Visitor>
auto step_parameters(const Options& o, std::size_t number_of_faces, Visitor& visitor)
{
  const TS::Solver_type solver = named_value(solver_names(), o.solver, "solver");
  return TSP::number_of_candidates(o.number_of_candidates)
    .random_seed(o.seed)
    .similarity_threshold(o.similarity_threshold)
    .flexibility_penalty(o.flexibility_penalty)
    .orientation_policy(named_value(policy_names(), o.orientation_policy, "orientation_policy"))
    .distance_weight(o.distance_weight)
    .fairness_weight(o.fairness_weight < 0 ? TS::default_fairness_weight(solver) : o.fairness_weight)
    .solver(solver)
    .number_of_iterations(o.iterations >= 0 ? o.iterations : TS::default_number_of_iterations(solver))
    .congruence_tolerance(o.congruence_tolerance)
    .planar_tiles(o.planar_tiles)
    .panel_tolerance(o.panel_tolerance)
    .number_of_optimized_candidates(o.optimized_candidates >= 0
                                      ? std::size_t(o.optimized_candidates)
                                      : TS::default_number_of_optimized_candidates(number_of_faces))
    .number_of_improvement_rounds(o.improvement_rounds)
    .visitor(std::ref(visitor));
}

// Caps the threads of the parallel loops while it lives (0: no cap).
class Thread_cap
{
public:
  explicit Thread_cap(int threads)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(threads > 0)
      m_control.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism, std::size_t(threads)));
#else
    (void)threads;
#endif
  }

private:
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> m_control;
#endif
};

} // namespace tilable_surfaces_python

#endif // TILABLE_SURFACES_PYTHON_OPTIONS_H
