// Replays every input the fuzzer once failed on (fuzz/Tilable_surfaces/
// regressions/) and the fuzzer's seeds through the fuzz target's body: each
// must be refused with Invalid_input or processed, and the outcome must be
// the one recorded in the file's name (accepted_* or refused_*).
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

} // namespace test_fuzz_regressions_unit
