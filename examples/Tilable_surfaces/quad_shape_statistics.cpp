// Reads a quad mesh, checks it, and prints statistics of its quad shapes:
// edge and diagonal lengths, signed volumes, planarity, and how far each quad
// is from its most similar other quad (the paper's dissimilarity, §3).
//
// Usage: quad_shape_statistics [mesh.off|obj|ply]   (default: bundled seashell)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/validation.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace TS = CGAL::Tilable_surfaces;

namespace {

struct Summary
{
  double min = 0, mean = 0, max = 0;
};

Summary summarize(std::vector<double> values)
{
  Summary s;
  if(values.empty())
    return s;
  s.min = *std::min_element(values.begin(), values.end());
  s.max = *std::max_element(values.begin(), values.end());
  for(double x : values)
    s.mean += x / double(values.size());
  return s;
}

void print_row(const std::string& name, const Summary& s)
{
  std::cout << "| " << std::left << std::setw(38) << name << std::right
            << " | " << std::setw(11) << s.min << " | " << std::setw(11) << s.mean
            << " | " << std::setw(11) << s.max << " |\n";
}

} // namespace

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1]
                                        : std::string(CGAL_TILABLE_SURFACES_EXAMPLE_DATA) + "/seashell.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh))
  {
    std::cerr << "error: cannot read a polygon mesh from '" << filename << "'\n";
    return 2;
  }
  try
  {
    TS::validate_panel_mesh(mesh);
  }
  catch(const TS::Invalid_input& e)
  {
    std::cerr << "error: " << filename << ": " << e.what() << "\n";
    return 2;
  }

  std::vector<TS::Panel> quads;
  for(auto f : faces(mesh))
    quads.push_back(TS::face_panel(f, mesh));

  std::vector<double> edges, diagonals, volumes, planarity;
  for(const TS::Panel& q : quads)
  {
    for(double e : TS::edge_lengths(q)) edges.push_back(e);
    for(double d : TS::diagonal_lengths(q)) diagonals.push_back(d);
    volumes.push_back(TS::signed_volume(q));
    planarity.push_back(TS::planarity_defect(q));
  }

  // Dissimilarity to the most similar other quad, relative to the mean edge
  // length: 0 means the quad already has a congruent twin.
  const double length_scale = TS::mean_edge_length(mesh);
  const std::size_t n = quads.size();
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
    {
      const double s = TS::dissimilarity(quads[i], quads[j]) / length_scale;
      nearest[i] = (std::min)(nearest[i], s);
      nearest[j] = (std::min)(nearest[j], s);
    }
  if(n < 2)
    nearest.clear();
  const std::size_t with_twin = std::count_if(nearest.begin(), nearest.end(),
                                              [](double s) { return s < 1e-6; });

  std::cout << filename << ": " << num_vertices(mesh) << " vertices, " << n
            << " quads, mean edge length " << length_scale << "\n\n";
  std::cout << "| quantity                               |         min |        mean |         max |\n"
            << "|----------------------------------------|-------------|-------------|-------------|\n";
  print_row("edge length", summarize(edges));
  print_row("diagonal length", summarize(diagonals));
  print_row("signed volume", summarize(volumes));
  print_row("planarity defect", summarize(planarity));
  print_row("nearest dissimilarity / mean edge", summarize(nearest));
  std::cout << "\n" << with_twin << " of " << n
            << " quads have a congruent twin (dissimilarity < 1e-6 mean edge length)\n";
  return 0;
}
