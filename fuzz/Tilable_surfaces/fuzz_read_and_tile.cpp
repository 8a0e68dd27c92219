// libFuzzer target over fuzz_one_input() (see fuzz_one_input.h): reading,
// validation and a small pipeline run. Built and run by scripts/fuzz.sh.
#include "fuzz_one_input.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size)
{
  fuzz_one_input(std::string(reinterpret_cast<const char*>(bytes), size));
  return 0;
}
