// Compiled twice by the testsuite: as is (must compile), and with a package
// parameter list that reuses a CGAL parameter name (must not compile).
#include <CGAL/Tilable_surfaces/named_parameters.h>

int main()
{
  const auto np = CGAL::Tilable_surfaces::parameters::number_of_tiles(3).number_of_iterations(2);
  (void)np;
  return 0;
}
