// Reproduces the paper's Table 1 (Fu et al. 2010) on the stand-ins of its six
// surfaces: for every surface and every K the paper reports, the mesh is made
// K-set tilable by make_k_set_tilable() (default parameters, random_seed 0),
// once with the default solver and once with the paper's conjugate gradient,
// and one markdown row sets them side by side: K, degree of flexibility, the
// measured congruence error and the symmetric Hausdorff distance to the input
// (max / mean, of the bounding-box diagonal) of each, the ratio of the two
// Hausdorff distances (default / paper), the times, and the distinct molds of
// the default solver's result (congruent S-quads count once). `--terms` prints the
// paper's normalized terms F̃_d..F̃_o of each run instead.
//
// Usage: paper_table [--solver gauss-newton|paper-cg|both] [--terms] [SURFACE ...]
//   SURFACE: swiss_re tunnel seashell decocube monkey_saddle de_beers_ginza (default: all)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;

namespace {

// The surfaces and the K values of the paper's Table 1, as far as its copy
// can be read (the monkey saddle's first clustering step, 24, is added).
const std::vector<std::pair<std::string, std::vector<int> > > paper_rows = {
  {"swiss_re", {24, 18, 9}},
  {"tunnel", {12, 10, 8}},
  {"seashell", {96, 60, 44, 21}},
  {"decocube", {21, 15, 9}},
  {"monkey_saddle", {24, 3, 1}},
  {"de_beers_ginza", {48, 44, 39, 34, 30, 27, 28, 22, 16}}};

struct Run
{
  const char* solver;
  TS::K_set_tilable_result result;
};

void print_header(bool terms, bool both)
{
  if(terms)
    std::printf("| surface | K | DOF | solver | F̃_d | F̃_f | F̃_e | F̃_a | F̃_o | Hausdorff max / mean | congruence | tilable | iterations | time (s) |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  else if(both)
    std::printf("| surface | K | DOF | congruence (default) | Hausdorff max / mean (default) | congruence (paper CG) | Hausdorff max / mean (paper CG) | Hausdorff ratio default / paper | time default / paper (s) | molds (default) |\n"
                "|---|---|---|---|---|---|---|---|---|---|\n");
  else
    std::printf("| surface | K | DOF | solver | congruence | Hausdorff max / mean | displacement max | iterations | time (s) |\n"
                "|---|---|---|---|---|---|---|---|---|\n");
}

std::string congruence(const TS::K_set_tilable_result& r)
{
  char text[64];
  std::snprintf(text, sizeof text, "%.1e%s", r.optimization.measure.congruence_error,
                r.is_tilable() ? "" : " **(not tilable)**");
  return text;
}

void print_rows(const std::string& surface, int k, const std::vector<Run>& runs, bool terms)
{
  if(terms || runs.size() == 1)
  {
    for(const Run& run : runs)
    {
      const TS::Tilability_measure& m = run.result.optimization.measure;
      const TS::Energy_terms& t = m.normalized_terms;
      if(terms)
        std::printf("| %s | %d | %zu | %s | %.2e | %.2e | %.2e | %.2e | %.2e | %.2e / %.2e | %.1e | %s | %d | %.2f |\n",
                    surface.c_str(), k, m.degree_of_flexibility, run.solver, t.distance, t.fairness,
                    t.edge_length, t.diagonal, t.volume, m.hausdorff_distance, m.mean_symmetric_distance,
                    m.congruence_error, run.result.is_tilable() ? "yes" : "**no**",
                    run.result.optimization.iterations, run.result.total_time);
      else
        std::printf("| %s | %d | %zu | %s | %s | %.2e / %.2e | %.2e | %d | %.2f |\n", surface.c_str(), k,
                    m.degree_of_flexibility, run.solver, congruence(run.result).c_str(),
                    m.hausdorff_distance, m.mean_symmetric_distance,
                    m.max_displacement / m.input_bbox_diagonal, run.result.optimization.iterations,
                    run.result.total_time);
    }
  }
  else
  {
    const TS::Tilability_measure& a = runs[0].result.optimization.measure;
    const TS::Tilability_measure& b = runs[1].result.optimization.measure;
    std::printf("| %s | %d | %zu | %s | %.2e / %.2e | %s | %.2e / %.2e | %.2f | %.2f / %.2f | %zu |\n",
                surface.c_str(), k, a.degree_of_flexibility, congruence(runs[0].result).c_str(),
                a.hausdorff_distance, a.mean_symmetric_distance, congruence(runs[1].result).c_str(),
                b.hausdorff_distance, b.mean_symmetric_distance,
                b.hausdorff_distance > 0 ? a.hausdorff_distance / b.hausdorff_distance : 0.0,
                runs[0].result.total_time, runs[1].result.total_time, a.number_of_distinct_molds);
  }
  std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::pair<const char*, TS::Solver_type> > solvers = {
    {"gauss-newton", TS::CONSTRAINED_GAUSS_NEWTON}, {"paper-cg", TS::PAPER_CONJUGATE_GRADIENT}};
  std::vector<std::string> selected;
  bool terms = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--solver" && i + 1 < argc)
    {
      const std::string s = argv[++i];
      if(s == "paper-cg") solvers.erase(solvers.begin());
      else if(s == "gauss-newton") solvers.pop_back();
      else if(s != "both") { std::cerr << "unknown solver " << s << "\n"; return 2; }
    }
    else if(a == "--terms")
      terms = true;
    else if(a == "--help" || a == "-h")
    {
      std::cout << "Usage: paper_table [--solver gauss-newton|paper-cg|both] [--terms] [SURFACE ...]\n"
                   "  --solver  which solvers to run, default both (side by side)\n"
                   "  --terms   print the paper's normalized terms of each run\n"
                   "  SURFACE: swiss_re tunnel seashell decocube monkey_saddle de_beers_ginza (default: all)\n";
      return 0;
    }
    else if(std::none_of(paper_rows.begin(), paper_rows.end(),
                         [&a](const auto& row) { return row.first == a; }))
    {
      std::cerr << "paper_table: unknown surface or option '" << a << "' (try --help)\n";
      return 2;
    }
    else
      selected.push_back(a);
  }

  print_header(terms, solvers.size() == 2);
  for(const auto& row : paper_rows)
  {
    if(!selected.empty() && std::find(selected.begin(), selected.end(), row.first) == selected.end())
      continue;
    Mesh input;
    const std::string path = std::string(CGAL_TILABLE_SURFACES_EXAMPLE_DATA) + "/" + row.first + ".off";
    if(!CGAL::IO::read_polygon_mesh(path, input))
    {
      std::cerr << "cannot read " << path << "\n";
      return 2;
    }
    for(int k : row.second)
    {
      std::vector<Run> runs;
      for(const auto& solver : solvers)
      {
        Mesh mesh = input;
        runs.push_back({solver.first, TS::make_k_set_tilable<CGAL::Parallel_if_available_tag>(
          mesh, TSP::number_of_tiles(k).solver(solver.second).random_seed(0u))});
      }
      print_rows(row.first, k, runs, terms);
    }
  }
  return 0;
}
