// Reproduces the paper's Table 1 (Fu et al. 2010) on the stand-ins of its six
// surfaces: for every surface and every K the paper reports, the mesh is made
// K-set tilable by make_k_set_tilable() (default parameters, random_seed 0)
// and one markdown row is printed: K, degree of flexibility, the normalized
// terms F̃_d..F̃_o, the approximation error to the input (max and mean, of the
// bounding-box diagonal), the measured congruence error, iterations and time.
//
// Usage: paper_table [--solver gauss-newton|paper-cg|both] [SURFACE ...]
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

void print_row(const std::string& surface, int k, const char* solver, const TS::K_set_tilable_result& r)
{
  const TS::Tilability_measure& m = r.optimization.measure;
  const TS::Energy_terms& t = m.normalized_terms;
  std::printf("| %s | %d | %zu | %s | %.2e | %.2e | %.2e | %.2e | %.2e | %.2e / %.2e | %.1e | %s | %d | %.2f |\n",
              surface.c_str(), k, m.degree_of_flexibility, solver, t.distance, t.fairness,
              t.edge_length, t.diagonal, t.volume, m.max_approximation_error,
              m.mean_approximation_error, m.congruence_error, r.is_tilable() ? "yes" : "**no**",
              r.optimization.iterations, r.total_time);
  std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::pair<const char*, TS::Solver_type> > solvers = {
    {"gauss-newton", TS::CONSTRAINED_GAUSS_NEWTON}};
  std::vector<std::string> selected;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--solver" && i + 1 < argc)
    {
      const std::string s = argv[++i];
      if(s == "paper-cg") solvers = {{"paper-cg", TS::PAPER_CONJUGATE_GRADIENT}};
      else if(s == "both") solvers.push_back({"paper-cg", TS::PAPER_CONJUGATE_GRADIENT});
      else if(s != "gauss-newton") { std::cerr << "unknown solver " << s << "\n"; return 2; }
    }
    else if(a == "--help" || a == "-h")
    {
      std::cout << "Usage: paper_table [--solver gauss-newton|paper-cg|both] [SURFACE ...]\n"
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

  std::printf("| surface | K | DOF | solver | F̃_d | F̃_f | F̃_e | F̃_a | F̃_o | approx. error max / mean | congruence | tilable | iterations | time (s) |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
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
      for(const auto& solver : solvers)
      {
        Mesh mesh = input;
        const TS::K_set_tilable_result r =
          TS::make_k_set_tilable(mesh, TSP::number_of_tiles(k).solver(solver.second).random_seed(0u));
        print_row(row.first, k, solver.first, r);
      }
  }
  return 0;
}
