// The whole pipeline of make_k_set_tilable() from ~1k to ~100k quads.
//
// On six generated surfaces (benchmark_surfaces.h) at K = 100, the
// seashell parametrization (a full grid closed around its tube), a saddle
// roof trimmed by an elliptic outline (a grid whose rows have different
// lengths), an oval torus (a grid closed both ways), an elliptic dome
// meshed with a pole (a fan of triangles, then rings of quads), a facade
// with window openings (a grid with holes) and an ellipsoid meshed as a quad
// ball (no grid), from about 1k to 100k quads (the quad ball to 10k), it
// prints a markdown table: the time of each
// phase (validation, clustering and within it the exact starts made: the
// sweep clusterings, and the multilevel start's coarse solve on
// refinements that are no grid; the exact starts solved, the displacement
// prediction that ranks the candidate clusterings, their optimization, the
// improvement rounds), the total,
// the peak memory, the congruence error, the number of distinct molds (S-quads
// congruent to one another count once, `number_of_distinct_molds`), the
// symmetric Hausdorff distance to the input and the pairs of faces of the
// result that cross each other; then the exponent a of a least-squares fit
// time ~ quads^a over the sizes that finished, and again over those above
// `large_mesh_faces`, which take another path (the search ends at an exact
// sweep, no candidate is solved from the input), for each surface. The peak
// memory is the process's high-water mark, reset before each run (where
// Linux allows it; the header says when it cannot, and the mark then only
// grows).
//
// The optimization is stopped through the visitor once a run has lasted
// `budget` seconds (default 600); such a row is marked "stopped" and its
// congruence error is where the solver was.
//
// Given mesh files instead, it runs each of them, at K = max(4, faces / 25)
// unless --k is given. `--faces-per-mold N` sets K = max(4, faces / N) for
// every mesh, generated or read. With `--subdivide L`, each file is also run after 1
// to L steps of Catmull-Clark subdivision (CGAL's, each step 4 times the
// quads, a triangle 3 quads) up to --max-quads: a series of meshes that are
// no grid, with its growth exponents.
//
// `--surface NAME` (repeatable) runs only the generated surfaces named;
// `--min-quads N` skips their sizes below N quads.
//
// Usage: benchmark_pipeline [--k K | --faces-per-mold N] [--min-quads N] [--max-quads N] [--budget SECONDS]
//                           [--surface NAME] [--subdivide L] [FILE ...]
#include "benchmark_surfaces.h"

#include <CGAL/Tilable_surfaces/IO/read_polygon_mesh.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include <CGAL/Real_timer.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <initializer_list>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace TS = CGAL::Tilable_surfaces;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

namespace {

// K of a mesh file without --k or --faces-per-mold: max(4, faces / this).
constexpr std::size_t default_faces_per_mold = 25;
// K of a generated surface without --k or --faces-per-mold.
constexpr std::size_t generated_tile_count = 100;

// What the visitor records; the pipeline copies its visitor, so the copies
// share this through a pointer.
struct Run_record
{
  CGAL::Real_timer clock;
  double budget = 0;
  bool stopped = false;
  std::map<std::string, double> phase_seconds; // summed over repeated phases
};

struct Budget_visitor : TS::Default_visitor
{
  Run_record* record;

  bool iteration(int, double, double)
  {
    if(record->clock.time() > record->budget)
      record->stopped = true;
    return !record->stopped;
  }
  void phase(const char* name, double seconds) { record->phase_seconds[name] += seconds; }
};

// The seconds of the phases named, summed; "-" when none was reported.
std::string seconds(const Run_record& r, std::initializer_list<const char*> phases)
{
  double sum = 0;
  bool seen = false;
  for(const char* phase : phases)
  {
    const auto it = r.phase_seconds.find(phase);
    seen = seen || it != r.phase_seconds.end();
    sum += it != r.phase_seconds.end() ? it->second : 0.0;
  }
  if(!seen)
    return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", sum);
  return text;
}

// Slope of the least-squares line through (log x, log y).
double growth_exponent(const std::vector<double>& x, const std::vector<double>& y)
{
  double mx = 0, my = 0;
  for(std::size_t i = 0; i < x.size(); ++i) { mx += std::log(x[i]); my += std::log(y[i]); }
  mx /= double(x.size());
  my /= double(x.size());
  double sxy = 0, sxx = 0;
  for(std::size_t i = 0; i < x.size(); ++i)
  {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

void print_growth(std::ostream& out, const char* surface, const std::vector<double>& sizes,
                  const std::vector<double>& times, const char* which)
{
  out << surface << ": ";
  if(sizes.size() >= 2)
    out << "time ~ quads^" << growth_exponent(sizes, times) << " over " << which << " (" << sizes.size() << ")\n";
  else
    out << "fewer than two of " << which << ": no growth exponent\n";
}

// One run of the pipeline on `mesh`, as a table row; false if it was stopped.
bool run(const std::string& name, Mesh& mesh, std::size_t k, double budget, double& total_time)
{
  Run_record record;
  record.budget = budget;
  benchmark_surfaces::reset_peak_memory();
  record.clock.start();
  const TS::K_set_tilable_result r =
    TS::make_k_set_tilable<CGAL::Parallel_if_available_tag>(
      mesh, TS::parameters::number_of_tiles(k).visitor(Budget_visitor{{}, &record}));
  const TS::Tilability_measure& m = r.optimization.measure;
  char cells[160];
  std::snprintf(cells, sizeof cells, "%.1f%s | %.0f | %.1e | %zu | %.2f | %zu | %zu", r.total_time,
                record.stopped ? " (stopped)" : "", benchmark_surfaces::peak_memory_mb(),
                m.congruence_error, m.number_of_distinct_molds, 100 * m.hausdorff_distance,
                m.self_intersecting_face_pairs, m.flattened_panels);
  std::cout << "| " << name << " | " << mesh.number_of_faces() << " | " << k << " | "
            << seconds(record, {"validation"}) << " | " << seconds(record, {"clustering"}) << " | "
            << seconds(record, {"exact starts"}) << " | " << seconds(record, {"sweep candidate", "multilevel start"})
            << " | " << seconds(record, {"displacement prediction"}) << " | "
            << seconds(record, {"candidate optimization"}) << " | " << seconds(record, {"improvement round"})
            << " | " << cells << " | "
            << TS::internal::origin_traits(r.clustering.candidates[r.clustering.chosen_candidate].origin).name
            << " |" << std::endl;
  total_time = r.total_time;
  return !record.stopped;
}

// Records a finished run of `mesh` in a series: all sizes, and those above
// large_mesh_faces.
struct Series_times
{
  std::vector<double> sizes, times, large_sizes, large_times;

  void add(const Mesh& mesh, double seconds)
  {
    sizes.push_back(double(mesh.number_of_faces()));
    times.push_back(seconds);
    if(mesh.number_of_faces() > TS::large_mesh_faces)
    {
      large_sizes.push_back(sizes.back());
      large_times.push_back(seconds);
    }
  }
  void print(std::ostream& out, const std::string& name) const
  {
    out << '\n';
    print_growth(out, name.c_str(), sizes, times, "the sizes that finished");
    print_growth(out, name.c_str(), large_sizes, large_times, "the sizes above large_mesh_faces that finished");
  }
};

// K for a mesh of `faces` faces: `k` when given (non-zero), else
// max(4, faces / faces_per_mold) when given, else `otherwise`.
std::size_t tile_count(std::size_t k, std::size_t faces_per_mold, std::size_t faces, std::size_t otherwise)
{
  if(k > 0)
    return k;
  return faces_per_mold > 0 ? (std::max)(std::size_t(4), faces / faces_per_mold) : otherwise;
}

// The mesh file `file`, then up to `subdivisions` Catmull-Clark steps of it
// of at most `max_quads` faces, at K = k or max(4, faces / faces_per_mold);
// their growth exponents to `growth`.
void run_file_series(const std::string& file, int subdivisions, std::size_t k, std::size_t faces_per_mold,
                     std::size_t max_quads, double budget, std::ostream& growth)
{
  const std::string name = file.substr(file.find_last_of('/') + 1);
  Series_times series;
  try
  {
    Mesh mesh;
    TS::IO::read_panel_mesh(file, mesh);
    for(int level = 0; level <= subdivisions && mesh.number_of_faces() <= max_quads; ++level)
    {
      if(level > 0)
        CGAL::Subdivision_method_3::CatmullClark_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
      if(mesh.number_of_faces() > max_quads)
        break;
      Mesh copy = mesh;
      double seconds_taken = 0;
      const std::string row = level == 0 ? name : name + " (subdivided " + std::to_string(level) + "x)";
      const std::size_t faces = mesh.number_of_faces();
      const std::size_t per_mold = faces_per_mold > 0 ? faces_per_mold : default_faces_per_mold;
      if(run(row, copy, tile_count(k, per_mold, faces, 0), budget, seconds_taken))
        series.add(mesh, seconds_taken);
    }
  }
  catch(const std::exception& e)
  {
    std::cout << "| " << name << " | refused: " << e.what() << " |\n";
  }
  if(subdivisions > 0)
    series.print(growth, name);
}

// A generated surface and the resolutions n it is run at.
struct Series
{
  std::string name;
  Mesh (*generate)(int);
  std::vector<int> resolutions;
};

} // namespace

int main(int argc, char** argv)
{
  std::size_t k = 0, faces_per_mold = 0, min_quads = 0, max_quads = 100000;
  int subdivisions = 0;
  double budget = 600;
  std::vector<std::string> files, surfaces;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if(i + 1 < argc && arg == "--k")
      k = std::stoul(argv[++i]);
    else if(i + 1 < argc && arg == "--faces-per-mold")
      faces_per_mold = std::stoul(argv[++i]);
    else if(i + 1 < argc && arg == "--min-quads")
      min_quads = std::stoul(argv[++i]);
    else if(i + 1 < argc && arg == "--max-quads")
      max_quads = std::stoul(argv[++i]);
    else if(i + 1 < argc && arg == "--budget")
      budget = std::stod(argv[++i]);
    else if(i + 1 < argc && arg == "--surface")
      surfaces.push_back(argv[++i]);
    else if(i + 1 < argc && arg == "--subdivide")
      subdivisions = std::stoi(argv[++i]);
    else if(arg.rfind("--", 0) == 0)
    {
      std::cerr << "usage: benchmark_pipeline [--k K | --faces-per-mold N] [--min-quads N] [--max-quads N] "
                   "[--budget SECONDS] "
                   "[--surface NAME] [--subdivide L] [FILE ...]\n";
      return EXIT_FAILURE;
    }
    else
      files.push_back(arg);
  }
  const std::vector<Series> generated = {
    {"seashell", benchmark_surfaces::seashell<Mesh>, {32, 100, 141, 224, 316}},
    {"trimmed roof", benchmark_surfaces::trimmed_roof<Mesh>, {41, 130, 409}},
    {"oval torus", benchmark_surfaces::oval_torus<Mesh>, {32, 100, 316}},
    {"polar dome", benchmark_surfaces::polar_dome<Mesh>, {32, 100, 315}},
    {"facade with openings", benchmark_surfaces::facade_with_openings<Mesh>, {36, 112, 352}},
    // No sweep: its candidates are solved from the input with the whole KKT
    // system, 1 to 3 s per iteration at 10k quads (results.md, Scale), so
    // 100k is left out.
    {"quad ball", benchmark_surfaces::quad_ball<Mesh>, {13, 41}}};
  for(const std::string& name : surfaces)
    if(std::none_of(generated.begin(), generated.end(), [&](const Series& s) { return s.name == name; }))
    {
      std::cerr << "benchmark_pipeline: no generated surface named \"" << name << "\"\n";
      return EXIT_FAILURE;
    }
  if(!benchmark_surfaces::reset_peak_memory())
    std::cout << "(the peak memory cannot be reset here: each row's is the largest so far)\n";
  std::cout << "| surface | quads | K | validation (s) | clustering (s) | exact starts made (s)"
               " | exact starts solved (s)"
               " | prediction (s)"
               " | candidate optimization (s) | improvement (s) | total (s) | peak memory (MB)"
               " | congruence | distinct molds | Hausdorff (% diag) | crossing face pairs | flattened panels"
               " | chosen |\n"
            << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  std::ostringstream growth;
  for(const std::string& file : files)
    run_file_series(file, subdivisions, k, faces_per_mold, max_quads, budget, growth);
  if(!files.empty())
  {
    std::cout << growth.str();
    return EXIT_SUCCESS;
  }

  // Each series of sizes of a generated surface; its growth exponents are
  // printed after the table.
  for(const Series& s : generated)
  {
    if(!surfaces.empty() && std::find(surfaces.begin(), surfaces.end(), s.name) == surfaces.end())
      continue;
    Series_times series;
    for(int n : s.resolutions)
    {
      Mesh mesh = s.generate(n);
      if(mesh.number_of_faces() > max_quads)
        break;
      if(mesh.number_of_faces() < min_quads)
        continue;
      double seconds_taken = 0;
      if(run(s.name, mesh, tile_count(k, faces_per_mold, mesh.number_of_faces(), generated_tile_count), budget,
             seconds_taken))
        series.add(mesh, seconds_taken);
    }
    series.print(growth, s.name);
  }
  std::cout << growth.str();
  return EXIT_SUCCESS;
}
