// Replays through the fuzz target's body every input the fuzzer once failed
// on (fuzz/Tilable_surfaces/regressions/), the outcome recorded in the file's
// name (accepted_* or refused_*), and the fuzzer's seeds from the test and
// example data (scripts/fuzz.sh), refused only for the mesh with faces of 5
// to 7 sides: each must be refused with Invalid_input or processed.
#include "../../fuzz/Tilable_surfaces/fuzz_one_input.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_fuzz_regressions_unit {

namespace fs = std::filesystem;

TEST(FuzzRegressions, EveryRecordedInputGivesItsRecordedOutcome)
{
  const fs::path dir = fs::path(CGAL_TILABLE_SURFACES_TEST_DATA) / ".." / ".." / ".." / "fuzz" /
                       "Tilable_surfaces" / "regressions";
  std::size_t replayed = 0;
  for(const auto& entry : fs::directory_iterator(dir))
  {
    const std::string name = entry.path().filename().string();
    const bool accepted = name.rfind("accepted_", 0) == 0;
    if(!accepted && name.rfind("refused_", 0) != 0)
      continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream data;
    data << in.rdbuf();
    EXPECT_EQ(fuzz_one_input(data.str()), accepted) << name;
    ++replayed;
  }
  EXPECT_GT(replayed, 0u);
}

TEST(FuzzRegressions, EverySeedFromTheDataGivesItsOutcome)
{
  const fs::path test_data(CGAL_TILABLE_SURFACES_TEST_DATA);
  std::size_t replayed = 0;
  for(const fs::path& dir : {test_data, test_data / ".." / ".." / ".." / "examples" / "Tilable_surfaces" / "data"})
    for(const auto& entry : fs::directory_iterator(dir))
    {
      const std::string extension = entry.path().extension().string();
      if(extension != ".off" && extension != ".obj")
        continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::ostringstream data;
      data << in.rdbuf();
      const std::string name = entry.path().filename().string();
      EXPECT_EQ(fuzz_one_input(data.str()), name != "double-torus-example.off") << name;
      ++replayed;
    }
  EXPECT_EQ(replayed, 19u) << "the 13 test meshes and the 6 example ones";
}

} // namespace test_fuzz_regressions_unit
