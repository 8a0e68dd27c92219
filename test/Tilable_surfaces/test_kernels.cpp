// The pipeline with the points of other kernels than Simple_cartesian<double>:
// exact predicates, with inexact and with exact constructions. Each result is
// checked for congruence independently. (Each kernel instantiates the whole
// pipeline: here, not among the input-handling tests that the sanitizers run.)
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include "any_mesh_check.h"

#include <gtest/gtest.h>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_kernels_unit {

namespace TS = CGAL::Tilable_surfaces;
using any_mesh_check::read;
using any_mesh_check::tile_and_check;

namespace {

// The monkey saddle at K = 30 with the points of `Kernel`: tilable, and the
// same numbers as with Simple_cartesian<double>, since the package computes in
// doubles whatever the kernel (it reads coordinates with to_double() and
// builds the moved points from doubles).
template <typename Kernel>
void check_same_as_on_doubles()
{
  typedef CGAL::Surface_mesh<typename Kernel::Point_3> Mesh;
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Plain;
  Mesh mesh = read<Mesh>("monkey_saddle.off");
  Plain plain = read<Plain>("monkey_saddle.off");
  const TS::K_set_tilable_result r = tile_and_check(mesh, 30), p = tile_and_check(plain, 30);
  EXPECT_EQ(r.optimization.measure.congruence_error, p.optimization.measure.congruence_error);
  auto v = vertices(plain).begin();
  for(auto w : vertices(mesh))
  {
    EXPECT_EQ(CGAL::to_double(mesh.point(w).x()), plain.point(*v).x());
    ++v;
  }
}

TEST(Kernels, ExactPredicatesInexactConstructions)
{
  check_same_as_on_doubles<CGAL::Exact_predicates_inexact_constructions_kernel>();
}

// Exact constructions work too (no static_assert is needed).
TEST(Kernels, ExactPredicatesExactConstructions)
{
  check_same_as_on_doubles<CGAL::Exact_predicates_exact_constructions_kernel>();
}

} // namespace

} // namespace test_kernels_unit
